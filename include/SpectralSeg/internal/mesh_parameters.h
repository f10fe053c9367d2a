// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// What the mesh-level entry points read from their named parameters: the
// execution, the metric, the k-way options; and the weighted dual graph of
// a mesh built from them.
#ifndef SPECTRALSEG_INTERNAL_MESH_PARAMETERS_H
#define SPECTRALSEG_INTERNAL_MESH_PARAMETERS_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Metrics/metric_values.h>
#include <SpectralSeg/Metrics/normalize_weights.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/internal/execution_from.h>
#include <SpectralSeg/named_parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <vector>

namespace SpectralSeg {
namespace internal {

struct No_nearest_source_map {};

// The metric's weights, checked, with the faces' thickness where the
// metric reports it (Metrics::metric_values())
template <typename Metric>
Metrics::Metric_values metric_weights_and_thickness(const Metric& metric, const Dual_graph& graph,
                                                    const Execution& exec)
{
  exec.report(metric.name() + " weights", 0.);
  Metrics::Metric_values v = Metrics::metric_values(metric, graph, exec);
  Metrics::check_weights(graph, v.weights, metric.name());
  exec.report(metric.name() + " weights", 1.);
  return v;
}

template <typename Metric>
std::vector<double> metric_weights(const Metric& metric, const Dual_graph& graph, const Execution& exec)
{
  return metric_weights_and_thickness(metric, graph, exec).weights;
}

template <typename NamedParameters>
auto metric_from(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return choose_parameter(get_parameter(np, SpectralSeg::internal_np::metric), Metrics::Part_aware_weight<>());
}

// The execution, the dual graph of the mesh and its weights under the
// metric of the named parameters.
struct Weighted_mesh_graph
{
  template <typename TriangleMesh, typename NamedParameters>
  Weighted_mesh_graph(const TriangleMesh& tm, const NamedParameters& np)
    : exec(execution_from(np)), graph(make_dual_graph(tm, np)),
      weighted(graph, metric_weights_and_thickness(metric_from(np), graph, exec))
  {}
  Execution exec;
  Dual_graph graph;
  Weighted_dual_graph weighted;
};

} // namespace internal
} // namespace SpectralSeg

#endif // SPECTRALSEG_INTERNAL_MESH_PARAMETERS_H
