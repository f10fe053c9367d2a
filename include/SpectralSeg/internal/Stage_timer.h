// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Stage timings: (stage, seconds since the previous lap) appended to a list.
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
  explicit Stage_timer(std::vector<std::pair<std::string, double>>& timings)
    : timings_(timings), clock_(std::chrono::steady_clock::now())
  {}
  // appends (stage, seconds since construction or the previous call)
  void operator()(const std::string& stage)
  {
    const auto now = std::chrono::steady_clock::now();
    timings_.emplace_back(stage, std::chrono::duration<double>(now - clock_).count());
    clock_ = now;
  }

private:
  std::vector<std::pair<std::string, double>>& timings_;
  std::chrono::steady_clock::time_point clock_;
};

} // namespace internal
} // namespace SpectralSeg

#endif // SPECTRALSEG_INTERNAL_STAGE_TIMER_H
