// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg render MESH LABELS.seg [--png OUT.png] [--mesh OUT.ply|.obj|.off] [--binary] [--parts-dir DIR] [--view dx,dy,dz,ux,uy,uz ...]
#ifndef SPECTRALSEG_TOOLS_COMMAND_RENDER_H
#define SPECTRALSEG_TOOLS_COMMAND_RENDER_H

#include "Argument_checks.h"
#include "Loaded_mesh.h"
#include "Mesh_outputs.h"

#include <SpectralSeg/Rendering/render_mesh_geometry.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
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
  bool binary = false;
  std::string parts_dir;
  std::vector<std::string> views;
  const CLI::App* cli = nullptr; // the parsed subcommand (null: none)
};

// "dx,dy,dz,ux,uy,uz" -> a view
inline SpectralSeg::Rendering::View parse_view(const std::string& text, std::size_t index)
{
  std::vector<double> v;
  std::size_t start = 0;
  while(start <= text.size())
  {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    std::size_t used = 0;
    double x = 0.;
    try
    {
      x = std::stod(item, &used);
    }
    catch(const std::exception&)
    {
      used = 0;
    }
    if(item.empty() || used != item.size() || !std::isfinite(x))
      throw Usage_error("--view '" + text + "': expected six numbers dx,dy,dz,ux,uy,uz");
    v.push_back(x);
    start = comma + 1;
  }
  if(v.size() != 6 || (v[0] == 0. && v[1] == 0. && v[2] == 0.) || (v[3] == 0. && v[4] == 0. && v[5] == 0.))
    throw Usage_error("--view '" + text + "': expected six numbers dx,dy,dz,ux,uy,uz with non-zero direction and up vectors");
  return SpectralSeg::Rendering::View{"view " + std::to_string(index + 1), {v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
}

inline void add_render_command(CLI::App& app, Render_command_options& o)
{
  CLI::App* cmd = app.add_subcommand(
    "render", "Draw a segmentation given as a label file (for example a ground truth, or the output of "
              "'segment'): a PNG picture from three sides and/or a mesh with one colour per segment");
  o.cli = cmd;
  cmd->add_option("MESH", o.mesh, "mesh file (.off, .obj, .ply, .stl) the labels refer to")->required();
  cmd->add_option("LABELS", o.labels, "one integer label per face of the mesh file, in file order (.seg)")->required();
  cmd->add_option("--png", o.png, "output: picture of the segments");
  add_mesh_output_options(*cmd, o.out_mesh, o.binary, o.parts_dir);
  cmd->add_option("--view", o.views,
                  "a view of the picture, repeatable: viewing direction (from the camera into the scene) and up "
                  "vector as dx,dy,dz,ux,uy,uz (default: three views chosen from the shape: along its thinnest "
                  "principal axis from both sides and from above at an angle, so that flat and long shapes show "
                  "their parts; 0,0,-1,0,1,0 -1,0,0,0,1,0 0,0,1,0,1,0: the world's front, side and back)");
}

inline int run_render(const Render_command_options& o, const Progress_printer& out)
{
  if(o.png.empty() && o.out_mesh.empty() && o.parts_dir.empty())
    throw Usage_error("render: nothing to write; give --png, --mesh and/or --parts-dir");
  SpectralSeg::Rendering::Render_options ro;
  if(!o.views.empty())
  {
    ro.views.clear();
    for(std::size_t i = 0; i < o.views.size(); ++i)
      ro.views.push_back(parse_view(o.views[i], i));
  }
  check_mesh_outputs(o.out_mesh, o.parts_dir, {{"--png", o.png}});
  std::vector<std::string> inapplicable = inapplicable_mesh_output_options(o.cli, o.out_mesh, o.parts_dir);
  if(o.png.empty() && given(o.cli, "--view"))
    inapplicable.push_back("--view cannot be used here: it applies to --png");
  refuse_inapplicable_options(inapplicable);
  const Loaded_mesh m(o.mesh, out);
  const std::vector<int> labels = labels_in_mesh_order(m, o.labels);
  write_mesh_outputs(o.out_mesh, o.binary, o.parts_dir, m, labels,
                     [](const std::string& line) { std::cout << line << "\n"; });
  if(!o.png.empty())
  {
    SpectralSeg::Rendering::render_face_labels_png(o.png, m.graph.geometry(), labels, ro);
    std::cout << "png: " << o.png << "\n";
  }
  return 0;
}

} // namespace spectralseg_cli

#endif
