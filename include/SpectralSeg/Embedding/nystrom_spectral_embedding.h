// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file nystrom_spectral_embedding.h
/// \brief The spectral embedding from a few sampled rows, by the Nyström
/// method (thesis ch. 5), and the sampling quality measure Gamma.
#ifndef SPECTRALSEG_EMBEDDING_NYSTROM_SPECTRAL_EMBEDDING_H
#define SPECTRALSEG_EMBEDDING_NYSTROM_SPECTRAL_EMBEDDING_H

#include <SpectralSeg/Embedding/Spectral_embedding.h>
#include <SpectralSeg/Embedding/exact_spectral_embedding.h>
#include <SpectralSeg/Embedding/internal/affinity.h>
#include <SpectralSeg/Sampling/farthest_point_samples.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <random>
#include <vector>

namespace SpectralSeg {
namespace Embedding {

/// \ingroup PkgSpectralSegEmbedding
/// \brief The Nyström sampling quality \f$\Gamma = \mathrm{tr}(C) -
/// \mathrm{tr}(B^T A^{-1} B)\f$ (thesis eq. 5.4): the summed squared distance,
/// in the kernel's feature space, from the unsampled faces to the span of the
/// sampled ones. Lower is better.
///
/// \param rows the affinity rows of the samples (samples x faces)
/// \param samples the sampled faces, in the order of `rows`
SPECTRALSEG_INLINE double nystrom_gamma(const internal::Row_matrix& rows,
                                        const std::vector<Dual_graph::size_type>& samples)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Eigen::Index l = static_cast<Eigen::Index>(samples.size());
  const Eigen::Index n = rows.cols();
  Eigen::MatrixXd a(l, l);
  for(Eigen::Index i = 0; i < l; ++i)
    for(Eigen::Index j = 0; j < l; ++j)
      a(i, j) = 0.5 * (rows(i, samples[std::size_t(j)]) + rows(j, samples[std::size_t(i)]));
  std::vector<char> sampled(static_cast<std::size_t>(n), 0);
  for(auto s : samples)
    sampled[s] = 1;
  // pseudo-inverse through the eigen-decomposition: robust to near-duplicate samples
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(a);
  const Eigen::VectorXd& d = eig.eigenvalues();
  const double tol = 1e-10 * std::max(1., d.cwiseAbs().maxCoeff());
  double traced = 0.;
  Eigen::VectorXd y(l);
  for(Eigen::Index f = 0; f < n; ++f)
  {
    if(sampled[std::size_t(f)])
      continue;
    y.noalias() = eig.eigenvectors().transpose() * rows.col(f);
    for(Eigen::Index i = 0; i < l; ++i)
      if(d(i) > tol)
        traced += y(i) * y(i) / d(i);
  }
  return double(n - l) - traced; // W_ii = 1, so tr(C) is the number of unsampled faces
}
#else
;
#endif

/// \cond SKIP_IN_MANUAL
namespace internal {

// Greedy Gamma-sampling (thesis 5.4): each new sample is the best of
// `candidates` random faces for the measure Gamma.
template <typename AffinityKernel>
std::vector<Dual_graph::size_type> gamma_samples(const Weighted_dual_graph& graph, std::size_t count,
                                                 std::size_t candidates, const AffinityKernel& kernel,
                                                 unsigned int seed, const Execution& exec)
{
  const std::size_t n = graph.graph().number_of_faces();
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::size_t> pick(0, n - 1);
  std::vector<Dual_graph::size_type> samples{static_cast<Dual_graph::size_type>(pick(random))};
  Row_matrix rows = graph.distance_rows(samples, Execution(1));
  while(samples.size() < count)
  {
    exec.report("gamma sampling", double(samples.size()) / double(count));
    std::vector<Dual_graph::size_type> tries;
    for(std::size_t c = 0; c < candidates; ++c)
    {
      const auto f = static_cast<Dual_graph::size_type>(pick(random));
      if(std::find(samples.begin(), samples.end(), f) == samples.end())
        tries.push_back(f);
    }
    if(tries.empty())
      continue;
    const Row_matrix candidate_rows = graph.distance_rows(tries, exec);
    std::vector<double> gamma(tries.size());
    ::SpectralSeg::internal::parallel_range(0, tries.size(), exec.threads(), [&](std::size_t t) {
      Row_matrix g(rows.rows() + 1, rows.cols());
      g.topRows(rows.rows()) = rows;
      g.row(rows.rows()) = candidate_rows.row(Eigen::Index(t));
      distances_to_affinities(g, kernel, Execution(1));
      std::vector<Dual_graph::size_type> s = samples;
      s.push_back(tries[t]);
      gamma[t] = nystrom_gamma(g, s);
    });
    const std::size_t best = static_cast<std::size_t>(std::min_element(gamma.begin(), gamma.end()) - gamma.begin());
    samples.push_back(tries[best]);
    rows.conservativeResize(rows.rows() + 1, Eigen::NoChange);
    rows.row(rows.rows() - 1) = candidate_rows.row(Eigen::Index(best));
  }
  return samples;
}

} // namespace internal
/// \endcond

/// \cond SKIP_IN_MANUAL
namespace internal {

// The farthest-point sampling of the Nyström embedding: from a face drawn
// with `seed`, keeping the distance rows.
SPECTRALSEG_INLINE Sampling::Farthest_point_options farthest_point_sampling(std::size_t faces, unsigned int seed)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::mt19937 random(seed);
  Sampling::Farthest_point_options o;
  o.start = static_cast<Dual_graph::size_type>(std::uniform_int_distribution<std::size_t>(0, faces - 1)(random));
  o.keep_distance_rows = true; // the embedding's rows, without running Dijkstra again
  return o;
}
#else
;
#endif

// The Nyström samples and their distance rows (samples x faces).
struct Nystrom_rows
{
  std::vector<Dual_graph::size_type> samples;
  Row_matrix distances;
};

// The `l` samples of nystrom_spectral_embedding() and their distance rows.
// Farthest-point samples are nested: the first `m` of `l` are the samples
// a call with `m` would choose, so one call serves several sample counts.
template <typename AffinityKernel>
Nystrom_rows nystrom_rows(const Weighted_dual_graph& graph, std::size_t l, const AffinityKernel& kernel,
                          const Embedding_options& options, const Execution& exec)
{
  const std::size_t n = graph.graph().number_of_faces();
  Nystrom_rows out;
  if(options.sampling == Sampling_method::gamma)
  {
    out.samples = gamma_samples(graph, l, options.gamma_candidates, kernel, options.seed, exec);
    out.distances = graph.distance_rows(out.samples, exec);
    return out;
  }
  Sampling::Farthest_point_samples samples =
    Sampling::farthest_point_samples(graph, l, farthest_point_sampling(n, options.seed), exec);
  out.samples = std::move(samples.faces);
  out.distances.resize(static_cast<Eigen::Index>(l), static_cast<Eigen::Index>(n));
  for(std::size_t i = 0; i < l; ++i) // each row freed once copied
  {
    out.distances.row(static_cast<Eigen::Index>(i)) =
      Eigen::Map<const Eigen::RowVectorXd>(samples.distance_rows[i].data(), static_cast<Eigen::Index>(n));
    std::vector<double>().swap(samples.distance_rows[i]);
  }
  return out;
}

// The Nyström embedding of `n` faces from the affinities of `samples`:
// `column(f, a)` puts the affinities of face `f` to the samples in `a`
// (one entry per sample). The affinities are asked for one face at a time,
// so that no samples-by-faces matrix of them need exist.
template <typename AffinityColumn>
Spectral_embedding nystrom_extension(std::size_t n, std::vector<Dual_graph::size_type> samples, double kernel_width,
                                     std::size_t dimensions, const Execution& exec, const AffinityColumn& column)
{
  const std::size_t l = samples.size();
  Spectral_embedding out;
  out.exact = false;
  out.samples = std::move(samples);
  out.kernel_width = kernel_width;

  exec.report("eigen-solve", 0.);
  const Eigen::Index ll = static_cast<Eigen::Index>(l);
  Eigen::MatrixXd at_samples(ll, ll); // column j: the affinities of sample j
  {
    Eigen::RowVectorXd affinities(ll);
    for(Eigen::Index j = 0; j < ll; ++j)
    {
      column(out.samples[std::size_t(j)], affinities);
      at_samples.col(j) = affinities.transpose();
    }
  }
  Eigen::MatrixXd a(ll, ll);
  for(Eigen::Index i = 0; i < ll; ++i)
    for(Eigen::Index j = 0; j < ll; ++j)
      a(i, j) = 0.5 * (at_samples(i, j) + at_samples(j, i));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(a);
  if(eig.info() != Eigen::Success)
    throw Error("Nyström embedding: the eigen-solver did not converge on the sample affinities");
  const Eigen::VectorXd delta = eig.eigenvalues().reverse();
  Eigen::MatrixXd e = eig.eigenvectors().rowwise().reverse();
  fix_signs(e);
  const double tol = 1e-12 * std::max(1., std::abs(delta(0)));
  Eigen::MatrixXd e_scaled = e;
  for(Eigen::Index c = 0; c < ll; ++c)
    e_scaled.col(c) = delta(c) > tol ? Eigen::VectorXd(e.col(c) / delta(c)) : Eigen::VectorXd::Zero(ll);
  const std::vector<Eigen::Index> kept = kept_columns(delta, dimensions, out);
  Eigen::VectorXd scale(static_cast<Eigen::Index>(kept.size())); // Delta^1/2 of the kept columns
  for(std::size_t i = 0; i < kept.size(); ++i)
    scale(Eigen::Index(i)) = std::sqrt(delta(kept[i]));
  // Each face's row of E~ = W_s^T E Delta^-1 (E on the samples), its kept
  // columns scaled by Delta^1/2 as the coordinates; and Gamma
  // (nystrom_gamma()) on the way: with y = E^T W_s,f, the face's term
  // y^T Delta^-1 y is the sum of E~(f, c)^2 delta(c).
  const double gamma_tol = 1e-10 * std::max(1., delta.cwiseAbs().maxCoeff());
  std::vector<char> sampled(n, 0);
  for(auto f : out.samples)
    sampled[f] = 1;
  std::vector<double> traced(n, 0.);
  out.coordinates.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(kept.size()));
  const std::size_t block = 1024; // faces per task, sharing one row buffer
  ::SpectralSeg::internal::parallel_range(0, (n + block - 1) / block, exec.threads(), [&](std::size_t b) {
    Eigen::RowVectorXd affinities(ll), extended(ll);
    for(std::size_t f = b * block; f < std::min(n, (b + 1) * block); ++f)
    {
      column(static_cast<Dual_graph::size_type>(f), affinities);
      extended.noalias() = affinities * e_scaled;
      for(std::size_t i = 0; i < kept.size(); ++i)
        out.coordinates(Eigen::Index(f), Eigen::Index(i)) = extended(kept[i]) * scale(Eigen::Index(i));
      if(!sampled[f])
        for(Eigen::Index c = 0; c < ll; ++c)
          if(delta(c) > gamma_tol)
            traced[f] += extended(c) * extended(c) * delta(c);
    }
  });
  double sum = 0.;
  for(double t : traced) // in face order: thread-independent
    sum += t;
  out.gamma = double(n - l) - sum;
  exec.report("eigen-solve", 1.);
  return out;
}

// The Nyström embedding from the affinity rows `w` of `samples`.
SPECTRALSEG_INLINE Spectral_embedding nystrom_embedding_from_affinities(const Row_matrix& w,
                                                                        std::vector<Dual_graph::size_type> samples,
                                                                        double kernel_width, std::size_t dimensions,
                                                                        const Execution& exec)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  return nystrom_extension(static_cast<std::size_t>(w.cols()), std::move(samples), kernel_width, dimensions, exec,
                           [&w](Dual_graph::size_type f, Eigen::RowVectorXd& a) { a = w.col(Eigen::Index(f)).transpose(); });
}
#else
;
#endif

// The Nyström embedding from the first `samples.size()` rows of
// `distances`, the distance rows of `samples` (and maybe of more samples
// after them): the same embedding as distances_to_affinities() on a copy
// of those rows, then nystrom_embedding_from_affinities(), without the
// copy. The kernel width comes from those rows.
template <typename Kernel>
Spectral_embedding nystrom_embedding_from_distances(const Row_matrix& distances,
                                                    std::vector<Dual_graph::size_type> samples, const Kernel& kernel,
                                                    std::size_t dimensions, const Execution& exec)
{
  const Eigen::Index l = static_cast<Eigen::Index>(samples.size());
  const double width = kernel_width(distances, l, kernel);
  return nystrom_extension(static_cast<std::size_t>(distances.cols()), std::move(samples), width, dimensions, exec,
                           [&](Dual_graph::size_type f, Eigen::RowVectorXd& a) {
                             for(Eigen::Index i = 0; i < l; ++i)
                               a(i) = affinity(distances(i, Eigen::Index(f)), kernel, width);
                           });
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegEmbedding
/// \brief Embeds every face from the distance rows of a few sampled faces.
///
/// The samples (`options.samples`, default `dimensions + 1`) are chosen by
/// farthest-point sampling (`Sampling::farthest_point_samples()`, starting
/// from a face drawn with `options.seed`) or by Gamma-sampling. Only their
/// rows of the distance matrix are computed; the kernel width comes from
/// those rows. With \f$A = E \Delta E^T\f$ the sample-to-sample affinities,
/// every face's coordinates are the Nyström extension
/// \f$W_{s,f}^T E \Delta^{-1/2}\f$, i.e. \f$[E; B^T E \Delta^{-1}]\f$ scaled
/// by \f$\Delta^{1/2}\f$; the first column is dropped and only positive
/// eigenvalues are kept. Memory grows as faces times samples.
///
/// \tparam AffinityKernel a model of `AffinityKernel`
/// \throws Invalid_input if `dimensions` is 0 or the samples outnumber the faces
template <typename AffinityKernel>
Spectral_embedding nystrom_spectral_embedding(const Weighted_dual_graph& graph, std::size_t dimensions,
                                              const AffinityKernel& kernel,
                                              const Embedding_options& options = Embedding_options(),
                                              const Execution& exec = Execution())
{
  const std::size_t n = graph.graph().number_of_faces();
  const std::size_t l = options.samples > 0 ? options.samples : dimensions + 1;
  if(dimensions == 0 || l > n || l < 2)
    throw Invalid_input("Nyström embedding: " + std::to_string(l) + " samples for " + std::to_string(dimensions) +
                        " dimensions on a mesh of " + std::to_string(n) + " faces");
  internal::Nystrom_rows rows = internal::nystrom_rows(graph, l, kernel, options, exec);
  const double width = internal::distances_to_affinities(rows.distances, kernel, exec); // in place
  return internal::nystrom_embedding_from_affinities(rows.distances, std::move(rows.samples), width, dimensions, exec);
}

} // namespace Embedding
} // namespace SpectralSeg

#endif
