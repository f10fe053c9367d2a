// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg render MESH LABELS.seg [--png OUT.png] [--mesh OUT.ply]
#ifndef SPECTRALSEG_TOOLS_COMMAND_RENDER_H
#define SPECTRALSEG_TOOLS_COMMAND_RENDER_H

#include "Loaded_mesh.h"

#include <SpectralSeg/IO/write_colored_mesh.h>
#include <SpectralSeg/Rendering/render_png.h>

#include <CLI/CLI.hpp>

#include <iostream>
#include <string>
#include <vector>

namespace spectralseg_cli {

struct Render_command_options
{
  std::string mesh;
  std::string labels;
  std::string png;
  std::string out_mesh;
};

inline void add_render_command(CLI::App& app, Render_command_options& o)
{
  CLI::App* cmd = app.add_subcommand(
    "render", "Draw a segmentation given as a label file (for example a ground truth, or the output of "
              "'segment'): a PNG picture from three sides and/or a mesh with one colour per segment");
  cmd->add_option("MESH", o.mesh, "mesh file (.off, .obj, .ply, .stl) the labels refer to")->required();
  cmd->add_option("LABELS", o.labels, "one integer label per face of the mesh file, in file order (.seg)")->required();
  cmd->add_option("--png", o.png, "output: picture of the segments");
  cmd->add_option("--mesh", o.out_mesh, "output: the mesh with one colour per segment (.ply or .off)");
}

inline int run_render(const Render_command_options& o, const Progress_printer& out)
{
  if(o.png.empty() && o.out_mesh.empty())
    throw SpectralSeg::Invalid_input("render: nothing to write; give --png and/or --mesh");
  const Loaded_mesh m(o.mesh, out);
  const std::vector<int> labels = labels_in_mesh_order(m, o.labels);
  if(!o.out_mesh.empty())
  {
    SpectralSeg::IO::write_colored_mesh(o.out_mesh, m.graph.geometry(), SpectralSeg::Rendering::label_colors(labels));
    std::cout << "mesh: " << o.out_mesh << "\n";
  }
  if(!o.png.empty())
  {
    SpectralSeg::Rendering::render_face_labels_png(o.png, m.points(), m.triangles(), labels);
    std::cout << "png: " << o.png << "\n";
  }
  return 0;
}

} // namespace spectralseg_cli

#endif
