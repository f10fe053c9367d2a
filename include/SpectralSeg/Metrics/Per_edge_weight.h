// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Per_edge_weight.h
/// \brief A user-defined metric from a function of one dual edge.
#ifndef SPECTRALSEG_METRICS_PER_EDGE_WEIGHT_H
#define SPECTRALSEG_METRICS_PER_EDGE_WEIGHT_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/internal/parallel_for.h>

#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Metrics {

/// \ingroup PkgSpectralSegMetrics
/// \brief Turns a function of one dual edge into a metric policy, the
/// shortest way to plug a user-defined metric into the library.
///
/// \tparam EdgeFunction a thread-safe callable
///   `double(const Dual_graph& graph, const Dual_graph::Edge& edge)` returning
///   a finite, non-negative weight
///
/// \cgalModels `DualEdgeWeight`
template <typename EdgeFunction>
class Per_edge_weight
{
public:
  /// \param fn the weight of one edge
  /// \param name the metric's name in reports
  explicit Per_edge_weight(EdgeFunction fn, std::string name = "user")
    : fn_(std::move(fn)), name_(std::move(name))
  {}

  /// the metric's name
  std::string name() const { return name_; }

  /// one weight per dual edge, computed in parallel
  std::vector<double> operator()(const Dual_graph& graph, const Execution& exec = Execution()) const
  {
    std::vector<double> w(graph.number_of_edges());
    ::SpectralSeg::internal::parallel_for(w.size(), exec, name_ + " weights",
                           [&](std::size_t e) { w[e] = fn_(graph, graph.edge(static_cast<Dual_graph::size_type>(e))); });
    return w;
  }

private:
  EdgeFunction fn_;
  std::string name_;
};

/// \ingroup PkgSpectralSegMetrics
/// \brief Builds a `Per_edge_weight`.
template <typename EdgeFunction>
Per_edge_weight<EdgeFunction> make_per_edge_weight(EdgeFunction fn, std::string name = "user")
{
  return Per_edge_weight<EdgeFunction>(std::move(fn), std::move(name));
}

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_PER_EDGE_WEIGHT_H
