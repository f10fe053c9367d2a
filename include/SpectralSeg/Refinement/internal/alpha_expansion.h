// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file alpha_expansion.h
/// \brief Alpha-expansion moves over a labelling problem with a Potts
/// smoothness term, on one of CGAL's max-flow implementations.
#ifndef SPECTRALSEG_REFINEMENT_INTERNAL_ALPHA_EXPANSION_H
#define SPECTRALSEG_REFINEMENT_INTERNAL_ALPHA_EXPANSION_H

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Refinement {
/// \cond SKIP_IN_MANUAL
namespace internal {

// A labelling problem: minimise sum_v cost[v * labels + l_v] +
// sum_{(u,v)} w_uv [l_u != l_v].
struct Potts_problem
{
  std::size_t vertices = 0;
  std::size_t labels = 0;
  std::vector<double> cost; // vertices x labels, row-major
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<double> weights;

  double energy(const std::vector<std::size_t>& l) const
  {
    double e = 0.;
    for(std::size_t v = 0; v < vertices; ++v)
      e += cost[v * labels + l[v]];
    for(std::size_t i = 0; i < edges.size(); ++i)
      if(l[edges[i].first] != l[edges[i].second])
        e += weights[i];
    return e;
  }
};

// The best alpha-expansion of `l` (Boykov, Veksler and Zabih 2001), with the
// graph construction of CGAL's alpha_expansion_graphcut(); `MaxFlow` is one
// of CGAL's Alpha_expansion_*_impl classes. A new max-flow object is built
// for every move (CGAL 5.5's MaxFlow graph keeps the previous flow after
// clear_graph(), which stops its driver after the first move).
template <typename MaxFlow>
std::vector<std::size_t> best_expansion(const Potts_problem& p, const std::vector<std::size_t>& l, std::size_t alpha)
{
  typedef typename MaxFlow::Vertex_descriptor Vertex;
  // A capacity no minimum cut can afford, kept finite: Boost's max-flow
  // codes overflow on DBL_MAX.
  double never = 1.;
  for(double c : p.cost)
    never += c;
  for(double w : p.weights)
    never += w;
  never *= 2.;
  MaxFlow flow;
  flow.clear_graph();
  std::vector<Vertex> vertex(p.vertices);
  for(std::size_t v = 0; v < p.vertices; ++v)
  {
    vertex[v] = flow.add_vertex();
    // vertices already labelled alpha stay so
    const double keep = l[v] == alpha ? never : p.cost[v * p.labels + l[v]];
    flow.add_tweight(vertex[v], p.cost[v * p.labels + alpha], keep);
  }
  for(std::size_t i = 0; i < p.edges.size(); ++i)
  {
    const std::size_t a = p.edges[i].first, b = p.edges[i].second;
    const double w = p.weights[i];
    if(l[a] == l[b])
    {
      if(l[a] != alpha)
        flow.add_edge(vertex[a], vertex[b], w, w);
    }
    else
    {
      Vertex between = flow.add_vertex();
      const double wa = l[a] == alpha ? 0. : w;
      const double wb = l[b] == alpha ? 0. : w;
      flow.add_edge(between, vertex[a], wa, wa);
      flow.add_edge(between, vertex[b], wb, wb);
      flow.add_tweight(between, 0., w);
    }
  }
  flow.init_vertices();
  flow.max_flow();
  std::vector<std::size_t> next = l;
  auto map = boost::make_iterator_property_map(next.begin(), boost::typed_identity_property_map<std::size_t>());
  for(std::size_t v = 0; v < p.vertices; ++v)
    flow.update(map, vertex, v, v, alpha);
  return next;
}

// Expansion moves over every label, sweep after sweep, each kept only when
// it lowers the energy (evaluated exactly, not read off the flow), until a
// whole sweep changes nothing. Deterministic. Returns the final energy.
template <typename MaxFlow>
double alpha_expansion(const Potts_problem& p, std::vector<std::size_t>& l)
{
  double energy = p.energy(l);
  if(p.vertices == 0 || p.labels < 2)
    return energy;
  const double tolerance = 1e-12;
  bool improved = true;
  while(improved)
  {
    improved = false;
    for(std::size_t alpha = 0; alpha < p.labels; ++alpha)
    {
      std::vector<std::size_t> next = best_expansion<MaxFlow>(p, l, alpha);
      const double e = p.energy(next);
      if(e < energy - tolerance * std::abs(energy))
      {
        energy = e;
        l.swap(next);
        improved = true;
      }
    }
  }
  return energy;
}

} // namespace internal
/// \endcond
} // namespace Refinement
} // namespace SpectralSeg

#endif // SPECTRALSEG_REFINEMENT_INTERNAL_ALPHA_EXPANSION_H
