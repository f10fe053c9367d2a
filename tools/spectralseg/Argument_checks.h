// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Checks of the command-line arguments: usage errors (exit code 2), strict
// number validators, output paths checked before the computation.
#ifndef SPECTRALSEG_TOOLS_ARGUMENT_CHECKS_H
#define SPECTRALSEG_TOOLS_ARGUMENT_CHECKS_H

#include <SpectralSeg/IO/Atomic_output_file.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace spectralseg_cli {

// An argument that makes no sense, whatever the input: exit code 2.
struct Usage_error : std::runtime_error
{
  explicit Usage_error(const std::string& what) : std::runtime_error(what) {}
};

// A whole number in [lo, hi], digits only: rejects signs, fractions,
// exponents, empty strings and values that overflow.
inline CLI::Validator Count(std::uint64_t lo, std::uint64_t hi)
{
  return CLI::Validator(
    [lo, hi](std::string& text) -> std::string {
      std::uint64_t v = 0;
      const char* end = text.data() + text.size();
      const auto r = std::from_chars(text.data(), end, v);
      const bool digits = !text.empty() && text.front() >= '0' && text.front() <= '9';
      if(!digits || r.ptr != end || r.ec != std::errc() || v < lo || v > hi)
        return "'" + text + "' is not a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
      return std::string();
    },
    "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

// A finite number in [lo, hi] (NaN and infinities are refused).
inline double parse_finite(const std::string& text, bool& ok)
{
  ok = false;
  if(text.empty())
    return 0.;
  std::size_t used = 0;
  double v = 0.;
  try
  {
    v = std::stod(text, &used);
  }
  catch(const std::exception&)
  {
    return 0.;
  }
  ok = used == text.size() && std::isfinite(v);
  return v;
}

inline CLI::Validator Finite_range(double lo, double hi)
{
  return CLI::Validator(
    [lo, hi](std::string& text) -> std::string {
      bool ok = false;
      const double v = parse_finite(text, ok);
      if(!ok || v < lo || v > hi)
        return "'" + text + "' is not a finite number from " + CLI::detail::to_string(lo) + " to " +
               CLI::detail::to_string(hi);
      return std::string();
    },
    "NUMBER");
}

// A comma-separated list of `min_items` to `max_items` finite numbers,
// each in [0, hi], with a positive sum; no empty item.
inline std::vector<double> parse_number_list(const std::string& option, const std::string& text, std::size_t min_items,
                                             std::size_t max_items, double hi)
{
  std::vector<double> out;
  std::size_t start = 0;
  double sum = 0.;
  while(start <= text.size())
  {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    bool ok = false;
    const double v = parse_finite(item, ok);
    if(!ok || v < 0. || v > hi)
      throw CLI::ValidationError(option, "'" + text + "': item '" + item + "' is not a finite number from 0 to " +
                                           CLI::detail::to_string(hi));
    out.push_back(v);
    sum += v;
    start = comma + 1;
  }
  if(out.size() < min_items || out.size() > max_items)
    throw CLI::ValidationError(option, "'" + text + "': expected " + std::to_string(min_items) + " to " +
                                         std::to_string(max_items) + " comma-separated numbers");
  if(!(sum > 0.))
    throw CLI::ValidationError(option, "'" + text + "': the numbers must not all be 0");
  return out;
}

// Refuses an empty value given to any option or positional of the chosen
// subcommand (`--from ''`, `--labels ''`).
inline void check_no_empty_values(const CLI::App& app)
{
  for(const CLI::App* sub : app.get_subcommands())
    for(const CLI::Option* option : sub->get_options())
      if(option->count() > 0 && option->get_items_expected_max() > 0)
        for(const std::string& value : option->results())
          if(value.empty())
            throw Usage_error(option->get_name() + ": an empty value");
}

// The number of single-character insertions, deletions and substitutions
// that turn `a` into `b`.
inline std::size_t edit_distance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for(std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for(std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for(std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// Before parsing: the first argument that is not an option of the main
// command must name a subcommand; otherwise a usage error names the
// closest subcommand (CLI11 would only say "A subcommand is required").
// Stops at the first other option (--help, --version, a mistyped option):
// CLI11 reports those.
inline void check_subcommand_name(const CLI::App& app, int argc, const char* const* argv)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string word = argv[i];
    if(word == "-q" || word == "--quiet")
      continue;
    if(!word.empty() && word.front() == '-')
      return;
    std::vector<std::string> names;
    for(const CLI::App* sub : app.get_subcommands({}))
      names.push_back(sub->get_name());
    if(names.empty() || std::find(names.begin(), names.end(), word) != names.end())
      return;
    std::string closest = names.front(), list;
    for(const std::string& name : names)
    {
      if(edit_distance(word, name) < edit_distance(word, closest))
        closest = name;
      list += (list.empty() ? "" : ", ") + name;
    }
    throw Usage_error("unknown command '" + word + "'; did you mean '" + closest + "'? (commands: " + list + ")");
  }
}

// Before any work: every output path given (empty: not asked for) can be
// created, so that a long computation does not end in "cannot write".
inline void check_outputs_writable(std::initializer_list<std::string> paths)
{
  for(const std::string& path : paths)
    SpectralSeg::IO::check_writable(path);
}

// An output file a command will write: the option that names it and its path
// (empty: not asked for); `-` means standard output where `to_stdout` allows it.
struct Output_file
{
  std::string option;
  std::string path;
  bool to_stdout = false;
};

// `dir/name` with the directory resolved (symbolic links, `.`, `..`), to
// compare output paths; the path itself if its directory does not exist.
inline std::string comparable_path(const std::string& path)
{
  const std::string resolved = SpectralSeg::IO::internal::resolved_path(path);
  if(resolved != path)
    return resolved; // it exists
  const std::string dir = SpectralSeg::IO::internal::directory_of(path);
  const std::string base = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  const std::string real_dir = SpectralSeg::IO::internal::resolved_path(dir);
  return real_dir == dir && dir != "." ? path : real_dir + "/" + base;
}

// Before any work. Usage errors first (exit code 2): `-` for an output that
// cannot go to standard output, two outputs naming the same file. Then each
// file can be created (exit code 1, see check_outputs_writable()).
inline void check_outputs(const std::vector<Output_file>& outputs)
{
  std::vector<std::pair<std::string, const Output_file*>> seen;
  for(const Output_file& o : outputs)
  {
    if(o.path.empty() || (o.to_stdout && o.path == "-"))
      continue;
    if(o.path == "-")
      throw Usage_error(o.option + " '-': only --json can write to standard output; give a file name");
    const std::string key = comparable_path(o.path);
    for(const auto& other : seen)
      if(other.first == key)
        throw Usage_error(other.second->option + " and " + o.option + " name the same file '" + o.path + "'");
    seen.emplace_back(key, &o);
  }
  for(const Output_file& o : outputs)
    if(!o.path.empty() && !(o.to_stdout && o.path == "-"))
      SpectralSeg::IO::check_writable(o.path);
}

// Whether the option `name` was given on the command line of `cmd` (false
// when the options were not filled from a command line: `cmd` is null).
inline bool given(const CLI::App* cmd, const std::string& name)
{
  // (a command without that option, e.g. batch and --binary: not given)
  const CLI::Option* option = cmd != nullptr ? cmd->get_option_no_throw(name) : nullptr;
  return option != nullptr && option->count() > 0;
}

// An option that the command asked for does not use is a usage error (exit
// code 2), never silently ignored: `reasons` holds one line per such option.
inline void refuse_inapplicable_options(const std::vector<std::string>& reasons)
{
  if(reasons.empty())
    return;
  std::string message;
  for(const std::string& r : reasons)
    message += (message.empty() ? "" : "; ") + r;
  throw Usage_error(message);
}

} // namespace spectralseg_cli

#endif
