// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Stage timings: (stage, seconds since the previous lap) appended to a list,
// or, accumulating, added to the entry of the same stage (stages that run
// once per piece of a recursive algorithm).
#ifndef SPECTRALSEG_INTERNAL_STAGE_TIMER_H
#define SPECTRALSEG_INTERNAL_STAGE_TIMER_H

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace internal {

class Stage_timer
{
public:
  explicit Stage_timer(std::vector<std::pair<std::string, double>>& timings, bool accumulate = false)
    : timings_(timings), clock_(std::chrono::steady_clock::now()), accumulate_(accumulate)
  {}
  // records (stage, seconds since construction or the previous call)
  void operator()(const std::string& stage)
  {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - clock_).count();
    clock_ = now;
    add(stage, seconds);
  }
  // records (stage, seconds) without reading the clock
  void add(const std::string& stage, double seconds)
  {
    if(accumulate_)
      for(auto& t : timings_)
        if(t.first == stage)
        {
          t.second += seconds;
          return;
        }
    timings_.emplace_back(stage, seconds);
  }

private:
  std::vector<std::pair<std::string, double>>& timings_;
  std::chrono::steady_clock::time_point clock_;
  bool accumulate_;
};

} // namespace internal
} // namespace SpectralSeg

#endif // SPECTRALSEG_INTERNAL_STAGE_TIMER_H
