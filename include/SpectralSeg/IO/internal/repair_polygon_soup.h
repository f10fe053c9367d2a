// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file repair_polygon_soup.h
/// \brief The repairs of `read_mesh_file()` and `triangle_soup_to_mesh()`,
/// one function per step: welding identical vertices, cleaning,
/// deduplicating and triangulating faces, counting non-manifold edges.
#ifndef SPECTRALSEG_IO_INTERNAL_REPAIR_POLYGON_SOUP_H
#define SPECTRALSEG_IO_INTERNAL_REPAIR_POLYGON_SOUP_H

#include <SpectralSeg/IO/Mesh_file_report.h>
#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <iterator>
#include <tuple>
#include <vector>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// Merges the points with identical coordinates: returns, for each point of
// the soup, its index among the merged points, which replace `points`. The
// merged points keep the order of their first occurrence. O(n log n), the
// sort on `threads` threads (the same result on any number).
SPECTRALSEG_INLINE std::vector<std::size_t> weld_identical_vertices(std::vector<std::array<double, 3>>& points,
                                                                    unsigned threads = 1)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = points.size();
  std::vector<std::size_t> order(n);
  for(std::size_t v = 0; v < n; ++v)
    order[v] = v;
  // equal coordinates end up together, the first occurrence first (ties
  // by index: a total order)
  ::SpectralSeg::internal::parallel_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return points[a] < points[b] || (!(points[b] < points[a]) && a < b);
  }, threads);
  std::vector<std::size_t> first(n); // each point's first occurrence
  for(std::size_t i = 0; i < n; ++i)
    first[order[i]] = (i > 0 && !(points[order[i - 1]] < points[order[i]])) ? first[order[i - 1]] : order[i];
  std::vector<std::size_t> weld(n);
  std::vector<std::array<double, 3>> unique;
  for(std::size_t v = 0; v < n; ++v)
  {
    if(first[v] == v)
    {
      weld[v] = unique.size();
      unique.push_back(points[v]);
    }
    else
      weld[v] = weld[first[v]];
  }
  if(unique.size() != n)
    points.swap(unique);
  return weld;
}
#else
;
#endif

// The triangles of the cleaned soup and where each face of the file went.
struct Clean_triangles
{
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::size_t> input_face_of_triangle;
  std::vector<std::size_t> first_triangle; // per file face, or no_face
  std::vector<std::size_t> duplicate_of;   // per file face: the face it repeats, or no_face
};

// Maps faces to welded vertices, drops faces with fewer than three
// distinct vertices and repeats of an earlier face's vertex set, and
// triangulates polygons with `triangulate` (a polygon's positions, as
// `Point`s, to triangles of indices into them: triangulate_polygon() of
// triangulate_polygon.h); counts each in `report`. The faces of three
// vertices are sorted on `threads` threads (the same result on any number).
template <typename Point, typename Triangulate>
Clean_triangles clean_and_triangulate_faces(const Polygon_soup& soup, const std::vector<std::size_t>& weld,
                                            Mesh_file_report& report, const Triangulate& triangulate,
                                            unsigned threads = 1)
{
  const std::size_t faces = soup.number_of_faces();
  Clean_triangles out;
  out.first_triangle.assign(faces, Mesh_file_report::no_face);
  out.duplicate_of.assign(faces, Mesh_file_report::no_face);
  out.triangles.reserve(faces);
  out.input_face_of_triangle.reserve(faces);

  // Each face's welded polygon (consecutive repeats removed) and its sorted
  // vertex set, the key that finds repeated faces.
  std::vector<std::size_t> polygons, keys;
  std::vector<std::size_t> begin(faces + 1, 0);
  std::vector<std::uint8_t> valid(faces, 0);
  // a soup of triangles only (the usual file): each face in place, on
  // `threads` threads; a triangle is valid when its three welded vertices
  // differ, and then its polygon is those three (what the loop below makes)
  bool all_triangles = soup.corners.size() == 3 * faces;
  for(std::size_t p = 0; all_triangles && p < faces; ++p)
    all_triangles = soup.face_begin[p + 1] == 3 * (p + 1);
  if(all_triangles)
  {
    polygons.resize(3 * faces);
    keys.resize(3 * faces);
    ::SpectralSeg::internal::parallel_range(0, faces, threads, [&](std::size_t p) {
      const std::size_t* corner = soup.face(p);
      std::size_t* polygon = polygons.data() + 3 * p;
      std::size_t* key = keys.data() + 3 * p;
      for(int i = 0; i < 3; ++i)
        polygon[i] = key[i] = weld[corner[i]];
      std::sort(key, key + 3);
      begin[p + 1] = 3 * (p + 1);
      valid[p] = key[0] != key[1] && key[1] != key[2] ? 1 : 0;
    });
  }
  else
  {
    polygons.reserve(soup.corners.size());
    keys.reserve(soup.corners.size());
    for(std::size_t p = 0; p < faces; ++p)
    {
      const std::size_t start = polygons.size();
      for(std::size_t i = 0; i < soup.face_size(p); ++i)
      {
        const std::size_t w = weld[soup.face(p)[i]];
        if(polygons.size() == start || polygons.back() != w)
          polygons.push_back(w);
      }
      while(polygons.size() > start + 1 && polygons[start] == polygons.back())
        polygons.pop_back();
      keys.insert(keys.end(), polygons.begin() + std::ptrdiff_t(start), polygons.end());
      std::sort(keys.begin() + std::ptrdiff_t(start), keys.end());
      begin[p + 1] = polygons.size();
      valid[p] = (polygons.size() - start >= 3 &&
                  std::adjacent_find(keys.begin() + std::ptrdiff_t(start), keys.end()) == keys.end())
                   ? 1
                   : 0;
    }
  }

  // Repeats: the valid faces sorted by key, ties by file order.
  const auto key_less = [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(keys.begin() + std::ptrdiff_t(begin[a]),
                                        keys.begin() + std::ptrdiff_t(begin[a + 1]),
                                        keys.begin() + std::ptrdiff_t(begin[b]),
                                        keys.begin() + std::ptrdiff_t(begin[b + 1]));
  };
  std::vector<std::size_t> order;
  order.reserve(faces);
  bool small_triangles = soup.points.size() < (std::size_t(1) << 32);
  for(std::size_t p = 0; p < faces; ++p)
    if(valid[p])
    {
      order.push_back(p);
      small_triangles = small_triangles && begin[p + 1] - begin[p] == 3;
    }
  if(small_triangles) // the common case, sorted by value: several times faster
  {
    std::vector<std::array<std::uint32_t, 4>> sorted(order.size()); // key, then file face
    ::SpectralSeg::internal::parallel_range(0, order.size(), threads, [&](std::size_t i) {
      const std::size_t* key = keys.data() + begin[order[i]];
      sorted[i] = {std::uint32_t(key[0]), std::uint32_t(key[1]), std::uint32_t(key[2]), std::uint32_t(order[i])};
    });
    if(faces < (std::size_t(1) << 32))
    {
      // the file face last: no two entries are equal
      ::SpectralSeg::internal::parallel_sort(sorted.begin(), sorted.end(),
                                             std::less<std::array<std::uint32_t, 4>>(), threads);
      for(std::size_t i = 0; i < sorted.size(); ++i)
        order[i] = sorted[i][3];
    }
    else
      std::stable_sort(order.begin(), order.end(), key_less);
  }
  else
    std::stable_sort(order.begin(), order.end(), key_less);
  for(std::size_t i = 1; i < order.size(); ++i)
    if(!key_less(order[i - 1], order[i]))
      out.duplicate_of[order[i]] =
        out.duplicate_of[order[i - 1]] != Mesh_file_report::no_face ? out.duplicate_of[order[i - 1]] : order[i - 1];

  if(all_triangles)
  {
    // each kept face's triangle at its rank among the kept faces
    std::size_t kept = 0;
    for(std::size_t p = 0; p < faces; ++p)
    {
      if(!valid[p])
        ++report.invalid_faces;
      else if(out.duplicate_of[p] != Mesh_file_report::no_face)
        ++report.duplicate_faces;
      else
        out.first_triangle[p] = kept++;
    }
    out.triangles.resize(kept);
    out.input_face_of_triangle.resize(kept);
    ::SpectralSeg::internal::parallel_range(0, faces, threads, [&](std::size_t p) {
      const std::size_t t = out.first_triangle[p];
      if(t == Mesh_file_report::no_face)
        return;
      const std::size_t* polygon = polygons.data() + 3 * p;
      out.triangles[t] = {polygon[0], polygon[1], polygon[2]};
      out.input_face_of_triangle[t] = p;
    });
    return out;
  }
  std::vector<std::size_t> poly;
  for(std::size_t p = 0; p < faces; ++p)
  {
    if(!valid[p])
    {
      ++report.invalid_faces;
      continue;
    }
    if(out.duplicate_of[p] != Mesh_file_report::no_face)
    {
      ++report.duplicate_faces;
      continue;
    }
    poly.assign(polygons.begin() + std::ptrdiff_t(begin[p]), polygons.begin() + std::ptrdiff_t(begin[p + 1]));
    out.first_triangle[p] = out.triangles.size();
    if(poly.size() == 3)
    {
      out.triangles.push_back({poly[0], poly[1], poly[2]});
      out.input_face_of_triangle.push_back(p);
      continue;
    }
    ++report.non_triangle_faces;
    std::vector<Point> positions;
    for(std::size_t v : poly)
      positions.push_back(Point(soup.points[v][0], soup.points[v][1], soup.points[v][2]));
    for(const auto& t : triangulate(positions))
    {
      ++report.triangles_from_polygons;
      out.triangles.push_back({poly[t[0]], poly[t[1]], poly[t[2]]});
      out.input_face_of_triangle.push_back(p);
    }
  }
  return out;
}

// The undirected edges of the triangles, (smaller, larger) vertex, sorted.
SPECTRALSEG_INLINE std::vector<std::uint64_t> sorted_edge_keys(const std::vector<std::array<std::size_t, 3>>& triangles)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<std::uint64_t> keys;
  keys.reserve(3 * triangles.size());
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i)
    {
      std::uint64_t a = t[std::size_t(i)], b = t[std::size_t((i + 1) % 3)];
      if(a > b)
        std::swap(a, b);
      keys.push_back((a << 32) | b);
    }
  std::sort(keys.begin(), keys.end());
  return keys;
}
#else
;
#endif

// Edges of the triangles shared by more than two of them.
SPECTRALSEG_INLINE std::size_t count_non_manifold_edges(const std::vector<std::array<std::size_t, 3>>& triangles)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::vector<std::uint64_t> keys = sorted_edge_keys(triangles);
  std::size_t n = 0;
  for(std::size_t i = 0; i < keys.size();)
  {
    std::size_t j = i + 1;
    while(j < keys.size() && keys[j] == keys[i])
      ++j;
    n += j - i > 2 ? 1 : 0;
    i = j;
  }
  return n;
}
#else
;
#endif

// True when the triangles already form a consistently oriented 2-manifold
// (with or without boundary): no directed edge twice, and the triangles
// around each vertex one fan. Then CGAL's orient_polygon_soup() has nothing
// to do. O(n log d) for n triangles and vertex degrees up to d (a fan of a
// million triangles around one vertex included); indices must fit 32 bits.
// The vertices are checked on `threads` threads (the answer is the same).
SPECTRALSEG_INLINE bool is_oriented_manifold_soup(std::size_t vertices, const std::vector<std::array<std::size_t, 3>>& triangles,
                                                  unsigned threads = 1)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(vertices >= (std::size_t(1) << 32))
    return false;
  // The link of vertex v: an edge a -> b for each triangle (v, a, b), one
  // for each directed edge v -> a of the triangles. A directed edge twice is
  // a link vertex with two successors; with unique directed edges every
  // link vertex has at most one successor and one predecessor: the link is
  // paths and cycles, and v is regular when it is exactly one of them.
  std::vector<std::size_t> first(vertices + 1, 0);
  for(const auto& t : triangles)
    for(std::size_t v : t)
      ++first[v + 1];
  for(std::size_t v = 0; v < vertices; ++v)
    first[v + 1] += first[v];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> link(first[vertices]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(const auto& t : triangles)
      for(std::size_t i = 0; i < 3; ++i)
        link[fill[t[i]]++] = {std::uint32_t(t[(i + 1) % 3]), std::uint32_t(t[(i + 2) % 3])};
  }
  const auto regular = [&](std::size_t v, std::vector<std::uint8_t>& has_predecessor) {
    const auto lo = link.begin() + std::ptrdiff_t(first[v]), hi = link.begin() + std::ptrdiff_t(first[v + 1]);
    const std::size_t degree = std::size_t(hi - lo);
    if(degree < 2)
      return true;
    std::sort(lo, hi); // by link vertex: its successor is found by bisection
    const auto successor_of = [&](std::uint32_t a) {
      const auto e = std::lower_bound(lo, hi, a, [](const std::pair<std::uint32_t, std::uint32_t>& x, std::uint32_t y) {
        return x.first < y;
      });
      return (e != hi && e->first == a) ? e : hi;
    };
    for(auto e = lo + 1; e != hi; ++e)
      if(e->first == (e - 1)->first)
        return false; // the directed edge v -> e->first twice
    // a path starts at a link vertex without predecessor
    has_predecessor.assign(degree, 0);
    for(auto e = lo; e != hi; ++e)
    {
      const auto s = successor_of(e->second);
      if(s != hi)
        has_predecessor[std::size_t(s - lo)] = 1;
    }
    std::size_t starts = 0;
    std::uint32_t start = lo->first;
    for(std::size_t i = 0; i < degree; ++i)
      if(!has_predecessor[i])
      {
        ++starts;
        start = (lo + std::ptrdiff_t(i))->first;
      }
    if(starts > 1)
      return false;
    // walk from the start: every link edge must be met
    std::size_t walked = 0;
    std::uint32_t at = start;
    for(;;)
    {
      const auto e = successor_of(at);
      if(e == hi)
        break;
      ++walked;
      at = e->second;
      if(at == start || walked > degree)
        break;
    }
    return walked == degree;
  };
  // each vertex's link is its own: the vertices in blocks, any order
  const std::size_t block = 4096;
  std::atomic<bool> ok(true);
  ::SpectralSeg::internal::parallel_range(0, (vertices + block - 1) / block, threads, [&](std::size_t b) {
    std::vector<std::uint8_t> has_predecessor;
    for(std::size_t v = b * block; v < std::min(vertices, (b + 1) * block) && ok.load(std::memory_order_relaxed); ++v)
      if(!regular(v, has_predecessor))
        ok = false;
  });
  return ok;
}
#else
;
#endif

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_REPAIR_POLYGON_SOUP_H
