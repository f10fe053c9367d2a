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

// The canonical text of the options that change what is written: every
// option of the command but those of batch_options_not_hashed(), as given or
// by its default, in the order of the help.
inline std::string batch_options_text(const CLI::App& cmd)
{
  std::string text;
  for(const CLI::Option* opt : cmd.get_options())
  {
    const std::string name = opt->get_name();
    bool excluded = false;
    for(const std::string& n : opt->get_lnames())
      excluded = excluded || batch_options_not_hashed().count("--" + n) > 0;
    if(excluded || batch_options_not_hashed().count(name) > 0)
      continue;
    std::string value;
    for(const std::string& r : opt->results())
      value += (value.empty() ? "" : ",") + r;
    if(opt->count() == 0 || value == opt->get_default_str()) // --max-k 20 is --max-k's default
      value = "(default " + opt->get_default_str() + ")";
    text += (text.empty() ? "" : " ") + name + "=" + value;
  }
  return text;
}

// The files of one mesh, as paths to open and relative to the output folder.
struct Mesh_outputs
{
  std::string labels, json, png, colored_mesh;             // to open
  std::string labels_rel, json_rel, png_rel, colored_rel; // in the summary
};

inline Mesh_outputs outputs_of(const Batch_plan& plan, const Batch_mesh& mesh)
{
  Mesh_outputs o;
  auto place = [&](const std::string& suffix, std::string& path, std::string& rel) {
    rel = mesh.name + suffix;
    path = (fs::path(plan.out) / rel).string();
  };
  place(".seg", o.labels, o.labels_rel);
  place(".json", o.json, o.json_rel);
  if(plan.png)
    place(".png", o.png, o.png_rel);
  if(!plan.colored_mesh.empty())
    place("." + plan.colored_mesh, o.colored_mesh, o.colored_rel);
  return o;
}

// Removes the outputs of a mesh that a run may have left (also temporary
// files of an interrupted write); the JSON report, the mark of a finished
// mesh, goes first. A coloured mesh is removed only in the format asked for
// (NAME.off could be a mesh file when the output folder holds the inputs).
inline void remove_mesh_outputs(const Batch_plan& plan, const Batch_mesh& mesh)
{
  const fs::path base = fs::path(plan.out) / mesh.name;
  std::error_code ec;
  std::vector<std::string> suffixes{"json", "seg", "png"};
  if(!plan.colored_mesh.empty())
    suffixes.push_back(plan.colored_mesh);
  for(const std::string& s : suffixes)
    fs::remove(base.string() + "." + s, ec);
  suffixes = {"json", "seg", "png", "ply", "off"};
  const std::string leaf = base.filename().string();
  fs::directory_iterator it(base.parent_path(), ec), end;
  for(; !ec && it != end; it.increment(ec))
  {
    const std::string f = it->path().filename().string();
    for(const std::string& s : suffixes)
    {
      const std::string prefix = "." + leaf + "." + s + ".tmp";
      if(f.size() > prefix.size() && f.compare(0, prefix.size(), prefix) == 0 &&
         f.find_first_not_of("0123456789_", prefix.size()) == std::string::npos)
        fs::remove(it->path(), ec);
    }
  }
}

// The summary row of a mesh whose outputs are finished: its JSON report holds
// the batch record written last, for the same options, and for the same
// input file (same size, and same modification time or content hash); every
// output it lists is there with its size, the labels with their hash.
// Empty if not (`why` says why).
inline std::optional<Batch_row> finished_row(const Batch_plan& plan, const Batch_mesh& mesh, std::string* why = nullptr)
{
  auto no = [&](const std::string& reason) -> std::optional<Batch_row> {
    if(why != nullptr)
      *why = reason;
    return std::nullopt;
  };
  const Mesh_outputs paths = outputs_of(plan, mesh);
  std::ifstream in(paths.json);
  if(!in)
    return no("no report");
  const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  if(report.is_discarded() || !report.is_object() || !report.contains("batch") || !report["batch"].is_object())
    return no("no finished report");
  try
  {
    const nlohmann::json& b = report.at("batch");
    if(b.at("format").get<int>() != 1 || b.at("name").get<std::string>() != mesh.name)
      return no("a report of another mesh");
    if(b.at("options_hash").get<std::string>() != plan.options_hash)
      return no("other options");
    const File_stamp input = stamp_of(mesh.input);
    if(!input.exists || input.size != b.at("input_size").get<long long>())
      return no("the input changed");
    if(input.mtime_ns != b.at("input_mtime_ns").get<long long>() &&
       hash_file(mesh.input) != b.at("input_hash").get<std::string>())
      return no("the input changed");
    const nlohmann::json& outputs = b.at("outputs");
    const std::vector<std::pair<std::string, std::string>> expected{
      {"labels", paths.labels_rel}, {"png", paths.png_rel}, {"colored_mesh", paths.colored_rel}};
    for(const auto& e : expected)
    {
      if(e.second.empty() != !outputs.contains(e.first))
        return no("other outputs");
      if(e.second.empty())
        continue;
      const nlohmann::json& record = outputs.at(e.first);
      const std::string path = (fs::path(plan.out) / e.second).string();
      if(record.at("file").get<std::string>() != e.second || stamp_of(path).size != record.at("size").get<long long>())
        return no("an output is missing or changed");
      if(record.contains("hash") && hash_file(path) != record.at("hash").get<std::string>())
        return no("an output changed");
    }
    Batch_row r;
    r.mesh = mesh.name;
    r.status = "ok";
    r.faces = report.at("faces").get<long long>();
    r.segments = report.at("segments").get<long long>();
    r.seconds = b.at("seconds").get<double>();
    r.warnings = b.at("warnings").get<std::vector<std::string>>();
    r.input = mesh.input;
    r.labels = paths.labels_rel;
    r.json = paths.json_rel;
    r.colored_mesh = paths.colored_rel;
    r.png = paths.png_rel;
    return r;
  }
  catch(const std::exception& e)
  {
    return no(std::string("a malformed report: ") + e.what());
  }
}

// The text a file descriptor's file holds from its start.
inline std::string read_whole_descriptor(int fd)
{
  std::string text;
  char buffer[1 << 14];
  off_t at = 0;
  for(;;)
  {
    const ssize_t n = ::pread(fd, buffer, sizeof(buffer), at);
    if(n <= 0)
      break;
    text.append(buffer, std::size_t(n));
    at += n;
  }
  return text;
}

// The lines of `text` that start with `prefix`, without it.
inline std::vector<std::string> lines_starting_with(const std::string& text, const std::string& prefix)
{
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, prefix.size(), prefix) == 0)
      out.push_back(line.substr(prefix.size()));
  return out;
}

// Segments one mesh, in the process of its own: the `segment` command's code
// path, then the batch record added to its JSON report, written last.
inline void segment_mesh(const Batch_plan& plan, const Batch_mesh& mesh)
{
  const auto start = std::chrono::steady_clock::now();
  const Mesh_outputs paths = outputs_of(plan, mesh);
  std::error_code ec;
  fs::create_directories(fs::path(paths.json).parent_path(), ec);
  if(ec)
    throw SpectralSeg::Io_error("cannot create the folder '" + fs::path(paths.json).parent_path().string() +
                                "': " + ec.message());
  remove_mesh_outputs(plan, mesh);
  const File_stamp before = stamp_of(mesh.input);

  Segment_options o = plan.segment;
  o.mesh = mesh.input;
  o.labels = paths.labels;
  o.json = paths.json;
  o.png = paths.png;
  o.out_mesh = paths.colored_mesh;
  o.threads = plan.threads_per_mesh;
  Progress_printer printer(false); // on the captured standard error: its warnings go to the summary
  run_segment(o, printer);

  if(stamp_of(mesh.input) != before)
    throw SpectralSeg::Invalid_input("'" + mesh.input + "' changed while it was segmented");
  std::ifstream in(paths.json);
  nlohmann::ordered_json report = nlohmann::ordered_json::parse(in);
  in.close();
  std::fflush(stderr);
  nlohmann::ordered_json b;
  b["format"] = 1;
  b["name"] = mesh.name;
  b["input"] = mesh.input;
  b["input_size"] = before.size;
  b["input_mtime_ns"] = before.mtime_ns;
  b["input_hash"] = hash_file(mesh.input);
  b["options_hash"] = plan.options_hash;
  b["options"] = plan.options;
  b["warnings"] = lines_starting_with(read_whole_descriptor(2), "warning: ");
  nlohmann::ordered_json outputs;
  outputs["labels"] = {{"file", paths.labels_rel}, {"size", stamp_of(paths.labels).size}, {"hash", hash_file(paths.labels)}};
  if(!paths.png.empty())
    outputs["png"] = {{"file", paths.png_rel}, {"size", stamp_of(paths.png).size}};
  if(!paths.colored_mesh.empty())
    outputs["colored_mesh"] = {{"file", paths.colored_rel}, {"size", stamp_of(paths.colored_mesh).size}};
  b["outputs"] = outputs;
  b["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report["batch"] = b;
  SpectralSeg::IO::write_text_file(paths.json, report.dump(2) + "\n");
}

// The child process of one mesh: dies with the batch (a killed batch leaves
// no process behind), writes its messages to `stderr_fd`, never returns.
[[noreturn]] inline void run_mesh_process(const Batch_plan& plan, const Batch_mesh& mesh, int stderr_fd)
{
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if(::getppid() != plan.parent)
    ::_exit(3);
  ::dup2(stderr_fd, 2);
  const int null = ::open("/dev/null", O_WRONLY);
  if(null >= 0)
    ::dup2(null, 1);
  int code = 0;
  try
  {
    segment_mesh(plan, mesh);
  }
  catch(const std::bad_alloc&)
  {
    std::fprintf(stderr, "error: out of memory: this mesh needs more memory than this machine allows a job; try "
                         "fewer --jobs\n");
    code = 1;
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "error: %s\n", e.what());
    code = 1;
  }
  std::cout.flush();
  std::fflush(stdout);
  std::fflush(stderr);
  ::_exit(code);
}

// A mesh being segmented by a child process.
struct Running_mesh
{
  std::size_t index = 0;
  std::FILE* messages = nullptr;
  std::chrono::steady_clock::time_point start;
  bool timed_out = false;
};

// The error of a failed mesh, from its process's exit and messages.
inline std::string failure_message(int status, const Running_mesh& r, double timeout)
{
  std::fflush(r.messages);
  const std::string text = read_whole_descriptor(::fileno(r.messages));
  if(r.timed_out)
    return "stopped after the --timeout of " + seconds_text(timeout) + " s";
  const std::vector<std::string> errors = lines_starting_with(text, "error: ");
  if(!errors.empty())
    return errors.back();
  if(WIFSIGNALED(status))
  {
    const int sig = WTERMSIG(status);
    std::string m = "stopped by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
    if(sig == SIGKILL)
      m += ": out of memory? (the system kills processes over the memory limit; try fewer --jobs)";
    return m;
  }
  return "exited with code " + std::to_string(WEXITSTATUS(status));
}

// Runs the meshes of `todo` (indices into `meshes`), at most plan.jobs at
// once, and fills their rows.
inline void run_mesh_processes(const Batch_plan& plan, const std::vector<Batch_mesh>& meshes,
                               const std::vector<std::size_t>& todo, std::vector<Batch_row>& rows,
                               const Progress_printer& out, std::size_t& done, std::size_t total)
{
  std::map<pid_t, Running_mesh> running;
  std::size_t next = 0;
  auto finish = [&](pid_t pid, int status) {
    auto it = running.find(pid);
    if(it == running.end())
      return;
    Running_mesh r = it->second;
    running.erase(it);
    const Batch_mesh& mesh = meshes[r.index];
    Batch_row& row = rows[r.index];
    std::string why;
    std::optional<Batch_row> finished;
    if(WIFEXITED(status) && WEXITSTATUS(status) == 0 && !r.timed_out)
      finished = finished_row(plan, mesh, &why);
    if(finished)
      row = *finished;
    else
    {
      row.mesh = mesh.name;
      row.input = mesh.input;
      row.status = "error";
      row.error = WIFEXITED(status) && WEXITSTATUS(status) == 0 && !r.timed_out
                    ? "the outputs are not complete (" + why + ")"
                    : failure_message(status, r, plan.timeout);
      row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count();
      remove_mesh_outputs(plan, mesh);
    }
    std::fclose(r.messages);
    ++done;
    out.message("[" + std::to_string(done) + "/" + std::to_string(total) + "] " + mesh.name + ": " +
                (row.status == "ok" ? "ok, " + std::to_string(row.segments) + " segments, " +
                                        seconds_text(row.seconds) + " s"
                                    : "error: " + row.error));
  };
  while(next < todo.size() || !running.empty())
  {
    while(running.size() < plan.jobs && next < todo.size())
    {
      Running_mesh r;
      r.index = todo[next++];
      r.messages = std::tmpfile();
      if(r.messages == nullptr)
        throw SpectralSeg::Io_error(std::string("cannot create a temporary file: ") + std::strerror(errno));
      std::cout.flush();
      std::fflush(stdout);
      std::fflush(stderr);
      r.start = std::chrono::steady_clock::now();
      const pid_t pid = ::fork();
      if(pid < 0)
      {
        std::fclose(r.messages);
        throw SpectralSeg::Error(std::string("cannot start a process: ") + std::strerror(errno));
      }
      if(pid == 0)
        run_mesh_process(plan, meshes[r.index], ::fileno(r.messages));
      running[pid] = r;
    }
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, plan.timeout > 0. ? WNOHANG : 0);
    if(pid > 0)
      finish(pid, status);
    else if(pid < 0 && errno != EINTR)
      throw SpectralSeg::Error(std::string("cannot wait for a process: ") + std::strerror(errno));
    else if(pid == 0)
    {
      const auto now = std::chrono::steady_clock::now();
      for(auto& p : running)
        if(!p.second.timed_out && std::chrono::duration<double>(now - p.second.start).count() > plan.timeout)
        {
          p.second.timed_out = true;
          ::kill(p.first, SIGKILL);
        }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
}

// Summary lines on standard output; returns the exit code (1 if a mesh failed).
inline int report_batch(const std::vector<Batch_row>& rows, const std::string& stem)
{
  std::size_t ok = 0, skipped = 0, failed = 0;
  for(const Batch_row& r : rows)
  {
    ok += r.status == "ok";
    skipped += r.skipped;
    failed += r.status != "ok";
  }
  std::cout << "meshes: " << rows.size() << "\nok: " << ok << "\nskipped: " << skipped << "\nfailed: " << failed
            << "\nsummary: " << stem << ".csv\nsummary: " << stem << ".jsonl\n";
  return failed > 0 ? 1 : 0;
}

inline nlohmann::ordered_json batch_record(const std::vector<Batch_row>& rows)
{
  std::size_t ok = 0, skipped = 0, failed = 0;
  for(const Batch_row& r : rows)
  {
    ok += r.status == "ok";
    skipped += r.skipped;
    failed += r.status != "ok";
  }
  nlohmann::ordered_json j;
  j["meshes"] = rows.size();
  j["ok"] = ok;
  j["skipped"] = skipped;
  j["failed"] = failed;
  return j;
}

inline int run_batch(const Batch_options& o, const Progress_printer& out)
{
  const auto start = std::chrono::steady_clock::now();
  if(o.inputs.empty() && o.lists.empty())
    throw Usage_error("batch: no mesh given: give mesh files or folders, or --list FILE");
  (void)parse_k(o.segment.k);
  refuse_inapplicable_options(inapplicable_segment_options(o.segment));
  const Shard shard = parse_shard(o.shard);

  Batch_plan plan;
  plan.segment = o.segment;
  plan.out = o.out;
  plan.png = o.png;
  plan.colored_mesh = o.colored_mesh;
  plan.force = o.force;
  plan.timeout = o.timeout;
  plan.jobs = o.jobs;
  const unsigned threads = SpectralSeg::Execution(o.segment.threads).threads();
  plan.threads_per_mesh = std::max(1u, threads / o.jobs);
  plan.options = batch_options_text(*o.command);
  plan.options_hash = hash_text(plan.options);
  plan.parent = ::getpid();

  std::error_code ec;
  fs::create_directories(o.out, ec);
  if(ec)
    throw SpectralSeg::Io_error("cannot create the output folder '" + o.out + "': " + ec.message());
  const std::string stem = (fs::path(o.out) / ("summary" + shard.suffix())).string();
  const std::string record = (fs::path(o.out) / ("batch" + shard.suffix() + ".json")).string();
  // the summary of an earlier run must not pass for this one's until it ends
  for(const std::string& f : {stem + ".csv", stem + ".jsonl", record})
    fs::remove(f, ec);
  if(shard.given)
    for(const char* f : {"summary.csv", "summary.jsonl", "batch.json"})
      fs::remove(fs::path(o.out) / f, ec);
  SpectralSeg::IO::check_writable(stem + ".csv");

  const Batch_list list = list_batch_meshes(o.inputs, o.lists, o.recursive, o.root, o.out);
  if(list.meshes.empty())
    throw SpectralSeg::Invalid_input("batch: no mesh file found in the inputs given");
  std::string names;
  for(const Batch_mesh& m : list.meshes)
    names += m.name + "\n";

  std::vector<Batch_mesh> meshes;
  for(std::size_t i = 0; i < list.meshes.size(); ++i)
    if(shard.takes(i))
      meshes.push_back(list.meshes[i]);
  out.message("batch: " + std::to_string(meshes.size()) + " meshes" +
              (shard.given ? " (shard " + o.shard + " of " + std::to_string(list.meshes.size()) + ")" : "") + ", " +
              std::to_string(o.jobs) + " at once, " + std::to_string(plan.threads_per_mesh) + " threads each");

  std::vector<Batch_row> rows(meshes.size());
  std::vector<std::size_t> todo;
  std::size_t done = 0;
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    std::optional<Batch_row> finished = o.force ? std::nullopt : finished_row(plan, meshes[i]);
    if(finished)
    {
      rows[i] = *finished;
      rows[i].skipped = true;
      ++done;
    }
    else
      todo.push_back(i);
  }
  if(done > 0)
    out.message("batch: " + std::to_string(done) + " meshes finished by an earlier run, skipped");
  run_mesh_processes(plan, meshes, todo, rows, out, done, meshes.size());

  write_summary(stem, rows);
  nlohmann::ordered_json j;
  j["format"] = 1;
  j["shard"] = shard.index;
  j["shards"] = shard.count;
  j["meshes_total"] = list.meshes.size();
  j["list_hash"] = hash_text(names);
  j["root"] = list.root;
  j["options"] = plan.options;
  j["options_hash"] = plan.options_hash;
  const nlohmann::ordered_json counts = batch_record(rows);
  for(const auto& item : counts.items())
    j[item.key()] = item.value();
  j["jobs"] = plan.jobs;
  j["threads_per_mesh"] = plan.threads_per_mesh;
  j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  SpectralSeg::IO::write_text_file(record, j.dump(2) + "\n");
  return report_batch(rows, stem);
}

inline int run_batch_merge(const Batch_merge_options& o, const Progress_printer& out)
{
  const std::regex pattern("batch-shard-([0-9]+)-of-([0-9]+)\\.json");
  std::map<std::size_t, std::map<std::size_t, nlohmann::json>> runs; // shards -> index -> record
  std::error_code ec;
  fs::directory_iterator it(o.folder, ec), end;
  if(ec)
    throw SpectralSeg::Io_error("cannot read the folder '" + o.folder + "': " + ec.message());
  for(; it != end; it.increment(ec))
  {
    std::smatch m;
    const std::string leaf = it->path().filename().string();
    if(!std::regex_match(leaf, m, pattern))
      continue;
    std::ifstream in(it->path());
    const nlohmann::json record = nlohmann::json::parse(in, nullptr, false);
    if(record.is_discarded() || !record.is_object())
      throw SpectralSeg::Invalid_input("'" + it->path().string() + "' is not a batch record");
    runs[std::stoul(m[2].str())][std::stoul(m[1].str())] = record;
  }
  if(runs.empty())
    throw SpectralSeg::Invalid_input("no shard of a batch in '" + o.folder +
                                     "' (batch --shard I/N writes batch-shard-I-of-N.json there)");
  if(runs.size() > 1)
  {
    std::string counts;
    for(const auto& r : runs)
      counts += (counts.empty() ? "" : " and ") + std::to_string(r.first);
    throw SpectralSeg::Invalid_input("'" + o.folder + "' holds the shards of batches split " + counts +
                                     " ways: remove the batch-shard-*-of-N.* files of the old one");
  }
  const std::size_t shards = runs.begin()->first;
  const auto& records = runs.begin()->second;
  std::string missing;
  for(std::size_t i = 0; i < shards; ++i)
    if(records.count(i) == 0)
      missing += (missing.empty() ? "" : ", ") + std::to_string(i);
  if(!missing.empty())
    throw SpectralSeg::Invalid_input("shards " + missing + " of " + std::to_string(shards) + " are missing in '" +
                                     o.folder + "' (unfinished or not run): run them with --shard I/" +
                                     std::to_string(shards) + " and merge again");
  const nlohmann::json& first = records.at(0);
  std::vector<Batch_row> rows;
  double seconds = 0.;
  for(const auto& r : records)
  {
    for(const char* key : {"options_hash", "list_hash", "meshes_total"})
      if(r.second.at(key) != first.at(key))
        throw SpectralSeg::Invalid_input("shard " + std::to_string(r.first) + " of " + std::to_string(shards) +
                                         " was run with other " +
                                         (std::string(key) == "options_hash" ? "options" : "meshes") +
                                         " than shard 0: run every shard with the same command");
    const std::string suffix = "-shard-" + std::to_string(r.first) + "-of-" + std::to_string(shards);
    const std::vector<Batch_row> part = read_summary_jsonl((fs::path(o.folder) / ("summary" + suffix + ".jsonl")).string());
    if(part.size() != r.second.at("meshes").get<std::size_t>())
      throw SpectralSeg::Invalid_input("the summary of shard " + std::to_string(r.first) + " has " +
                                       std::to_string(part.size()) + " rows, its record says " +
                                       r.second.at("meshes").dump());
    rows.insert(rows.end(), part.begin(), part.end());
    seconds += r.second.at("seconds").get<double>();
  }
  sort_rows(rows);
  for(std::size_t i = 1; i < rows.size(); ++i)
    if(rows[i].mesh == rows[i - 1].mesh)
      throw SpectralSeg::Invalid_input("mesh '" + rows[i].mesh + "' is in two shards");
  if(rows.size() != first.at("meshes_total").get<std::size_t>())
    throw SpectralSeg::Invalid_input("the shards hold " + std::to_string(rows.size()) + " meshes, the batch has " +
                                     first.at("meshes_total").dump());
  const std::string stem = (fs::path(o.folder) / "summary").string();
  write_summary(stem, rows);
  nlohmann::ordered_json j;
  j["format"] = 1;
  j["shard"] = 0;
  j["shards"] = 1;
  j["merged_shards"] = shards;
  j["meshes_total"] = first.at("meshes_total");
  j["list_hash"] = first.at("list_hash");
  j["root"] = first.at("root");
  j["options"] = first.at("options");
  j["options_hash"] = first.at("options_hash");
  const nlohmann::ordered_json counts = batch_record(rows);
  for(const auto& item : counts.items())
    j[item.key()] = item.value();
  j["seconds"] = seconds;
  SpectralSeg::IO::write_text_file((fs::path(o.folder) / "batch.json").string(), j.dump(2) + "\n");
  out.message("batch-merge: " + std::to_string(shards) + " shards, " + std::to_string(rows.size()) + " meshes");
  return report_batch(rows, stem);
}

} // namespace spectralseg_cli

#endif
