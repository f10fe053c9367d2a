// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef SPECTRALSEG_INTERNAL_POINT_NEIGHBOURS_H
#define SPECTRALSEG_INTERNAL_POINT_NEIGHBOURS_H

#include <SpectralSeg/internal/separate_compilation.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace internal {

// k-nearest-neighbour queries on a fixed point set (CGAL kd-tree). The tree
// is built in the constructor, so const queries may run concurrently.
class Point_neighbours
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Pointer_property_map<K::Point_3>::const_type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<K>> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef Search::Tree Tree;
  typedef Search::Distance Distance;

public:
  Point_neighbours(const Point_neighbours&) = delete;
  Point_neighbours& operator=(const Point_neighbours&) = delete;

  explicit Point_neighbours(const std::vector<Eigen::Vector3d>& points);

  std::size_t size() const { return points_.size(); }

  // The k nearest points to q as (index, squared distance), nearest first;
  // ties are broken by index so that the result is deterministic.
  std::vector<std::pair<std::size_t, double>> nearest(const Eigen::Vector3d& q, std::size_t k) const;

  // The same into `out` (cleared first), so that a caller reuses its storage.
  void nearest(const Eigen::Vector3d& q, std::size_t k, std::vector<std::pair<std::size_t, double>>& out) const;

private:
  std::vector<K::Point_3> points_;
  Point_map map_;
  std::unique_ptr<Tree> tree_;
};

#if SPECTRALSEG_DEFINE_FUNCTIONS
SPECTRALSEG_INLINE Point_neighbours::Point_neighbours(const std::vector<Eigen::Vector3d>& points)
{
  points_.reserve(points.size());
  for(const auto& p : points)
    points_.emplace_back(p.x(), p.y(), p.z());
  map_ = Point_map(points_.data());
  std::vector<std::size_t> ids(points_.size());
  for(std::size_t i = 0; i < ids.size(); ++i)
    ids[i] = i;
  tree_.reset(new Tree(ids.begin(), ids.end(), Tree::Splitter(), Traits(map_)));
  tree_->build();
}

SPECTRALSEG_INLINE std::vector<std::pair<std::size_t, double>> Point_neighbours::nearest(const Eigen::Vector3d& q,
                                                                                         std::size_t k) const
{
  std::vector<std::pair<std::size_t, double>> out;
  nearest(q, k, out);
  return out;
}

SPECTRALSEG_INLINE void Point_neighbours::nearest(const Eigen::Vector3d& q, std::size_t k,
                                                  std::vector<std::pair<std::size_t, double>>& out) const
{
  out.clear();
  if(points_.empty() || k == 0)
    return;
  const Search search(*tree_, K::Point_3(q.x(), q.y(), q.z()), static_cast<unsigned int>(k), 0, true,
                      Distance(map_));
  for(const auto& n : search)
    out.emplace_back(n.first, n.second);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return a.second < b.second || (a.second == b.second && a.first < b.first);
  });
}
#endif

} // namespace internal
} // namespace SpectralSeg

#endif // SPECTRALSEG_INTERNAL_POINT_NEIGHBOURS_H
