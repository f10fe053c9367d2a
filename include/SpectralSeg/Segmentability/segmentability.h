// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file segmentability.h
/// \brief Whether a piece of a mesh has parts: the four contour tests of the
/// thesis (6.2.4, fig. 6.7) and the two sample faces they suggest (6.3.3).
#ifndef SPECTRALSEG_SEGMENTABILITY_SEGMENTABILITY_H
#define SPECTRALSEG_SEGMENTABILITY_SEGMENTABILITY_H

#include <SpectralSeg/Mesh_piece.h>
#include <SpectralSeg/Segmentability/Contour_analysis.h>
#include <SpectralSeg/Segmentability/Test.h>
#include <SpectralSeg/Segmentability/convexity.h>
#include <SpectralSeg/Segmentability/inner_distances.h>
#include <SpectralSeg/Segmentability/integrated_bending_score.h>
#include <SpectralSeg/Segmentability/multidimensional_scaling.h>
#include <SpectralSeg/Segmentability/principal_curvatures.h>
#include <SpectralSeg/Segmentability/spectral_projection.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \ingroup PkgSpectralSegSegmentability
/// \brief Parameters of the segmentability test.
struct Segmentability_options
{
  /// \f$\eta\f$: a piece is segmentable when a contour's score exceeds it
  double threshold = 0.1;
  /// only the L tests (the thesis's structure-only mode)
  bool structure_only = false;
  /// a piece is segmentable only when an L test and an M test both pass
  /// (our addition; `false`, the thesis: the first test that passes
  /// decides). A torso's L contour is convex while noise or bends can make
  /// its M contour pass; a part that sticks out shows in both. Ignored with
  /// `structure_only`.
  bool require_agreement = false;
  /// the MDS re-embedded contours are not tested on a piece whose L
  /// spectrum is that of a chain, \f$\lambda_3 \ge r\,\lambda_2\f$ (our
  /// addition; 0, the thesis: always tested). A path has \f$r \to 4\f$, as
  /// has a tube longer than its circumference; branching pieces have 1 to 2.
  /// The projections of a chain are thin arcs, and the re-embedding of an
  /// arc shows only its noise: a finger or a straight bar then passes.
  double chain_eigenvalue_ratio = 0.;
  /// raster resolution, smoothing tolerance, contour size, \f$w_{cvx}\f$
  Contour_options contour;
  /// operators and eigensolver
  Projection_options projection;
};

/// \ingroup PkgSpectralSegSegmentability
/// \brief What the segmentability test found.
struct Segmentability_result
{
  /// whether a test passed
  bool segmentable = false;
  /// the test that passed (`Test::none` if none did)
  Test test = Test::none;
  /// score of the passing test, or the largest score of the tests run
  double score = 0.;
  /// the score of each test, NaN for the tests not run
  std::array<double, 4> scores{{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                                std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()}};
  /// the projection of the passing test (or of the last one run)
  Planar_projection projection;
  /// its contour analysis
  Contour_analysis contour;
  /// the projection behind `test`: structure for the L tests, geometry for the M tests
  Projection projection_kind() const
  {
    return test == Test::geometry || test == Test::geometry_normalized ? Projection::geometry : Projection::structure;
  }
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// test_segmentability() with the projections' sparse factorisations in the
// elimination order `vertex_order` of the piece's vertices (empty: their
// approximate minimum degree order). When no test passes and an L contour
// (L, then L-MDS) scores above `structure_fallback` (below the threshold;
// not with `require_agreement`), that test passes after all (the scores
// of every test run are kept).
SPECTRALSEG_INLINE Segmentability_result test_segmentability(
    const Mesh_piece& piece, const Principal_curvatures* curvatures, const Segmentability_options& options,
    const SpectralSeg::internal::Elimination_permutation& vertex_order,
    double structure_fallback = std::numeric_limits<double>::infinity())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Segmentability_result r;
  r.score = 0.;
  const int projections = options.structure_only || !curvatures ? 1 : 2;
  const bool agreement = options.require_agreement && projections == 2;
  Segmentability_result first; // with agreement: the first family that passed
  bool chain = false;           // whether the piece's L spectrum is a chain's
  const bool fallback = !agreement && structure_fallback < options.threshold;
  Segmentability_result structure; // with `fallback`: the L family's projection and contours
  const auto fall_back = [&]() {
    if(structure.projection.points.empty())
      return r; // no L contour above the fallback threshold
    for(Test t : {Test::structure, Test::structure_normalized})
    {
      const double s = structure.scores[static_cast<std::size_t>(t)];
      if(s > structure_fallback)
      {
        structure.scores = r.scores;
        structure.segmentable = true;
        structure.test = t;
        structure.score = s;
        return structure;
      }
    }
    return r;
  };
  // the projection's holes count only where the piece has a handle: a
  // piece's border loops (where cuts took parts off) may also project as holes
  Contour_options contour_options = options.contour;
  contour_options.count_holes = options.contour.count_holes && piece.genus() > 0;
  for(int p = 0; p < projections; ++p)
  {
    const Projection kind = p == 0 ? Projection::structure : Projection::geometry;
    Planar_projection proj = internal::spectral_projection(piece, kind, curvatures, options.projection, vertex_order);
    // the MDS re-embedding is computed only when the plain contour fails
    Contour_analysis a = analyse_contour(proj.points, piece.triangles(), contour_options, false);
    const Test plain = p == 0 ? Test::structure : Test::geometry;
    const Test normalized = p == 0 ? Test::structure_normalized : Test::geometry_normalized;
    r.scores[static_cast<std::size_t>(plain)] = a.score;
    r.projection = std::move(proj);
    r.contour = std::move(a);
    bool passed = false;
    if(p == 0)
      chain = options.chain_eigenvalue_ratio > 0. &&
              r.projection.eigenvalues(1) >= options.chain_eigenvalue_ratio * r.projection.eigenvalues(0);
    for(Test t : {plain, normalized})
    {
      if(t == normalized && chain)
        break;
      if(t == normalized)
      {
        add_normalized(r.contour, options.contour);
        r.scores[static_cast<std::size_t>(t)] = r.contour.normalized_score;
      }
      const double s = r.scores[static_cast<std::size_t>(t)];
      if(std::isfinite(s) && !(agreement && first.segmentable))
        r.score = std::max(r.score, s);
      if(s > options.threshold)
      {
        if(!agreement)
        {
          r.segmentable = true;
          r.test = t;
          r.score = s;
          return r;
        }
        passed = true;
        if(!first.segmentable)
        {
          r.test = t;
          r.score = s;
        }
        break;
      }
    }
    // the L family's projection and contours, when they can pass after all
    // (moved: the M family writes its own)
    if(fallback && p == 0 &&
       (r.scores[static_cast<std::size_t>(Test::structure)] > structure_fallback ||
        r.scores[static_cast<std::size_t>(Test::structure_normalized)] > structure_fallback))
      structure = std::move(r);
    if(!agreement)
      continue;
    if(!passed)
    {
      // the score of a failed agreement: the larger score of the family
      // that failed
      const std::size_t i = static_cast<std::size_t>(plain), j = static_cast<std::size_t>(normalized);
      double fail = 0.;
      for(std::size_t k : {i, j})
        if(std::isfinite(r.scores[k]))
          fail = std::max(fail, r.scores[k]);
      r.segmentable = false;
      r.test = Test::none;
      r.score = fail;
      return r;
    }
    if(!first.segmentable)
    {
      first = r; // the L family passed: its contour gives the samples
      first.segmentable = true;
    }
    else
    {
      first.scores = r.scores;
      return first;
    }
  }
  return fallback ? fall_back() : r;
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegSegmentability
/// \brief Tests whether a piece is segmentable (thesis fig. 6.7): the
/// contours of the L projection, of its MDS re-embedding, of the M
/// projection and of its MDS re-embedding are scored in turn with
/// \f$S = 1 - \max(C_1, C_2^{w_{cvx}})\f$; the first score above
/// \f$\eta\f$ makes the piece segmentable. With `structure_only`, only the
/// L tests run.
///
/// \param piece a connected piece
/// \param curvatures the mesh's principal curvatures (needed for the M tests)
/// \param options \f$\eta\f$, modes and the contour and solver parameters
SPECTRALSEG_INLINE Segmentability_result
test_segmentability(const Mesh_piece& piece, const Principal_curvatures* curvatures,
                    const Segmentability_options& options = Segmentability_options())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  return internal::test_segmentability(piece, curvatures, options, SpectralSeg::internal::Elimination_permutation());
}
#else
;
#endif

/// \ingroup PkgSpectralSegSegmentability
/// \brief Pairs of sample faces of a piece, the first of them the thesis's
/// (6.3.3): on the contour that passed, the vertex of largest integrated
/// bending score and the vertex farthest from it in inner distance. The
/// others (our addition) start from the next local maxima of the score
/// along the contour, highest first, each paired with the vertex farthest
/// from it: one pair per protrusion the contour shows. Each vertex is
/// mapped to the piece vertex nearest to it in the projection, then to the
/// face around that vertex whose centroid is nearest to it. Pairs that map
/// to the same two faces are listed once.
///
/// \param piece the piece tested
/// \param result its test (the contour of the last test run when none passed)
/// \param count at most this many pairs (at least one is returned)
/// \return pairs of local faces; the two faces of a pair may coincide on
///         degenerate contours
SPECTRALSEG_INLINE std::vector<std::pair<Mesh_piece::size_type, Mesh_piece::size_type>>
bending_sample_face_pairs(const Mesh_piece& piece, const Segmentability_result& result, std::size_t count)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const bool normalized = result.test == Test::structure_normalized || result.test == Test::geometry_normalized;
  const Contour& c = normalized ? result.contour.normalized : result.contour.contour;
  const Eigen::MatrixXd inner = normalized ? inner_distances(c) : result.contour.inner;
  std::vector<std::pair<std::size_t, std::size_t>> vertices;
  if(count <= 1 || c.size() <= 2)
    vertices.push_back(bending_samples(c, inner));
  else
  {
    // the local maxima of the score, highest first (ties: smaller index):
    // the first is the global maximum of bending_samples()
    const std::vector<double> scores = integrated_bending_scores(c, inner);
    const std::size_t n = scores.size();
    std::vector<std::size_t> maxima;
    for(std::size_t i = 0; i < n; ++i)
      if(scores[i] >= scores[(i + n - 1) % n] && scores[i] >= scores[(i + 1) % n])
        maxima.push_back(i);
    std::stable_sort(maxima.begin(), maxima.end(), [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
    maxima.resize(std::min(maxima.size(), count));
    for(std::size_t s : maxima)
    {
      Eigen::Index t = 0;
      inner.row(Eigen::Index(s)).maxCoeff(&t);
      vertices.emplace_back(s, std::size_t(t));
    }
  }
  auto to_face = [&](std::size_t contour_vertex) {
    const Eigen::Vector2d q = result.contour.contour[contour_vertex]; // in projection coordinates
    Mesh_piece::size_type best_v = 0;
    double best = std::numeric_limits<double>::infinity();
    for(Mesh_piece::size_type v = 0; v < result.projection.points.size(); ++v)
    {
      const double d = (result.projection.points[v] - q).squaredNorm();
      if(d < best)
      {
        best = d;
        best_v = v;
      }
    }
    Mesh_piece::size_type best_f = 0;
    best = std::numeric_limits<double>::infinity();
    const Eigen::Vector3d& p = piece.point(best_v);
    for(Mesh_piece::size_type f = 0; f < piece.number_of_faces(); ++f)
    {
      const auto& t = piece.triangles()[f];
      if(t[0] != best_v && t[1] != best_v && t[2] != best_v)
        continue;
      const double d = (piece.geometry().centroids[piece.faces()[f]] - p).squaredNorm();
      if(d < best)
      {
        best = d;
        best_f = f;
      }
    }
    return best_f;
  };
  std::vector<std::pair<Mesh_piece::size_type, Mesh_piece::size_type>> pairs;
  for(const auto& st : vertices)
  {
    const std::pair<Mesh_piece::size_type, Mesh_piece::size_type> faces(to_face(st.first), to_face(st.second));
    if(std::find(pairs.begin(), pairs.end(), faces) == pairs.end())
      pairs.push_back(faces);
  }
  return pairs;
}
#else
;
#endif

/// \ingroup PkgSpectralSegSegmentability
/// \brief The two sample faces of a segmentable piece (thesis 6.3.3): on the
/// contour that passed, the vertex of largest integrated bending score and
/// the vertex farthest from it in inner distance; each is mapped to the
/// piece vertex nearest to it in the projection, then to the face around
/// that vertex whose centroid is nearest to it (the first of
/// `bending_sample_face_pairs()`).
///
/// \return two local faces; they may coincide on degenerate contours
/// (with no passing test, from the contour of the last test run)
SPECTRALSEG_INLINE std::pair<Mesh_piece::size_type, Mesh_piece::size_type>
bending_sample_faces(const Mesh_piece& piece, const Segmentability_result& result)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  return bending_sample_face_pairs(piece, result, 1).front();
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_SEGMENTABILITY_H
