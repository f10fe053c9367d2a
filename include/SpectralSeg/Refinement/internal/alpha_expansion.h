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
//
// Only the candidates of the move are variables of its max-flow problem: a
// vertex for which alpha costs more than its current label plus all its
// edge weights (`around`) cannot take alpha in an optimal move (keeping its
// label would be cheaper whatever its neighbours do), so it keeps its label
// and enters its neighbours' terms as a constant. Returns false when no
// vertex can take alpha.
template <typename MaxFlow>
bool best_expansion(const Potts_problem& p, const std::vector<double>& around, std::vector<std::size_t>& l,
                    std::size_t alpha)
{
  typedef typename MaxFlow::Vertex_descriptor Vertex;
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> candidate(p.vertices, none);
  std::vector<std::size_t> vertex_of;
  for(std::size_t v = 0; v < p.vertices; ++v)
    if(l[v] != alpha && p.cost[v * p.labels + alpha] - p.cost[v * p.labels + l[v]] <= around[v])
    {
      candidate[v] = vertex_of.size();
      vertex_of.push_back(v);
    }
  if(vertex_of.empty())
    return false;
  // t-weights: cost of taking alpha, cost of keeping the label
  std::vector<double> take(vertex_of.size()), keep(vertex_of.size());
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
  {
    take[i] = p.cost[vertex_of[i] * p.labels + alpha];
    keep[i] = p.cost[vertex_of[i] * p.labels + l[vertex_of[i]]];
  }
  for(std::size_t e = 0; e < p.edges.size(); ++e)
  {
    const std::size_t a = p.edges[e].first, b = p.edges[e].second;
    if((candidate[a] == none) == (candidate[b] == none))
      continue;
    const std::size_t c = candidate[a] != none ? a : b, fixed = candidate[a] != none ? b : a;
    if(l[fixed] != alpha)
      take[candidate[c]] += p.weights[e];
    if(l[fixed] != l[c])
      keep[candidate[c]] += p.weights[e];
  }

  MaxFlow flow;
  flow.clear_graph();
  std::vector<Vertex> vertex(vertex_of.size());
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
  {
    vertex[i] = flow.add_vertex();
    flow.add_tweight(vertex[i], take[i], keep[i]);
  }
  for(std::size_t e = 0; e < p.edges.size(); ++e)
  {
    const std::size_t a = candidate[p.edges[e].first], b = candidate[p.edges[e].second];
    if(a == none || b == none)
      continue;
    const double w = p.weights[e];
    if(l[vertex_of[a]] == l[vertex_of[b]])
      flow.add_edge(vertex[a], vertex[b], w, w);
    else
    {
      Vertex between = flow.add_vertex();
      flow.add_edge(between, vertex[a], w, w);
      flow.add_edge(between, vertex[b], w, w);
      flow.add_tweight(between, 0., w);
    }
  }
  flow.init_vertices();
  flow.max_flow();
  std::vector<std::size_t> moved(vertex_of.size(), none);
  auto map = boost::make_iterator_property_map(moved.begin(), boost::typed_identity_property_map<std::size_t>());
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
    flow.update(map, vertex, i, i, alpha);
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
    if(moved[i] == alpha)
      l[vertex_of[i]] = alpha;
  return true;
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
  std::vector<double> around(p.vertices, 0.);
  for(std::size_t e = 0; e < p.edges.size(); ++e)
  {
    around[p.edges[e].first] += p.weights[e];
    around[p.edges[e].second] += p.weights[e];
  }
  bool improved = true;
  while(improved)
  {
    improved = false;
    for(std::size_t alpha = 0; alpha < p.labels; ++alpha)
    {
      std::vector<std::size_t> next = l;
      if(!best_expansion<MaxFlow>(p, around, next, alpha))
        continue;
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
