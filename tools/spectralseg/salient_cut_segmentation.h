// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg segment --k auto --auto-method salient-cuts: the thesis's
// chapter-6 method, its hierarchy in the JSON report, cut at a number of
// parts or a depth.
#ifndef SPECTRALSEG_TOOLS_SALIENT_CUT_SEGMENTATION_H
#define SPECTRALSEG_TOOLS_SALIENT_CUT_SEGMENTATION_H

#include "Argument_checks.h"

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
  std::size_t parts = 0;                                         // 0: every leaf
  std::size_t depth = std::numeric_limits<std::size_t>::max(); // max: every leaf
};

inline void add_salient_cut_options(CLI::App& cmd, Salient_cut_options& o)
{
  cmd.add_option("--auto-method", o.method,
                 "--k auto: contrast-merge (over-segment into --max-k clusters, merge while the weakest "
                 "boundary is not both concave and a jump of the part-aware metric; the default, best on psb-dev), "
                 "concave-merge (the same, judged by concavity alone) or salient-cuts (the thesis's chapter 6: "
                 "recursive cuts of the pieces that pass the segmentability test, at their most salient place)")
    ->check(CLI::IsMember({"contrast-merge", "concave-merge", "salient-cuts"}))
    ->capture_default_str();
  cmd.add_option("--eta", o.eta, "salient-cuts: segmentability threshold (a piece is cut when a contour scores above it)")
    ->check(Finite_range(0., 1.))
    ->capture_default_str();
  cmd.add_flag("--structure-only", o.structure_only, "salient-cuts: only the L-projection (structure) tests");
  cmd.add_option("--min-part-area", o.min_part_area,
                 "salient-cuts: no part under this fraction of its component's area (0: the thesis's behaviour)")
    ->check(Finite_range(0., 0.49))
    ->capture_default_str();
  cmd.add_option("--max-parts", o.max_parts, "salient-cuts: no cut once there are this many parts (0: no limit)")
    ->capture_default_str()
    ->check(Count(0, 1000000));
  cmd.add_option("--parts", o.parts,
                 "salient-cuts: keep only the first cuts, for this many parts (the hierarchy is still reported whole)")
    ->check(Count(1, 1000000));
  cmd.add_option("--depth", o.depth, "salient-cuts: stop every branch of the hierarchy at this depth (0: one part)")
    ->check(Count(0, 1000000));
}

inline nlohmann::ordered_json hierarchy_json(const SpectralSeg::Part_hierarchy& h, std::size_t node)
{
  const SpectralSeg::Part_node& n = h.nodes[node];
  nlohmann::ordered_json j;
  j["faces"] = n.faces.size();
  j["area"] = n.area;
  j["depth"] = n.depth;
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
    j["salience"] = n.cut_salience;
    j["children"] = {hierarchy_json(h, n.children[0]), hierarchy_json(h, n.children[1])};
  }
  return j;
}

// Runs the salient-cut method on a loaded mesh; fills labels, adds its
// report entries and stage timings.
inline std::vector<int> run_salient_cuts(const Salient_cut_options& o, const SpectralSeg::Dual_graph& graph,
                                         const SpectralSeg::Execution& exec, nlohmann::ordered_json& report,
                                         std::vector<std::pair<std::string, double>>& timings)
{
  SpectralSeg::Automatic_segmentation_options<> options;
  options.segmentability.threshold = o.eta;
  options.segmentability.structure_only = o.structure_only;
  options.min_part_area_fraction = o.min_part_area;
  options.max_parts = o.max_parts;
  SpectralSeg::Automatic_segmentation_result r =
    SpectralSeg::segment_automatically(graph, SpectralSeg::sequence_weights(graph, exec), options, exec);
  for(const auto& t : r.timings)
    timings.push_back(t);
  std::vector<int> labels = r.labels;
  if(o.parts > 0)
    labels = r.hierarchy.labels_with_parts(o.parts);
  if(o.depth != std::numeric_limits<std::size_t>::max())
  {
    const std::vector<int> at_depth = r.hierarchy.labels_at_depth(o.depth);
    if(o.parts == 0 || std::set<int>(at_depth.begin(), at_depth.end()).size() <
                         std::set<int>(labels.begin(), labels.end()).size())
      labels = at_depth;
  }
  report["auto_method"] = "salient-cuts";
  report["eta"] = o.eta;
  report["structure_only"] = o.structure_only;
  report["min_part_area"] = o.min_part_area;
  report["parts_found"] = r.number_of_segments;
  nlohmann::ordered_json roots = nlohmann::json::array();
  for(std::size_t root : r.hierarchy.roots)
    roots.push_back(hierarchy_json(r.hierarchy, root));
  report["hierarchy"] = roots;
  return labels;
}

} // namespace spectralseg_cli

#endif
