// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg eval --mesh MESH PRED.seg GT.seg [GT.seg ...] [--json OUT.json]
#ifndef SPECTRALSEG_TOOLS_COMMAND_EVAL_H
#define SPECTRALSEG_TOOLS_COMMAND_EVAL_H

#include "Argument_checks.h"
#include "Loaded_mesh.h"

#include <SpectralSeg/IO/Atomic_output_file.h>
#include <SpectralSeg/evaluation.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace spectralseg_cli {

struct Eval_options
{
  std::string mesh;
  std::string predicted;
  std::vector<std::string> ground_truths;
  std::string json;
};

inline void add_eval_command(CLI::App& app, Eval_options& o)
{
  CLI::App* cmd = app.add_subcommand(
    "eval", "Score a segmentation against ground-truth segmentations with the Princeton Segmentation Benchmark "
            "measures (Rand index error, GCE, LCE, Hamming distance, cut discrepancy; lower is better)");
  cmd->add_option("--mesh", o.mesh, "mesh file (.off, .obj, .ply, .stl) the labels refer to")->required();
  cmd->add_option("PRED", o.predicted, "segmentation to score: one integer label per face of the mesh file, "
                                       "in file order (.seg)")->required();
  cmd->add_option("GT", o.ground_truths, "one or more ground-truth segmentations, same format; each score is "
                                         "averaged over them")->required();
  cmd->add_option("--json", o.json,
                  "also write the averaged and per-ground-truth scores to this JSON file ('-': on standard output, "
                  "instead of the lines of scores)");
}

inline nlohmann::ordered_json scores_json(const SpectralSeg::Evaluation::Scores& s)
{
  nlohmann::ordered_json j; // NaN is written as null
  j["rand_index_error"] = s.rand_index_error;
  j["global_consistency_error"] = s.global_consistency_error;
  j["local_consistency_error"] = s.local_consistency_error;
  j["hamming_distance"] = s.hamming_distance;
  j["hamming_missing_rate"] = s.hamming_missing_rate;
  j["hamming_false_alarm_rate"] = s.hamming_false_alarm_rate;
  j["cut_discrepancy"] = s.cut_discrepancy;
  return j;
}

inline int run_eval(const Eval_options& o, const Progress_printer& out)
{
  namespace E = SpectralSeg::Evaluation;
  check_outputs({{"--json", o.json, true}});
  const Loaded_mesh m(o.mesh, out);
  const std::vector<int> predicted = labels_in_mesh_order(m, o.predicted);
  std::vector<std::vector<int>> truths;
  for(const std::string& path : o.ground_truths)
    truths.push_back(labels_in_mesh_order(m, path));

  const std::vector<E::Scores> each = E::evaluate_each(m.graph, predicted, truths);
  const E::Scores mean = E::average(each);
  std::size_t undefined_cd = 0;
  for(const E::Scores& s : each)
    undefined_cd += std::isnan(s.cut_discrepancy) ? 1 : 0;
  if(undefined_cd > 0)
    out.message("note: the cut discrepancy is undefined against " + std::to_string(undefined_cd) + " of " +
                std::to_string(each.size()) +
                " ground truths (exactly one of the two segmentations has a single segment): left out of its mean");

  const nlohmann::ordered_json averaged = scores_json(mean);
  const bool json_to_stdout = o.json == "-";
  if(!json_to_stdout) // with --json -, the JSON report is all that goes to standard output
  {
    std::cout << "ground_truths: " << truths.size() << "\n";
    std::cout << std::setprecision(6);
    for(auto it = averaged.begin(); it != averaged.end(); ++it)
    {
      std::cout << it.key() << ": ";
      if(it->is_null())
        std::cout << "nan\n";
      else
        std::cout << it->get<double>() << "\n";
    }
  }

  if(!o.json.empty())
  {
    nlohmann::ordered_json j;
    j["mesh"] = o.mesh;
    j["faces"] = m.graph.number_of_faces();
    j["predicted"] = o.predicted;
    j["ground_truths"] = o.ground_truths;
    j["scores"] = averaged;
    j["cut_discrepancy_ground_truths"] = each.size() - undefined_cd;
    nlohmann::ordered_json per = nlohmann::ordered_json::array();
    for(std::size_t i = 0; i < each.size(); ++i)
    {
      nlohmann::ordered_json g;
      g["file"] = o.ground_truths[i];
      g["scores"] = scores_json(each[i]);
      per.push_back(std::move(g));
    }
    j["per_ground_truth"] = std::move(per);
    if(json_to_stdout)
      std::cout << j.dump(2) << "\n";
    else
    {
      SpectralSeg::IO::write_text_file(o.json, j.dump(2) + "\n");
      std::cout << "json: " << o.json << "\n";
    }
  }
  return 0;
}

} // namespace spectralseg_cli

#endif
