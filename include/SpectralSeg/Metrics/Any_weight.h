// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Any_weight.h
/// \brief A metric policy chosen at run time.
#ifndef SPECTRALSEG_METRICS_ANY_WEIGHT_H
#define SPECTRALSEG_METRICS_ANY_WEIGHT_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Metrics {

/// \ingroup PkgSpectralSegMetrics
/// \brief Holds any model of `DualEdgeWeight`, for metrics chosen at run time
/// (a command-line option, a configuration file). The static policies are
/// preferred in code: this wrapper costs one indirect call per metric
/// evaluation, not per edge.
///
/// \cgalModels `DualEdgeWeight`
class Any_weight
{
public:
  /// wraps `metric`
  template <typename DualEdgeWeight>
  Any_weight(DualEdgeWeight metric) // NOLINT: implicit on purpose
    : holder_(std::make_shared<Holder<DualEdgeWeight>>(std::move(metric)))
  {}

  /// the wrapped metric's name
  std::string name() const { return holder_->name(); }

  /// the wrapped metric's weights
  std::vector<double> operator()(const Dual_graph& graph, const Execution& exec = Execution()) const
  {
    return holder_->weights(graph, exec);
  }

private:
  struct Base
  {
    virtual ~Base() = default;
    virtual std::string name() const = 0;
    virtual std::vector<double> weights(const Dual_graph&, const Execution&) const = 0;
  };
  template <typename M>
  struct Holder : Base
  {
    explicit Holder(M m) : metric(std::move(m)) {}
    std::string name() const override { return metric.name(); }
    std::vector<double> weights(const Dual_graph& g, const Execution& e) const override { return metric(g, e); }
    M metric;
  };
  std::shared_ptr<const Base> holder_;
};

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_ANY_WEIGHT_H
