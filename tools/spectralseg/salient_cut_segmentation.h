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

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace spectralseg_cli {

struct Salient_cut_options
{
  Salient_cut_options(); // the library's defaults (segmentation_methods.cpp)
  std::string method = "contrast-merge";
  double eta = 0.1;
  bool structure_only = false;
  double min_part_area = 0.;
  std::size_t max_parts = 0;
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

// Runs the salient-cut method on a loaded mesh; fills labels, adds its
// report entries (the hierarchy among them) and stage timings. Defined in
// segmentation_methods.cpp, the translation unit of the methods.
std::vector<int> run_salient_cuts(const Salient_cut_options& o, const SpectralSeg::Dual_graph& graph,
                                  const SpectralSeg::Execution& exec, nlohmann::ordered_json& report,
                                  std::vector<std::pair<std::string, double>>& timings, const Progress_printer& out);

} // namespace spectralseg_cli

#endif
