// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Angular_weight.h
/// \brief The angular edge weight of the dual graph (thesis 3.3).
#ifndef SPECTRALSEG_METRICS_ANGULAR_WEIGHT_H
#define SPECTRALSEG_METRICS_ANGULAR_WEIGHT_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/exceptions.h>

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Metrics {

/// \ingroup PkgSpectralSegMetrics
/// \brief Angular distance, which makes concave creases expensive to cross:
/// a dual edge across a concave fold weighs \f$\arccos(n_i\cdot n_j)/\pi\f$
/// (in \f$[0, 1]\f$), one across a convex or flat fold weighs a small
/// \f$\epsilon\f$ (default 0.001, as in the thesis).
///
/// Concavity is judged with the face normals, so the mesh must be oriented
/// outward (the command-line tool orients closed meshes itself).
///
/// \cgalModels `DualEdgeWeight`
class Angular_weight
{
public:
  /// \param convex_weight the weight \f$\epsilon\f$ of convex and flat folds (non-negative)
  explicit Angular_weight(double convex_weight = 0.001) : epsilon_(convex_weight)
  {
    if(!(convex_weight >= 0) || !std::isfinite(convex_weight))
      throw Invalid_input("Angular_weight: the convex-fold weight must be finite and non-negative");
  }

  /// the weight given to convex and flat folds
  double convex_weight() const { return epsilon_; }

  /// the name used by the command-line tool and in reports
  std::string name() const { return "angular"; }

  /// the weight of one dual edge
  double weight(const Dual_graph::Edge& e) const
  {
    return e.concave ? e.normal_angle / boost::math::constants::pi<double>() : epsilon_;
  }

  /// one weight per dual edge of `graph`
  std::vector<double> operator()(const Dual_graph& graph, const Execution& = Execution()) const
  {
    std::vector<double> w(graph.number_of_edges());
    for(Dual_graph::size_type e = 0; e < graph.number_of_edges(); ++e)
      w[e] = weight(graph.edge(e));
    return w;
  }

private:
  double epsilon_;
};

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_ANGULAR_WEIGHT_H
