// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Geodesic_weight.h
/// \brief The geodesic edge weight of the dual graph (thesis 3.2).
#ifndef SPECTRALSEG_METRICS_GEODESIC_WEIGHT_H
#define SPECTRALSEG_METRICS_GEODESIC_WEIGHT_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>

#include <string>
#include <vector>

namespace SpectralSeg {
namespace Metrics {

/// \ingroup PkgSpectralSegMetrics
/// \brief Approximate geodesic distance: the weight of a dual edge is the
/// length of the path from one face centroid to the midpoint of the shared
/// edge and on to the other centroid, \f$\|c_i - m\| + \|c_j - m\|\f$.
///
/// Shortest paths in the dual graph with this weight approximate geodesic
/// distances between faces.
///
/// \cgalModels `DualEdgeWeight`
class Geodesic_weight
{
public:
  /// the name used by the command-line tool and in reports
  std::string name() const { return "geodesic"; }

  /// one weight per dual edge of `graph`
  std::vector<double> operator()(const Dual_graph& graph, const Execution& = Execution()) const
  {
    std::vector<double> w(graph.number_of_edges());
    for(Dual_graph::size_type e = 0; e < graph.number_of_edges(); ++e)
      w[e] = graph.edge(e).geodesic_length;
    return w;
  }
};

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_GEODESIC_WEIGHT_H
