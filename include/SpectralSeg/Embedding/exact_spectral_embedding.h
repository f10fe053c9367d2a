// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file exact_spectral_embedding.h
/// \brief The spectral embedding from the full affinity matrix (thesis fig. 4.2).
#ifndef SPECTRALSEG_EMBEDDING_EXACT_SPECTRAL_EMBEDDING_H
#define SPECTRALSEG_EMBEDDING_EXACT_SPECTRAL_EMBEDDING_H

#include <SpectralSeg/Embedding/Spectral_embedding.h>
#include <SpectralSeg/Embedding/internal/affinity.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Eigenvalues>
#include <Spectra/MatOp/DenseSymMatProd.h>
#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace SpectralSeg {
namespace Embedding {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The `count` largest eigenpairs of a dense symmetric matrix, largest first.
SPECTRALSEG_INLINE void leading_eigenpairs(const Row_matrix& w, Eigen::Index count, Eigen::VectorXd& values,
                                           Eigen::MatrixXd& vectors)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Eigen::Index n = w.rows();
  count = std::min(count, n);
  if(n <= 400 || count + 1 >= n)
  {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(Eigen::MatrixXd(w), Eigen::ComputeEigenvectors);
    if(solver.info() != Eigen::Success)
      throw Error("exact spectral embedding: the dense eigen-solver did not converge");
    values = solver.eigenvalues().reverse().head(count);
    vectors = solver.eigenvectors().rowwise().reverse().leftCols(count);
    return;
  }
  const Eigen::MatrixXd dense(w);
  Spectra::DenseSymMatProd<double> op(dense);
  const Eigen::Index ncv = std::min(n, std::max<Eigen::Index>(2 * count + 1, 20));
  Spectra::SymEigsSolver<Spectra::DenseSymMatProd<double>> solver(op, count, ncv);
  solver.init();
  solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-10);
  if(solver.info() != Spectra::CompInfo::Successful)
    throw Error("exact spectral embedding: Spectra did not converge on the affinity matrix");
  values = solver.eigenvalues();
  vectors = solver.eigenvectors();
}
#else
;
#endif

// The eigenpairs an embedding keeps of `values` (in decreasing order):
// after the first, those with a positive eigenvalue, at most `dimensions`.
// Sets out.first_eigenvalue, out.dropped_dimensions and out.eigenvalues;
// returns the kept columns.
SPECTRALSEG_INLINE std::vector<Eigen::Index> kept_columns(const Eigen::VectorXd& values, std::size_t dimensions,
                                                          Spectral_embedding& out)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  out.first_eigenvalue = values.size() > 0 ? values(0) : 0.;
  const double tol = 1e-12 * std::max(1., std::abs(out.first_eigenvalue));
  std::vector<Eigen::Index> kept;
  for(Eigen::Index c = 1; c < values.size() && kept.size() < dimensions; ++c)
    if(values(c) > tol)
      kept.push_back(c);
  out.dropped_dimensions = dimensions - kept.size();
  out.eigenvalues.resize(static_cast<Eigen::Index>(kept.size()));
  for(std::size_t i = 0; i < kept.size(); ++i)
    out.eigenvalues(Eigen::Index(i)) = values(kept[i]);
  return kept;
}
#else
;
#endif

// U = V(:, kept) * sqrt(lambda(kept)), the columns of kept_columns().
SPECTRALSEG_INLINE void scaled_columns(const Eigen::VectorXd& values, const Eigen::MatrixXd& vectors,
                                       std::size_t dimensions, Spectral_embedding& out)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::vector<Eigen::Index> kept = kept_columns(values, dimensions, out);
  out.coordinates.resize(vectors.rows(), static_cast<Eigen::Index>(kept.size()));
  for(std::size_t i = 0; i < kept.size(); ++i)
    out.coordinates.col(Eigen::Index(i)) = vectors.col(kept[i]) * std::sqrt(values(kept[i]));
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegEmbedding
/// \brief Embeds every face from the full matrix of pairwise distances.
///
/// All rows of the distance matrix \f$G\f$ are computed (one Dijkstra run per
/// face, in parallel), turned into affinities \f$W = \kappa(G)\f$ by the
/// kernel, and the `dimensions + 1` largest eigenpairs of \f$W\f$ are
/// computed (Spectra's Lanczos solver; a dense solver for small meshes). The
/// first eigenvector is dropped (implicit centring), and the next ones with a
/// positive eigenvalue are scaled by the square root of the eigenvalue.
/// Faces in different connected components have affinity 0.
///
/// \tparam AffinityKernel a model of `AffinityKernel`
/// \throws Invalid_input if `dimensions` is 0 or not less than the number of faces
template <typename AffinityKernel>
Spectral_embedding exact_spectral_embedding(const Weighted_dual_graph& graph, std::size_t dimensions,
                                            const AffinityKernel& kernel, const Execution& exec = Execution())
{
  const std::size_t n = graph.graph().number_of_faces();
  if(dimensions == 0 || dimensions >= n)
    throw Invalid_input("spectral embedding: " + std::to_string(dimensions) + " dimensions asked for a mesh of " +
                        std::to_string(n) + " faces");
  std::vector<Dual_graph::size_type> all(n);
  std::iota(all.begin(), all.end(), 0u);
  internal::Row_matrix w = graph.distance_rows(all, exec);
  Spectral_embedding out;
  out.exact = true;
  out.kernel_width = internal::distances_to_affinities(w, kernel, exec);
  w = 0.5 * (w + w.transpose()).eval(); // Dijkstra is symmetric up to rounding
  exec.report("eigen-solve", 0.);
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  internal::leading_eigenpairs(w, static_cast<Eigen::Index>(dimensions + 1), values, vectors);
  internal::fix_signs(vectors);
  exec.report("eigen-solve", 1.);
  internal::scaled_columns(values, vectors, dimensions, out);
  return out;
}

} // namespace Embedding
} // namespace SpectralSeg

#endif
