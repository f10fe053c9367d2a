// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Spectral_embedding.h
/// \brief The spectral embedding of the faces of a mesh (thesis 4.2, fig. 4.2).
#ifndef SPECTRALSEG_EMBEDDING_SPECTRAL_EMBEDDING_H
#define SPECTRALSEG_EMBEDDING_SPECTRAL_EMBEDDING_H

#include <SpectralSeg/Dual_graph.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace SpectralSeg {
namespace Embedding {

/// \ingroup PkgSpectralSegEmbedding
/// \brief How the affinity matrix is eigen-decomposed.
enum class Method
{
  automatic, ///< `exact` up to `Embedding_options::exact_face_limit` faces, `nystrom` above
  exact,     ///< the full distance and affinity matrices (memory grows as faces squared)
  nystrom    ///< a few sampled rows and the Nyström extension (memory grows as faces times samples)
};

/// \ingroup PkgSpectralSegEmbedding
/// \brief How the Nyström samples are chosen (thesis 5.4).
enum class Sampling_method
{
  farthest_point, ///< max-min sampling under the metric (fast, the default)
  gamma           ///< greedy minimisation of the quality measure Gamma over random candidates (slow)
};

/// \ingroup PkgSpectralSegEmbedding
/// \brief Parameters of the embedding.
struct Embedding_options
{
  /// exact or sampled
  Method method = Method::automatic;
  /// largest mesh embedded exactly by `Method::automatic`: 2,000 faces
  /// (a 2,000 x 2,000 matrix takes 32 MB and a fraction of a second)
  std::size_t exact_face_limit = 2000;
  /// Nyström samples; 0 means the number of dimensions plus one (thesis: \f$l = k + 1\f$)
  std::size_t samples = 0;
  /// how the Nyström samples are chosen
  Sampling_method sampling = Sampling_method::farthest_point;
  /// Gamma-sampling: random candidates tried per sample (thesis: 90)
  std::size_t gamma_candidates = 90;
  /// seed of the random choices (start face of the sampling, Gamma candidates)
  unsigned int seed = 0;
};

/// \ingroup PkgSpectralSegEmbedding
/// \brief The embedding of every face, and how it was obtained.
struct Spectral_embedding
{
  /// one row per face, one column per kept dimension; the columns are the
  /// leading eigenvectors of the affinity matrix after the first, scaled by
  /// the square roots of their (positive) eigenvalues
  Eigen::MatrixXd coordinates;
  /// the eigenvalues of the kept columns, in decreasing order
  Eigen::VectorXd eigenvalues;
  /// the largest eigenvalue, dropped for implicit centring (thesis 4.2.4)
  double first_eigenvalue = 0.;
  /// the kernel width \f$\sigma\f$
  double kernel_width = 0.;
  /// `true` if the exact path was taken
  bool exact = true;
  /// the sampled faces of the Nyström path, in the order they were chosen
  std::vector<Dual_graph::size_type> samples;
  /// sampling quality \f$\Gamma = \mathrm{tr}(C) - \mathrm{tr}(B^T A^{-1} B)\f$ of the Nyström samples
  double gamma = 0.;
  /// dimensions asked for but dropped because their eigenvalue was not positive
  std::size_t dropped_dimensions = 0;
};

} // namespace Embedding
} // namespace SpectralSeg

#endif
