// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg descriptor MESH --output FILE.json ...
// spectralseg rank QUERY FOLDER ...
// Shape retrieval (thesis 3.6): the shape descriptor of a mesh, and a folder
// of meshes ranked by chi-square distance to a query.
#ifndef SPECTRALSEG_TOOLS_COMMAND_RETRIEVAL_H
#define SPECTRALSEG_TOOLS_COMMAND_RETRIEVAL_H

#include "Progress_printer.h"
#include "metric_choice.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace spectralseg_cli {

inline Metric_options retrieval_metric_options()
{
  Metric_options m;
  m.weights = {0.02, 0., 0.98};
  return m;
}

// The metric and descriptor options both commands share.
struct Descriptor_choice
{
  // --metric part-aware, geodesic or euclidean; the thesis's retrieval weights
  Metric_options metric = retrieval_metric_options();
  std::size_t bins = 64;
  std::size_t sources = 32;
  double range = 4.;
  unsigned threads = 0;
};

struct Descriptor_command_options
{
  std::string mesh;
  std::string output;
  Descriptor_choice choice;
  const CLI::App* cli = nullptr; // the parsed subcommand (null: none)
};

struct Rank_command_options
{
  std::string query;
  std::vector<std::string> folders;
  std::size_t top = 0;
  std::string output;
  Descriptor_choice choice;
  const CLI::App* cli = nullptr;
};

void add_descriptor_command(CLI::App& app, Descriptor_command_options& o);
void add_rank_command(CLI::App& app, Rank_command_options& o);
int run_descriptor(const Descriptor_command_options& o, Progress_printer& out);
int run_rank(const Rank_command_options& o, Progress_printer& out);

} // namespace spectralseg_cli

#endif
