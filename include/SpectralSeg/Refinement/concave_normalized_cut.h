// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file concave_normalized_cut.h
/// \brief The normalized cut of a segmentation on the dual graph weighted by
/// concavity: how well its boundaries follow concave creases.
#ifndef SPECTRALSEG_REFINEMENT_CONCAVE_NORMALIZED_CUT_H
#define SPECTRALSEG_REFINEMENT_CONCAVE_NORMALIZED_CUT_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Refinement {

/// \ingroup PkgSpectralSegRefinement
/// \brief The normalized cut of a segmentation on the dual graph whose edges
/// weigh \f$w_e = \ell_e \exp(-\theta_e / s)\f$: \f$\ell_e\f$ the length of
/// the mesh edge, \f$\theta_e\f$ its dihedral angle where the fold is
/// concave (0 where it is flat or convex), \f$s\f$ `angle_scale`.
///
/// The value is \f$\sum_c \mathrm{cut}(c) / \mathrm{vol}(c)\f$ over the
/// segments \f$c\f$, with \f$\mathrm{cut}(c)\f$ the weight of the edges
/// between \f$c\f$ and the other segments and \f$\mathrm{vol}(c)\f$ the
/// weight of the edges of \f$c\f$'s faces (an edge inside \f$c\f$ counted
/// twice). Lower is better: a boundary along a concave crease costs little
/// (the minima rule), a boundary through a smooth or convex stretch costs its
/// length, and each segment's cost is relative to its size, so neither
/// slivers nor long seams are cheap. `segment_k_way()` uses it to choose
/// between over-segmentations with different numbers of extra clusters
/// (`K_way_options::alternative_extra_clusters`); segmentations with the same number
/// of segments compare directly.
///
/// \param graph the dual graph
/// \param labels one label per face (any integers)
/// \param angle_scale \f$s\f$, in radians; positive
/// \throws Invalid_input if `labels` does not have one entry per face or
///         `angle_scale` is not a positive number
SPECTRALSEG_INLINE double concave_normalized_cut(const Dual_graph& graph, const std::vector<int>& labels,
                                                 double angle_scale)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(labels.size() != graph.number_of_faces())
    throw Invalid_input("concave_normalized_cut: expected " + std::to_string(graph.number_of_faces()) +
                        " labels, got " + std::to_string(labels.size()));
  if(!(angle_scale > 0.) || !std::isfinite(angle_scale))
    throw Invalid_input("concave_normalized_cut: the angle scale must be a positive number");
  // segments numbered in the order of their first face: labels in
  // [0, number of faces) through a table, any others through a map
  std::vector<std::size_t> segment_of(labels.size());
  std::size_t segments = 0;
  const bool small = std::all_of(labels.begin(), labels.end(),
                                 [&](int l) { return l >= 0 && std::size_t(l) < labels.size(); });
  if(small)
  {
    const std::size_t none = std::size_t(-1);
    std::vector<std::size_t> dense(labels.empty() ? 0 : std::size_t(*std::max_element(labels.begin(), labels.end())) + 1,
                                   none);
    for(std::size_t f = 0; f < labels.size(); ++f)
    {
      std::size_t& d = dense[std::size_t(labels[f])];
      if(d == none)
        d = segments++;
      segment_of[f] = d;
    }
  }
  else
  {
    std::map<int, std::size_t> dense;
    for(std::size_t f = 0; f < labels.size(); ++f)
      segment_of[f] = dense.try_emplace(labels[f], dense.size()).first->second;
    segments = dense.size();
  }
  std::vector<double> cut(segments, 0.), vol(segments, 0.);
  for(std::size_t d = 0; d < graph.number_of_edges(); ++d) // in edge order: thread-independent
  {
    const Dual_graph::Edge& e = graph.edge(static_cast<Dual_graph::size_type>(d));
    const double w = e.length * std::exp(-(e.concave ? e.normal_angle : 0.) / angle_scale);
    const std::size_t a = segment_of[e.face[0]], b = segment_of[e.face[1]];
    vol[a] += w;
    vol[b] += w;
    if(a != b)
    {
      cut[a] += w;
      cut[b] += w;
    }
  }
  double value = 0.;
  for(std::size_t c = 0; c < cut.size(); ++c)
    if(vol[c] > 0.)
      value += cut[c] / vol[c];
  return value;
}
#else
;
#endif

} // namespace Refinement
} // namespace SpectralSeg

#endif // SPECTRALSEG_REFINEMENT_CONCAVE_NORMALIZED_CUT_H
