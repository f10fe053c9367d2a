// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's second translation unit: the segmentation methods (k-way, the
// merge methods, the salient cuts), the metrics and their ray casters, and
// the options' defaults taken from the library. The rest of the tool
// (main.cpp: the commands, reading, outputs, batch) only declares them, so
// that two cores compile the tool side by side (doc/install.md).
#include "command_segment.h"

#include <SpectralSeg/Kernels/Any_kernel.h>
#include <SpectralSeg/Kernels/Exponential_kernel.h>
#include <SpectralSeg/Kernels/Gaussian_kernel.h>
#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Metrics/VSI_weight.h>
#include <SpectralSeg/Ray_casting/AABB_ray_caster.h>
#ifdef SPECTRALSEG_HAS_EMBREE
#include <SpectralSeg/Ray_casting/Embree_ray_caster.h>
#endif
#include <SpectralSeg/Refinement/graph_cut_boost_backends.h> // --graph-cut-backend boost-csr, boost-list
#include <SpectralSeg/automatic_segmentation.h>
#include <SpectralSeg/k_way_segmentation.h>
#include <SpectralSeg/segment_hybrid.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace spectralseg_cli {

Segment_options::Segment_options()
{
  const SpectralSeg::K_way_options k_way;
  extra_clusters = k_way.extra_clusters;
  alternative_extra_clusters = k_way.alternative_extra_clusters;
  contrast_merge_clusters = k_way.contrast_merge_clusters;
  min_candidate_clusters = k_way.min_candidate_clusters;
  crease_angle = k_way.crease_angle;
  merge_size_exponent = k_way.merge_size_exponent;
  flat_seam_angle = k_way.flat_seam_angle;
  merge_separation = k_way.merge_separation_scale;
  neck_scale = SpectralSeg::Hybrid_options().neck_scale;
  over_segmentations = SpectralSeg::Hybrid_options().over_segmentations;
}

Salient_cut_options::Salient_cut_options()
{
  const SpectralSeg::Automatic_segmentation_options<> automatic;
  min_part_area = automatic.min_part_area_fraction;
  max_parts = automatic.max_parts;
}

static_assert(SpectralSeg::Metrics::VSI::Reference_point_options().max_measured_faces == default_max_measured_faces,
              "--max-measured-faces: the tool's default is the library's");

namespace {

template <typename RayCaster>
SpectralSeg::Metrics::Any_weight make_vsi_metric(const Metric_options& o)
{
  using namespace SpectralSeg::Metrics;
  VSI_options vsi;
  vsi.images.sample_fraction = o.vsi_fraction;
  vsi.reference.max_measured_faces = o.max_measured_faces;
  if(o.name == "vsi")
    return VSI_weight<RayCaster>(vsi);
  const double gamma = o.weights.size() > 2 ? o.weights[2] : 0.;
  return Part_aware_weight<RayCaster>(o.weights.at(0), o.weights.at(1), gamma, vsi, 0.001,
                                      o.normalization == "max" ? Normalization::maximum() : Normalization::quantile(0.99));
}

// One node of a hierarchy and its subtree; `cuts`: the salient-cut method's
// (with the segmentability tests), else merges.
nlohmann::ordered_json hierarchy_json(const SpectralSeg::Part_hierarchy& h, std::size_t node, bool cuts)
{
  const SpectralSeg::Part_node& n = h.nodes[node];
  nlohmann::ordered_json j;
  j["faces"] = n.faces.size();
  j["area"] = n.area;
  j["depth"] = n.depth;
  if(cuts)
    j["tested"] = n.tested;
  if(n.tested)
  {
    j["test"] = SpectralSeg::Segmentability::test_name(n.test);
    j["score"] = n.score;
    nlohmann::ordered_json scores;
    const char* names[] = {"L", "L-MDS", "M", "M-MDS"};
    for(int t = 0; t < 4; ++t)
      if(std::isfinite(n.scores[std::size_t(t)]))
        scores[names[t]] = n.scores[std::size_t(t)];
    j["scores"] = scores;
  }
  if(!n.is_leaf())
  {
    j["cut"] = n.cut_order;
    if(cuts)
      j["salience"] = n.cut_salience;
    else
      j["boundary_strength"] = n.boundary_strength;
    j["children"] = {hierarchy_json(h, n.children[0], cuts), hierarchy_json(h, n.children[1], cuts)};
  }
  return j;
}

// The "hierarchy" entry of the JSON report: the number of cuts of the
// method's answer, the number of leaves, and the trees from their roots.
nlohmann::ordered_json hierarchy_report(const SpectralSeg::Part_hierarchy& h, bool cuts)
{
  nlohmann::ordered_json j;
  j["kind"] = cuts ? "cuts" : "merges";
  j["chosen_cuts"] = h.chosen_cuts;
  j["leaves"] = h.number_of_leaves();
  nlohmann::ordered_json roots = nlohmann::json::array();
  for(std::size_t root : h.roots)
    roots.push_back(hierarchy_json(h, root, cuts));
  j["roots"] = roots;
  return j;
}

// A warning when --parts asks for more parts than the hierarchy has leaves.
void warn_missing_parts(std::size_t parts, const SpectralSeg::Part_hierarchy& h, const Progress_printer& out)
{
  if(parts > 0 && !h.nodes.empty() && parts > h.number_of_leaves())
    out.message("warning: --parts " + std::to_string(parts) + ", but the hierarchy has " +
                std::to_string(h.number_of_leaves()) + " leaves: " + std::to_string(h.number_of_leaves()) + " parts");
}

} // namespace

SpectralSeg::Metrics::Any_weight make_metric(const Metric_options& o)
{
  using namespace SpectralSeg::Metrics;
  if(o.name == "geodesic")
    return Geodesic_weight();
  if(o.name == "angular")
    return Angular_weight();
#ifdef SPECTRALSEG_HAS_EMBREE
  if(o.ray_caster == "embree")
    return make_vsi_metric<SpectralSeg::Ray_casting::Embree_ray_caster>(o);
#endif
  return make_vsi_metric<SpectralSeg::Ray_casting::AABB_ray_caster>(o);
}

// Runs the salient-cut method on a loaded mesh; fills labels, adds its
// report entries and stage timings.
std::vector<int> run_salient_cuts(const Salient_cut_options& o, const SpectralSeg::Dual_graph& graph,
                                  const SpectralSeg::Execution& exec, nlohmann::ordered_json& report,
                                  std::vector<std::pair<std::string, double>>& timings, const Progress_printer& out)
{
  typedef SpectralSeg::Automatic_segmentation_options<> Options_type;
  const bool thesis = o.method == "salient-cuts-thesis";
  Options_type options = thesis ? Options_type::thesis() : Options_type();
  options.segmentability.threshold = o.eta;
  options.segmentability.structure_only = o.structure_only;
  if(!thesis || o.min_part_area_given)
    options.min_part_area_fraction = o.min_part_area;
  if(!thesis || o.max_parts_given)
    options.max_parts = o.max_parts;
  SpectralSeg::Automatic_segmentation_result r =
    SpectralSeg::segment_automatically(graph, SpectralSeg::sequence_weights(graph, exec), options, exec);
  for(const auto& t : r.timings)
    timings.push_back(t);
  std::vector<int> labels = r.labels;
  if(o.parts > 0)
    labels = r.hierarchy.labels_with_parts(o.parts);
  warn_missing_parts(o.parts, r.hierarchy, out);
  if(o.depth != std::numeric_limits<std::size_t>::max())
  {
    const std::vector<int> at_depth = r.hierarchy.labels_at_depth(o.depth);
    if(o.parts == 0 || std::set<int>(at_depth.begin(), at_depth.end()).size() <
                         std::set<int>(labels.begin(), labels.end()).size())
      labels = at_depth;
  }
  report["auto_method"] = o.method;
  report["eta"] = o.eta;
  report["structure_only"] = o.structure_only;
  report["min_part_area"] = options.min_part_area_fraction;
  report["parts_found"] = r.number_of_segments;
  report["hierarchy"] = hierarchy_report(r.hierarchy, true);
  return labels;
}


std::vector<int> run_k_way_methods(const Segment_options& o, std::size_t k, const SpectralSeg::Dual_graph& graph,
                                   const SpectralSeg::Execution& exec, nlohmann::ordered_json& report,
                                   std::vector<std::pair<std::string, double>>& timings, std::string& metric_name,
                                   const Progress_printer& out)
{
  const std::size_t n = graph.number_of_faces();
  std::size_t most_extra = o.extra_clusters;
  for(std::size_t e : o.alternative_extra_clusters)
    most_extra = std::max(most_extra, e);
  check_segmentation_fits(n,
                          k == 0 ? std::min(o.max_k, n - 1)
                                 : std::min(std::max(k + most_extra, o.contrast_merge_clusters), n - 1),
                          o.sampling,
                          o.samples, SpectralSeg::Embedding::Embedding_options().exact_face_limit);
  const auto started = std::chrono::steady_clock::now();
  const SpectralSeg::Metrics::Any_weight metric = make_metric(o.metric);
  const SpectralSeg::Weighted_dual_graph weighted(graph, SpectralSeg::Metrics::metric_values(metric, graph, exec));
  timings.emplace_back("metric", std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  metric_name = metric.name();

  SpectralSeg::K_way_options options;
  options.embedding.method = o.sampling == "exact" ? SpectralSeg::Embedding::Method::exact
                             : o.sampling == "auto" ? SpectralSeg::Embedding::Method::automatic
                                                    : SpectralSeg::Embedding::Method::nystrom;
  if(o.sampling == "gamma")
    options.embedding.sampling = SpectralSeg::Embedding::Sampling_method::gamma;
  options.embedding.samples = o.samples;
  options.embedding.seed = o.seed;
  options.extra_clusters = o.extra_clusters;
  options.alternative_extra_clusters = o.alternative_extra_clusters;
  options.contrast_merge_clusters = o.contrast_merge_clusters;
  options.min_candidate_clusters = o.min_candidate_clusters;
  options.boundary_enhancement = !o.no_graph_cut;
  if(o.graph_cut == "thesis")
    options.graph_cut = SpectralSeg::Refinement::Graph_cut_options();
  options.crease_angle = o.crease_angle;
  options.merge_size_exponent = o.merge_size_exponent;
  options.flat_seam_angle = o.flat_seam_angle;
  options.merge_separation_scale = o.merge_separation;
  options.keep_embedding_coordinates = false; // the tool reports the samples and width only: less memory
  if(o.graph_cut_backend == "maxflow")
    options.graph_cut.backend = SpectralSeg::Refinement::Graph_cut_backend::maxflow;
  else if(o.graph_cut_backend == "boost-csr")
    options.graph_cut.backend = SpectralSeg::Refinement::Graph_cut_backend::boost_compressed_sparse_row;
  else if(o.graph_cut_backend == "boost-list")
    options.graph_cut.backend = SpectralSeg::Refinement::Graph_cut_backend::boost_adjacency_list;
  auto run = [&](const auto& kernel) {
    SpectralSeg::Basic_K_way_automatic_options<std::decay_t<decltype(kernel)>> automatic;
    automatic.k_way = options.with_kernel(kernel);
    automatic.max_k = std::max<std::size_t>(2, std::min(o.max_k, n - 1));
    if(o.min_boundary_contrast > 0.)
      automatic.min_boundary_contrast = o.min_boundary_contrast;
    automatic.parts = o.salient.parts;
    if(k == 0 && o.salient.method == "contrast-merge")
    {
      SpectralSeg::Basic_hybrid_options<std::decay_t<decltype(kernel)>> hybrid;
      hybrid.k_way = automatic.k_way;
      hybrid.clusters = automatic.max_k;
      if(o.min_boundary_contrast > 0.)
        hybrid.min_boundary_contrast = o.min_boundary_contrast;
      hybrid.neck_scale = o.neck_scale;
      hybrid.over_segmentations = o.over_segmentations;
      hybrid.parts = o.salient.parts;
      return SpectralSeg::segment_hybrid(weighted, hybrid, exec);
    }
    return k == 0 ? SpectralSeg::segment_k_way_automatic(weighted, automatic, exec)
                  : SpectralSeg::segment_k_way(weighted, k, automatic.k_way, exec);
  };
  // one instantiation of the methods for both kernels
  const SpectralSeg::K_way_result r =
    run(o.kernel == "gaussian" ? SpectralSeg::Kernels::Any_kernel(SpectralSeg::Kernels::Gaussian_kernel())
                               : SpectralSeg::Kernels::Any_kernel(SpectralSeg::Kernels::Exponential_kernel()));
  for(const auto& t : r.timings)
    timings.push_back(t);
  if(k > 0 && r.number_of_segments != k)
  {
    const std::size_t parts = graph.number_of_components();
    out.message("warning: " + std::to_string(r.number_of_segments) + " segments instead of " + std::to_string(k) +
                (parts > k ? ": the mesh is " + std::to_string(parts) +
                               " separate parts that do not touch (each larger than 1% of the area), and a segment "
                               "never spans two of them"
                           : ""));
  }

  if(k == 0)
  {
    report["auto_method"] = o.salient.method;
    report["hierarchy"] = hierarchy_report(r.hierarchy, false);
  }
  warn_missing_parts(o.salient.parts, r.hierarchy, out);
  report["kernel"] = o.kernel;
  report["embedding"] = r.embedding.exact ? "exact" : "nystrom";
  report["samples"] = r.embedding.samples;
  report["kernel_width"] = r.embedding.kernel_width;
  report["graph_cut"] = !o.no_graph_cut;
  if(k > 0)
  { // the kept over-segmentation's
    report["extra_clusters"] = r.extra_clusters;
    report["merge"] = r.contrast_merge ? "contrast" : "concave";
  }
  if(k > 0 && (!o.alternative_extra_clusters.empty() || o.contrast_merge_clusters > 0))
    report["concave_normalized_cut"] = r.normalized_cut;
  if(k > 0 && !r.candidates.empty())
  { // every over-segmentation tried, in order, with the cuts the choice saw
    nlohmann::ordered_json candidates = nlohmann::ordered_json::array();
    for(const SpectralSeg::K_way_candidate& c : r.candidates)
      candidates.push_back({{"extra_clusters", c.extra_clusters},
                            {"merge", c.contrast_merge ? "contrast" : "concave"},
                            {"segments", c.number_of_segments},
                            {"concave_normalized_cut_before_graph_cut", c.normalized_cut_before_graph_cut},
                            {"concave_normalized_cut", c.normalized_cut},
                            {"kept", c.kept}});
    report["candidates"] = candidates;
  }
  if(r.embedding.exact && o.sampling == "auto")
    for(const char* option : {"--samples", "--seed"})
      if(given(o.cli, option))
        out.message(std::string("warning: ") + option + " was ignored: --sampling auto chose the exact embedding (" +
                    std::to_string(n) + " faces, at most " +
                    std::to_string(SpectralSeg::Embedding::Embedding_options().exact_face_limit) +
                    "), which takes no samples");
  return r.labels;
}

} // namespace spectralseg_cli
