// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file metric_values.h
/// \brief `Metrics::Metric_values` and `Metrics::metric_values()`: a metric's
/// edge weights with the faces' thickness, where the metric measures it.
#ifndef SPECTRALSEG_METRICS_METRIC_VALUES_H
#define SPECTRALSEG_METRICS_METRIC_VALUES_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>

#include <type_traits>
#include <utility>
#include <vector>

namespace SpectralSeg {
/// \cond SKIP_IN_MANUAL
namespace internal {
// whether a metric also has the call metric(graph, exec, &face_thickness)
template <typename M, typename = void>
struct reports_thickness : std::false_type
{};
template <typename M>
struct reports_thickness<M, std::void_t<decltype(std::declval<const M&>()(
                              std::declval<const Dual_graph&>(), std::declval<const Execution&>(),
                              static_cast<std::vector<double>*>(nullptr)))>> : std::true_type
{};
} // namespace internal
/// \endcond

namespace Metrics {

/// \ingroup PkgSpectralSegMetrics
/// \brief What a metric gives for a dual graph: one weight per dual edge and,
/// when the metric measures it, the thickness of the shape at each face.
struct Metric_values
{
  /// one weight per dual edge, in the order of `Dual_graph::edges()`
  std::vector<double> weights;
  /// empty, or one value per face: the diameter of the largest ball inside
  /// the shape touching the face (`NaN` where it is not known)
  std::vector<double> face_thickness;
};

/// \ingroup PkgSpectralSegMetrics
/// \brief The weights of `metric` on `graph`, and the faces' thickness when
/// the metric measures it: a model of `DualEdgeWeight` that also has the
/// call `metric(graph, exec, &thickness)` fills `thickness` (or leaves it
/// empty) besides returning the weights; for any other model the thickness
/// is empty.
///
/// `Metrics::VSI_weight` and `Metrics::Part_aware_weight` (the default)
/// report the diameters of their reference points' inscribed balls
/// (`VSI::Reference_points::diameters`); `Metrics::Blend` and
/// `Metrics::Any_weight` pass on those of their components. The contrast
/// merge (`segment_hybrid()`) reads them from `Weighted_dual_graph::face_thickness()`.
template <typename DualEdgeWeight>
Metric_values metric_values(const DualEdgeWeight& metric, const Dual_graph& graph,
                            const Execution& exec = Execution())
{
  Metric_values v;
  if constexpr(SpectralSeg::internal::reports_thickness<DualEdgeWeight>::value)
    v.weights = metric(graph, exec, &v.face_thickness);
  else
    v.weights = metric(graph, exec);
  return v;
}

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_METRIC_VALUES_H
