// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality benchmark on a directory laid out like the Princeton Segmentation
// Benchmark (off/<id>.off, seg/<id>/<id>_<j>.seg, index.tsv): segments each
// model with SpectralSeg's k-way method (k = k_by_model) and, optionally,
// CGAL's SDF segmentation (its defaults), and scores each result against all
// human segmentations of the model (Rand index error, averaged over the
// humans, then over the models).
//
// usage: bench_psb_quality PSB_DIR [options]
//   --methods kway,contrast,auto,salient,sdf methods to run (default kway): k-way with the humans' k,
//                           the default automatic method (segment_hybrid: over-segment, merge by concave and
//                           metric contrast), k-way choosing k by concavity (segment_k_way_automatic), the thesis's recursive salient
//                           cuts (segment_automatically, ch. 6), CGAL's SDF segmentation (the peer); cpc, seg_mat
//                           and cgal_sdf score the peers' labels in PSB_DIR/peers/METHOD/ID.seg
//   --eta E  --min-part-area F  --structure-only   parameters of the salient-cut method
//   --salient-thesis        the salient-cut method as published (Automatic_segmentation_options::thesis())
//                           instead of the improved default
//   --salient-set K=V,...   single settings of the salient-cut method, over the variant's: size=S (size
//                           saturation), base=covariance|perimeter|loop|curve (protrusion base), floor=0|1 (M's
//                           concave weights at least epsilon), whiten=none|m|both, agree=0|1 (L and M must both pass),
//                           min-salience=X, roots=0|1 (min-salience applies to a component's first cut)
//                           unsegmentable-roots=0|1 (a component that fails the test is still cut when min-salience
//                           allows), pairs=N (sample-face pairs tried per piece),
//                           sequence=distance|harmonic, sequence-scale=S (the harmonic sequence's angle scale),
//                           chain=R (chain eigenvalue ratio), continuation=X (L threshold below a passed piece),
//                           contrast=C (a cut's boundary at least C times as concave as its piece; 0: off),
//                           holes=0|1 (the projection's holes count on pieces with a handle),
//                           loop-disc=R (below the roots, no test of a piece with less area than R times the
//                           flat disc its longest cut loop bounds; 0: off)
//   --markdown FILE.md      also write the tables to this file
//   --png-dir DIR           pictures of the 2 best and 2 worst models of each method, beside a human one
//   --labels-dir DIR        each result's labels, METHOD_ID.seg, one per face of the .off file
//   --candidates-out F.tsv  method kway: every over-segmentation candidate of each model (K_way_result::candidates)
//                           with its concave normalized cut before and after its graph cut, whether it was kept,
//                           and its own Rand-index error: the choice between them can be replayed offline
//                           (with --labels-dir also each candidate's labels, candidateI_ID.seg)
//   --shard i/N             run only the models whose row number is i mod N
//   --out FILE.tsv          per-model rows (default: stdout only)
//   --alpha A --beta B --gamma C   part-aware coefficients
//   --no-graph-cut  --sampling exact|nystrom|auto  --kernel exponential|gaussian
//   --ray-caster aabb|embree  --threads N  --normalization p99|max
//   --samples-factor F (Nyström samples F*k+1)  --vsi-fraction F
//   --reference-fraction F  faces that cast their cone for their reference point (default 1)
//   --reference-rays N  rays of each face's cone for its reference point (default: the library's, 16)
//   --reference-smoothing N  smoothing iterations of the reference points (default: the library's, 3)
//   --reference-cone DEG  full opening angle of that cone (default: the library's, 80)
//   --over-segmentations N  method contrast: over-segmentations that vote (default: the library's, 5)
//   --auto-k MAX   choose k itself (segment_k_way_automatic, k in [2, MAX]) instead of k_by_model
//   --auto-contrast C  its merge limit (boundary's mean concave angle over the mesh's, default 3)
//   --auto-spectrum T  with --auto-k: k from choose_number_of_segments(threshold T) instead
//   --extra-clusters N  K-means clusters beyond k, merged back (default 3; 0 = thesis)
//   --alternative-extra-clusters A,B  also tried, the lowest concave normalized cut kept (default: the library's; none: only --extra-clusters)
//   --contrast-merge-clusters N  the k-way's contrast-merge candidate's clusters (default 20; 0: none)
//   --contrast-merge-extra E  the contrast-merge candidate's clusters at least k + E (default: no such floor)
//   --min-candidate-clusters N  k-way's candidates of fewer clusters are not tried (default 6; 0: all)
//   --cut-angle-scale S  concavity scale (radians) of that normalized cut (default 0.1)
//   --seed S       start face of the Nyström sampling
//   --thesis       the thesis's k-way method (K_way_options::thesis(): no extra clusters, its graph cut,
//                  no crease split); the options below change single settings
//   --mu M         graph-cut smoothness (default 10; thesis 0.3)   --mean-edge | --longest-edge (thesis)
//   --band B       graph-cut band width (default 0.4; 0: every face may move, the thesis)
//   --crease-angle A  split clusters along closed concave creases of A degrees (default 30; 0: off), k-way and contrast
//   --merge-size-exponent E  the merge's area factor exponent (default 0.1; 0: the strength alone)
//   --flat-seam-angle A  boundaries of a mean concave angle below A degrees merged first, largest pair first
//                   (default 0.5; 0: off), k-way and the automatic merges
//   --merge-separation S     the scale of the merge's embedding-separation factor (default 2; 0: off)
//   --merge-min-area-fraction F  segments under this fraction of the area are merged first (default 0.005)
//   --neck-scale S  the contrast merge's neck-ratio scale (default 0.4; 0: no neck factor)
//   --reference-faces N  the contrast merge's reference resolution (Hybrid_options::reference_faces;
//                   default 50000; 0: the mesh's own); --k auto only, not k-way's contrast candidate
//   --max-min-seeds
// Merge shards with: bench_psb_quality --merge a.tsv b.tsv ...
#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/automatic_segmentation.h>
#include <SpectralSeg/segment_hybrid.h>
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/Kernels/Exponential_kernel.h>
#include <SpectralSeg/Kernels/Gaussian_kernel.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Rendering/render_mesh_geometry.h>
#include <SpectralSeg/evaluation.h>
#include <SpectralSeg/k_way_segmentation.h>
#ifdef SPECTRALSEG_HAS_EMBREE
#include <SpectralSeg/Ray_casting/Embree_ray_caster.h>
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace fs = std::filesystem;

namespace {

struct Row
{
  std::string id, category, method;
  std::size_t faces = 0, k = 0, segments = 0;
  double ri_error = 0, seconds = 0;
  std::vector<int> labels; // kept only for --png-dir
};

struct Options
{
  std::string dir, out, candidates_out;
  std::vector<std::string> methods{"kway"};
  std::size_t shard = 0, shards = 1;
  double alpha = 0.01, beta = 0.195, gamma = 0.795;
  bool graph_cut = true;
  std::string sampling = "auto", kernel = "exponential", ray_caster =
#ifdef SPECTRALSEG_HAS_EMBREE
    "embree";
#else
    "aabb";
#endif
  unsigned threads = 0;
  std::string normalization = "p99"; // p99 (the library's default) or max (the thesis)
  std::size_t samples = 0;
  int extra_clusters = -1;
  int contrast_merge_clusters = -1; // < 0: the default
  int contrast_merge_extra = -1;    // >= 0: the contrast candidate's clusters at least k plus this many
  int min_candidate_clusters = -1;  // < 0: the default
  std::string alternative_extra_clusters = "-"; // "-": the default; "": none
  double cut_angle_scale = -1;
  double auto_contrast = 3;
  bool auto_contrast_given = false;  // automatic k: merge while the weakest boundary's contrast is below this
  double auto_spectrum = 0;  // > 0: --auto-k uses choose_number_of_segments with this threshold instead
  unsigned seed = 0;         // start face of the Nyström sampling
  std::string markdown;      // also write the tables to this file
  std::string png_dir;       // pictures of the best and worst models of each method
  std::string labels_dir;    // each result's labels, METHOD_ID.seg in the .off's face order
  double samples_factor = 0; // experiment: Nyström samples = factor * k + 1
  double vsi_fraction = 0.01;
  double reference_fraction = 1.; // VSI::Reference_point_options::measured_fraction
  std::size_t reference_rays = 0;  // > 0: VSI::Reference_point_options::rays
  double reference_cone = 0.;      // > 0: VSI::Reference_point_options::cone_angle_degrees
  long reference_smoothing = -1;   // >= 0: VSI::Reference_point_options::smoothing_iterations
  std::size_t over_segmentations = 0; // > 0: Hybrid_options::over_segmentations (method contrast)
  double eta = 0.1, min_part_area = -1.; // < 0: the variant's
  bool structure_only = false, perimeter_base = false, salient_thesis = false;
  std::vector<std::string> salient_set;
  std::size_t auto_k = 0; // > 0: method kway chooses k itself, at most this many (method auto: default 20)
  bool thesis = false;     // K_way_options::thesis(): no extra clusters, the thesis's graph cut, no crease split
  double mu = -1;          // graph-cut smoothness (< 0: the default)
  int mean_edge = -1;      // graph cut: edge lengths over the mean (1) or the longest (0) edge length (< 0: default)
  double band = -1;        // graph-cut band width (< 0: the default)
  double crease_angle = -1; // crease split angle in degrees (< 0: the default)
  double merge_size_exponent = -1; // < 0: the default
  double flat_seam_angle = -1;      // < 0: the default
  double merge_separation = -1;    // < 0: the default
  double merge_min_area_fraction = -1; // < 0: the default
  double neck_scale = -1;          // contrast merge: < 0: the default
  long reference_faces = -1;       // contrast merge: < 0: the default
  bool max_min_seeds = false; // K-means seeded by max-min in the embedding instead of the samples
};


std::vector<std::string> split(const std::string& s, char sep)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while(std::getline(ss, item, sep))
    out.push_back(item);
  return out;
}

void print_tables(const std::vector<Row>& rows, std::FILE* to = stdout)
{
  std::map<std::string, std::map<std::string, std::pair<double, int>>> by_cat; // method -> category -> (sum, n)
  std::map<std::string, std::pair<double, int>> overall;
  std::map<std::string, double> time;
  for(const Row& r : rows)
  {
    auto& c = by_cat[r.method][r.category];
    c.first += r.ri_error;
    ++c.second;
    overall[r.method].first += r.ri_error;
    ++overall[r.method].second;
    time[r.method] += r.seconds;
  }
  std::vector<std::string> methods;
  for(const auto& m : overall)
    methods.push_back(m.first);
  std::fprintf(to, "\n| category |");
  for(const auto& m : methods)
    std::fprintf(to, " %s |", m.c_str());
  std::fprintf(to, "\n|---|");
  for(std::size_t i = 0; i < methods.size(); ++i)
    std::fprintf(to, "---:|");
  std::fprintf(to, "\n");
  for(const auto& cat : by_cat.begin()->second)
  {
    std::fprintf(to, "| %s |", cat.first.c_str());
    for(const auto& m : methods)
    {
      const auto& c = by_cat[m][cat.first];
      std::fprintf(to, " %.3f |", c.second ? c.first / c.second : 0.);
    }
    std::fprintf(to, "\n");
  }
  std::fprintf(to, "| **all (%d models)** |", overall.begin()->second.second);
  for(const auto& m : methods)
    std::fprintf(to, " **%.3f** |", overall[m].first / overall[m].second);
  // psb-dev's two parts: the 38 models of the first subset (ids ending in
  // 1) and the 57 added later, which no setting was tuned on before them
  for(const bool first : {true, false})
  {
    std::map<std::string, std::pair<double, int>> part;
    for(const Row& r : rows)
      if(!r.id.empty() && (r.id.back() == '1') == first)
      {
        part[r.method].first += r.ri_error;
        ++part[r.method].second;
      }
    if(part.empty() || part.begin()->second.second == overall.begin()->second.second)
      continue;
    std::fprintf(to, "\n| %s (%d models) |", first ? "ids ending in 1" : "the other ids", part.begin()->second.second);
    for(const auto& m : methods)
      std::fprintf(to, " %.3f |", part[m].second ? part[m].first / part[m].second : 0.);
  }
  std::map<std::string, double> segments;
  for(const Row& r : rows)
    segments[r.method] += double(r.segments);
  std::fprintf(to, "\n| segments per model |");
  for(const auto& m : methods)
    std::fprintf(to, " %.1f |", segments[m] / overall[m].second);
  std::fprintf(to, "\n| total time (s) |");
  for(const auto& m : methods)
    std::fprintf(to, " %.1f |", time[m]);
  std::fprintf(to, "\n");
}

std::vector<Row> read_rows(const std::string& path)
{
  std::vector<Row> rows;
  std::ifstream in(path);
  std::string line;
  while(std::getline(in, line))
  {
    const auto f = split(line, '\t');
    if(f.size() < 8 || f[0] == "id")
      continue;
    Row r;
    r.id = f[0];
    r.category = f[1];
    r.method = f[2];
    r.faces = std::stoul(f[3]);
    r.k = std::stoul(f[4]);
    r.segments = std::stoul(f[5]);
    r.ri_error = std::stod(f[6]);
    r.seconds = std::stod(f[7]);
    rows.push_back(r);
  }
  return rows;
}

template <typename RayCaster>
SpectralSeg::Metrics::Metric_values part_aware(const Options& o, const SpectralSeg::Dual_graph& g, const SpectralSeg::Execution& exec)
{
  SpectralSeg::Metrics::VSI_options vo;
  vo.images.sample_fraction = o.vsi_fraction;
  vo.reference.measured_fraction = o.reference_fraction;
  if(o.reference_rays > 0)
    vo.reference.rays = o.reference_rays;
  if(o.reference_cone > 0.)
    vo.reference.cone_angle_degrees = o.reference_cone;
  if(o.reference_smoothing >= 0)
    vo.reference.smoothing_iterations = std::size_t(o.reference_smoothing);
  const auto n = o.normalization == "max" ? SpectralSeg::Metrics::Normalization::maximum()
                                          : SpectralSeg::Metrics::Normalization::quantile(0.99);
  return SpectralSeg::Metrics::metric_values(
    SpectralSeg::Metrics::Part_aware_weight<RayCaster>(o.alpha, o.beta, o.gamma, vo, 0.001, n), g, exec);
}

// the part-aware weights (and the faces' thickness) with the ray caster of the options
SpectralSeg::Metrics::Metric_values part_aware_weights(const Options& o, const SpectralSeg::Dual_graph& g,
                                       const SpectralSeg::Execution& exec)
{
#ifdef SPECTRALSEG_HAS_EMBREE
  if(o.ray_caster == "embree")
    return part_aware<SpectralSeg::Ray_casting::Embree_ray_caster>(o, g, exec);
#endif
  return part_aware<SpectralSeg::Ray_casting::AABB_ray_caster>(o, g, exec);
}

// With `candidates`, the k-way candidates are kept there with their labels.
std::vector<int> run_kway(const Options& o, const SpectralSeg::Dual_graph& g, std::size_t k,
                          std::vector<SpectralSeg::K_way_candidate>* candidates = nullptr)
{
  const SpectralSeg::Execution exec(o.threads);
  const SpectralSeg::Weighted_dual_graph wg(g, part_aware_weights(o, g, exec));
  SpectralSeg::K_way_options ko = o.thesis ? SpectralSeg::K_way_options::thesis() : SpectralSeg::K_way_options();
  ko.boundary_enhancement = o.graph_cut;
  if(o.mu >= 0.)
    ko.graph_cut.smoothness = o.mu;
  if(o.mean_edge >= 0)
    ko.graph_cut.normalize_by_mean_edge = o.mean_edge == 1;
  if(o.band >= 0.)
    ko.graph_cut.band_width = o.band;
  if(o.crease_angle >= 0.)
    ko.crease_angle = o.crease_angle;
  if(o.merge_size_exponent >= 0.)
    ko.merge_size_exponent = o.merge_size_exponent;
  if(o.flat_seam_angle >= 0.)
    ko.flat_seam_angle = o.flat_seam_angle;
  if(o.merge_separation >= 0.)
    ko.merge_separation_scale = o.merge_separation;
  if(o.merge_min_area_fraction >= 0.)
    ko.merge_min_area_fraction = o.merge_min_area_fraction;
  ko.seed_with_samples = !o.max_min_seeds;
  ko.embedding.seed = o.seed;
  if(o.extra_clusters >= 0)
    ko.extra_clusters = std::size_t(o.extra_clusters);
  if(o.alternative_extra_clusters != "-")
  {
    ko.alternative_extra_clusters.clear();
    std::stringstream list(o.alternative_extra_clusters);
    for(std::string item; std::getline(list, item, ',');)
      if(!item.empty())
        ko.alternative_extra_clusters.push_back(std::size_t(std::stoul(item)));
  }
  if(o.contrast_merge_clusters >= 0)
    ko.contrast_merge_clusters = std::size_t(o.contrast_merge_clusters);
  if(o.contrast_merge_extra >= 0 && ko.contrast_merge_clusters > 0)
    ko.contrast_merge_clusters = std::max(ko.contrast_merge_clusters, k + std::size_t(o.contrast_merge_extra));
  if(o.min_candidate_clusters >= 0)
    ko.min_candidate_clusters = std::size_t(o.min_candidate_clusters);
  if(o.cut_angle_scale > 0)
    ko.cut_angle_scale = o.cut_angle_scale;
  ko.embedding.samples = o.samples_factor > 0 ? static_cast<std::size_t>(o.samples_factor * double(k)) + 1 : o.samples;
  ko.embedding.method = o.sampling == "exact"   ? SpectralSeg::Embedding::Method::exact
                        : o.sampling == "nystrom" ? SpectralSeg::Embedding::Method::nystrom
                                                  : SpectralSeg::Embedding::Method::automatic;
  if(o.auto_k > 0 && o.auto_spectrum > 0)
  { // k from the spectrum (choose_number_of_segments), then plain k-way
    const auto e = SpectralSeg::internal::embed(wg, std::min<std::size_t>(o.auto_k, g.number_of_faces() - 1),
                                                SpectralSeg::Kernels::Exponential_kernel(), ko.embedding, exec);
    const std::size_t chosen = SpectralSeg::choose_number_of_segments(e, o.auto_k, o.auto_spectrum);
    return SpectralSeg::segment_k_way(wg, chosen, ko, exec).labels;
  }
  if(o.auto_k > 0)
  {
    SpectralSeg::K_way_automatic_options automatic;
    automatic.k_way = ko;
    automatic.max_k = o.auto_k;
    automatic.min_boundary_contrast = o.auto_contrast;
    return SpectralSeg::segment_k_way_automatic(wg, automatic, exec).labels;
  }
  ko.keep_candidate_labels = candidates != nullptr;
  auto r = o.kernel == "gaussian" ? SpectralSeg::segment_k_way(wg, k, ko.with_kernel(SpectralSeg::Kernels::Gaussian_kernel()), exec)
                                  : SpectralSeg::segment_k_way(wg, k, ko, exec);
  if(candidates)
    *candidates = std::move(r.candidates);
  return r.labels;
}

// the default automatic method: over-segment and merge by concave and metric contrast
std::vector<int> run_contrast(const Options& o, const SpectralSeg::Dual_graph& g)
{
  const SpectralSeg::Execution exec(o.threads);
  const SpectralSeg::Weighted_dual_graph wg(g, part_aware_weights(o, g, exec));
  SpectralSeg::Hybrid_options ho;
  ho.k_way.boundary_enhancement = o.graph_cut;
  ho.k_way.embedding.seed = o.seed;
  if(o.merge_separation >= 0.)
    ho.k_way.merge_separation_scale = o.merge_separation;
  if(o.auto_contrast > 0 && o.auto_contrast_given)
    ho.min_boundary_contrast = o.auto_contrast;
  if(o.neck_scale >= 0.)
    ho.neck_scale = o.neck_scale;
  if(o.reference_faces >= 0)
    ho.reference_faces = std::size_t(o.reference_faces);
  if(o.crease_angle >= 0.)
    ho.k_way.crease_angle = o.crease_angle;
  if(o.flat_seam_angle >= 0.)
    ho.k_way.flat_seam_angle = o.flat_seam_angle;
  if(o.over_segmentations > 0)
    ho.over_segmentations = o.over_segmentations;
  return SpectralSeg::segment_hybrid(wg, ho, exec).labels;
}

// a peer's labels (one per face of the .off file) in the mesh's face order
std::vector<int> read_in_mesh_order(const std::string& file, const std::vector<std::size_t>& input_face_of_face)
{
  const std::vector<int> file_order = SpectralSeg::Evaluation::read_labels(file);
  std::vector<int> mesh_order(input_face_of_face.size());
  for(std::size_t face = 0; face < mesh_order.size(); ++face)
    mesh_order[face] = file_order.at(input_face_of_face[face]);
  return mesh_order;
}

std::vector<int> run_salient(const Options& o, const SpectralSeg::Dual_graph& g)
{
  const SpectralSeg::Execution exec(o.threads);
  typedef SpectralSeg::Automatic_segmentation_options<> Options_type;
  Options_type so = o.salient_thesis ? Options_type::thesis() : Options_type();
  so.segmentability.threshold = o.eta;
  so.segmentability.structure_only = o.structure_only;
  if(o.min_part_area >= 0.)
    so.min_part_area_fraction = o.min_part_area;
  using SpectralSeg::Salience::Protrusion_term;
  if(o.perimeter_base)
    std::get<2>(so.salience.terms()) = Protrusion_term(Protrusion_term::Base::perimeter);
  for(const std::string& kv : o.salient_set)
  {
    const std::size_t eq = kv.find('=');
    if(eq == std::string::npos)
      throw std::runtime_error("--salient-set: expected KEY=VALUE, got '" + kv + "'");
    const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
    if(key == "size")
      std::get<0>(so.salience.terms()) = SpectralSeg::Salience::Size_term(std::stod(value));
    else if(key == "base")
      std::get<2>(so.salience.terms()) =
        Protrusion_term(value == "curve" ? Protrusion_term::Base::curve_covariance
                        : value == "loop" ? Protrusion_term::Base::cut_loop
                        : value == "perimeter" ? Protrusion_term::Base::perimeter
                                               : Protrusion_term::Base::covariance);
    else if(key == "floor")
      so.segmentability.projection.concave_floor = value == "1";
    else if(key == "whiten")
      so.segmentability.projection.whiten =
        value == "both" ? SpectralSeg::Segmentability::Projection_options::Whitening::both
        : value == "m"  ? SpectralSeg::Segmentability::Projection_options::Whitening::geometry
                        : SpectralSeg::Segmentability::Projection_options::Whitening::none;
    else if(key == "agree")
      so.segmentability.require_agreement = value == "1";
    else if(key == "min-salience")
      so.min_cut_salience = std::stod(value);
    else if(key == "pairs")
      so.sample_pairs = std::stoul(value);
    else if(key == "unsegmentable-roots")
      so.cut_unsegmentable_roots = value == "1";
    else if(key == "sequence")
      so.sequence = value == "distance" ? Options_type::Sequence::distance_difference
                                        : Options_type::Sequence::concave_harmonic;
    else if(key == "sequence-scale")
      so.sequence_angle_scale = std::stod(value);
    else if(key == "chain")
      so.segmentability.chain_eigenvalue_ratio = std::stod(value);
    else if(key == "continuation")
      so.continuation_threshold = std::stod(value);
    else if(key == "contrast")
      so.min_cut_contrast = std::stod(value);
    else if(key == "roots")
      so.min_cut_salience_at_roots = value == "1";
    else if(key == "loop-disc")
      so.min_area_over_loop_disc = std::stod(value);
    else if(key == "holes")
      so.segmentability.contour.count_holes = value == "1";
    else
      throw std::runtime_error("--salient-set: unknown key '" + key + "'");
  }
  return SpectralSeg::segment_automatically(g, SpectralSeg::sequence_weights(g, exec), so, exec).labels;
}

std::vector<int> run_sdf(Mesh& mesh)
{
  auto sdf = mesh.add_property_map<Mesh::Face_index, double>("f:sdf").first;
  auto seg = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:seg").first;
  CGAL::sdf_values(mesh, sdf);
  CGAL::segmentation_from_sdf_values(mesh, sdf, seg);
  std::vector<int> labels;
  for(auto f : mesh.faces())
    labels.push_back(static_cast<int>(get(seg, f)));
  mesh.remove_property_map(sdf);
  mesh.remove_property_map(seg);
  return labels;
}

// Pictures of the two best and two worst models of each method, beside the
// first human segmentation of the same model.
void render_best_and_worst(const Options& o, std::vector<Row> rows)
{
  fs::create_directories(o.png_dir);
  std::map<std::string, std::vector<const Row*>> by_method;
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.ri_error < b.ri_error; });
  for(const Row& r : rows)
    by_method[r.method].push_back(&r);
  for(const auto& m : by_method)
  {
    const auto& list = m.second;
    std::vector<std::pair<std::string, const Row*>> picks;
    for(std::size_t i = 0; i < 2 && i < list.size(); ++i)
      picks.emplace_back("best" + std::to_string(i + 1), list[i]);
    for(std::size_t i = 0; i < 2 && i + 2 < list.size(); ++i)
      picks.emplace_back("worst" + std::to_string(i + 1), list[list.size() - 1 - i]);
    for(const auto& pick : picks)
    {
      const Row& r = *pick.second;
      Mesh mesh;
      const auto report = SpectralSeg::IO::read_mesh_file((fs::path(o.dir) / "off" / (r.id + ".off")).string(), mesh);
      const SpectralSeg::Dual_graph g = SpectralSeg::make_dual_graph(mesh);
      SpectralSeg::Rendering::Render_options ro;
      ro.view_width = ro.view_height = 320;
      const std::string stem = m.first + "_" + pick.first + "_" + r.id;
      SpectralSeg::Rendering::render_face_labels_png((fs::path(o.png_dir) / (stem + ".png")).string(), g.geometry(),
                                                     r.labels, ro);
      const std::vector<int> human_file = SpectralSeg::Evaluation::read_labels(
        (fs::path(o.dir) / "seg" / r.id / (r.id + "_0.seg")).string());
      std::vector<int> human(g.number_of_faces());
      for(std::size_t f = 0; f < human.size(); ++f)
        human[f] = human_file.at(report.input_face_of_face[f]);
      SpectralSeg::Rendering::render_face_labels_png((fs::path(o.png_dir) / (stem + "_human.png")).string(),
                                                     g.geometry(), human, ro);
      std::printf("png: %s (%s, %s, RI error %.3f)\n", stem.c_str(), r.category.c_str(), m.first.c_str(), r.ri_error);
    }
  }
}

// the option being read, for the error message of a bad value
std::string parsed_option;

int run(int argc, char** argv)
{
  std::vector<std::string> args(argv + 1, argv + argc);
  if(!args.empty() && args[0] == "--merge")
  {
    std::vector<Row> all;
    for(std::size_t i = 1; i < args.size(); ++i)
    {
      const auto r = read_rows(args[i]);
      all.insert(all.end(), r.begin(), r.end());
    }
    print_tables(all);
    return 0;
  }
  // --markdown applies to a normal run; a merge prints to stdout
  if(args.empty())
  {
    std::fprintf(stderr, "usage: %s PSB_DIR [--methods kway,sdf] [--shard i/N] [--out F.tsv] ...\n", argv[0]);
    return 1;
  }
  Options o;
  o.dir = args[0];
  for(std::size_t i = 1; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    parsed_option = a;
    auto next = [&]() -> std::string {
      if(i + 1 >= args.size())
        throw std::runtime_error("missing value after " + a);
      return args[++i];
    };
    if(a == "--eta")
      o.eta = std::stod(next());
    else if(a == "--min-part-area")
      o.min_part_area = std::stod(next());
    else if(a == "--structure-only")
      o.structure_only = true;
    else if(a == "--perimeter-base")
      o.perimeter_base = true;
    else if(a == "--salient-thesis")
      o.salient_thesis = true;
    else if(a == "--salient-set")
      o.salient_set = split(next(), ',');
    else if(a == "--methods")
      o.methods = split(next(), ',');
    else if(a == "--shard")
    {
      const auto p = split(next(), '/');
      o.shard = std::stoul(p.at(0));
      o.shards = std::stoul(p.at(1));
    }
    else if(a == "--out")
      o.out = next();
    else if(a == "--alpha")
      o.alpha = std::stod(next());
    else if(a == "--beta")
      o.beta = std::stod(next());
    else if(a == "--gamma")
      o.gamma = std::stod(next());
    else if(a == "--no-graph-cut")
      o.graph_cut = false;
    else if(a == "--sampling")
      o.sampling = next();
    else if(a == "--kernel")
      o.kernel = next();
    else if(a == "--ray-caster")
      o.ray_caster = next();
    else if(a == "--normalization")
      o.normalization = next();
    else if(a == "--max-min-seeds")
      o.max_min_seeds = true;
    else if(a == "--mean-edge")
      o.mean_edge = 1;
    else if(a == "--longest-edge")
      o.mean_edge = 0;
    else if(a == "--band")
      o.band = std::stod(next());
    else if(a == "--crease-angle")
      o.crease_angle = std::stod(next());
    else if(a == "--flat-seam-angle")
      o.flat_seam_angle = std::stod(next());
    else if(a == "--merge-size-exponent")
      o.merge_size_exponent = std::stod(next());
    else if(a == "--merge-separation")
      o.merge_separation = std::stod(next());
    else if(a == "--neck-scale")
      o.neck_scale = std::stod(next());
    else if(a == "--reference-faces")
      o.reference_faces = std::stol(next());
    else if(a == "--merge-min-area-fraction")
      o.merge_min_area_fraction = std::stod(next());
    else if(a == "--thesis")
      o.thesis = true;
    else if(a == "--mu")
      o.mu = std::stod(next());
    else if(a == "--auto-k")
      o.auto_k = std::stoul(next());
    else if(a == "--auto-contrast")
    {
      o.auto_contrast = std::stod(next());
      o.auto_contrast_given = true;
    }
    else if(a == "--auto-spectrum")
      o.auto_spectrum = std::stod(next());
    else if(a == "--markdown")
      o.markdown = next();
    else if(a == "--labels-dir")
      o.labels_dir = next();
    else if(a == "--candidates-out")
      o.candidates_out = next();
    else if(a == "--png-dir")
      o.png_dir = next();
    else if(a == "--seed")
      o.seed = unsigned(std::stoul(next()));
    else if(a == "--extra-clusters")
      o.extra_clusters = std::stoi(next());
    else if(a == "--contrast-merge-clusters")
      o.contrast_merge_clusters = std::stoi(next());
    else if(a == "--contrast-merge-extra")
      o.contrast_merge_extra = std::stoi(next());
    else if(a == "--min-candidate-clusters")
      o.min_candidate_clusters = std::stoi(next());
    else if(a == "--alternative-extra-clusters")
    {
      o.alternative_extra_clusters = next();
      if(o.alternative_extra_clusters == "none")
        o.alternative_extra_clusters.clear();
    }
    else if(a == "--cut-angle-scale")
      o.cut_angle_scale = std::stod(next());
    else if(a == "--samples-factor")
      o.samples_factor = std::stod(next());
    else if(a == "--vsi-fraction")
      o.vsi_fraction = std::stod(next());
    else if(a == "--reference-fraction")
      o.reference_fraction = std::stod(next());
    else if(a == "--reference-rays")
      o.reference_rays = std::stoul(next());
    else if(a == "--reference-smoothing")
      o.reference_smoothing = long(std::stoul(next()));
    else if(a == "--reference-cone")
      o.reference_cone = std::stod(next());
    else if(a == "--over-segmentations")
      o.over_segmentations = std::stoul(next());
    else if(a == "--samples")
      o.samples = std::stoul(next());
    else if(a == "--threads")
      o.threads = static_cast<unsigned>(std::stoul(next()));
    else
      throw std::runtime_error("unknown option " + a);
  }
  parsed_option.clear();

  std::ifstream index(fs::path(o.dir) / "index.tsv");
  if(!index)
  {
    std::fprintf(stderr, "no index.tsv in %s\n", o.dir.c_str());
    return 1;
  }
  std::ofstream out;
  if(!o.out.empty())
  {
    out.open(o.out);
    out << "id\tcategory\tmethod\tfaces\tk\tsegments\tri_error\tseconds\n";
  }
  std::ofstream candidates_out;
  if(!o.candidates_out.empty())
  {
    candidates_out.open(o.candidates_out);
    candidates_out << "id\tcategory\tk\tcandidate\textra_clusters\tmerge\tsegments\tcut_before_graph_cut\tcut\tri_error\tkept\n";
  }
  std::vector<Row> rows;
  std::string line;
  std::getline(index, line); // header
  for(std::size_t row = 0; std::getline(index, line); ++row)
  {
    if(row % o.shards != o.shard)
      continue;
    const auto f = split(line, '\t');
    const std::string id = f.at(0), category = f.at(1);
    const std::size_t k = std::stoul(f.at(3));
    Mesh mesh;
    const auto report = SpectralSeg::IO::read_mesh_file((fs::path(o.dir) / "off" / (id + ".off")).string(), mesh);
    const SpectralSeg::Dual_graph g = SpectralSeg::make_dual_graph(mesh);
    std::vector<std::vector<int>> humans;
    for(const auto& e : fs::directory_iterator(fs::path(o.dir) / "seg" / id))
    {
      const std::vector<int> file_order = SpectralSeg::Evaluation::read_labels(e.path().string());
      std::vector<int> mesh_order(g.number_of_faces());
      for(std::size_t face = 0; face < mesh_order.size(); ++face)
        mesh_order[face] = file_order.at(report.input_face_of_face[face]);
      humans.push_back(mesh_order);
    }
    for(const std::string& method : o.methods)
    {
      const auto t0 = std::chrono::steady_clock::now();
      const bool peer = method == "cpc" || method == "seg_mat" || method == "cgal_sdf";
      if(method != "sdf" && method != "kway" && method != "auto" && method != "salient" && method != "contrast" && !peer)
        throw std::runtime_error("unknown method '" + method +
                                 "' (kway, auto, contrast, salient, sdf, or a peer's labels: cpc, seg_mat, cgal_sdf)");
      Options mo = o;
      if(method == "auto" && mo.auto_k == 0)
        mo.auto_k = 20;
      std::vector<SpectralSeg::K_way_candidate> candidates;
      const bool log_candidates = candidates_out.is_open() && method == "kway" && o.auto_k == 0;
      const std::vector<int> labels = peer ? read_in_mesh_order((fs::path(o.dir) / "peers" / method / (id + ".seg")).string(),
                                                                report.input_face_of_face)
                                      : method == "sdf"       ? run_sdf(mesh)
                                      : method == "salient" ? run_salient(mo, g)
                                      : method == "contrast" ? run_contrast(mo, g)
                                                            : run_kway(mo, g, k, log_candidates ? &candidates : nullptr);
      const std::string method_name = method == "kway" && o.auto_k > 0 ? "kway-auto" : method;
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      // Rand-index error against each human, averaged over the humans
      const auto mean_error = [&humans](const std::vector<int>& l) {
        double sum = 0;
        for(const auto& h : humans)
          sum += SpectralSeg::Evaluation::rand_index_error(l, h);
        return sum / double(humans.size());
      };
      const double ri = mean_error(labels);
      Row r{id, category, method_name, g.number_of_faces(), k, 0, ri, seconds, {}};
      r.segments = std::set<int>(labels.begin(), labels.end()).size();
      // labels in the .off file's face order, as NAME.seg in --labels-dir
      const auto write_labels = [&](const std::string& name, const std::vector<int>& mesh_order) {
        fs::create_directories(o.labels_dir);
        std::ofstream seg(fs::path(o.labels_dir) / (name + ".seg"));
        for(std::size_t input = 0; input < report.face_of_input_face.size(); ++input)
          seg << (report.face_of_input_face[input] != report.no_face ? mesh_order.at(report.face_of_input_face[input])
                                                                      : -1)
              << '\n';
      };
      if(!o.labels_dir.empty())
        write_labels(method_name + "_" + id, labels);
      if(!o.png_dir.empty())
        r.labels = labels;
      rows.push_back(r);
      std::printf("%s\t%s\t%s\t%zu\t%zu\t%zu\t%.4f\t%.2f\n", id.c_str(), category.c_str(), method_name.c_str(), r.faces, k,
                  r.segments, ri, seconds);
      std::fflush(stdout);
      if(out)
        out << id << '\t' << category << '\t' << method_name << '\t' << r.faces << '\t' << k << '\t' << r.segments << '\t'
            << ri << '\t' << seconds << '\n';
      for(std::size_t i = 0; i < candidates.size(); ++i)
      {
        const SpectralSeg::K_way_candidate& c = candidates[i];
        candidates_out << id << '\t' << category << '\t' << k << '\t' << i << '\t' << c.extra_clusters << '\t'
                       << (c.contrast_merge ? "contrast" : "concave") << '\t' << c.number_of_segments << '\t'
                       << std::setprecision(17) << c.normalized_cut_before_graph_cut << '\t' << c.normalized_cut
                       << '\t' << std::setprecision(6) << mean_error(c.labels) << '\t' << (c.kept ? 1 : 0) << '\n';
        if(!o.labels_dir.empty())
          write_labels("candidate" + std::to_string(i) + "_" + id, c.labels);
      }
    }
  }
  print_tables(rows);
  if(!o.markdown.empty())
  {
    std::FILE* md = std::fopen(o.markdown.c_str(), "w");
    if(!md)
      throw std::runtime_error("cannot write " + o.markdown);
    std::fprintf(md, "Rand-index error (1 - RI, lower is better), averaged over each model's human segmentations, then "
                     "over the models of each category; k = k_by_model for kway, chosen by the method for auto.\n");
    print_tables(rows, md);
    std::fclose(md);
  }
  if(!o.png_dir.empty())
    render_best_and_worst(o, rows);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return run(argc, argv);
  }
  catch(const std::logic_error& e) // std::stod and the like
  {
    if(parsed_option.empty())
      std::fprintf(stderr, "error: %s\n", e.what());
    else
      std::fprintf(stderr, "error: bad value after %s (%s)\n", parsed_option.c_str(), e.what());
    return 1;
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
