// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg: the command-line tool of SpectralSeg.
#include "command_batch.h"
#include "command_distance.h"
#include "command_eval.h"
#include "command_info.h"
#include "command_render.h"
#include "command_retrieval.h"
#include "command_segment.h"
#include "Argument_checks.h"
#include "heap_tuning.h"

#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/version.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>

namespace {

// Exit codes (user manual, "Exit status").
constexpr int exit_ok = 0;
constexpr int exit_failure = 1; // bad input, a failed computation or write
constexpr int exit_usage = 2;   // arguments that make no sense

// Flushes standard output and reports a write error (a full disk, a closed
// pipe): results the user asked for must not vanish silently.
int finish(int code)
{
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  if(failed)
  {
    std::fprintf(stderr, "error: cannot write to standard output: %s\n", std::strerror(errno != 0 ? errno : EIO));
    return code == exit_ok ? exit_failure : code;
  }
  return code;
}

} // namespace

int main(int argc, char** argv)
{
  using namespace spectralseg_cli;
  // over a file-size limit (ulimit -f), writes fail with EFBIG and are
  // reported, instead of the process being killed with a half-written file
  std::signal(SIGXFSZ, SIG_IGN);
  keep_freed_memory_in_heap(); // heap_tuning.h
  CLI::App app{"spectralseg: part-aware spectral segmentation of triangle meshes"};
  app.require_subcommand(1);
  app.fallthrough();
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "no progress or warnings on stderr");
  app.set_version_flag("--version", "spectralseg " SPECTRALSEG_VERSION_STRING);
  // CLI11's parse errors are usage errors: "error: ..." and exit code 2 (below)
  app.failure_message(
    [](const CLI::App* a, const CLI::Error& e) { return "error: " + CLI::FailureMessage::simple(a, e); });

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
  Batch_options batch;
  Batch_merge_options batch_merge;
  add_batch_commands(app, batch, batch_merge);
  Descriptor_command_options descriptor;
  add_descriptor_command(app, descriptor);
  Rank_command_options rank;
  add_rank_command(app, rank);

  try
  {
    check_subcommand_name(app, argc, argv);
    app.parse(argc, argv);
    check_no_empty_values(app);
  }
  catch(const CLI::ParseError& e)
  {
    // --help and --version are "errors" of code 0; CLI11's own codes (106, 109...) become 2
    return finish(app.exit(e) == 0 ? exit_ok : exit_usage);
  }
  catch(const Usage_error& e)
  {
    std::cerr << "error: " << e.what() << "\nRun with --help for more information." << std::endl;
    return finish(exit_usage);
  }
  Progress_printer out(quiet);
  try
  {
    if(app.got_subcommand("info"))
      return finish(run_info(info, out));
    if(app.got_subcommand("distance"))
      return finish(run_distance(distance, out));
    if(app.got_subcommand("segment"))
      return finish(run_segment(segment, out));
    if(app.got_subcommand("eval"))
      return finish(run_eval(eval, out));
    if(app.got_subcommand("render"))
      return finish(run_render(render, out));
    if(app.got_subcommand("batch"))
      return finish(run_batch(batch, out));
    if(app.got_subcommand("batch-merge"))
      return finish(run_batch_merge(batch_merge, out));
    if(app.got_subcommand("descriptor"))
      return finish(run_descriptor(descriptor, out));
    if(app.got_subcommand("rank"))
      return finish(run_rank(rank, out));
  }
  catch(const Usage_error& e)
  {
    std::cerr << "error: " << e.what() << std::endl;
    return finish(exit_usage);
  }
  catch(const SpectralSeg::Error& e)
  {
    std::cerr << "error: " << e.what() << std::endl;
    return finish(exit_failure);
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "error: out of memory: the computation needs more memory than this machine allows it; "
                 "try a smaller mesh, or for 'segment' fewer --samples, a smaller --k or --max-k, or "
                 "--sampling nystrom"
              << std::endl;
    return finish(exit_failure);
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << std::endl;
    return finish(exit_failure);
  }
  return finish(exit_ok);
}
