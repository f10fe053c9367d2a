// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file convexity.h
/// \brief The convexity of a contour and the segmentability score (thesis 6.2.4).
#ifndef SPECTRALSEG_SEGMENTABILITY_CONVEXITY_H
#define SPECTRALSEG_SEGMENTABILITY_CONVEXITY_H

#include <SpectralSeg/Segmentability/Contour.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \ingroup PkgSpectralSegSegmentability
/// \brief The convexity measures of a contour, as returned by `convexity()`.
///
/// All three are in \f$[0, 1]\f$ and equal 1 for a convex contour.
struct Convexity
{
  /// \f$C_1\f$: the area enclosed by the contour divided by the area of its
  /// convex hull
  double area_ratio = 1.;
  /// \f$C_2\f$: the perimeter of the convex hull divided by the perimeter
  /// of the contour
  double perimeter_ratio = 1.;
  /// \f$C = \max(C_1, C_2^{w})\f$, \f$w\f$ the perimeter exponent
  double convexity = 1.;
};

/// \ingroup PkgSpectralSegSegmentability
/// \brief The convexity of a contour: the area ratio \f$C_1\f$, the
/// perimeter ratio \f$C_2\f$, and their combination
/// \f$C = \max(C_1, C_2^{w})\f$.
///
/// \f$C_1\f$ misses thin dents that remove little area and \f$C_2\f$ is
/// sensitive to a jaggy boundary; the exponent \f$w\f$ lowers \f$C_2\f$ to
/// the range of \f$C_1\f$, and the maximum keeps whichever says "more
/// convex". The convex hull is CGAL's `convex_hull_2()` with exact
/// predicates. The area of the contour is the absolute value of its signed
/// area (a self-intersecting contour counts each region with its winding
/// number); both ratios are clamped to \f$[0, 1]\f$.
///
/// With holes (our addition, `Contour_options::count_holes`), the measures
/// are those of the region the contour encloses less its holes: \f$C_1\f$
/// takes the region's area, \f$(1 - h)\f$ times the contour's, and the
/// perimeter of \f$C_2\f$ adds the holes' boundaries.
///
/// \param c the contour (any orientation)
/// \param perimeter_exponent the exponent \f$w\f$ (the thesis uses 4)
/// \param holes \f$h\f$, the share of the area inside the contour that the
///        region does not cover (0: none, the thesis)
/// \param hole_perimeter the length of the holes' boundaries
/// \return the measures; all three are 1 for a degenerate contour (fewer
///         than three points, or a convex hull of zero area), which has no
///         concavity to show
/// \throws Invalid_input if a coordinate is not finite,
///         `perimeter_exponent` is not finite and positive, `holes` is not in
///         \f$[0, 1]\f$ or `hole_perimeter` is negative or not finite
SPECTRALSEG_INLINE Convexity convexity(const Contour& c, double perimeter_exponent = 4., double holes = 0.,
                                       double hole_perimeter = 0.)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_finite(c, "convexity");
  if(!(perimeter_exponent > 0.) || !std::isfinite(perimeter_exponent))
    throw Invalid_input("convexity: the perimeter exponent must be finite and positive, got " +
                        std::to_string(perimeter_exponent));
  if(!(holes >= 0. && holes <= 1.) || !(hole_perimeter >= 0.) || !std::isfinite(hole_perimeter))
    throw Invalid_input("convexity: the holes' share must be in [0, 1] and their perimeter finite and non-negative");
  Convexity result;
  if(c.size() < 3)
    return result;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<K::Point_2> points, hull_points;
  points.reserve(c.size());
  for(const Eigen::Vector2d& p : c)
    points.emplace_back(p.x(), p.y());
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull_points));
  Contour hull;
  hull.reserve(hull_points.size());
  for(const K::Point_2& p : hull_points)
    hull.emplace_back(p.x(), p.y());
  const double hull_area = std::abs(signed_area(hull));
  const double contour_perimeter = perimeter(c);
  if(hull.size() < 3 || !(hull_area > 0.) || !(contour_perimeter > 0.))
    return result;
  result.area_ratio = std::clamp((1. - holes) * std::abs(signed_area(c)) / hull_area, 0., 1.);
  result.perimeter_ratio = std::clamp(perimeter(hull) / (contour_perimeter + hole_perimeter), 0., 1.);
  result.convexity = std::max(result.area_ratio, std::pow(result.perimeter_ratio, perimeter_exponent));
  return result;
}
#else
;
#endif

/// \ingroup PkgSpectralSegSegmentability
/// \brief The segmentability score \f$S = 1 - C\f$ of a contour, with
/// \f$C\f$ the convexity of `convexity()`: 0 for a convex contour, close
/// to 1 for a very concave one. The thesis deems a contour segmentable when
/// \f$S > 0.1\f$.
///
/// \return a value in \f$[0, 1)\f$ (\f$C_2 > 0\f$ whenever the hull has
///         a positive area); 0 for a degenerate contour
/// \throws Invalid_input as `convexity()`
SPECTRALSEG_INLINE double segmentability_score(const Contour& c, double perimeter_exponent = 4.)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  return 1. - convexity(c, perimeter_exponent).convexity;
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_CONVEXITY_H
