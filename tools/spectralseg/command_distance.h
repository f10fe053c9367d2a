// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg distance MESH --from FACE ...
#ifndef SPECTRALSEG_TOOLS_COMMAND_DISTANCE_H
#define SPECTRALSEG_TOOLS_COMMAND_DISTANCE_H

#include "Argument_checks.h"
#include "Loaded_mesh.h"
#include "metric_choice.h"

#include <SpectralSeg/IO/write_face_values.h>
#include <SpectralSeg/Rendering/render_mesh_geometry.h>
#include <SpectralSeg/dual_graph_distances.h>

#include <CLI/CLI.hpp>

#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace spectralseg_cli {

struct Distance_options
{
  std::string mesh;
  long long from = 0;
  Metric_options metric;
  std::string field;
  std::string png;
  unsigned threads = 0;
  const CLI::App* cli = nullptr; // the parsed subcommand (null: none)
};

inline void add_distance_command(CLI::App& app, Distance_options& o)
{
  CLI::App* cmd = app.add_subcommand("distance", "Distance field from one face under a dual-graph metric");
  o.cli = cmd;
  cmd->add_option("MESH", o.mesh, "mesh file (.off, .obj, .ply, .stl)")->required();
  cmd->add_option("--from", o.from, "source face, by its index in the file (0-based)")->required();
  add_metric_options(*cmd, o.metric);
  cmd->add_option("--field", o.field, "output: one distance per face of the file, in file order ('inf' for "
                                      "faces in other components, 'nan' for dropped faces)")->required();
  cmd->add_option("--png", o.png, "output: picture of the field (blue near, red far, grey unreachable)");
  cmd->add_option("--threads", o.threads, "threads (0 = all)")->check(Count(0, 4096));
}

inline int run_distance(const Distance_options& o, Progress_printer& out)
{
  check_outputs({{"--field", o.field}, {"--png", o.png}});
  refuse_inapplicable_options(inapplicable_metric_options(o.cli, o.metric));
  const Loaded_mesh m(o.mesh, out, true, o.threads);
  const std::size_t source = m.mesh_face_of_input_face(o.from);
  const SpectralSeg::Execution exec(o.threads, out.callback());
  const SpectralSeg::Metrics::Any_weight metric = make_metric(o.metric);
  exec.report(metric.name() + " weights", 0.);
  const std::vector<double> weights = metric(m.graph, exec);
  exec.report(metric.name() + " weights", 1.);
  const SpectralSeg::Weighted_dual_graph weighted(m.graph, weights);
  exec.report("dijkstra", 0.);
  const std::vector<double> d = weighted.distances(static_cast<SpectralSeg::Dual_graph::size_type>(source));
  exec.report("dijkstra", 1.);

  SpectralSeg::IO::write_face_values(
    o.field, SpectralSeg::IO::values_in_input_order(m.report, d, std::numeric_limits<double>::quiet_NaN()));
  std::cout << "field: " << o.field << "\n";
  if(!o.png.empty())
  {
    SpectralSeg::Rendering::render_face_field_png(o.png, m.graph.geometry(), d);
    std::cout << "png: " << o.png << "\n";
  }
  std::size_t unreachable = 0;
  for(double v : d)
    unreachable += std::isinf(v) ? 1 : 0;
  if(unreachable > 0)
    out.message("note: " + std::to_string(unreachable) +
                " faces lie in other connected components than the source: their distance is inf");
  return 0;
}

} // namespace spectralseg_cli

#endif
