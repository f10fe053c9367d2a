// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file spread_samples.h
/// \brief A subset of points spread over space (along a Morton curve).
#ifndef SPECTRALSEG_METRICS_VSI_SPREAD_SAMPLES_H
#define SPECTRALSEG_METRICS_VSI_SPREAD_SAMPLES_H

#include <SpectralSeg/internal/separate_compilation.h>
#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace SpectralSeg {
namespace Metrics {
namespace VSI {

/// \ingroup PkgSpectralSegVSI
/// \brief Chooses about `count` points spread over space: the points are
/// ordered along a Morton (Z-order) curve over their bounding box and taken
/// at regular steps. Deterministic; returns sorted indices.
SPECTRALSEG_INLINE std::vector<std::uint32_t> spread_samples(const std::vector<Eigen::Vector3d>& points,
                                                             std::size_t count)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = points.size();
  std::vector<std::uint32_t> all(n);
  std::iota(all.begin(), all.end(), 0u);
  if(count >= n)
    return all;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for(const auto& p : points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = std::max((hi - lo).maxCoeff(), std::numeric_limits<double>::min());
  auto spread_bits = [](std::uint64_t v) { // 21 bits -> every third bit
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  std::vector<std::uint64_t> code(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Vector3d q = (points[i] - lo) / extent * double((1 << 21) - 1);
    code[i] = spread_bits(std::uint64_t(q.x())) | spread_bits(std::uint64_t(q.y())) << 1 |
              spread_bits(std::uint64_t(q.z())) << 2;
  }
  std::stable_sort(all.begin(), all.end(), [&](std::uint32_t a, std::uint32_t b) { return code[a] < code[b]; });
  std::vector<std::uint32_t> picked;
  for(std::size_t i = 0; i < count; ++i)
    picked.push_back(all[static_cast<std::size_t>((double(i) + 0.5) * double(n) / double(count))]);
  std::sort(picked.begin(), picked.end());
  picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
  return picked;
}
#else
;
#endif

} // namespace VSI
} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_VSI_SPREAD_SAMPLES_H
