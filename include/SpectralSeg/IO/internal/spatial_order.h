// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The order along a Hilbert curve in which the readers store a mesh's
// vertices and faces, whatever their order in the file.
#ifndef SPECTRALSEG_IO_INTERNAL_SPATIAL_ORDER_H
#define SPECTRALSEG_IO_INTERNAL_SPATIAL_ORDER_H

#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <CGAL/Hilbert_sort_median_3.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace SpectralSeg {
namespace IO {
namespace internal {

// A point to sort, carrying the index it had: CGAL's spatial-sorting traits
// below compare positions along one axis with ties broken by the other two
// axes and then by the keys' tie triples (`ties[index]`; without ties, by
// index). The comparisons are a strict total order, so each median split of
// CGAL's Hilbert sort puts the same keys on each side whatever the order
// they come in: the sorted sequence depends on the keys only (not on the
// input order, nor on a shuffle). The triples stay out of the keys, which
// the median splits move: 32 bytes a key instead of 56.
struct Spatial_order_key
{
  std::array<double, 3> position;
  std::size_t index;
};

class Spatial_order_traits
{
public:
  typedef Spatial_order_key Point_3;
  typedef std::array<std::size_t, 3> Tie;

  explicit Spatial_order_traits(const Tie* ties = nullptr) : ties_(ties) {}

  template <int axis>
  struct Less
  {
    const Tie* ties;
    bool operator()(const Spatial_order_key& p, const Spatial_order_key& q) const
    {
      for(int i = 0; i < 3; ++i)
      {
        const int c = (axis + i) % 3;
        if(p.position[c] != q.position[c])
          return p.position[c] < q.position[c];
      }
      return ties != nullptr ? ties[p.index] < ties[q.index] : p.index < q.index;
    }
  };
  typedef Less<0> Less_x_3;
  typedef Less<1> Less_y_3;
  typedef Less<2> Less_z_3;
  Less_x_3 less_x_3_object() const { return Less_x_3{ties_}; }
  Less_y_3 less_y_3_object() const { return Less_y_3{ties_}; }
  Less_z_3 less_z_3_object() const { return Less_z_3{ties_}; }

private:
  const Tie* ties_;
};

// The indices of `keys` in the order of a Hilbert curve through their
// positions (CGAL's median policy: the curve adapts to where the points are),
// equal positions in the order of `ties[index]` (null: of index).
// The keys themselves are sorted, not indices into them: the median splits
// then read memory in sequence instead of jumping through an index array.
// With several threads the independent splits of the curve's first level
// run side by side and its eight octants are sorted in parallel, as in
// CGAL's parallel Hilbert sort; every split and every octant's sort is the
// sequential sort's, on the same keys, so the order does not depend on the
// number of threads.
SPECTRALSEG_INLINE std::vector<std::size_t> hilbert_order(std::vector<Spatial_order_key>& keys, unsigned threads = 1,
                                                         const Spatial_order_traits::Tie* ties = nullptr)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  typedef CGAL::Hilbert_sort_median_3<Spatial_order_traits, CGAL::Sequential_tag> Sort;
  const Sort sort{Spatial_order_traits(ties)};
  if(threads < 2 || keys.size() <= 2048)
    sort(keys.begin(), keys.end());
  else
  {
    // the first level of Sort's recursive_sort<0, false, false, false>:
    // axes x = 0, y = 1, z = 2, none reversed
    typedef std::vector<Spatial_order_key>::iterator It;
    typedef Spatial_order_traits T;
    const T k(ties);
    using CGAL::internal::hilbert_split;
    using CGAL::internal::Hilbert_cmp_3;
    const It m0 = keys.begin(), m8 = keys.end();
    const It m4 = hilbert_split(m0, m8, Hilbert_cmp_3<T, 0, false>(k));
    It m1, m2, m3, m5, m6, m7;
    ::SpectralSeg::internal::parallel_range(0, 2, threads, [&](std::size_t i) {
      if(i == 0)
        m2 = hilbert_split(m0, m4, Hilbert_cmp_3<T, 1, false>(k));
      else
        m6 = hilbert_split(m4, m8, Hilbert_cmp_3<T, 1, true>(k));
    });
    ::SpectralSeg::internal::parallel_range(0, 4, threads, [&](std::size_t i) {
      switch(i)
      {
      case 0: m1 = hilbert_split(m0, m2, Hilbert_cmp_3<T, 2, false>(k)); break;
      case 1: m3 = hilbert_split(m2, m4, Hilbert_cmp_3<T, 2, true>(k)); break;
      case 2: m5 = hilbert_split(m4, m6, Hilbert_cmp_3<T, 2, false>(k)); break;
      default: m7 = hilbert_split(m6, m8, Hilbert_cmp_3<T, 2, true>(k)); break;
      }
    });
    ::SpectralSeg::internal::parallel_range(0, 8, threads, [&](std::size_t i) {
      switch(i)
      {
      case 0: sort.recursive_sort<2, false, false, false>(m0, m1); break;
      case 1: sort.recursive_sort<1, false, false, false>(m1, m2); break;
      case 2: sort.recursive_sort<1, false, false, false>(m2, m3); break;
      case 3: sort.recursive_sort<0, false, true, true>(m3, m4); break;
      case 4: sort.recursive_sort<0, false, true, true>(m4, m5); break;
      case 5: sort.recursive_sort<1, true, false, true>(m5, m6); break;
      case 6: sort.recursive_sort<1, true, false, true>(m6, m7); break;
      default: sort.recursive_sort<2, true, true, false>(m7, m8); break;
      }
    });
  }
  std::vector<std::size_t> order(keys.size());
  ::SpectralSeg::internal::parallel_range(0, keys.size(), threads, [&](std::size_t i) { order[i] = keys[i].index; });
  return order;
}
#else
;
#endif

// Reorders `items` along `order` (items[order[0]] first, `order` a
// permutation) and returns the new index of each item; on `threads` threads.
template <typename T>
std::vector<std::size_t> apply_order(std::vector<T>& items, const std::vector<std::size_t>& order,
                                     unsigned threads = 1)
{
  std::vector<std::size_t> new_index(items.size());
  std::vector<T> sorted(items.size());
  ::SpectralSeg::internal::parallel_range(0, order.size(), threads, [&](std::size_t i) {
    new_index[order[i]] = i;
    sorted[i] = items[order[i]];
  });
  items.swap(sorted);
  return new_index;
}

// Renumbers `points` and `triangles` in place along Hilbert curves: the
// vertices by position, the triangles by centroid (ties by their vertices),
// each triangle starting at its lowest vertex index (its orientation kept).
// Returns the new index of each triangle. Vertices at the same position (the
// copies that splitting a non-manifold vertex makes) keep their relative
// order; everything else ends in an order that does not depend on the input
// order, so that the memory access patterns of what follows, and its
// results, do not either. Sorted on `threads` threads (the same order on
// any number).
template <typename Point>
std::vector<std::size_t> sort_along_hilbert_curve(std::vector<Point>& points,
                                                  std::vector<std::array<std::size_t, 3>>& triangles,
                                                  unsigned threads = 1)
{
  std::vector<Spatial_order_key> keys(points.size());
  ::SpectralSeg::internal::parallel_range(0, points.size(), threads, [&](std::size_t v) {
    keys[v] = {{{CGAL::to_double(points[v].x()), CGAL::to_double(points[v].y()), CGAL::to_double(points[v].z())}}, v};
  });
  const std::vector<std::size_t> new_vertex = apply_order(points, hilbert_order(keys, threads), threads);

  keys.resize(triangles.size()); // every key is written below
  ::SpectralSeg::internal::parallel_range(0, triangles.size(), threads, [&](std::size_t t) {
    std::array<std::size_t, 3>& tri = triangles[t];
    for(std::size_t& v : tri)
      v = new_vertex[v];
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    Spatial_order_key& k = keys[t];
    k.position = {{0.0, 0.0, 0.0}};
    for(const std::size_t v : tri)
    {
      k.position[0] += CGAL::to_double(points[v].x()) / 3;
      k.position[1] += CGAL::to_double(points[v].y()) / 3;
      k.position[2] += CGAL::to_double(points[v].z()) / 3;
    }
    k.index = t;
  });
  // equal centroids in the order of the triangles' vertices
  return apply_order(triangles, hilbert_order(keys, threads, triangles.data()), threads);
}

} // namespace internal
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_SPATIAL_ORDER_H
