// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Any_weight.h
/// \brief A metric policy chosen at run time.
#ifndef SPECTRALSEG_METRICS_ANY_WEIGHT_H
#define SPECTRALSEG_METRICS_ANY_WEIGHT_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Metrics/metric_values.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
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
    return holder_->weights(graph, exec, nullptr);
  }

  /// the wrapped metric's weights; with `face_thickness`, the faces'
  /// thickness if the wrapped metric reports it (see `Metrics::metric_values()`)
  std::vector<double> operator()(const Dual_graph& graph, const Execution& exec,
                                 std::vector<double>* face_thickness) const
  {
    return holder_->weights(graph, exec, face_thickness);
  }

private:
  struct Base
  {
    virtual ~Base() = default;
    virtual std::string name() const = 0;
    virtual std::vector<double> weights(const Dual_graph&, const Execution&, std::vector<double>*) const = 0;
  };
  template <typename M>
  struct Holder : Base
  {
    explicit Holder(M m) : metric(std::move(m)) {}
    std::string name() const override { return metric.name(); }
    std::vector<double> weights(const Dual_graph& g, const Execution& e, std::vector<double>* t) const override
    {
      if(!t)
        return metric(g, e);
      Metric_values v = metric_values(metric, g, e);
      *t = std::move(v.face_thickness);
      return std::move(v.weights);
    }
    M metric;
  };
  std::shared_ptr<const Base> holder_;
};

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_ANY_WEIGHT_H
