// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg segment --k auto --auto-method salient-cuts: the top-down
// method of the thesis's chapter 6, improved (salient-cuts) or as published
// (salient-cuts-thesis), its hierarchy in the JSON report, cut at a number of
// parts or a depth.
#ifndef SPECTRALSEG_TOOLS_SALIENT_CUT_SEGMENTATION_H
#define SPECTRALSEG_TOOLS_SALIENT_CUT_SEGMENTATION_H

#include "Argument_checks.h"
#include "Progress_printer.h"

#include <SpectralSeg/automatic_segmentation.h>
#include <SpectralSeg/segment_hybrid.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace spectralseg_cli {

struct Salient_cut_options
{
  std::string method = "contrast-merge";
  double eta = 0.1;
  bool structure_only = false;
  double min_part_area = SpectralSeg::Automatic_segmentation_options<>().min_part_area_fraction;
  std::size_t max_parts = SpectralSeg::Automatic_segmentation_options<>().max_parts;
  bool min_part_area_given = false, max_parts_given = false; // else salient-cuts-thesis keeps the thesis's
  std::size_t parts = 0;                                         // 0: every leaf
  std::size_t depth = std::numeric_limits<std::size_t>::max(); // max: every leaf
};

inline void add_salient_cut_options(CLI::App& cmd, Salient_cut_options& o)
{
  cmd.add_option("--auto-method", o.method,
                 "--k auto: contrast-merge (over-segment into --max-k clusters, merge while the weakest "
                 "boundary is not both concave and a jump of the part-aware metric; the default, best on psb-dev), "
                 "concave-merge (the same, judged by concavity alone), salient-cuts (top-down, after the thesis's chapter 6: "
                 "recursive cuts of the pieces that pass the segmentability test, at their most salient place; "
                 "with our salience and test, see doc/benchmarks.md) or salient-cuts-thesis (the same as published)")
    ->check(CLI::IsMember({"contrast-merge", "concave-merge", "salient-cuts", "salient-cuts-thesis"}))
    ->capture_default_str();
  cmd.add_option("--eta", o.eta, "salient-cuts: segmentability threshold (a piece is cut when a contour scores above it)")
    ->check(Finite_range(0., 1.))
    ->capture_default_str();
  cmd.add_flag("--structure-only", o.structure_only, "salient-cuts: only the L-projection (structure) tests");
  cmd.add_option("--min-part-area", o.min_part_area,
                 "salient-cuts: no part under this fraction of its component's area (0: the thesis's behaviour, "
                 "the default of salient-cuts-thesis)")
    ->check(Finite_range(0., 0.49))
    ->each([&o](const std::string&) { o.min_part_area_given = true; })
    ->capture_default_str();
  cmd.add_option("--max-parts", o.max_parts,
                 "salient-cuts: no cut once there are this many parts (0: no limit, the default of salient-cuts-thesis)")
    ->capture_default_str()
    ->each([&o](const std::string&) { o.max_parts_given = true; })
    ->check(Count(0, 1000000));
  cmd.add_option("--parts", o.parts,
                 "--k auto: this many parts, the method's hierarchy cut there instead of where the method stops "
                 "(salient-cuts: its first cuts; the merge methods: their last merges undone, or more merges); "
                 "the JSON report still holds the whole hierarchy")
    ->check(Count(1, 1000000));
  cmd.add_option("--depth", o.depth, "salient-cuts: stop every branch of the hierarchy at this depth (0: one part)")
    ->check(Count(0, 1000000));
}

// One node of a hierarchy and its subtree; `cuts`: the salient-cut method's
// (with the segmentability tests), else merges.
inline nlohmann::ordered_json hierarchy_json(const SpectralSeg::Part_hierarchy& h, std::size_t node, bool cuts)
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
inline nlohmann::ordered_json hierarchy_report(const SpectralSeg::Part_hierarchy& h, bool cuts)
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
inline void warn_missing_parts(std::size_t parts, const SpectralSeg::Part_hierarchy& h, const Progress_printer& out)
{
  if(parts > 0 && !h.nodes.empty() && parts > h.number_of_leaves())
    out.message("warning: --parts " + std::to_string(parts) + ", but the hierarchy has " +
                std::to_string(h.number_of_leaves()) + " leaves: " + std::to_string(h.number_of_leaves()) + " parts");
}

// Runs the salient-cut method on a loaded mesh; fills labels, adds its
// report entries and stage timings.
inline std::vector<int> run_salient_cuts(const Salient_cut_options& o, const SpectralSeg::Dual_graph& graph,
                                         const SpectralSeg::Execution& exec, nlohmann::ordered_json& report,
                                         std::vector<std::pair<std::string, double>>& timings,
                                         const Progress_printer& out)
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

} // namespace spectralseg_cli

#endif
