// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file inner_distances.h
/// \brief Shortest paths inside a polygon between its vertices (thesis 6.2.4).
#ifndef SPECTRALSEG_SEGMENTABILITY_INNER_DISTANCES_H
#define SPECTRALSEG_SEGMENTABILITY_INNER_DISTANCES_H

#include <SpectralSeg/Segmentability/Contour.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \cond SKIP_IN_MANUAL
namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Contour_kernel;

// Even-odd test of a point against the closed polygon `polygon`; points on
// the boundary may go either way.
SPECTRALSEG_INLINE bool inside_even_odd(const std::vector<Contour_kernel::Point_2>& polygon,
                                        const Contour_kernel::Point_2& q)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  bool inside = false;
  const std::size_t n = polygon.size();
  for(std::size_t k = 0; k < n; ++k)
  {
    const Contour_kernel::Point_2& a = polygon[k];
    const Contour_kernel::Point_2& b = polygon[(k + 1) % n];
    const bool a_above = a.y() > q.y(), b_above = b.y() > q.y();
    if(a_above == b_above)
      continue;
    // the edge crosses the horizontal line through q: on which side of it?
    const CGAL::Orientation o = CGAL::orientation(a, b, q);
    if((b_above && o == CGAL::LEFT_TURN) || (!b_above && o == CGAL::RIGHT_TURN))
      inside = !inside;
  }
  return inside;
}
#else
;
#endif

// Whether the open segments pq and rs cross at one point inside both.
SPECTRALSEG_INLINE bool cross_properly(const Contour_kernel::Point_2& p, const Contour_kernel::Point_2& q,
                                       const Contour_kernel::Point_2& r, const Contour_kernel::Point_2& s)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const CGAL::Orientation o1 = CGAL::orientation(p, q, r), o2 = CGAL::orientation(p, q, s);
  const CGAL::Orientation o3 = CGAL::orientation(r, s, p), o4 = CGAL::orientation(r, s, q);
  return o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o1 != o2 && o3 != CGAL::COLLINEAR &&
         o4 != CGAL::COLLINEAR && o3 != o4;
}
#else
;
#endif

// Whether vertices i and j of the polygon see each other through its
// interior (see inner_distances()).
SPECTRALSEG_INLINE bool see_each_other(const std::vector<Contour_kernel::Point_2>& polygon, std::size_t i,
                                       std::size_t j)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = polygon.size();
  const Contour_kernel::Point_2& p = polygon[i];
  const Contour_kernel::Point_2& q = polygon[j];
  if(p == q)
    return true; // a repeated point: distance 0 either way
  for(std::size_t k = 0; k < n; ++k)
  {
    if(k == i || k == j)
      continue;
    const Contour_kernel::Point_2& r = polygon[k];
    // a vertex on the segment: the path through that vertex is as short
    if(CGAL::collinear(p, q, r) && CGAL::collinear_are_ordered_along_line(p, r, q))
      return false;
    const std::size_t l = (k + 1) % n;
    if(l == i || l == j)
      continue;
    if(cross_properly(p, q, r, polygon[l]))
      return false;
  }
  return inside_even_odd(polygon, CGAL::midpoint(p, q));
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegSegmentability
/// \brief The inner distances between the vertices of a contour: the
/// lengths of the shortest paths between them that stay inside the polygon.
///
/// A visibility graph is built on the vertices: two consecutive vertices
/// are always joined (by their edge); two other vertices are joined by a
/// straight segment if it crosses no edge of the contour, passes through no
/// other vertex (the path through that vertex is as short) and its midpoint
/// is inside the contour (even-odd rule). The shortest paths in this graph
/// (Floyd-Warshall) are the inner distances. The orientation tests use
/// CGAL's exact predicates, so the result does not depend on rounding.
///
/// The walk along the contour always exists, so every distance is finite,
/// also for a self-intersecting contour (which smoothing and simplification
/// may produce; the paths there are only approximately inner).
/// The cost is \f$O(n^3)\f$ for \f$n\f$ vertices: meant for simplified
/// contours (the thesis uses 50 vertices).
///
/// \param c the contour (any orientation)
/// \return the symmetric \f$n \times n\f$ matrix of inner distances, with a
///         zero diagonal; empty for an empty contour
/// \throws Invalid_input if a coordinate is not finite
SPECTRALSEG_INLINE Eigen::MatrixXd inner_distances(const Contour& c)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_finite(c, "inner_distances");
  typedef internal::Contour_kernel::Point_2 Point;
  const std::size_t n = c.size();
  const Eigen::Index size = Eigen::Index(n);
  std::vector<Point> polygon;
  polygon.reserve(n);
  for(const Eigen::Vector2d& p : c)
    polygon.emplace_back(p.x(), p.y());

  Eigen::MatrixXd d = Eigen::MatrixXd::Constant(size, size, std::numeric_limits<double>::infinity());
  for(std::size_t i = 0; i < n; ++i)
  {
    d(Eigen::Index(i), Eigen::Index(i)) = 0.;
    for(std::size_t j = i + 1; j < n; ++j)
    {
      const bool consecutive = j == i + 1 || (i == 0 && j == n - 1);
      if(consecutive || internal::see_each_other(polygon, i, j))
        d(Eigen::Index(i), Eigen::Index(j)) = d(Eigen::Index(j), Eigen::Index(i)) = (c[j] - c[i]).norm();
    }
  }
  const double unreachable = std::numeric_limits<double>::infinity();
  for(Eigen::Index k = 0; k < size; ++k)
    for(Eigen::Index j = 0; j < size; ++j)
    {
      const double dkj = d(k, j);
      if(dkj == unreachable)
        continue;
      for(Eigen::Index i = 0; i < size; ++i)
        d(i, j) = std::min(d(i, j), d(i, k) + dkj);
    }
  // Floyd-Warshall keeps the matrix symmetric up to the order of additions
  d = 0.5 * (d + d.transpose()).eval();
  return d;
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_INNER_DISTANCES_H
