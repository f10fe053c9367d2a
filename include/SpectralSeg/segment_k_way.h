// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file segment_k_way.h
/// \brief k-way segmentation of a weighted dual graph, with a given or an
/// automatically chosen number of segments (thesis ch. 4 and 5).
#ifndef SPECTRALSEG_SEGMENT_K_WAY_H
#define SPECTRALSEG_SEGMENT_K_WAY_H

#include <SpectralSeg/Clustering/Kmeans.h>
#include <SpectralSeg/Embedding/exact_spectral_embedding.h>
#include <SpectralSeg/Embedding/nystrom_spectral_embedding.h>
#include <SpectralSeg/K_way_options.h>
#include <SpectralSeg/Kernels/Any_kernel.h>
#include <SpectralSeg/Refinement/concave_normalized_cut.h>
#include <SpectralSeg/Refinement/connected_segments.h>
#include <SpectralSeg/Refinement/crease_regions.h>
#include <SpectralSeg/Refinement/graph_cut_boundaries.h>
#include <SpectralSeg/Refinement/merge_segments.h>
#include <SpectralSeg/Refinement/sharp_crease_share.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/Stage_timer.h>
#include <SpectralSeg/internal/merge_by_contrast.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <deque>
#include <functional>
#include <future>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace SpectralSeg {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The embedding of `segment_k_way()`: exact for small meshes (or when asked,
// or when the mesh is too small for the Nyström samples), else Nyström.
template <typename AffinityKernel>
Embedding::Spectral_embedding embed(const Weighted_dual_graph& graph, std::size_t dims, const AffinityKernel& kernel,
                                    const Embedding::Embedding_options& options, const Execution& exec)
{
  const std::size_t n = graph.graph().number_of_faces();
  const bool exact = options.method == Embedding::Method::exact ||
                     (options.method == Embedding::Method::automatic && n <= options.exact_face_limit) ||
                     (options.samples > 0 ? options.samples : dims + 1) > n;
  return exact ? Embedding::exact_spectral_embedding(graph, dims, kernel, exec)
               : Embedding::nystrom_spectral_embedding(graph, dims, kernel, options, exec);
}

// K-means on r.embedding into k clusters.
template <typename AffinityKernel>
void kmeans_clusters(std::size_t k, const Basic_K_way_options<AffinityKernel>& options, K_way_result& r,
                     Stage_timer& lap, const Execution& exec)
{
  if(r.embedding.coordinates.cols() == 0)
    throw Error("k-way segmentation: the affinity matrix has no positive eigenvalue after the first");
  exec.report("k-means", 0.);
  std::vector<std::size_t> seeds;
  if(!r.embedding.exact && options.seed_with_samples)
    for(std::size_t i = 0; i < k && i < r.embedding.samples.size(); ++i)
      seeds.push_back(r.embedding.samples[i]);
  r.clusters = Clustering::kmeans(r.embedding.coordinates, k, seeds, options.kmeans_iterations, exec,
                                 options.kmeans_sample_limit);
  r.labels = r.clusters.labels;
  exec.report("k-means", 1.);
  lap("k-means");
}

// The mean embedding coordinates of each of the `m` segments of `labels`
// (one row per segment), the proxies of the graph cut after a merge; the
// columns on `threads` threads.
SPECTRALSEG_INLINE Eigen::MatrixXd mean_proxies(const Eigen::MatrixXd& coordinates, const std::vector<int>& labels,
                                                std::size_t m, unsigned threads = 1)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Eigen::MatrixXd proxies = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m), coordinates.cols());
  std::vector<double> count(m, 0.);
  for(int l : labels)
    count[std::size_t(l)] += 1.;
  // column after column, as the coordinates are stored; each sum in face
  // order: thread-independent
  parallel_range(0, std::size_t(coordinates.cols()), threads, [&](std::size_t j) {
    const double* x = coordinates.col(Eigen::Index(j)).data();
    double* sum = proxies.col(Eigen::Index(j)).data();
    for(std::size_t f = 0; f < labels.size(); ++f)
      sum[labels[f]] += x[f];
  });
  for(std::size_t c = 0; c < m; ++c)
    proxies.row(static_cast<Eigen::Index>(c)) /= std::max(1., count[c]);
  return proxies;
}
#else
;
#endif

// A graph cut made up to its moves: the problem, with the data terms read
// from the embedding, so that the embedding can go before the moves run.
struct Pending_cut
{
  /// whether there is a graph cut to run
  bool run = false;
  Refinement::internal::Graph_cut_problem problem;
  /// refine_clusters(): the segments were merged down before the cut (else
  /// they may be merged after it, which reads the embedding)
  bool merged = false;
};

// graph_cut_merged() up to the graph cut's moves; with `release`,
// `r.embedding.coordinates` are released then (nothing reads them after).
template <typename AffinityKernel>
Pending_cut prepare_graph_cut_merged(const Weighted_dual_graph& graph, std::size_t m, std::size_t clusters,
                                     const Basic_K_way_options<AffinityKernel>& options, K_way_result& r,
                                     bool release, unsigned threads)
{
  Pending_cut p;
  if(options.boundary_enhancement && m > 1 && m <= clusters)
  {
    p.run = true;
    p.problem = Refinement::internal::graph_cut_problem(
      graph.graph(), r.embedding.coordinates, mean_proxies(r.embedding.coordinates, r.labels, m, threads), r.labels,
      options.graph_cut, threads);
  }
  if(release)
    r.embedding.coordinates.resize(0, 0);
  return p;
}

// The rest of graph_cut_merged() after prepare_graph_cut_merged(): the
// moves (`p` is emptied), then the segments made connected.
template <typename AffinityKernel>
void finish_graph_cut_merged(const Weighted_dual_graph& graph, const Basic_K_way_options<AffinityKernel>& options,
                             K_way_result& r, Pending_cut& p, const Execution& exec, Stage_timer* lap)
{
  if(p.run)
  {
    exec.report("graph cut", 0.);
    Refinement::internal::solve_graph_cut(p.problem, r.labels, options.graph_cut, exec.threads());
    p = Pending_cut();
    exec.report("graph cut", 1.);
    if(lap)
      (*lap)("graph cut");
  }
  r.number_of_segments = Refinement::make_segments_connected(graph.graph(), r.labels);
  if(lap)
    (*lap)("connected segments");
}

// The `m` merged segments of `r.labels` (at most `clusters`, else a graph
// cut on that many labels would crawl, a mesh of many connected
// components: then skipped) refined by the graph cut with their mean
// embedding coordinates as proxies (when `options.boundary_enhancement`),
// then made connected; with `lap`, the stages timed as "graph cut" (when it
// ran) and "connected segments". With `release`, `r.embedding.coordinates`
// are released as soon as nothing reads them any more (before the graph
// cut's moves).
template <typename AffinityKernel>
void graph_cut_merged(const Weighted_dual_graph& graph, std::size_t m, std::size_t clusters,
                      const Basic_K_way_options<AffinityKernel>& options, K_way_result& r, const Execution& exec,
                      Stage_timer* lap = nullptr, bool release = false)
{
  Pending_cut p = prepare_graph_cut_merged(graph, m, clusters, options, r, release, exec.threads());
  finish_graph_cut_merged(graph, options, r, p, exec, lap);
}

// The answer of a merge method cut at `parts` parts in its hierarchy
// instead: the labels of the hierarchy's first cuts, boundaries smoothed by
// the graph cut (when `graph_cut` and at most `clusters` segments) and
// segments made connected; `r.hierarchy` and `r.embedding` must be set.
template <typename AffinityKernel>
void cut_hierarchy(const Weighted_dual_graph& graph, std::size_t parts, std::size_t clusters,
                   const Basic_K_way_options<AffinityKernel>& options, K_way_result& r, const Execution& exec)
{
  r.labels = r.hierarchy.labels_with_parts(parts);
  const std::size_t m = r.labels.empty() ? 0 : std::size_t(*std::max_element(r.labels.begin(), r.labels.end()) + 1);
  graph_cut_merged(graph, m, clusters, options, r, exec);
}

// The weakest-boundary merge of refine_clusters() on `labels` (segments of
// `r`'s embedding) down to `k_final`; the merges in r.hierarchy (or, with
// `keep`, in `*keep`). Returns the number of segments left.
template <typename AffinityKernel>
std::size_t merge_weakest_segments(const Weighted_dual_graph& graph, std::size_t k_final,
                                   const Basic_K_way_options<AffinityKernel>& options, K_way_result& r,
                                   std::vector<int>& labels, Refinement::internal::Merge_history* keep)
{
  const std::vector<double> concave = Refinement::concave_angle_weights(graph.graph());
  Refinement::internal::Merge_history history;
  const std::size_t m = Refinement::internal::merge_weakest(
    graph.graph(), concave, labels, k_final, options.merge_strength_limit, options.merge_min_area_fraction,
    options.merge_size_exponent, merge_separation(graph, options, r.embedding.coordinates), &history,
    flat_seam_radians(options));
  keep_merges(graph, std::move(history), r, keep);
  return m;
}

// refine_clusters() up to its graph cut's moves: the merge (when
// over-segmented) and the graph cut's problem; with `release`,
// `r.embedding.coordinates` are released then when nothing reads them
// after (the segments were merged down before the cut).
template <typename AffinityKernel>
Pending_cut prepare_refine_clusters(const Weighted_dual_graph& graph, std::size_t k, std::size_t k_final,
                                    const Basic_K_way_options<AffinityKernel>& options, K_way_result& r,
                                    Stage_timer& lap, Refinement::internal::Merge_history* keep, bool release,
                                    unsigned threads)
{
  const Eigen::MatrixXd& coordinates = r.embedding.coordinates;
  // Over-segmented: merge first, then cut the k merged segments with their
  // mean embedding as proxies. With several connected components the
  // segments can outnumber the clusters (each component is at least one),
  // and a graph cut on that many labels would crawl: there, cut the K-means
  // clusters first and merge afterwards.
  Pending_cut p;
  Eigen::MatrixXd proxies = r.clusters.centroids;
  if(k > k_final)
  {
    std::vector<int> labels = r.labels;
    if(options.crease_angle > 0.)
    {
      std::vector<int> region;
      if(Refinement::crease_regions(graph.graph(), options.crease_angle, region) > 1)
        Refinement::split_along_regions(region, labels);
    }
    Refinement::make_segments_connected(graph.graph(), labels);
    const std::size_t m = merge_weakest_segments(graph, k_final, options, r, labels, keep);
    if(m <= k)
    {
      proxies = mean_proxies(coordinates, labels, m, threads);
      r.labels = std::move(labels);
      p.merged = true;
    }
    lap("merge");
  }
  if(options.boundary_enhancement)
  {
    p.run = true;
    p.problem =
      Refinement::internal::graph_cut_problem(graph.graph(), coordinates, proxies, r.labels, options.graph_cut, threads);
  }
  if(release && p.merged)
    r.embedding.coordinates.resize(0, 0);
  return p;
}

// The rest of refine_clusters() after prepare_refine_clusters(): the graph
// cut's moves (`p` is emptied), connected segments, and the merge when the
// segments were not merged before.
template <typename AffinityKernel>
void finish_refine_clusters(const Weighted_dual_graph& graph, std::size_t k_final,
                            const Basic_K_way_options<AffinityKernel>& options, K_way_result& r, Pending_cut& p,
                            Stage_timer& lap, const Execution& exec, Refinement::internal::Merge_history* keep,
                            bool release)
{
  const bool merged = p.merged;
  if(p.run)
  {
    exec.report("graph cut", 0.);
    Refinement::internal::solve_graph_cut(p.problem, r.labels, options.graph_cut, exec.threads());
    p = Pending_cut();
    exec.report("graph cut", 1.);
    lap("graph cut");
  }
  r.number_of_segments = Refinement::make_segments_connected(graph.graph(), r.labels);
  lap("connected segments");
  if(!merged && r.number_of_segments > k_final)
  {
    r.number_of_segments = merge_weakest_segments(graph, k_final, options, r, r.labels, keep);
    lap("merge");
  }
  if(release)
    r.embedding.coordinates.resize(0, 0);
}

// Merge (when over-segmented), graph cut and connected segments on the k
// K-means clusters of kmeans_clusters(): k_final segments; the merges in
// r.hierarchy (or, with `keep`, in `*keep`, for hierarchy_from_merges()
// later: a candidate that loses never builds its hierarchy). With
// `release`, `r.embedding.coordinates` are released as soon as nothing
// reads them any more (before the graph cut's moves, or at the end).
template <typename AffinityKernel>
void refine_clusters(const Weighted_dual_graph& graph, std::size_t k, std::size_t k_final,
                     const Basic_K_way_options<AffinityKernel>& options, K_way_result& r, Stage_timer& lap,
                     const Execution& exec, Refinement::internal::Merge_history* keep = nullptr, bool release = false)
{
  Pending_cut p = prepare_refine_clusters(graph, k, k_final, options, r, lap, keep, release, exec.threads());
  finish_refine_clusters(graph, k_final, options, r, p, lap, exec, keep, release);
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegKWay
/// \brief Segments the faces of a weighted dual graph into `k` parts.
///
/// With \f$m = k +\f$ `options.extra_clusters` (2 by default, 0 for the
/// thesis's method):
/// 1. spectral embedding in \f$m\f$ dimensions: exact for small meshes,
///    Nyström with \f$m + 1\f$ farthest-point samples for large ones
///    (`options.embedding`);
/// 2. K-means in the embedding into \f$m\f$ clusters, seeded with the
///    sample faces (Nyström) or by max-min (exact);
/// 3. if \f$m > k\f$: the clusters are split along the closed loops of
///    sharp concave creases (`options.crease_angle`,
///    `Refinement::crease_regions()`), made connected regions, and the
///    adjacent ones with the weakest (least concave) boundary are merged
///    until \f$k\f$ are left (`Refinement::merge_weakest_boundaries()`,
///    flat seams first: `options.flat_seam_angle`);
///    each merged segment's proxy is its mean in the embedding;
/// 4. graph-cut boundary enhancement on the \f$k\f$ segments (optional;
///    `options.graph_cut`, by default in a band along the boundaries);
/// 5. every segment made one connected region (`Refinement::make_segments_connected()`).
///
/// With `options.alternative_extra_clusters` ({8} by default, empty for
/// the thesis's method), steps 1-5 are also run with each of those numbers
/// of extra clusters (where several candidates are tried, those of fewer
/// than `options.min_candidate_clusters` clusters are left out); with
/// `options.contrast_merge_clusters` (20 by default, 0 for the thesis's
/// method) the mesh is also over-segmented into
/// that many clusters (at least \f$k\f$) and merged down to \f$k\f$ by
/// contrast as in `segment_hybrid()`, then cut (steps 4-5). Of all these
/// candidates the one with the lowest
/// `Refinement::concave_normalized_cut()` is kept (ties to the first tried,
/// `extra_clusters`): its boundaries follow concave creases best.
/// `K_way_result::extra_clusters` and `K_way_result::contrast_merge` say
/// which was kept; `K_way_result::candidates` lists every candidate with
/// its cut before and after its graph cut (and its labels, with
/// `options.keep_candidate_labels`). The Nyström
/// farthest-point samples are nested, so the samples and distance rows of
/// the largest count serve every candidate. Each candidate's embedding,
/// K-means, merge and graph-cut data terms (the stages that read its
/// embedding) run one candidate after the other; with several threads each
/// candidate's graph-cut moves start on a thread of their own as soon as
/// its data terms are made, beside the next candidate's stages. Without
/// `options.keep_embedding_coordinates`, each candidate's embedding is
/// released as soon as its data terms are made, so that one candidate's
/// embedding is alive at a time (unless its merge comes after its graph
/// cut, see below), and the result's
/// `embedding.coordinates` is empty. The result does not depend on the
/// number of threads, nor on `options.keep_embedding_coordinates`.
///
/// On a mesh with more connected components than \f$m\f$ the merge cannot
/// bring the segments down to \f$m\f$ labels; there the graph cut runs on
/// the \f$m\f$ K-means clusters and the merge comes last.
///
/// \tparam AffinityKernel a model of `AffinityKernel`
/// \param graph the dual graph weighted by a metric
/// \param k the number of segments wanted
/// \param options every parameter of the method, the kernel included
/// \param exec threads and progress callback
/// \throws Invalid_input if `k` is 0 or larger than the number of faces,
///         `options.merge_separation_scale` is negative or not a number, or
///         `options.flat_seam_angle` is not in [0, 180)
/// \throws Error if the affinity matrix has no positive eigenvalue after the first
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename AffinityKernel = Kernels::Exponential_kernel>
K_way_result segment_k_way(const Weighted_dual_graph& graph, std::size_t k,
                           const Basic_K_way_options<AffinityKernel>& options = Basic_K_way_options<AffinityKernel>(),
                           const Execution& exec = Execution())
{
  const std::size_t n = graph.graph().number_of_faces();
  if(k == 0 || k > n)
    throw Invalid_input("k-way segmentation: k = " + std::to_string(k) + " but the mesh has " + std::to_string(n) +
                        " faces (k must be between 1 and the number of faces)");
  if(!(options.merge_separation_scale >= 0.))
    throw Invalid_input("k-way segmentation: the merge separation scale must be a number of at least 0");
  if(!(options.flat_seam_angle >= 0. && options.flat_seam_angle < 180.))
    throw Invalid_input("k-way segmentation: the flat seam angle must be a number of degrees in [0, 180)");
  K_way_result r;
  internal::Stage_timer lap(r.timings);
  if(k == 1 || n < 3)
  {
    r.labels.assign(n, 0);
    r.number_of_segments = Refinement::make_segments_connected(graph.graph(), r.labels);
    return r;
  }

  // the embedding's dimensions and the number of K-means clusters with `e`
  // extra clusters (k clusters in fewer dimensions on a mesh of k faces)
  const auto dimensions_of = [&](std::size_t e) { return std::min(k + e, n - 1); };
  const auto clusters_of = [&](std::size_t e) { return std::max(k, dimensions_of(e)); };
  // the numbers of extra clusters to try, each once, in the given order
  std::vector<std::size_t> extras{options.extra_clusters};
  for(std::size_t e : options.alternative_extra_clusters)
    if(std::find(extras.begin(), extras.end(), e) == extras.end())
      extras.push_back(e);
  // with several candidates, those of too few clusters are left out (the
  // one of the most clusters stays if all of them would go)
  const bool choice = extras.size() > 1 || options.contrast_merge_clusters > 0;
  if(choice)
  {
    const auto most = std::max_element(extras.begin(), extras.end(), [&](std::size_t a, std::size_t b) {
      return clusters_of(a) < clusters_of(b);
    });
    const std::size_t fallback = *most;
    extras.erase(std::remove_if(extras.begin(), extras.end(),
                                [&](std::size_t e) { return clusters_of(e) < options.min_candidate_clusters; }),
                 extras.end());
    if(extras.empty())
      extras.push_back(fallback);
  }
  if(extras.size() == 1 && options.contrast_merge_clusters == 0)
  {
    r.embedding = internal::embed(graph, dimensions_of(extras.front()), options.kernel, options.embedding, exec);
    lap("embedding");
    internal::kmeans_clusters(clusters_of(extras.front()), options, r, lap, exec);
    internal::refine_clusters(graph, clusters_of(extras.front()), k, options, r, lap, exec, nullptr,
                              !options.keep_embedding_coordinates);
    r.extra_clusters = clusters_of(extras.front()) - k;
    if(choice) // the others left out: the kept one's value, as with a choice
      r.normalized_cut = Refinement::concave_normalized_cut(graph.graph(), r.labels, options.cut_angle_scale);
    return r;
  }

  // Several over-segmentations, each in full; the lowest concave normalized
  // cut is kept, ties to the first tried. Each is one embedding's
  // dimensions and K-means clusters, merged weakest boundary first or, the
  // last with `contrast_merge_clusters`, by contrast.
  struct Candidate
  {
    std::size_t dimensions, clusters;
    bool contrast;
  };
  std::vector<Candidate> specs;
  for(std::size_t e : extras)
    specs.push_back(Candidate{dimensions_of(e), clusters_of(e), false});
  if(options.contrast_merge_clusters > 0)
  {
    const std::size_t d = std::min(std::max(options.contrast_merge_clusters, k), n - 1);
    specs.push_back(Candidate{d, std::max(k, d), true});
  }
  std::vector<K_way_result> candidates(specs.size());
  // their merges, made into a hierarchy for the kept candidate only
  std::vector<Refinement::internal::Merge_history> histories(specs.size());
  std::vector<std::vector<std::pair<std::string, double>>> times(specs.size());
  // their graph cuts up to the moves
  std::vector<internal::Pending_cut> cuts(specs.size());
  // their concave normalized cuts before the graph cut, for the report
  std::vector<double> before(specs.size(), 0.);
  const bool release = !options.keep_embedding_coordinates;
  const Embedding::Embedding_options& eo = options.embedding;
  // Nyström with farthest-point samples: the samples are nested, so the
  // samples and distance rows of the most clusters serve every candidate.
  const bool share = eo.sampling == Embedding::Sampling_method::farthest_point && eo.samples == 0 &&
                     (eo.method == Embedding::Method::nystrom ||
                      (eo.method == Embedding::Method::automatic && n > eo.exact_face_limit));
  // the contrast candidate's crease regions and concave angles depend on
  // the mesh only: made on another thread while this one samples (whose
  // diameter search runs on one)
  const bool contrast = options.contrast_merge_clusters > 0 && exec.threads() > 1;
  std::future<internal::Contrast_merge_shared> made;
  if(contrast)
    made = std::async(std::launch::async, [&graph, &options] {
      return internal::contrast_merge_shared(graph, options, internal::default_reference_faces);
    });
  Embedding::internal::Nystrom_rows shared;
  if(share)
  {
    std::size_t largest = 0;
    for(const Candidate& c : specs)
      largest = std::max(largest, c.dimensions);
    shared = Embedding::internal::nystrom_rows(graph, largest + 1, options.kernel, eo, exec);
    lap("embedding");
  }
  // Each candidate in turn: the stages that read the embedding (embedding
  // and K-means, which use every thread, the merge and the graph cut's data
  // terms) on this thread, which reports progress to `exec`. Then, with
  // several threads, its mostly sequential stages (max-flow moves,
  // connected segments) start on a thread of their own while this thread
  // goes on with the next candidate, at most `exec.threads() - 1` of them
  // at a time; the last candidate's run here. Those threads stop when this
  // one throws. A candidate's result does not depend on where, or on how
  // many threads, it ran.
  const auto refine = [&](std::size_t i, const Execution& x) {
    internal::Stage_timer t(times[i], true);
    K_way_result& c = candidates[i];
    if(specs[i].contrast)
      internal::finish_graph_cut_merged(graph, options, c, cuts[i], x, &t);
    else
      internal::finish_refine_clusters(graph, k, options, c, cuts[i], t, x, &histories[i], release);
    c.extra_clusters = specs[i].clusters - k;
    c.normalized_cut = Refinement::concave_normalized_cut(graph.graph(), c.labels, options.cut_angle_scale);
    t("choice");
  };
  std::atomic<bool> stop(false);
  const Execution other(1, [&stop](const std::string&, double) { return !stop.load(); });
  std::deque<std::future<void>> running;
  try
  {
    for(std::size_t i = 0; i < specs.size(); ++i)
    {
      internal::Stage_timer t(times[i], true);
      K_way_result& c = candidates[i];
      const std::size_t dimensions = specs[i].dimensions;
      if(share) // the candidate's leading rows, made into affinities one face at a time
        c.embedding = Embedding::internal::nystrom_embedding_from_distances(
          shared.distances,
          std::vector<Dual_graph::size_type>(shared.samples.begin(),
                                             shared.samples.begin() + static_cast<std::ptrdiff_t>(dimensions + 1)),
          options.kernel, dimensions, exec);
      else
        c.embedding = internal::embed(graph, dimensions, options.kernel, eo, exec);
      if(i + 1 == specs.size())
        shared = Embedding::internal::Nystrom_rows(); // no longer needed
      t("embedding");
      internal::kmeans_clusters(specs[i].clusters, options, c, t, exec);
      // the merge and the graph cut's data terms, the last to read the
      // embedding: without coordinates in the result, it goes before the
      // next candidate's is made
      if(specs[i].contrast)
      {
        // the contrast merge down to k segments: its hierarchy cut at k
        const internal::Contrast_merge_shared shared_merge =
          contrast ? made.get()
                   : internal::contrast_merge_shared(graph, options, internal::default_reference_faces, exec.threads());
        const std::size_t m = internal::merge_clusters_by_contrast(
          graph, options, k, std::numeric_limits<double>::infinity(), internal::default_neck_scale,
          internal::default_reference_faces, c, &histories[i], &shared_merge);
        t("merge");
        cuts[i] = internal::prepare_graph_cut_merged(graph, m, specs[i].clusters, options, c, release, exec.threads());
        c.contrast_merge = true;
      }
      else
        cuts[i] = internal::prepare_refine_clusters(graph, specs[i].clusters, k, options, c, t, &histories[i], release,
                                                    exec.threads());
      if(cuts[i].run)
        t("graph cut");
      before[i] = Refinement::concave_normalized_cut(graph.graph(), c.labels, options.cut_angle_scale);
      if(i + 1 == specs.size() || exec.threads() < 2)
      {
        refine(i, exec);
        continue;
      }
      while(running.size() + 1 >= exec.threads())
      {
        running.front().get(); // rethrows a candidate's exception
        running.pop_front();
      }
      running.push_back(std::async(std::launch::async, [&refine, &other, i] { refine(i, other); }));
    }
    for(; !running.empty(); running.pop_front())
      running.front().get();
  }
  catch(...)
  {
    stop = true;
    for(auto& f : running)
      if(f.valid())
        f.wait();
    throw;
  }
  std::size_t kept = 0;
  for(std::size_t i = 1; i < candidates.size(); ++i)
    if(candidates[i].normalized_cut < candidates[kept].normalized_cut) // strict: ties to the first tried
      kept = i;
  std::vector<K_way_candidate> report(candidates.size());
  for(std::size_t i = 0; i < candidates.size(); ++i)
  {
    report[i].extra_clusters = specs[i].clusters - k;
    report[i].contrast_merge = specs[i].contrast;
    report[i].normalized_cut_before_graph_cut = before[i];
    report[i].normalized_cut = candidates[i].normalized_cut;
    report[i].kept = i == kept;
    report[i].number_of_segments = candidates[i].number_of_segments;
    if(options.keep_candidate_labels)
      report[i].labels = candidates[i].labels;
  }
  std::vector<std::pair<std::string, double>> timings = std::move(r.timings); // the shared sampling
  internal::Stage_timer sum(timings, true);
  for(const auto& candidate_times : times)
    for(const auto& t : candidate_times)
      sum.add(t.first, t.second);
  r = std::move(candidates[kept]);
  r.timings = std::move(timings);
  r.candidates = std::move(report);
  const Refinement::internal::Merge_history& h = histories[kept];
  if(!h.labels.empty())
    r.hierarchy = internal::hierarchy_from_merges(h.labels, graph.graph().geometry().areas, h.steps, h.answer);
  return r;
}

/// \ingroup PkgSpectralSegKWay
/// \brief `segment_k_way()` that chooses the number of segments itself,
/// between 2 and `options.max_k` (the rule of `spectralseg segment --k auto`; our
/// addition, the thesis takes k from the user).
///
/// The mesh is over-segmented into `options.max_k` clusters (embedding in
/// `max_k` dimensions, Nyström with `max_k + 1` samples), then adjacent segments are
/// merged weakest boundary first (`Refinement::merge_weakest_boundaries()`
/// with `Refinement::concave_angle_weights()`) for as long as the weakest
/// boundary's mean concave dihedral angle is below `options.min_boundary_contrast`
/// times the mean concave angle of all the mesh's edges (both means weighted
/// by edge length), and never below 2 segments. Parts that meet at a crease
/// stay apart, pieces of one smooth body are joined. The limit is relative
/// so that it does not depend on the mesh resolution: coarse meshes have
/// larger dihedral angles everywhere.
///
/// Segments under `options.k_way.merge_min_area_fraction` of the area are merged
/// whatever their boundary, as in `segment_k_way()`. The default contrast
/// and the choice of a relative limit are explained, with their scores, in
/// doc/benchmarks.md.
///
/// `options.k_way.extra_clusters` and `options.k_way.merge_strength_limit`
/// are replaced by the rule's values; the other k-way options apply as in
/// `segment_k_way()`.
/// \tparam AffinityKernel a model of `AffinityKernel`
/// \param graph the dual graph weighted by a metric
/// \param options the k-way options, `max_k` and `min_boundary_contrast`
/// \param exec threads and progress callback
/// \throws Invalid_input if `options.max_k` is below 2
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename AffinityKernel = Kernels::Exponential_kernel>
K_way_result segment_k_way_automatic(const Weighted_dual_graph& graph,
                                     const Basic_K_way_automatic_options<AffinityKernel>& options =
                                       Basic_K_way_automatic_options<AffinityKernel>(),
                                     const Execution& exec = Execution())
{
  const std::size_t n = graph.graph().number_of_faces();
  if(options.max_k < 2)
    throw Invalid_input("automatic k-way segmentation: the largest k must be at least 2");
  if(n < 3)
    return segment_k_way(graph, 1, options.k_way, exec);
  Basic_K_way_options<AffinityKernel> o = options.k_way;
  o.extra_clusters = options.max_k - 2;
  o.alternative_extra_clusters.clear();
  o.contrast_merge_clusters = 0;
  // the mesh's mean concave angle, each dual edge counted with its length
  const std::vector<double> w = Refinement::concave_angle_weights(graph.graph());
  double sum = 0., length = 0.;
  for(std::size_t d = 0; d < w.size(); ++d)
  {
    const double l = graph.graph().edge(static_cast<Dual_graph::size_type>(d)).length;
    sum += l * w[d];
    length += l;
  }
  o.merge_strength_limit = options.min_boundary_contrast * (length > 0. ? sum / length : 0.);
  if(options.parts > 0)
    o.keep_embedding_coordinates = true; // the hierarchy's cut reads them
  K_way_result r = segment_k_way(graph, 2, o, exec);
  if(options.parts > 0 && !r.hierarchy.nodes.empty())
    internal::cut_hierarchy(graph, options.parts, std::min(options.max_k, n - 1), o, r, exec);
  if(!options.k_way.keep_embedding_coordinates)
    r.embedding.coordinates.resize(0, 0);
  return r;
}

/// \cond SKIP_IN_MANUAL
#if SPECTRALSEG_DEFAULT_INSTANCES
SPECTRALSEG_INSTANTIATE K_way_result segment_k_way<Kernels::Exponential_kernel>(
  const Weighted_dual_graph&, std::size_t, const Basic_K_way_options<Kernels::Exponential_kernel>&, const Execution&);
SPECTRALSEG_INSTANTIATE K_way_result segment_k_way_automatic<Kernels::Exponential_kernel>(
  const Weighted_dual_graph&, const Basic_K_way_automatic_options<Kernels::Exponential_kernel>&, const Execution&);
SPECTRALSEG_INSTANTIATE K_way_result segment_k_way<Kernels::Any_kernel>(
  const Weighted_dual_graph&, std::size_t, const Basic_K_way_options<Kernels::Any_kernel>&, const Execution&);
SPECTRALSEG_INSTANTIATE K_way_result segment_k_way_automatic<Kernels::Any_kernel>(
  const Weighted_dual_graph&, const Basic_K_way_automatic_options<Kernels::Any_kernel>&, const Execution&);
#endif
/// \endcond

/// \cond SKIP_IN_MANUAL
// Deprecated positional forms (kernel, options and, for the automatic rule,
// max_k and min_boundary_contrast as separate arguments).
template <typename T> struct Is_k_way_options : std::false_type {};
template <typename K> struct Is_k_way_options<Basic_K_way_options<K>> : std::true_type {};

template <typename AffinityKernel,
          typename = std::enable_if_t<!Is_k_way_options<AffinityKernel>::value>>
[[deprecated("put the kernel into the options: segment_k_way(graph, k, options.with_kernel(kernel), exec)")]]
K_way_result segment_k_way(const Weighted_dual_graph& graph, std::size_t k, const AffinityKernel& kernel,
                           const K_way_options& options = K_way_options(), const Execution& exec = Execution())
{
  return segment_k_way(graph, k, options.with_kernel(kernel), exec);
}

template <typename AffinityKernel = Kernels::Exponential_kernel>
[[deprecated("use segment_k_way_automatic(graph, K_way_automatic_options, exec)")]]
K_way_result segment_k_way_automatic(const Weighted_dual_graph& graph, std::size_t max_k,
                                     const AffinityKernel& kernel = AffinityKernel(),
                                     const K_way_options& options = K_way_options(),
                                     const Execution& exec = Execution(), double min_boundary_contrast = 3.)
{
  Basic_K_way_automatic_options<AffinityKernel> o;
  o.k_way = options.with_kernel(kernel);
  o.max_k = max_k;
  o.min_boundary_contrast = min_boundary_contrast;
  return segment_k_way_automatic(graph, o, exec);
}
/// \endcond

} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENT_K_WAY_H
