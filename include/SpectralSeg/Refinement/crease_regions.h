// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file crease_regions.h
/// \brief The regions of a mesh enclosed by closed loops of sharp concave
/// creases, and the split of a segmentation along them.
#ifndef SPECTRALSEG_REFINEMENT_CREASE_REGIONS_H
#define SPECTRALSEG_REFINEMENT_CREASE_REGIONS_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Refinement {

/// \ingroup PkgSpectralSegRefinement
/// \brief Labels the faces by the regions that closed loops of sharp
/// concave creases enclose; returns the number of regions.
///
/// Two faces are in the same region when a path of adjacent faces joins them
/// without crossing a concave edge whose dihedral angle (the angle between
/// the face normals, `Dual_graph::Edge::normal_angle`) is at least
/// `min_angle_degrees`; contact edges (`Dual_graph::Edge::contact`) and
/// flat or convex edges never separate. A region is therefore bounded by
/// concave creases all around: a shaft entering a housing, a knob on a lid,
/// a recessed panel. On smooth shapes sharp concave edges seldom close a
/// loop, so the whole surface is one region (and each connected component
/// of the graph one region). Deterministic; regions are numbered by their
/// smallest face.
///
/// \param graph the dual graph
/// \param min_angle_degrees the crease angle in degrees; 0 or less, or 180
///        or more, gives one region per connected component
/// \param region one region number per face (output)
/// \throws Invalid_input if `min_angle_degrees` is not a number
SPECTRALSEG_INLINE std::size_t crease_regions(const Dual_graph& graph, double min_angle_degrees,
                                              std::vector<int>& region)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(std::isnan(min_angle_degrees))
    throw Invalid_input("crease_regions: the crease angle is not a number");
  const std::size_t n = graph.number_of_faces();
  const bool off = !(min_angle_degrees > 0.) || !(min_angle_degrees < 180.);
  const double angle = min_angle_degrees * boost::math::constants::pi<double>() / 180.;
  std::vector<std::size_t> parent(n);
  for(std::size_t f = 0; f < n; ++f)
    parent[f] = f;
  const auto find = [&parent](std::size_t x) {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for(const Dual_graph::Edge& e : graph.edges())
    if(off || e.contact || !e.concave || e.normal_angle < angle)
    {
      const std::size_t a = find(e.face[0]), b = find(e.face[1]);
      if(a != b)
        parent[std::max(a, b)] = std::min(a, b); // the smallest face is the root
    }
  region.assign(n, -1);
  std::vector<int> number(n, -1);
  int count = 0;
  for(std::size_t f = 0; f < n; ++f)
  {
    const std::size_t root = find(f);
    if(number[root] < 0)
      number[root] = count++;
    region[f] = number[root];
  }
  return std::size_t(count);
}
#else
;
#endif

/// \ingroup PkgSpectralSegRefinement
/// \brief Splits every segment along the crease regions it overlaps:
/// afterwards two faces share a label only when they shared a label and a
/// crease region before. Returns the number of labels, renumbered
/// `0 .. count-1` by their smallest face.
///
/// `segment_k_way()` applies it to its K-means clusters before merging
/// (`K_way_options::crease_angle`), so that a cluster straddling a closed
/// concave crease is cut along the crease, and the merge then sees the crease
/// as a strong boundary.
/// \param region one region number per face (from `crease_regions()`)
/// \param labels one label per face, in and out
/// \throws Invalid_input if the sizes differ
SPECTRALSEG_INLINE std::size_t split_along_regions(const std::vector<int>& region, std::vector<int>& labels)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(region.size() != labels.size())
    throw Invalid_input("split_along_regions: " + std::to_string(region.size()) + " regions for " +
                        std::to_string(labels.size()) + " labels");
  std::map<std::pair<int, int>, int> combined;
  for(std::size_t f = 0; f < labels.size(); ++f)
    labels[f] = combined.try_emplace(std::make_pair(labels[f], region[f]), int(combined.size())).first->second;
  return combined.size();
}
#else
;
#endif

} // namespace Refinement
} // namespace SpectralSeg

#endif // SPECTRALSEG_REFINEMENT_CREASE_REGIONS_H
