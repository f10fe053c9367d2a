// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file normalize_weights.h
/// \brief Validation and linear normalisation of dual-edge weights.
#ifndef SPECTRALSEG_METRICS_NORMALIZE_WEIGHTS_H
#define SPECTRALSEG_METRICS_NORMALIZE_WEIGHTS_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/exceptions.h>

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
inline void check_weights(const Dual_graph& graph, const std::vector<double>& weights,
                          const std::string& who = "metric")
{
  if(weights.size() != graph.number_of_edges())
    throw Invalid_input(who + ": " + std::to_string(weights.size()) + " weights for " +
                        std::to_string(graph.number_of_edges()) + " dual edges");
  for(std::size_t e = 0; e < weights.size(); ++e)
    if(!(weights[e] >= 0) || !std::isfinite(weights[e]))
      throw Invalid_input(who + ": weight of dual edge " + std::to_string(e) +
                          " is negative or not finite (" + std::to_string(weights[e]) + ")");
}

/// \ingroup PkgSpectralSegMetrics
/// \brief Scales non-negative weights linearly into \f$[0, 1]\f$ by dividing
/// them by their maximum (all-zero weights stay zero).
///
/// This is the normalisation the blend applies to each component before
/// mixing (thesis 3.5). Dividing by the maximum keeps zero at zero, so a
/// weight never becomes zero because it is the smallest one.
inline void normalize_weights(std::vector<double>& weights)
{
  const double m = weights.empty() ? 0. : *std::max_element(weights.begin(), weights.end());
  if(m > 0)
    for(double& w : weights)
      w /= m;
}

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_NORMALIZE_WEIGHTS_H
