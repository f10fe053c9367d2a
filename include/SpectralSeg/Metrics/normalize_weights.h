// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file normalize_weights.h
/// \brief Validation and linear normalisation of dual-edge weights.
#ifndef SPECTRALSEG_METRICS_NORMALIZE_WEIGHTS_H
#define SPECTRALSEG_METRICS_NORMALIZE_WEIGHTS_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Metrics {

/// \ingroup PkgSpectralSegMetrics
/// \brief Throws `Invalid_input` unless `weights` holds one finite,
/// non-negative value per dual edge of `graph`. `who` names the metric in
/// the message.
SPECTRALSEG_INLINE void check_weights(const Dual_graph& graph, const std::vector<double>& weights,
                                      const std::string& who = "metric")
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(weights.size() != graph.number_of_edges())
    throw Invalid_input(who + ": " + std::to_string(weights.size()) + " weights for " +
                        std::to_string(graph.number_of_edges()) + " dual edges");
  for(std::size_t e = 0; e < weights.size(); ++e)
    if(!(weights[e] >= 0) || !std::isfinite(weights[e]))
      throw Invalid_input(who + ": weight of dual edge " + std::to_string(e) +
                          " is negative or not finite (" + std::to_string(weights[e]) + ")");
}
#else
;
#endif

/// \ingroup PkgSpectralSegMetrics
/// \brief How a blend brings each component's weights into \f$[0, 1]\f$.
///
/// - `maximum()`: divide by the largest weight (the thesis, 3.5);
/// - `quantile(q)`: divide by the `q`-quantile of the weights and clamp at 1,
///   so that a few extreme edges (thin shells such as ears, where reference
///   points of adjacent faces land on different sides) do not squeeze all
///   other weights towards 0. The part-aware metric uses `quantile(0.99)`.
struct Normalization
{
  /// the quantile in (0, 1]; 1 means the maximum
  double quantile_level = 1.;

  /// divide by the maximum
  static Normalization maximum() { return Normalization{1.}; }
  /// divide by the `q`-quantile, clamp at 1
  static Normalization quantile(double q)
  {
    if(!(q > 0. && q <= 1.))
      throw Invalid_input("Normalization::quantile: the level must be in (0, 1]");
    return Normalization{q};
  }
};

/// \ingroup PkgSpectralSegMetrics
/// \brief Scales non-negative weights linearly into \f$[0, 1]\f$ by dividing
/// them by their maximum (all-zero weights stay zero).
///
/// This is the normalisation the blend applies to each component before
/// mixing (thesis 3.5). Dividing by the maximum keeps zero at zero, so a
/// weight never becomes zero because it is the smallest one.
SPECTRALSEG_INLINE void normalize_weights(std::vector<double>& weights)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const double m = weights.empty() ? 0. : *std::max_element(weights.begin(), weights.end());
  if(m > 0)
    for(double& w : weights)
      w /= m;
}
#else
;
#endif

/// \ingroup PkgSpectralSegMetrics
/// \brief Scales non-negative weights into \f$[0, 1]\f$ as `normalization`
/// says. A zero quantile falls back to the maximum.
SPECTRALSEG_INLINE void normalize_weights(std::vector<double>& weights, const Normalization& normalization)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(weights.empty())
    return;
  if(normalization.quantile_level >= 1.)
  {
    normalize_weights(weights);
    return;
  }
  std::vector<double> sorted = weights;
  const std::size_t i = std::min(sorted.size() - 1,
                                 static_cast<std::size_t>(normalization.quantile_level * double(sorted.size())));
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(i), sorted.end());
  const double scale = sorted[i];
  if(!(scale > 0))
  {
    normalize_weights(weights);
    return;
  }
  for(double& w : weights)
    w = std::min(1., w / scale);
}
#else
;
#endif

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_NORMALIZE_WEIGHTS_H
