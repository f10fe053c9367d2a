// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg segment MESH --k K ...
#ifndef SPECTRALSEG_TOOLS_COMMAND_SEGMENT_H
#define SPECTRALSEG_TOOLS_COMMAND_SEGMENT_H

#include "Argument_checks.h"
#include "Loaded_mesh.h"
#include "Mesh_outputs.h"
#include "Work_limits.h"
#include "metric_choice.h"
#include "salient_cut_segmentation.h"

#include <SpectralSeg/IO/write_face_values.h>
#include <SpectralSeg/Rendering/render_mesh_geometry.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace spectralseg_cli {

struct Segment_options
{
  Segment_options();
  std::string mesh;
  std::string k;
  std::size_t max_k = 20;
  Metric_options metric;
  std::string kernel = "exponential";
  std::string sampling = "auto";
  std::size_t samples = 0;
  bool no_graph_cut = false;
  std::string graph_cut_backend = "default";
  unsigned threads = 0;
  unsigned seed = 0;
  // the library's defaults, set by the constructor (segmentation_methods.cpp)
  std::size_t extra_clusters = 0;
  std::vector<std::size_t> alternative_extra_clusters;
  std::size_t contrast_merge_clusters = 0;
  std::size_t min_candidate_clusters = 0;
  std::string graph_cut = "banded";
  double crease_angle = 0.;
  double merge_size_exponent = 0.;
  double flat_seam_angle = 0.;
  double merge_separation = 0.;
  double min_boundary_contrast = 0.; // 0: the method's default (contrast-merge 4, concave-merge 3)
  double neck_scale = 0.;
  std::size_t over_segmentations = 1;
  std::string labels, out_mesh, png, json;
  bool binary = false;   // PLY outputs in binary
  std::string parts_dir; // one PLY file per segment
  Salient_cut_options salient;
  const CLI::App* cli = nullptr; // the parsed subcommand, to tell the options given (null: none)
};

// The options of the method, all but the input and the outputs: shared by
// `segment` and `batch`.
inline void add_segment_method_options(CLI::App* cmd, Segment_options& o)
{
  cmd->add_option("--k", o.k,
                  "number of segments: a positive integer, or 'auto' to let --auto-method choose it")
    ->required();
  cmd->add_option("--max-k", o.max_k, "largest k considered by --k auto")->capture_default_str()->check(Count(2, max_clusters));
  cmd->add_option("--min-boundary-contrast", o.min_boundary_contrast,
                  "--k auto, contrast-merge and concave-merge: segments are merged while their boundary's contrast "
                  "to the whole mesh is below this (default 4 for contrast-merge, 3 for concave-merge)")
    ->check(Finite_range(0., 1e6));
  cmd->add_option("--neck-scale", o.neck_scale,
                  "--k auto, contrast-merge: a boundary's metric contrast is multiplied by its neck ratio (the "
                  "square root of the smaller segment's area over the boundary's length) over this, so that limbs "
                  "stay and slices of a body merge (0: off)")
    ->capture_default_str()
    ->check(Finite_range(0., 1e6));
  cmd->add_option("--over-segmentations", o.over_segmentations,
                  "--k auto, contrast-merge: this many over-segmentations (--max-k clusters, then 2, 4, ... fewer) "
                  "are merged and the answer closest to the others' is kept (1: one, as before 2026-11-27)")
    ->capture_default_str()
    ->check(Count(1, 10));
  add_metric_options(*cmd, o.metric);
  cmd->add_option("--kernel", o.kernel, "affinity kernel")
    ->check(CLI::IsMember({"exponential", "gaussian"}))
    ->capture_default_str();
  cmd->add_option("--sampling", o.sampling,
                  "embedding: exact (full matrix), nystrom (farthest-point samples), gamma (Nyström with Gamma-sampling) or auto (exact up to 2000 faces, nystrom above)")
    ->check(CLI::IsMember({"auto", "exact", "nystrom", "gamma"}))
    ->capture_default_str();
  cmd->add_option("--samples", o.samples, "Nyström samples (default: one more than the K-means clusters)")->check(Count(0, max_samples));
  cmd->add_flag("--no-graph-cut", o.no_graph_cut, "skip the graph-cut boundary enhancement");
  cmd->add_option("--graph-cut", o.graph_cut,
                  "graph-cut settings: banded (a strong smoothness term acting near the boundaries, one sweep of moves) or thesis "
                  "(the thesis's weak smoothness term, every face free, moves until none helps)")
    ->check(CLI::IsMember({"banded", "thesis"}))
    ->capture_default_str();
  cmd->add_option("--crease-angle", o.crease_angle,
                  "with extra clusters and in --k auto's contrast merge: split the K-means clusters along closed loops "
                  "of concave creases of at least this many degrees before merging (0: off)")
    ->capture_default_str()
    ->check(Finite_range(0., 180.));
  cmd->add_option("--flat-seam-angle", o.flat_seam_angle,
                  "in the merges of extra clusters and in --k auto's merges: a boundary whose mean concave angle is "
                  "below this many degrees is a flat seam, merged before every other boundary, the one between the "
                  "largest segments first (0: off)")
    ->capture_default_str()
    ->check(Finite_range(0., 180.));
  cmd->add_option("--merge-size-exponent", o.merge_size_exponent,
                  "with extra clusters: the merge multiplies a boundary's strength by the area fraction of the "
                  "smaller of its two segments to this power, so that small parts go before large ones (0: off)")
    ->capture_default_str()
    ->check(Finite_range(0., 10.));
  cmd->add_option("--merge-separation", o.merge_separation,
                  "with extra clusters, on meshes whose folds are mostly blunt: the merge weakens the boundary "
                  "between two segments that overlap in the spectral embedding (pieces of one body), in proportion "
                  "while their separation is below this scale (0: off)")
    ->capture_default_str()
    ->check(Finite_range(0., 1e6));
  cmd->add_option("--graph-cut-backend", o.graph_cut_backend,
                  "max-flow code of the graph cut: maxflow (fastest, GPL), boost-csr or boost-list (LGPL)")
    ->check(CLI::IsMember({"default", "maxflow", "boost-csr", "boost-list"}))
    ->capture_default_str();
  cmd->add_option("--threads", o.threads, "threads (0 = all); the labels do not depend on it")->check(Count(0, 4096));
  cmd->add_option("--seed", o.seed, "seed of the sampling's start face")->capture_default_str()->check(Count(0, UINT32_MAX));
  cmd->add_option("--extra-clusters", o.extra_clusters,
                  "K-means makes k + N clusters, then the segments with the weakest (least concave) boundaries "
                  "are merged until k are left (0, with --alternative-extra-clusters none and --contrast-merge-clusters 0: the "
                  "thesis's method)")->capture_default_str()->check(Count(0, max_clusters));
  const CLI::Validator count = Count(0, max_clusters);
  cmd
    ->add_option_function<std::vector<std::string>>(
      "--alternative-extra-clusters",
      [&o](const std::vector<std::string>& items) {
        o.alternative_extra_clusters.clear();
        for(const std::string& item : items)
          if(item == "none" && items.size() > 1)
            throw CLI::ValidationError("--alternative-extra-clusters", "'none' cannot be combined with numbers");
          else if(item != "none")
            o.alternative_extra_clusters.push_back(std::stoul(item)); // checked below
      },
      "other numbers of extra clusters to try besides --extra-clusters (comma-separated, default 8): each is a "
      "whole segmentation, and the one whose boundaries best follow concave creases (lowest concave normalized "
      "cut) is kept (see also --contrast-merge-clusters); 'none': one segmentation fewer")
    ->delimiter(',')
    ->check(CLI::Validator(
      [count](std::string& text) { return text == "none" ? std::string() : count(text); },
      "INT in [0, " + std::to_string(max_clusters) + "] or 'none'"));
  cmd->add_option("--contrast-merge-clusters", o.contrast_merge_clusters,
                  "one more segmentation to choose from, in the same way: K-means makes this many clusters (at "
                  "least k), merged by contrast down to k as --k auto does (its hierarchy cut at k parts); 0: not "
                  "tried")
    ->capture_default_str()
    ->check(Count(0, max_clusters));
  cmd->add_option("--min-candidate-clusters", o.min_candidate_clusters,
                  "of the segmentations of --extra-clusters and --alternative-extra-clusters, those of fewer "
                  "K-means clusters than this (k + extra) are not tried when others are (with k = 2 or 3, k + 2 "
                  "clusters cut the largest body in pieces rather than find its parts); 0: all are tried")
    ->capture_default_str()
    ->check(Count(0, max_clusters));
  add_salient_cut_options(*cmd, o.salient);
}

inline void add_segment_command(CLI::App& app, Segment_options& o)
{
  CLI::App* cmd = app.add_subcommand("segment", "Segment a mesh into k parts by spectral clustering (k-way), or into as many parts as it has (--k auto)");
  o.cli = cmd;
  cmd->add_option("MESH", o.mesh, "mesh file (.off, .obj, .ply, .stl)")->required();
  add_segment_method_options(cmd, o);
  cmd->add_option("--labels", o.labels, "output: one segment label per face of the file, in file order")->required();
  add_mesh_output_options(*cmd, o.out_mesh, o.binary, o.parts_dir);
  cmd->add_option("--png", o.png, "output: picture of the segments");
  cmd->add_option("--json", o.json,
                  "output: report with the stage timings, segments and their areas ('-': on standard output, "
                  "which then carries nothing else)");
}

// The options given that the method asked for does not use, each with the
// reason: refused (exit code 2), not ignored.
inline std::vector<std::string> inapplicable_segment_options(const Segment_options& o)
{
  const CLI::App* cmd = o.cli;
  std::vector<std::string> w;
  const auto ignored = [&](std::initializer_list<const char*> options, const std::string& why) {
    for(const char* option : options)
      if(given(cmd, option))
        w.push_back(std::string(option) + " cannot be used here: " + why);
  };
  const bool automatic = o.k == "auto";
  const bool salient = automatic && (o.salient.method == "salient-cuts" || o.salient.method == "salient-cuts-thesis");
  if(!automatic)
    ignored({"--max-k", "--min-boundary-contrast", "--auto-method", "--neck-scale", "--over-segmentations", "--parts"},
            "it applies to --k auto");
  else if(o.salient.method != "contrast-merge")
    ignored({"--neck-scale", "--over-segmentations"}, "it applies to --auto-method contrast-merge");
  if(!salient)
    ignored({"--eta", "--structure-only", "--min-part-area", "--max-parts", "--depth"},
            "it applies to --k auto --auto-method salient-cuts");
  if(salient)
    ignored({"--metric", "--weights", "--ray-caster", "--normalization", "--vsi-fraction", "--max-measured-faces",
             "--kernel", "--sampling",
             "--samples", "--seed", "--no-graph-cut", "--graph-cut", "--crease-angle", "--flat-seam-angle",
             "--graph-cut-backend",
             "--extra-clusters", "--alternative-extra-clusters", "--contrast-merge-clusters",
             "--min-candidate-clusters", "--max-k", "--min-boundary-contrast"},
            "--auto-method salient-cuts uses none of the k-way options");
  else
  {
    if(automatic)
      ignored({"--extra-clusters", "--alternative-extra-clusters", "--contrast-merge-clusters",
               "--min-candidate-clusters"},
              "--k auto over-segments into --max-k clusters itself");
    if(o.sampling == "exact")
      ignored({"--samples", "--seed"}, "it sets the Nyström sampling, and --sampling exact takes no samples");
    if(o.no_graph_cut)
      ignored({"--graph-cut-backend", "--graph-cut"}, "--no-graph-cut skips the graph cut");
    // one segmentation left: no alternative other than --extra-clusters itself, no contrast merge
    if(!automatic && o.contrast_merge_clusters == 0 &&
       std::all_of(o.alternative_extra_clusters.begin(), o.alternative_extra_clusters.end(),
                   [&o](std::size_t e) { return e == o.extra_clusters; }))
      ignored({"--min-candidate-clusters"}, "it chooses which segmentations to try, and --alternative-extra-clusters "
                                            "none (or the same as --extra-clusters) --contrast-merge-clusters 0 "
                                            "leave one");
    // k clusters and no contrast merge: nothing is merged
    if(!automatic && o.extra_clusters == 0 && o.contrast_merge_clusters == 0 &&
       std::all_of(o.alternative_extra_clusters.begin(), o.alternative_extra_clusters.end(),
                   [](std::size_t e) { return e == 0; }))
      ignored({"--flat-seam-angle"}, "it orders the merges of extra clusters, and --extra-clusters 0 "
                                     "--alternative-extra-clusters none --contrast-merge-clusters 0 merge nothing");
    for(const std::string& m : inapplicable_metric_options(cmd, o.metric))
      w.push_back(m);
  }
  for(const std::string& m : inapplicable_mesh_output_options(cmd, o.out_mesh, o.parts_dir))
    w.push_back(m);
  return w;
}

// The outputs of `segment`: labels, coloured mesh, picture, JSON report.
// (with `--json -` the JSON report is all that goes to standard output: the
// lines naming the files go to standard error, unless -q)
template <typename Lap>
int write_segment_outputs(const Segment_options& o, const Loaded_mesh& m, const std::vector<int>& mesh_labels,
                          const SpectralSeg::Execution& exec, const std::string& metric, nlohmann::ordered_json& report,
                          const std::vector<std::pair<std::string, double>>& timings, Lap& lap,
                          std::chrono::steady_clock::time_point started, const Progress_printer& out)
{
  const bool json_to_stdout = o.json == "-";
  const auto say = [&](const std::string& line) {
    if(json_to_stdout)
      out.message(line);
    else
      std::cout << line << "\n";
  };
  // segments numbered in the file's face order, in every output
  const std::vector<int> labels = SpectralSeg::IO::number_segments_in_input_order(m.report, mesh_labels);
  const std::size_t n = labels.size();
  const std::size_t segments = labels.empty() ? 0 : std::size_t(*std::max_element(labels.begin(), labels.end()) + 1);
  SpectralSeg::IO::write_face_values(o.labels, SpectralSeg::IO::values_in_input_order(m.report, labels, -1));
  say("segments: " + std::to_string(segments));
  say("labels: " + o.labels);
  write_mesh_outputs(o.out_mesh, o.binary, o.parts_dir, m, labels, say);
  if(!o.png.empty())
  {
    SpectralSeg::Rendering::render_face_labels_png(o.png, m.graph.geometry(), labels);
    say("png: " + o.png);
  }
  lap("write");

  if(!o.json.empty())
  {
    std::vector<double> areas(segments, 0.);
    std::vector<std::size_t> counts(segments, 0);
    for(std::size_t f = 0; f < n; ++f)
    {
      areas[std::size_t(labels[f])] += m.graph.geometry().areas[f];
      ++counts[std::size_t(labels[f])];
    }
    nlohmann::ordered_json head;
    head["mesh"] = o.mesh;
    head["faces"] = n;
    head["k"] = o.k == "auto" ? nlohmann::ordered_json("auto") : nlohmann::ordered_json(std::stoul(o.k));
    head["segments"] = segments;
    for(auto it = report.begin(); it != report.end(); ++it)
      head[it.key()] = it.value();
    report = std::move(head);
    if(!metric.empty())
      report["metric"] = metric;
    report["threads"] = exec.threads();
    nlohmann::ordered_json segs = nlohmann::json::array();
    for(std::size_t s = 0; s < segments; ++s)
      segs.push_back({{"label", s}, {"faces", counts[s]}, {"area", areas[s]}});
    report["segment_list"] = segs;
    nlohmann::ordered_json t;
    for(const auto& st : timings)
      t[st.first] = st.second;
    // the wall time: candidates of --alternative-extra-clusters run side by
    // side, so the stage times can add up to more
    t["total"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    report["timings_seconds"] = t;
    if(json_to_stdout)
      std::cout << report.dump(2) << "\n";
    else
    {
      SpectralSeg::IO::write_text_file(o.json, report.dump(2) + "\n");
      say("json: " + o.json);
    }
  }
  return 0;
}

// The value of --k: a number of segments, or 0 for 'auto'.
// \throws Usage_error if it is neither
inline std::size_t parse_k(const std::string& text)
{
  if(text == "auto")
    return 0;
  std::size_t used = 0;
  long long v = 0;
  try
  {
    v = std::stoll(text, &used);
  }
  catch(const std::exception&)
  {
    used = 0;
  }
  if(used != text.size() || v < 1 || v > static_cast<long long>(max_clusters))
    throw Usage_error("--k must be a positive integer up to " + std::to_string(max_clusters) + " or 'auto' (got '" + text + "')");
  return static_cast<std::size_t>(v);
}

// Runs the metric and the k-way or merge method (--k K, or --k auto with a
// merge method) on a loaded mesh; adds the report entries and the stage
// timings (the metric's among them), names the metric, returns the labels.
// Defined in segmentation_methods.cpp, the translation unit of the methods.
std::vector<int> run_k_way_methods(const Segment_options& o, std::size_t k, const SpectralSeg::Dual_graph& graph,
                                   const SpectralSeg::Execution& exec, nlohmann::ordered_json& report,
                                   std::vector<std::pair<std::string, double>>& timings, std::string& metric,
                                   const Progress_printer& out);

inline int run_segment(const Segment_options& o, Progress_printer& out)
{
  using clock = std::chrono::steady_clock;
  nlohmann::ordered_json report;
  std::vector<std::pair<std::string, double>> timings;
  const auto started = clock::now();
  auto t0 = started;
  auto lap = [&](const std::string& stage) {
    const auto now = clock::now();
    timings.emplace_back(stage, std::chrono::duration<double>(now - t0).count());
    t0 = now;
  };

  const std::size_t k = parse_k(o.k);
  check_mesh_outputs(o.out_mesh, o.parts_dir, {{"--labels", o.labels}, {"--png", o.png}, {"--json", o.json, true}});
  refuse_inapplicable_options(inapplicable_segment_options(o));

  const Loaded_mesh m(o.mesh, out, !o.out_mesh.empty() || !o.parts_dir.empty(), o.threads);
  lap("read");
  const std::size_t n = m.graph.number_of_faces();
  if(k > n)
    throw SpectralSeg::Invalid_input("--k " + std::to_string(k) + " is larger than the number of faces (" +
                                     std::to_string(n) + ")");
  const SpectralSeg::Execution exec(o.threads, out.callback());
  if(k == 0 && (o.salient.method == "salient-cuts" || o.salient.method == "salient-cuts-thesis"))
  {
    std::vector<int> labels = run_salient_cuts(o.salient, m.graph, exec, report, timings, out);
    t0 = clock::now();
    return write_segment_outputs(o, m, labels, exec, "", report, timings, lap, started, out);
  }
  std::string metric;
  std::vector<int> labels = run_k_way_methods(o, k, m.graph, exec, report, timings, metric, out);
  t0 = clock::now();
  return write_segment_outputs(o, m, labels, exec, metric, report, timings, lap, started, out);
}

} // namespace spectralseg_cli

#endif
