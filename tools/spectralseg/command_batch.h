// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg batch INPUT... --out DIR --k K ...: segments many meshes with
// the options of `segment`, one process per mesh, --jobs at once; resumable,
// shardable across machines. spectralseg batch-merge DIR: the shards'
// summaries merged into one.
#ifndef SPECTRALSEG_TOOLS_BATCH_COMMAND_H
#define SPECTRALSEG_TOOLS_BATCH_COMMAND_H

#include "Argument_checks.h"
#include "Batch_inputs.h"
#include "Batch_summary.h"
#include "Progress_printer.h"
#include "command_segment.h"

#include <SpectralSeg/Execution.h>
#include <SpectralSeg/IO/Atomic_output_file.h>
#include <SpectralSeg/exceptions.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <new>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace spectralseg_cli {

struct Batch_options
{
  Segment_options segment; // the method; MESH and the outputs are set per mesh
  std::vector<std::string> inputs;
  std::vector<std::string> lists;
  std::string out;
  bool recursive = false;
  std::string root;
  std::string shard;
  unsigned jobs = 1;
  bool png = false;
  std::string colored_mesh; // "", "ply" or "off"
  bool force = false;
  double timeout = 0.;
  CLI::App* command = nullptr;
};

struct Batch_merge_options
{
  std::string folder;
};

// The options that do not change what is written for a mesh: left out of the
// options hash (a rerun with more --jobs or threads reuses the outputs).
inline const std::set<std::string>& batch_options_not_hashed()
{
  static const std::set<std::string> names{"--help",  "INPUT", "--list",  "--out",   "--recursive", "--root",
                                           "--shard", "--jobs", "--force", "--timeout", "--threads"};
  return names;
}

inline void add_batch_commands(CLI::App& app, Batch_options& o, Batch_merge_options& m)
{
  CLI::App* cmd = app.add_subcommand(
    "batch", "Segment many meshes (files, folders, list files) into an output folder with the options of 'segment': "
             "labels and a JSON report per mesh, a summary table; resumable, and shardable across machines");
  o.command = cmd;
  cmd->add_option("INPUT", o.inputs,
                  "mesh files, and folders whose mesh files (.off, .obj, .ply, .stl) are taken (with their "
                  "subfolders if -r)");
  cmd->add_option("--list", o.lists,
                  "text file naming one mesh file per line, relative to the current folder ('-': standard input; "
                  "empty lines and lines starting with # are skipped); repeatable");
  cmd->add_option("--out", o.out, "output folder (created if needed)")->required();
  cmd->add_flag("-r,--recursive", o.recursive, "also take the mesh files in the subfolders of the folders given");
  cmd->add_option("--root", o.root,
                  "the outputs of a mesh are named by its path relative to this folder (default: the deepest folder "
                  "holding every folder given and the folder of every file)");
  add_segment_method_options(cmd, o.segment);
  o.segment.cli = cmd; // options the method does not use are refused, as by segment
  cmd->get_option("--threads")
    ->description("threads in all (0 = all), shared by the meshes segmented at once: each gets max(1, threads / "
                  "--jobs); the labels do not depend on it");
  cmd->add_option("--jobs", o.jobs, "meshes segmented at once, each in a process of its own")
    ->capture_default_str()
    ->check(Count(1, 1024));
  cmd->add_option("--shard", o.shard,
                  "I/N: only the meshes at positions I, I+N, I+2N... (from 0) of the sorted list, so that N machines "
                  "share the list; 'batch-merge' then merges their summaries");
  cmd->add_flag("--png", o.png, "also write a picture of the segments of each mesh (NAME.png)");
  cmd->add_option("--colored-mesh", o.colored_mesh,
                  "also write each mesh with one colour per segment, in this format (NAME.ply or NAME.off)")
    ->check(CLI::IsMember({"ply", "off"}));
  cmd->add_flag("--force", o.force, "segment every mesh again, also those whose outputs are finished");
  cmd->add_option("--timeout", o.timeout, "a mesh still running after this many seconds is stopped and recorded as "
                                          "failed (0: no limit)")
    ->check(Finite_range(0., 1e9));
  cmd->footer("Each mesh NAME (its path relative to --root) gets OUT/NAME.seg and OUT/NAME.json; the summary is "
              "OUT/summary.csv and OUT/summary.jsonl (OUT/summary-shard-I-of-N.* for a shard). A mesh whose JSON "
              "report shows it finished with the same options on the same file is skipped. Exit status: 0 if every "
              "mesh was segmented, 1 if any failed (see the summary), 2 for a usage error.");

  CLI::App* merge = app.add_subcommand(
    "batch-merge", "Merge the summaries of the shards of a batch (batch --shard I/N) in an output folder into "
                   "OUT/summary.csv and OUT/summary.jsonl, as one unsharded run would have written them");
  merge->add_option("OUT", m.folder, "the output folder the shards wrote to")->required();
}

// What is fixed for every mesh of a run.
struct Batch_plan
{
  Segment_options segment;
  std::string out;
  bool png = false;
  std::string colored_mesh;
  bool force = false;
  double timeout = 0.;
  unsigned jobs = 1;
  unsigned threads_per_mesh = 1;
  std::string options;      // canonical text of the options that change the outputs
  std::string options_hash; // its hash
  pid_t parent = 0;
};

// spectralseg batch: returns the exit code.
int run_batch(const Batch_options& o, const Progress_printer& out);

// spectralseg batch-merge: returns the exit code.
int run_batch_merge(const Batch_merge_options& o, const Progress_printer& out);

} // namespace spectralseg_cli

#endif
