// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Wall-clock timing for the benchmarks.
#ifndef SPECTRALSEG_BENCHMARK_TIMING_H
#define SPECTRALSEG_BENCHMARK_TIMING_H

#include <chrono>

namespace spectralseg_bench {

// Seconds elapsed since t0.
inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Seconds taken by f().
template <typename F>
double seconds(const F& f)
{
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return seconds_since(t0);
}

} // namespace spectralseg_bench

#endif
