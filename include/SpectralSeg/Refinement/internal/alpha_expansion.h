// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file alpha_expansion.h
/// \brief Alpha-expansion moves over a labelling problem with a Potts
/// smoothness term, on one of CGAL's max-flow implementations.
#ifndef SPECTRALSEG_REFINEMENT_INTERNAL_ALPHA_EXPANSION_H
#define SPECTRALSEG_REFINEMENT_INTERNAL_ALPHA_EXPANSION_H

#include <boost/property_map/property_map.hpp>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <future>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Refinement {
/// \cond SKIP_IN_MANUAL
namespace internal {

// A labelling problem: minimise sum_v cost(v, l_v) +
// sum_{(u,v)} w_uv [l_u != l_v]. Only the finite data terms are stored, in
// compressed rows: most vertices of a graph cut in a band can take two or
// three of the labels, and a dense vertices x labels table is the largest
// array of the problem on a large mesh.
struct Potts_problem
{
  std::size_t vertices = 0;
  std::size_t labels = 0;
  // vertex v may take the labels label[first[v]], ..., label[first[v + 1] - 1]
  // (ascending) at the costs beside them; every other label is out of reach
  std::vector<std::size_t> first{0};
  std::vector<std::uint32_t> label;
  std::vector<double> cost;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<double> weights;

  // Appends a vertex with its cost for each label (infinite: out of reach).
  void add_vertex(const std::vector<double>& costs)
  {
    for(std::size_t c = 0; c < costs.size(); ++c)
      if(std::isfinite(costs[c]))
      {
        label.push_back(std::uint32_t(c));
        cost.push_back(costs[c]);
      }
    first.push_back(label.size());
    ++vertices;
  }

  double cost_of(std::size_t v, std::size_t c) const
  {
    for(std::size_t i = first[v]; i < first[v + 1]; ++i)
      if(label[i] == c)
        return cost[i];
    return std::numeric_limits<double>::infinity();
  }

  double energy(const std::vector<std::size_t>& l) const
  {
    double e = 0.;
    for(std::size_t v = 0; v < vertices; ++v)
      e += cost_of(v, l[v]);
    for(std::size_t i = 0; i < edges.size(); ++i)
      if(l[edges[i].first] != l[edges[i].second])
        e += weights[i];
    return e;
  }
};

// The vertices' edges in compressed rows, and for each label the vertices
// for which it has a finite cost (a label with an infinite cost is out of a
// vertex's reach), built once for all the moves.
struct Potts_adjacency
{
  std::vector<std::size_t> offset;                      // vertices + 1
  std::vector<std::pair<std::size_t, double>> neighbour; // (vertex, weight)
  std::vector<double> around;                           // sum of a vertex's edge weights
  std::vector<std::vector<std::size_t>> able;           // per label

  explicit Potts_adjacency(const Potts_problem& p)
    : offset(p.vertices + 1, 0), neighbour(2 * p.edges.size()), around(p.vertices, 0.), able(p.labels)
  {
    for(const auto& e : p.edges)
    {
      ++offset[e.first + 1];
      ++offset[e.second + 1];
    }
    for(std::size_t v = 0; v < p.vertices; ++v)
      offset[v + 1] += offset[v];
    std::vector<std::size_t> next(offset.begin(), offset.end() - 1);
    for(std::size_t i = 0; i < p.edges.size(); ++i)
    {
      const std::size_t a = p.edges[i].first, b = p.edges[i].second;
      neighbour[next[a]++] = std::make_pair(b, p.weights[i]);
      neighbour[next[b]++] = std::make_pair(a, p.weights[i]);
      around[a] += p.weights[i];
      around[b] += p.weights[i];
    }
    std::vector<std::size_t> count(p.labels, 0);
    for(std::uint32_t c : p.label)
      ++count[c];
    for(std::size_t c = 0; c < p.labels; ++c)
      able[c].reserve(count[c]);
    for(std::size_t v = 0; v < p.vertices; ++v)
      for(std::size_t i = p.first[v]; i < p.first[v + 1]; ++i)
        able[p.label[i]].push_back(v);
  }
};

// Whether a max-flow class can serve move after move: it has reserve(),
// which empties its graph and makes room for the next one's vertices and
// edges. The others are made again for every move.
template <typename MaxFlow, typename = void>
struct Reusable_max_flow : std::false_type
{};
template <typename MaxFlow>
struct Reusable_max_flow<MaxFlow, std::void_t<decltype(std::declval<MaxFlow&>().reserve(std::size_t(), std::size_t()))>>
  : std::true_type
{};

// The best alpha-expansion of `l` (Boykov, Veksler and Zabih 2001), with the
// graph construction of CGAL's alpha_expansion_graphcut(); `MaxFlow` is one
// of CGAL's Alpha_expansion_*_impl classes or Maxflow_impl (maxflow.h). A
// max-flow object without reserve() is built anew for every move (CGAL 5.5's
// MaxFlow graph keeps the previous flow after clear_graph(), which stops its
// driver after the first move).
//
// Only the candidates of the move are variables of its max-flow problem: a
// vertex for which alpha costs more than its current label plus all its
// edge weights cannot take alpha in an optimal move (keeping its label
// would be cheaper whatever its neighbours do), so it keeps its label and
// enters its neighbours' terms as a constant; so does a vertex for which
// alpha is out of reach (infinite cost). The work of a move is therefore
// proportional to its candidates and their edges, not to the problem.
// Returns the vertices that took alpha (`l` unchanged) and, in `delta`,
// the change of energy if they do. `flow_object` is the calling thread's
// max-flow object: kept from move to move when Reusable_max_flow, else made
// anew.
template <typename MaxFlow>
std::vector<std::size_t> best_expansion(const Potts_problem& p, const Potts_adjacency& adjacency,
                                        const std::vector<std::size_t>& l, std::size_t alpha,
                                        std::vector<std::size_t>& candidate, double& delta,
                                        std::unique_ptr<MaxFlow>& flow_object)
{
  typedef typename MaxFlow::Vertex_descriptor Vertex;
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> vertex_of;
  for(const std::size_t v : adjacency.able[alpha])
    if(l[v] != alpha && p.cost_of(v, alpha) - p.cost_of(v, l[v]) <= adjacency.around[v])
    {
      candidate[v] = vertex_of.size();
      vertex_of.push_back(v);
    }
  delta = 0.;
  if(vertex_of.empty())
    return {};
  // t-weights: cost of taking alpha, cost of keeping the label, with the
  // edges to the vertices that are not candidates as constants
  // (and the size of the max-flow graph: an edge between two candidates of
  // different labels takes a vertex and two edges, of the same label one)
  std::vector<double> take(vertex_of.size()), keep(vertex_of.size());
  std::size_t graph_vertices = vertex_of.size(), graph_edges = 0;
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
  {
    const std::size_t v = vertex_of[i];
    take[i] = p.cost_of(v, alpha);
    keep[i] = p.cost_of(v, l[v]);
    for(std::size_t j = adjacency.offset[v]; j < adjacency.offset[v + 1]; ++j)
    {
      const std::size_t u = adjacency.neighbour[j].first;
      if(candidate[u] != none)
      {
        if(candidate[u] > i)
        {
          const bool between = l[u] != l[v];
          graph_vertices += between;
          graph_edges += 1 + between;
        }
        continue;
      }
      if(l[u] != alpha)
        take[i] += adjacency.neighbour[j].second;
      if(l[u] != l[v])
        keep[i] += adjacency.neighbour[j].second;
    }
  }

  if constexpr(Reusable_max_flow<MaxFlow>::value)
  {
    if(!flow_object)
      flow_object = std::make_unique<MaxFlow>();
    flow_object->reserve(graph_vertices, graph_edges);
  }
  else
  {
    flow_object = std::make_unique<MaxFlow>();
    flow_object->clear_graph();
  }
  MaxFlow& flow = *flow_object;
  std::vector<Vertex> vertex(vertex_of.size());
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
  {
    vertex[i] = flow.add_vertex();
    flow.add_tweight(vertex[i], take[i], keep[i]);
  }
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
  {
    const std::size_t v = vertex_of[i];
    for(std::size_t j = adjacency.offset[v]; j < adjacency.offset[v + 1]; ++j)
    {
      const std::size_t u = adjacency.neighbour[j].first, b = candidate[u];
      if(b == none || b < i) // each edge between candidates once
        continue;
      const double w = adjacency.neighbour[j].second;
      if(l[v] == l[u])
        flow.add_edge(vertex[i], vertex[b], w, w);
      else
      {
        Vertex between = flow.add_vertex();
        flow.add_edge(between, vertex[i], w, w);
        flow.add_edge(between, vertex[b], w, w);
        flow.add_tweight(between, 0., w);
      }
    }
  }
  flow.init_vertices();
  flow.max_flow();
  std::vector<std::size_t> moved(vertex_of.size(), none);
  auto map = boost::make_iterator_property_map(moved.begin(), boost::typed_identity_property_map<std::size_t>());
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
    flow.update(map, vertex, i, i, alpha);

  // the vertices that take alpha, and the exact change of energy: their
  // data terms and the edges around them (an edge between two of them once)
  std::vector<std::size_t> taken;
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
    if(moved[i] == alpha)
      taken.push_back(vertex_of[i]);
  for(const std::size_t v : vertex_of)
    candidate[v] = none;
  for(const std::size_t v : taken)
    candidate[v] = 0; // marks the vertices that move
  for(const std::size_t v : taken)
  {
    delta += p.cost_of(v, alpha) - p.cost_of(v, l[v]);
    for(std::size_t j = adjacency.offset[v]; j < adjacency.offset[v + 1]; ++j)
    {
      const std::size_t u = adjacency.neighbour[j].first;
      const double w = adjacency.neighbour[j].second;
      const bool u_moves = candidate[u] != none;
      if(u_moves && u < v)
        continue;
      const std::size_t u_after = u_moves ? alpha : l[u];
      delta += (u_after != alpha ? w : 0.) - (l[u] != l[v] ? w : 0.);
    }
  }
  for(const std::size_t v : taken)
    candidate[v] = none;
  return taken;
}

// Expansion moves over every label, sweep after sweep, each kept only when
// it lowers the energy, until a whole sweep changes nothing. The change of
// energy of a move is evaluated exactly over the vertices it moves, not
// read off the flow. A label's move is run again only when a vertex that
// may take it, or a neighbour of one, changed label since its last run:
// otherwise its max-flow problem, and so its answer, would be the same.
//
// With `threads` > 1, the move of the next label due is computed on another
// thread beside the current one, from a copy of the same labelling. A move
// reads the labels of the vertices that may take its label and of their
// neighbours only, so when the current move changes none of those, the
// next one's answer is the one it would have computed after it, and it is
// kept; otherwise it is computed again in its turn, without waiting for
// the stale one to end (no move starts beside until it has). The moves,
// their order and the result are those of one thread, bit for bit. Deterministic. With
// `sweeps` > 0, at most that many sweeps run (0: until one changes
// nothing). Returns the final energy.
template <typename MaxFlow>
double alpha_expansion(const Potts_problem& p, std::vector<std::size_t>& l, unsigned threads = 1,
                       std::size_t sweeps = 0)
{
  double energy = p.energy(l);
  if(p.vertices == 0 || p.labels < 2)
    return energy;
  const std::size_t none = std::size_t(-1);
  const double tolerance = 1e-12;
  const Potts_adjacency adjacency(p);
  std::vector<std::size_t> candidate(p.vertices, none), other_candidate;
  std::unique_ptr<MaxFlow> flow, other_flow; // one per thread
  const bool pairs = threads > 1 && p.labels > 2;
  if(pairs)
    other_candidate.assign(p.vertices, none);
  std::vector<char> dirty(p.labels, 1);
  const auto touch = [&](std::size_t v) {
    for(std::size_t i = p.first[v]; i < p.first[v + 1]; ++i)
      dirty[p.label[i]] = 1;
  };
  const auto may_take = [&](std::size_t v, std::size_t c) {
    for(std::size_t i = p.first[v]; i < p.first[v + 1]; ++i)
      if(p.label[i] == c)
        return true;
    return false;
  };
  // whether the move of label c reads the label of a vertex of `moved`
  const auto reads = [&](std::size_t c, const std::vector<std::size_t>& moved) {
    for(const std::size_t v : moved)
    {
      if(may_take(v, c))
        return true;
      for(std::size_t j = adjacency.offset[v]; j < adjacency.offset[v + 1]; ++j)
        if(may_take(adjacency.neighbour[j].first, c))
          return true;
    }
    return false;
  };
  // keeps the move of alpha when it lowers the energy; whether it did
  const auto apply = [&](std::size_t alpha, const std::vector<std::size_t>& taken, double delta) {
    if(taken.empty() || !(delta < -tolerance * std::abs(energy)))
      return false;
    energy += delta;
    for(const std::size_t v : taken)
      l[v] = alpha;
    // the moves of the other labels near the vertices that moved must be
    // run again; alpha's own cannot improve on itself
    for(const std::size_t v : taken)
    {
      touch(v);
      for(std::size_t j = adjacency.offset[v]; j < adjacency.offset[v + 1]; ++j)
        touch(adjacency.neighbour[j].first);
    }
    dirty[alpha] = 0; // touch() marked it too
    return true;
  };
  // The move computed beside, on a copy of the labels as they were when it
  // started: when the current move makes it stale, this thread goes on
  // without waiting for it, and no other starts until it has ended (it uses
  // the other thread's scratch). Declared last: destroyed (waited for)
  // first.
  double beta_delta = 0.;
  std::future<std::vector<std::size_t>> beside;
  const auto beside_free = [&] {
    if(!beside.valid())
      return true;
    if(beside.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
      return false;
    beside.get(); // a stale move's answer (or its exception) goes
    return true;
  };
  bool improved = true;
  for(std::size_t sweep = 0; improved && (sweeps == 0 || sweep < sweeps); ++sweep)
  {
    improved = false;
    for(std::size_t alpha = 0; alpha < p.labels;)
    {
      if(!dirty[alpha])
      {
        ++alpha;
        continue;
      }
      dirty[alpha] = 0;
      std::size_t beta = alpha + 1;
      while(beta < p.labels && !dirty[beta])
        ++beta;
      double delta = 0.;
      if(!pairs || beta == p.labels || !beside_free())
      {
        const std::vector<std::size_t> taken = best_expansion<MaxFlow>(p, adjacency, l, alpha, candidate, delta, flow);
        improved |= apply(alpha, taken, delta);
        ++alpha;
        continue;
      }
      beside = std::async(std::launch::async, [&, beta, labels = l]() {
        return best_expansion<MaxFlow>(p, adjacency, labels, beta, other_candidate, beta_delta, other_flow);
      });
      const std::vector<std::size_t> taken = best_expansion<MaxFlow>(p, adjacency, l, alpha, candidate, delta, flow);
      const bool moved = apply(alpha, taken, delta);
      improved |= moved;
      // beta is next when no label between became due, and its answer
      // stands when alpha's move changed nothing it reads
      std::size_t next = alpha + 1;
      while(next < beta && !dirty[next])
        ++next;
      if(next == beta && !(moved && reads(beta, taken)))
      {
        const std::vector<std::size_t> beta_taken = beside.get();
        dirty[beta] = 0;
        improved |= apply(beta, beta_taken, beta_delta);
        alpha = beta + 1;
      }
      else
        alpha = next;
    }
  }
  if(beside.valid())
    beside.wait(); // before the scratch it uses goes
  return energy;
}

} // namespace internal
/// \endcond
} // namespace Refinement
} // namespace SpectralSeg

#endif // SPECTRALSEG_REFINEMENT_INTERNAL_ALPHA_EXPANSION_H
