// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Checks of the command-line arguments: usage errors (exit code 2), strict
// number validators, output paths checked before the computation.
#ifndef SPECTRALSEG_TOOLS_ARGUMENT_CHECKS_H
#define SPECTRALSEG_TOOLS_ARGUMENT_CHECKS_H

#include <SpectralSeg/IO/Atomic_output_file.h>

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <system_error>
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

// Before any work: every output path given (empty: not asked for) can be
// created, so that a long computation does not end in "cannot write".
inline void check_outputs_writable(std::initializer_list<std::string> paths)
{
  for(const std::string& path : paths)
    SpectralSeg::IO::check_writable(path);
}

} // namespace spectralseg_cli

#endif
