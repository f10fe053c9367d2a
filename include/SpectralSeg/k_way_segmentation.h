// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file k_way_segmentation.h
/// \brief Segmentation into k parts by spectral clustering of the part-aware
/// metric (thesis ch. 4 and 5).
#ifndef SPECTRALSEG_K_WAY_SEGMENTATION_H
#define SPECTRALSEG_K_WAY_SEGMENTATION_H

#include <SpectralSeg/Clustering/Kmeans.h>
#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Embedding/exact_spectral_embedding.h>
#include <SpectralSeg/Embedding/nystrom_spectral_embedding.h>
#include <SpectralSeg/Kernels/Exponential_kernel.h>
#include <SpectralSeg/Kernels/Gaussian_kernel.h>
#include <SpectralSeg/Refinement/connected_segments.h>
#include <SpectralSeg/Refinement/merge_segments.h>
#include <SpectralSeg/Refinement/graph_cut_boundaries.h>
#include <SpectralSeg/face_distances.h>

#include <chrono>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegKWay
/// \brief Parameters of `segment_k_way()`.
struct K_way_options
{
  /// exact or Nyström embedding, samples, seed
  Embedding::Embedding_options embedding;
  /// whether the K-means labels are refined by the graph cut (thesis 4.3.3)
  bool boundary_enhancement = true;
  /// \f$\mu\f$, \f$\nu\f$ and max-flow backend of the graph cut
  Refinement::Graph_cut_options graph_cut;
  /// bound on K-means rounds
  std::size_t kmeans_iterations = 100;
  /// Nyström path: seed K-means with the first `k` sample faces (the
  /// thesis, 5.5); if false, with max-min seeds in the embedding, as the
  /// exact path does
  bool seed_with_samples = true;
  /// over-segment and merge (our addition): the embedding and K-means use
  /// `k + extra_clusters` clusters, then the adjacent segments whose
  /// boundary has the smallest mean concave dihedral angle are merged until
  /// `k` are left (`Refinement::merge_weakest_boundaries()` with
  /// `Refinement::concave_angle_weights()`). K-means splits large bodies
  /// into pieces of similar spread and leaves small parts (fins, horns,
  /// fingers) unsplit; the extra clusters take those small parts and the
  /// merge joins the body pieces across their smooth seams. 0 gives the
  /// thesis's method (`thesis()`).
  std::size_t extra_clusters = 3;
  /// merging also stops when every boundary's mean concave angle (radians)
  /// is at least this
  double merge_strength_limit = std::numeric_limits<double>::infinity();
  /// segments smaller than this fraction of the mesh area are merged
  /// first, whatever their boundary: without it the sharp crease around an
  /// ear keeps the ear while the smooth hip joint merges the leg into the
  /// body
  double merge_min_area_fraction = 0.005;

  /// the thesis's k-way method: K-means with exactly `k` clusters
  static K_way_options thesis()
  {
    K_way_options o;
    o.extra_clusters = 0;
    return o;
  }
};

/// \ingroup PkgSpectralSegKWay
/// \brief What `segment_k_way()` produced.
struct K_way_result
{
  /// one segment per face, in `[0, number_of_segments)`, each segment one
  /// connected region, numbered by their smallest face
  std::vector<int> labels;
  /// number of segments: `k`, or more on a mesh with more connected
  /// components than `k`, or fewer if a cluster vanished
  std::size_t number_of_segments = 0;
  /// the spectral embedding the clusters were found in
  Embedding::Spectral_embedding embedding;
  /// K-means result, before the graph cut
  Clustering::Kmeans_result clusters;
  /// seconds spent in each stage, in order
  std::vector<std::pair<std::string, double>> timings;
};

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

// Appends (stage, seconds since the previous call) to a timing list.
class Stage_timer
{
public:
  explicit Stage_timer(std::vector<std::pair<std::string, double>>& timings)
    : timings_(timings), clock_(std::chrono::steady_clock::now())
  {}
  void operator()(const std::string& stage)
  {
    const auto now = std::chrono::steady_clock::now();
    timings_.emplace_back(stage, std::chrono::duration<double>(now - clock_).count());
    clock_ = now;
  }

private:
  std::vector<std::pair<std::string, double>>& timings_;
  std::chrono::steady_clock::time_point clock_;
};

// K-means, merge (when over-segmented), graph cut and connected segments on
// r.embedding: k clusters, k_final segments.
inline void cluster(const Weighted_dual_graph& graph, std::size_t k, std::size_t k_final, const K_way_options& options,
                    K_way_result& r, Stage_timer& lap, const Execution& exec)
{
  if(r.embedding.coordinates.cols() == 0)
    throw Error("k-way segmentation: the affinity matrix has no positive eigenvalue after the first");
  exec.report("k-means", 0.);
  std::vector<std::size_t> seeds;
  if(!r.embedding.exact && options.seed_with_samples)
    for(std::size_t i = 0; i < k && i < r.embedding.samples.size(); ++i)
      seeds.push_back(r.embedding.samples[i]);
  r.clusters = Clustering::kmeans(r.embedding.coordinates, k, seeds, options.kmeans_iterations, exec);

  r.labels = r.clusters.labels;
  exec.report("k-means", 1.);
  lap("k-means");
  // Over-segmented: merge first, then cut the k merged segments with their
  // mean embedding as proxies. With several connected components the
  // segments can outnumber the clusters (each component is at least one),
  // and a graph cut on that many labels would crawl: there, cut the K-means
  // clusters first and merge afterwards.
  std::vector<double> concave;
  const auto merge = [&](std::vector<int>& labels) {
    if(concave.empty())
      concave = Refinement::concave_angle_weights(graph.graph());
    return Refinement::merge_weakest_boundaries(graph.graph(), concave, labels, k_final, options.merge_strength_limit,
                                                options.merge_min_area_fraction);
  };
  Eigen::MatrixXd proxies = r.clusters.centroids;
  bool merged = false;
  if(k > k_final)
  {
    std::vector<int> labels = r.labels;
    Refinement::make_segments_connected(graph.graph(), labels);
    const std::size_t m = merge(labels);
    if(m <= k)
    {
      proxies = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m), r.embedding.coordinates.cols());
      std::vector<double> count(m, 0.);
      for(std::size_t f = 0; f < labels.size(); ++f) // in face order: thread-independent
      {
        proxies.row(labels[f]) += r.embedding.coordinates.row(static_cast<Eigen::Index>(f));
        count[std::size_t(labels[f])] += 1.;
      }
      for(std::size_t c = 0; c < m; ++c)
        proxies.row(static_cast<Eigen::Index>(c)) /= std::max(1., count[c]);
      r.labels = std::move(labels);
      merged = true;
    }
    lap("merge");
  }
  if(options.boundary_enhancement)
  {
    exec.report("graph cut", 0.);
    Refinement::graph_cut_boundaries(graph.graph(), r.embedding.coordinates, proxies, r.labels, options.graph_cut);
    exec.report("graph cut", 1.);
    lap("graph cut");
  }
  r.number_of_segments = Refinement::make_segments_connected(graph.graph(), r.labels);
  lap("connected segments");
  if(!merged && r.number_of_segments > k_final)
  {
    r.number_of_segments = merge(r.labels);
    lap("merge");
  }
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegKWay
/// \brief Segments the faces of a weighted dual graph into `k` parts.
///
/// With \f$m = k +\f$ `options.extra_clusters` (3 by default, 0 for the
/// thesis's method):
/// 1. spectral embedding in \f$m\f$ dimensions: exact for small meshes,
///    Nyström with \f$m + 1\f$ farthest-point samples for large ones
///    (`options.embedding`);
/// 2. K-means in the embedding into \f$m\f$ clusters, seeded with the
///    sample faces (Nyström) or by max-min (exact);
/// 3. if \f$m > k\f$: the clusters are made connected regions and the
///    adjacent ones with the weakest (least concave) boundary are merged
///    until \f$k\f$ are left (`Refinement::merge_weakest_boundaries()`);
///    each merged segment's proxy is its mean in the embedding;
/// 4. graph-cut boundary enhancement on the \f$k\f$ segments (optional);
/// 5. every segment made one connected region (`Refinement::make_segments_connected()`).
///
/// On a mesh with more connected components than \f$m\f$ the merge cannot
/// bring the segments down to \f$m\f$ labels; there the graph cut runs on
/// the \f$m\f$ K-means clusters and the merge comes last.
///
/// \tparam AffinityKernel a model of `AffinityKernel`
/// \throws Invalid_input if `k` is 0 or larger than the number of faces
template <typename AffinityKernel = Kernels::Exponential_kernel>
K_way_result segment_k_way(const Weighted_dual_graph& graph, std::size_t k,
                           const AffinityKernel& kernel = AffinityKernel(),
                           const K_way_options& options = K_way_options(), const Execution& exec = Execution())
{
  const std::size_t n = graph.graph().number_of_faces();
  if(k == 0 || k > n)
    throw Invalid_input("k-way segmentation: k = " + std::to_string(k) + " but the mesh has " + std::to_string(n) +
                        " faces (k must be between 1 and the number of faces)");
  K_way_result r;
  internal::Stage_timer lap(r.timings);
  if(k == 1 || n < 3)
  {
    r.labels.assign(n, 0);
    r.number_of_segments = Refinement::make_segments_connected(graph.graph(), r.labels);
    return r;
  }

  const std::size_t clusters = std::min(k + options.extra_clusters, n - 1);
  const std::size_t dims = std::min(clusters, n - 1);
  r.embedding = internal::embed(graph, dims, kernel, options.embedding, exec);
  lap("embedding");
  internal::cluster(graph, std::max(k, clusters), k, options, r, lap, exec);
  return r;
}

/// \ingroup PkgSpectralSegKWay
/// \brief Estimates a number of segments from the spectrum of the affinity
/// matrix.
///
/// With \f$\lambda_1 \ge \lambda_2 \ge \dots\f$ the leading eigenvalues
/// of the affinity matrix (\f$\lambda_1\f$ is the one dropped for
/// centring, \f$\lambda_2\f$ the largest kept one), each part of a shape
/// contributes a large eigenvalue. The rule counts the eigenvalues after the
/// first that reach `threshold` times \f$\lambda_2\f$, adds one for the
/// first, and clamps the result to \f$[2, k_{max}]\f$ (our rule; the
/// thesis takes k from the user). `segment_k_way_automatic()` does not use
/// it (doc/benchmarks.md compares the two).
inline std::size_t choose_number_of_segments(const Embedding::Spectral_embedding& e, std::size_t max_k,
                                             double threshold = 0.3)
{
  std::size_t count = 0;
  const double lambda2 = e.eigenvalues.size() > 0 ? e.eigenvalues(0) : 0.;
  for(Eigen::Index i = 0; i < e.eigenvalues.size(); ++i)
    if(e.eigenvalues(i) >= threshold * lambda2)
      ++count;
  return std::max<std::size_t>(2, std::min(max_k, count + 1));
}

/// \ingroup PkgSpectralSegKWay
/// \brief `segment_k_way()` that chooses the number of segments itself,
/// between 2 and `max_k` (the rule of `spectralseg segment --k auto`; our
/// addition, the thesis takes k from the user).
///
/// The mesh is over-segmented into `max_k` clusters (embedding in `max_k`
/// dimensions, Nyström with `max_k + 1` samples), then adjacent segments are
/// merged weakest boundary first (`Refinement::merge_weakest_boundaries()`
/// with `Refinement::concave_angle_weights()`) for as long as the weakest
/// boundary's mean concave dihedral angle is below `min_boundary_contrast`
/// times the mean concave angle of all the mesh's edges (both means weighted
/// by edge length), and never below 2 segments. Parts that meet at a crease
/// stay apart, pieces of one smooth body are joined. The limit is relative
/// so that it does not depend on the mesh resolution: coarse meshes have
/// larger dihedral angles everywhere.
///
/// Segments under `options.merge_min_area_fraction` of the area are merged
/// whatever their boundary, as in `segment_k_way()`. The default contrast
/// and the choice of a relative limit are explained, with their scores, in
/// doc/benchmarks.md.
///
/// `options.extra_clusters` and `options.merge_strength_limit` are replaced
/// by the rule's values; the other options apply as in `segment_k_way()`.
/// \throws Invalid_input if `max_k` is below 2
template <typename AffinityKernel = Kernels::Exponential_kernel>
K_way_result segment_k_way_automatic(const Weighted_dual_graph& graph, std::size_t max_k = 20,
                                     const AffinityKernel& kernel = AffinityKernel(),
                                     const K_way_options& options = K_way_options(), const Execution& exec = Execution(),
                                     double min_boundary_contrast = 3.)
{
  const std::size_t n = graph.graph().number_of_faces();
  if(max_k < 2)
    throw Invalid_input("automatic k-way segmentation: the largest k must be at least 2");
  if(n < 3)
    return segment_k_way(graph, 1, kernel, options, exec);
  K_way_options o = options;
  o.extra_clusters = max_k - 2;
  // the mesh's mean concave angle, each dual edge counted with its length
  const std::vector<double> w = Refinement::concave_angle_weights(graph.graph());
  double sum = 0., length = 0.;
  for(std::size_t d = 0; d < w.size(); ++d)
  {
    const double l = graph.graph().edge(static_cast<Dual_graph::size_type>(d)).length;
    sum += l * w[d];
    length += l;
  }
  o.merge_strength_limit = min_boundary_contrast * (length > 0. ? sum / length : 0.);
  return segment_k_way(graph, 2, kernel, o, exec);
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// What both mesh entry points need: the execution, the dual graph of the
// mesh and its weights under the chosen metric.
struct Weighted_mesh_graph
{
  template <typename TriangleMesh, typename NamedParameters>
  Weighted_mesh_graph(const TriangleMesh& tm, const NamedParameters& np)
    : exec(execution_from(np)), graph(make_dual_graph(tm, np)),
      weighted(graph, metric_weights(metric_from(np), graph, exec))
  {}
  Execution exec;
  Dual_graph graph;
  Weighted_dual_graph weighted;
};

template <typename NamedParameters>
K_way_options k_way_options_from(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  K_way_options o = choose_parameter(get_parameter(np, SpectralSeg::internal_np::k_way_options), K_way_options());
  o.embedding.method = choose_parameter(get_parameter(np, SpectralSeg::internal_np::embedding_method), o.embedding.method);
  o.embedding.samples = choose_parameter(get_parameter(np, SpectralSeg::internal_np::number_of_nystrom_samples), o.embedding.samples);
  o.embedding.sampling = choose_parameter(get_parameter(np, SpectralSeg::internal_np::sampling_method), o.embedding.sampling);
  o.embedding.seed = static_cast<unsigned int>(
    choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), o.embedding.seed));
  o.boundary_enhancement =
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::boundary_enhancement), o.boundary_enhancement);
  return o;
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegKWay
/// \brief Segments a triangle mesh into `k` parts by spectral clustering of
/// the part-aware metric, and returns the number of segments.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         with triangle faces oriented outward
/// \tparam SegmentMap a writable property map from faces to an integer type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param k the number of segments wanted
/// \param segments receives the segment of each face, in `[0, returned value)`
/// \param np optional named parameters among:
///   - `metric`: a model of `DualEdgeWeight`; default `Metrics::Part_aware_weight<>()`
///   - `kernel`: a model of `AffinityKernel`; default `Kernels::Exponential_kernel()`
///   - `embedding_method`: `Embedding::Method::automatic` (default), `exact` or `nystrom`
///   - `number_of_nystrom_samples`: Nyström samples; default `k + 1`
///   - `sampling_method`: `Embedding::Sampling_method::farthest_point` (default) or `gamma`
///   - `random_seed`: seed of the sampling's start face (default 0)
///   - `boundary_enhancement`: graph-cut refinement, default `true`
///   - `k_way_options`: a whole `K_way_options` (\f$\mu\f$, \f$\nu\f$, graph-cut backend, ...;
///     the parameters above override its fields)
///   - `number_of_threads`, `progress_callback`, `vertex_point_map`,
///     `vertex_index_map`, `face_index_map`: as for `face_distances()`
///
/// The output does not depend on the number of threads.
/// \throws Invalid_input for `k` = 0 or larger than the number of faces, a
///         non-triangle face or a non-finite coordinate
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename TriangleMesh, typename SegmentMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t k_way_segmentation(const TriangleMesh& tm, std::size_t k, SegmentMap segments,
                               const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const internal::Weighted_mesh_graph g(tm, np);
  const auto kernel = choose_parameter(get_parameter(np, SpectralSeg::internal_np::kernel), Kernels::Exponential_kernel());
  const K_way_result r = segment_k_way(g.weighted, k, kernel, internal::k_way_options_from(np), g.exec);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  typedef typename boost::property_traits<SegmentMap>::value_type Label;
  for(auto f : faces(tm))
    put(segments, f, static_cast<Label>(r.labels[get(fim, f)]));
  return r.number_of_segments;
}

/// \ingroup PkgSpectralSegKWay
/// \brief The spectral embedding of the faces of `tm` in `dimensions`
/// dimensions, for users who run their own clustering. Rows follow the face
/// index map. Named parameters as for `k_way_segmentation()`.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Embedding::Spectral_embedding spectral_embedding(const TriangleMesh& tm, std::size_t dimensions,
                                                 const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const internal::Weighted_mesh_graph g(tm, np);
  const auto kernel = choose_parameter(get_parameter(np, SpectralSeg::internal_np::kernel), Kernels::Exponential_kernel());
  return internal::embed(g.weighted, dimensions, kernel, internal::k_way_options_from(np).embedding, g.exec);
}

} // namespace SpectralSeg

#endif
