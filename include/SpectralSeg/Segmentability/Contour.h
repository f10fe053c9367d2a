// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Contour.h
/// \brief The closed 2D polygon analysed by the segmentability test, and
/// its area and perimeter.
#ifndef SPECTRALSEG_SEGMENTABILITY_CONTOUR_H
#define SPECTRALSEG_SEGMENTABILITY_CONTOUR_H

#include <SpectralSeg/exceptions.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \ingroup PkgSpectralSegSegmentability
/// \brief A closed polygon in the plane: its vertices in order, the last one
/// joined to the first (which is not repeated at the end).
///
/// The functions of this package return counter-clockwise contours
/// (positive `signed_area()`), except where a degenerate input has no
/// orientation (fewer than three vertices, zero area).
typedef std::vector<Eigen::Vector2d> Contour;

/// \ingroup PkgSpectralSegSegmentability
/// \brief The signed area enclosed by `c` (shoelace formula): positive when
/// `c` is counter-clockwise, `0` with fewer than three vertices. For a
/// self-intersecting contour, each region counts with its winding number.
inline double signed_area(const Contour& c)
{
  const std::size_t n = c.size();
  if(n < 3)
    return 0.;
  double twice = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Vector2d& p = c[i];
    const Eigen::Vector2d& q = c[(i + 1) % n];
    twice += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * twice;
}

/// \ingroup PkgSpectralSegSegmentability
/// \brief The length of the closed polygon `c`, closing edge included
/// (twice the distance between the points when there are two, `0` with
/// fewer).
inline double perimeter(const Contour& c)
{
  const std::size_t n = c.size();
  if(n < 2)
    return 0.;
  double length = 0.;
  for(std::size_t i = 0; i < n; ++i)
    length += (c[(i + 1) % n] - c[i]).norm();
  return length;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// Reverses the order of the vertices of `c` if it is clockwise.
inline void make_counterclockwise(Contour& c)
{
  if(signed_area(c) < 0.)
    std::reverse(c.begin(), c.end());
}

inline void check_finite(const Contour& c, const char* function)
{
  for(const Eigen::Vector2d& p : c)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw Invalid_input(std::string(function) + ": the contour has a non-finite coordinate");
}

// The length of the diagonal of the bounding box of `c` (0 if empty).
inline double bounding_box_diagonal(const Contour& c)
{
  if(c.empty())
    return 0.;
  Eigen::Vector2d lo = c.front(), hi = c.front();
  for(const Eigen::Vector2d& p : c)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

} // namespace internal
/// \endcond

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_CONTOUR_H
