// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg info MESH
#ifndef SPECTRALSEG_TOOLS_COMMAND_INFO_H
#define SPECTRALSEG_TOOLS_COMMAND_INFO_H

#include "Loaded_mesh.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <string>

namespace spectralseg_cli {

struct Info_options
{
  std::string mesh;
  bool json = false;
};

inline void add_info_command(CLI::App& app, Info_options& o)
{
  CLI::App* cmd = app.add_subcommand("info", "Print the size, topology and defects of a mesh file");
  cmd->add_option("MESH", o.mesh, "mesh file (.off, .obj, .ply, .stl)")->required();
  cmd->add_flag("--json", o.json, "print the report as JSON");
}

inline int run_info(const Info_options& o, const Progress_printer& out)
{
  const Loaded_mesh m(o.mesh, out);
  const SpectralSeg::Mesh_geometry& g = m.graph.geometry();
  Eigen::Vector3d lo = g.points.front(), hi = g.points.front();
  for(const auto& p : g.points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  nlohmann::ordered_json j;
  j["file"] = o.mesh;
  j["file_vertices"] = m.report.input_vertices;
  j["file_faces"] = m.report.input_faces;
  j["faces"] = num_faces(m.mesh);
  j["vertices"] = num_vertices(m.mesh);
  j["components"] = m.graph.number_of_components();
  j["closed"] = m.report.closed;
  j["boundary_edges"] = m.graph.number_of_border_edges();
  j["non_manifold_edges"] = m.report.non_manifold_edges;
  j["split_vertices"] = m.report.split_vertices;
  j["degenerate_faces"] = g.number_of_degenerate_faces();
  j["duplicate_faces"] = m.report.duplicate_faces;
  j["invalid_faces"] = m.report.invalid_faces;
  j["triangulated_faces"] = m.report.non_triangle_faces;
  j["merged_vertices"] = m.report.merged_vertices;
  j["bbox_min"] = {lo.x(), lo.y(), lo.z()};
  j["bbox_max"] = {hi.x(), hi.y(), hi.z()};
  if(o.json)
  {
    std::cout << j.dump(2) << std::endl;
    return 0;
  }
  for(auto it = j.begin(); it != j.end(); ++it)
    std::cout << it.key() << ": " << (it->is_string() ? it->get<std::string>() : it->dump()) << "\n";
  return 0;
}

} // namespace spectralseg_cli

#endif
