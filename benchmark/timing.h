// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Wall-clock timing for the benchmarks.
#ifndef SPECTRALSEG_BENCHMARK_TIMING_H
#define SPECTRALSEG_BENCHMARK_TIMING_H

#include <chrono>

namespace spectralseg_bench {

// Seconds taken by f().
template <typename F>
double seconds(const F& f)
{
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace spectralseg_bench

#endif
