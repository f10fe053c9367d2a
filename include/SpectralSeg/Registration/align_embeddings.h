// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file align_embeddings.h
/// \brief Rigid alignment of two spectral embeddings by iterative closest
/// points, for registration (thesis 3.6).
#ifndef SPECTRALSEG_REGISTRATION_ALIGN_EMBEDDINGS_H
#define SPECTRALSEG_REGISTRATION_ALIGN_EMBEDDINGS_H

#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Registration {

/// \ingroup PkgSpectralSegRegistration
/// \brief Parameters of `align_embeddings()`.
struct Alignment_options
{
  /// iterations of closest points and best rigid motion, per start
  std::size_t iterations = 30;
  /// rows of each embedding used (every i-th row, evenly spread); the
  /// motion found is applied to all rows
  std::size_t max_points = 1000;
  /// also fit a uniform scale (Umeyama's similarity) instead of a rigid motion
  bool with_scaling = false;
  /// start from every sign flip of the coordinate axes (the sign of an
  /// eigenvector is arbitrary): \f$2^d\f$ starts for \f$d\f$ dimensions
  bool try_sign_flips = true;
  /// row `i` of the source is known to match row `i` of the target (a mesh
  /// and a deformed copy with the same faces): one best motion per start
  /// from those pairs, no closest-point search; measures how much an
  /// embedding changes under a deformation
  bool rows_correspond = false;
};

/// \ingroup PkgSpectralSegRegistration
/// \brief The motion that brings one embedding onto another.
struct Embedding_alignment
{
  /// homogeneous \f$(d+1) \times (d+1)\f$ transform applied to the rows of
  /// the source (after the sign flips, which it includes)
  Eigen::MatrixXd transform;
  /// the source rows moved by `transform`
  Eigen::MatrixXd aligned;
  /// root mean square distance from each used source row to its closest
  /// target row (with `rows_correspond`: to its own target row), after the motion
  double rms_closest = 0.;
  /// the start that won: bit `j` set means axis `j` was flipped
  unsigned sign_flips = 0;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

SPECTRALSEG_INLINE Eigen::MatrixXd strided_rows(const Eigen::MatrixXd& m, std::size_t max_points)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Eigen::Index n = m.rows();
  const Eigen::Index k = std::min<Eigen::Index>(n, static_cast<Eigen::Index>(max_points));
  Eigen::MatrixXd r(k, m.cols());
  for(Eigen::Index i = 0; i < k; ++i)
    r.row(i) = m.row(static_cast<Eigen::Index>(double(i) * double(n) / double(k)));
  return r;
}
#else
;
#endif

// Closest-point iterations from `source` (points as columns) onto `target`;
// returns the accumulated transform and sets `rms`.
SPECTRALSEG_INLINE Eigen::MatrixXd icp(const Eigen::MatrixXd& source, const Eigen::MatrixXd& target,
                                       const Alignment_options& o, double& rms)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Eigen::Index d = source.rows();
  Eigen::MatrixXd total = Eigen::MatrixXd::Identity(d + 1, d + 1);
  Eigen::MatrixXd moved = source, matched(d, source.cols());
  const std::size_t iterations = o.rows_correspond ? 1 : o.iterations;
  for(std::size_t it = 0; it <= iterations; ++it)
  {
    double sum = 0.;
    for(Eigen::Index i = 0; i < moved.cols(); ++i)
    {
      Eigen::Index best = i;
      const double nearest = o.rows_correspond
                               ? (target.col(i) - moved.col(i)).squaredNorm()
                               : (target.colwise() - moved.col(i)).colwise().squaredNorm().minCoeff(&best);
      matched.col(i) = target.col(best);
      sum += nearest;
    }
    rms = std::sqrt(sum / double(moved.cols()));
    if(it == iterations)
      break;
    const Eigen::MatrixXd step = Eigen::umeyama(moved, matched, o.with_scaling);
    moved = (step.topLeftCorner(d, d) * moved).colwise() + step.topRightCorner(d, 1).col(0);
    total = step * total;
  }
  return total;
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegRegistration
/// \brief Aligns the embedding `source` onto `target` (one point per row,
/// the same number of columns; the row counts may differ) without knowing
/// which rows correspond: iterative closest points (closest target row,
/// then the best rigid motion, or similarity, by Umeyama's method) from
/// each sign flip of the axes, the start with the smallest final distance
/// kept (the first on ties). This is how the thesis registers two meshes
/// (3.6): embed both spectrally, align the embeddings, read the
/// correspondence off the closest points.
///
/// With `Alignment_options::rows_correspond`, the rows are known to match
/// and each start takes the best motion of those pairs instead.
///
/// Deterministic; the cost is \f$2^d\f$ starts times `iterations` times the
/// squared number of rows used (`max_points`).
///
/// \throws Invalid_input if a matrix is empty, the column counts differ, or
///         the row counts differ with `rows_correspond`
SPECTRALSEG_INLINE Embedding_alignment align_embeddings(const Eigen::MatrixXd& source, const Eigen::MatrixXd& target,
                                                        const Alignment_options& options = Alignment_options())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(source.rows() == 0 || target.rows() == 0 || source.cols() == 0)
    throw Invalid_input("align_embeddings: an embedding is empty");
  if(source.cols() != target.cols())
    throw Invalid_input("align_embeddings: " + std::to_string(source.cols()) + " against " +
                        std::to_string(target.cols()) + " dimensions");
  if(source.cols() > 16)
    throw Invalid_input("align_embeddings: at most 16 dimensions");
  if(options.rows_correspond && source.rows() != target.rows())
    throw Invalid_input("align_embeddings: rows_correspond with " + std::to_string(source.rows()) + " and " +
                        std::to_string(target.rows()) + " rows");
  const Eigen::Index d = source.cols();
  const Eigen::MatrixXd s = internal::strided_rows(source, options.max_points).transpose();
  const Eigen::MatrixXd t = internal::strided_rows(target, options.max_points).transpose();
  const unsigned starts = options.try_sign_flips ? (1u << d) : 1u;
  Embedding_alignment best;
  best.rms_closest = std::numeric_limits<double>::infinity();
  for(unsigned flips = 0; flips < starts; ++flips)
  {
    Eigen::MatrixXd flip = Eigen::MatrixXd::Identity(d + 1, d + 1);
    for(Eigen::Index j = 0; j < d; ++j)
      if(flips & (1u << j))
        flip(j, j) = -1.;
    double rms = 0.;
    const Eigen::MatrixXd motion = internal::icp(flip.topLeftCorner(d, d) * s, t, options, rms);
    if(rms < best.rms_closest)
    {
      best.rms_closest = rms;
      best.transform = motion * flip;
      best.sign_flips = flips;
    }
  }
  best.aligned =
    ((best.transform.topLeftCorner(d, d) * source.transpose()).colwise() + best.transform.topRightCorner(d, 1).col(0))
      .transpose();
  return best;
}
#else
;
#endif

} // namespace Registration
} // namespace SpectralSeg

#endif // SPECTRALSEG_REGISTRATION_ALIGN_EMBEDDINGS_H
