// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Contour_analysis.h
/// \brief The contour analysis of one 2D projection in the segmentability
/// test, in one call (thesis 6.2.3 and 6.2.4).
#ifndef SPECTRALSEG_SEGMENTABILITY_CONTOUR_ANALYSIS_H
#define SPECTRALSEG_SEGMENTABILITY_CONTOUR_ANALYSIS_H

#include <SpectralSeg/Segmentability/Contour.h>
#include <SpectralSeg/Segmentability/convexity.h>
#include <SpectralSeg/Segmentability/inner_distances.h>
#include <SpectralSeg/Segmentability/integrated_bending_score.h>
#include <SpectralSeg/Segmentability/multidimensional_scaling.h>
#include <SpectralSeg/Segmentability/simplify_contour.h>
#include <SpectralSeg/Segmentability/smooth_contour.h>
#include <SpectralSeg/Segmentability/trace_outer_contour.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \ingroup PkgSpectralSegSegmentability
/// \brief The parameters of `analyse_contour()`; the defaults are the
/// thesis's.
struct Contour_options
{
  /// width and height of the raster the projection is drawn on
  /// (`trace_outer_contour()`)
  std::size_t resolution = 200;
  /// tolerance of the Fourier smoothing, relative to the diagonal of the
  /// contour's bounding box (`smooth_contour()`)
  double smoothing_error = 0.005;
  /// number of vertices left by the simplification (`simplify_contour()`)
  std::size_t vertices = 50;
  /// exponent \f$w\f$ of the perimeter ratio in the convexity
  /// (`convexity()`)
  double perimeter_exponent = 4.;
  /// whether the holes of the projection count (our addition; `false`, the
  /// thesis: only the outer contour): the convexity is then that of the
  /// region the projection covers, \f$C_1\f$ its area and \f$C_2\f$ the
  /// length of all its boundaries, the holes' included, against the hull's,
  /// so that a handle, whose projection encloses an opening, makes a piece
  /// less convex (`convexity()` with holes). `test_segmentability()` counts
  /// them only on pieces with a handle (`Mesh_piece::genus()` at least 1):
  /// the border loops of a piece that cuts have taken parts off may project
  /// as holes too. The re-embedded contour \f$\zeta^*\f$ has no holes
  bool count_holes = false;
};

/// \ingroup PkgSpectralSegSegmentability
/// \brief Everything `analyse_contour()` computes for one projection.
///
/// For a projection with nothing to draw (see `trace_outer_contour()`) all
/// contours are empty, `inner` is 0 x 0 and both scores are 0.
struct Contour_analysis
{
  /// the outer contour traced on the raster (pixel centres)
  Contour traced;
  /// the contour after smoothing and simplification: the thesis's
  /// \f$\zeta\f$
  Contour contour;
  /// the segmentability score \f$S(\zeta)\f$, one minus `convexity()` of
  /// `contour` (`segmentability_score()`; with `Contour_options::count_holes`,
  /// of the region less its holes: `holes` and `hole_perimeter`)
  double score = 0.;
  /// the share of the area inside `traced` that the projection does not
  /// cover (its holes; computed with `Contour_options::count_holes` only)
  double holes = 0.;
  /// the length of the holes' boundaries (with `Contour_options::count_holes`)
  double hole_perimeter = 0.;
  /// the inner distances between the vertices of `contour`
  /// (`inner_distances()`), also what `bending_samples()` needs
  Eigen::MatrixXd inner;
  /// whether `normalized` and `normalized_score` have been computed
  /// (`add_normalized()`)
  bool has_normalized = false;
  /// `contour` re-embedded by multidimensional scaling of its inner
  /// distances, vertex \f$k\f$ from vertex \f$k\f$ of `contour`: the
  /// thesis's articulation-invariant \f$\zeta^*\f$
  Contour normalized;
  /// the segmentability score \f$S(\zeta^*)\f$
  double normalized_score = 0.;
};

/// \ingroup PkgSpectralSegSegmentability
/// \brief Computes \f$\zeta^*\f$ and its score for an analysis made by
/// `analyse_contour()` (nothing if `analysis.has_normalized` is already
/// set), for callers that look at \f$S(\zeta^*)\f$ only when \f$S(\zeta)\f$
/// did not decide.
///
/// \param analysis the analysis, completed in place
/// \param options only `perimeter_exponent` is read
/// \throws Invalid_input if `analysis.inner` does not match
///         `analysis.contour`
SPECTRALSEG_INLINE void add_normalized(Contour_analysis& analysis, const Contour_options& options = Contour_options())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(analysis.has_normalized)
    return;
  const Eigen::Index n = Eigen::Index(analysis.contour.size());
  if(analysis.inner.rows() != n || analysis.inner.cols() != n)
    throw Invalid_input("add_normalized: the inner distances do not match the contour");
  analysis.normalized = multidimensional_scaling(analysis.inner);
  analysis.normalized_score = segmentability_score(analysis.normalized, options.perimeter_exponent);
  analysis.has_normalized = true;
}
#else
;
#endif

/// \ingroup PkgSpectralSegSegmentability
/// \brief The contour analysis of one 2D projection of a mesh: traces the
/// outer contour of the projected triangles, smooths and simplifies it to
/// \f$\zeta\f$, scores it, computes its inner distances and, if
/// `compute_normalized`, the articulation-invariant contour \f$\zeta^*\f$
/// and its score.
///
/// The stages are `trace_outer_contour()`, `smooth_contour()`,
/// `simplify_contour()`, `segmentability_score()`, `inner_distances()`,
/// then `add_normalized()` (`multidimensional_scaling()` and
/// `segmentability_score()`). The thesis deems the projection segmentable
/// when `score` or `normalized_score` exceeds 0.1.
///
/// \param points the projected 2D vertex positions
/// \param triangles the faces, as vertex index triples into `points`
/// \param options the parameters of the stages
/// \param compute_normalized whether to compute \f$\zeta^*\f$ now; if not,
///        `add_normalized()` can do it later
/// \throws Invalid_input on non-finite coordinates, out-of-range indices or
///         invalid options (see the stages)
SPECTRALSEG_INLINE Contour_analysis analyse_contour(const std::vector<Eigen::Vector2d>& points,
                                                    const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                                    const Contour_options& options = Contour_options(),
                                                    bool compute_normalized = true)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Contour_analysis analysis;
  std::pair<double, double> holes(0., 0.);
  analysis.traced = trace_outer_contour(points, triangles, options.resolution, options.count_holes ? &holes : nullptr);
  analysis.holes = holes.first;
  analysis.hole_perimeter = holes.second;
  analysis.contour =
      simplify_contour(smooth_contour(analysis.traced, options.smoothing_error), options.vertices);
  analysis.score =
      1. - convexity(analysis.contour, options.perimeter_exponent, analysis.holes, analysis.hole_perimeter).convexity;
  analysis.inner = inner_distances(analysis.contour);
  if(compute_normalized)
    add_normalized(analysis, options);
  return analysis;
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_CONTOUR_ANALYSIS_H
