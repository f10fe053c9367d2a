// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg: the command-line tool of SpectralSeg.
#include "command_distance.h"
#include "command_eval.h"
#include "command_info.h"
#include "command_render.h"
#include "command_segment.h"

#include <SpectralSeg/exceptions.h>

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

int main(int argc, char** argv)
{
  using namespace spectralseg_cli;
  CLI::App app{"spectralseg: part-aware spectral segmentation of triangle meshes"};
  app.require_subcommand(1);
  app.fallthrough();
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "no progress or warnings on stderr");
  app.set_version_flag("--version", "spectralseg 0.1.0");

  Info_options info;
  add_info_command(app, info);
  Distance_options distance;
  add_distance_command(app, distance);
  Segment_options segment;
  add_segment_command(app, segment);
  Eval_options eval;
  add_eval_command(app, eval);
  Render_command_options render;
  add_render_command(app, render);

  CLI11_PARSE(app, argc, argv);
  Progress_printer out(quiet);
  try
  {
    if(app.got_subcommand("info"))
      return run_info(info, out);
    if(app.got_subcommand("distance"))
      return run_distance(distance, out);
    if(app.got_subcommand("segment"))
      return run_segment(segment, out);
    if(app.got_subcommand("eval"))
      return run_eval(eval, out);
    if(app.got_subcommand("render"))
      return run_render(render, out);
  }
  catch(const SpectralSeg::Error& e)
  {
    std::cerr << "error: " << e.what() << std::endl;
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << std::endl;
    return 2;
  }
  return 0;
}
