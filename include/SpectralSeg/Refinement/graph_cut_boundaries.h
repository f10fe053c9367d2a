// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file graph_cut_boundaries.h
/// \brief Boundary enhancement of a k-way segmentation by an alpha-expansion
/// graph cut (thesis 4.3.3).
#ifndef SPECTRALSEG_REFINEMENT_GRAPH_CUT_BOUNDARIES_H
#define SPECTRALSEG_REFINEMENT_GRAPH_CUT_BOUNDARIES_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Refinement/internal/alpha_expansion.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/bucket_shortest_paths.h>
#include <SpectralSeg/internal/parallel_for.h>

// The max-flow implementations: Kolmogorov's MaxFlow (the default) here;
// Boost's two, which are compiled only when asked for, in
// graph_cut_boost_backends.h (included at the end of this file when
// MaxFlow is not available, since one of them is then the default).
#ifdef SPECTRALSEG_USE_MAXFLOW
#include <SpectralSeg/Refinement/internal/maxflow.h>
#endif

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Refinement {

/// \ingroup PkgSpectralSegRefinement
/// \brief The max-flow implementation used by the alpha expansion.
///
/// The two Boost backends are compiled only in programs that include
/// `<SpectralSeg/Refinement/graph_cut_boost_backends.h>` (or that do not
/// define `SPECTRALSEG_USE_MAXFLOW`, where the Boost one on compressed
/// sparse rows is the default); `graph_cut_boundaries()` throws
/// `Invalid_input` for them otherwise. This keeps their compile time and
/// GCC's `-Wmaybe-uninitialized` false positives in Boost's
/// `boykov_kolmogorov_max_flow.hpp` out of programs that do not use them.
enum class Graph_cut_backend
{
  /// Boost's Boykov-Kolmogorov max-flow on an adjacency list (CGAL's
  /// default; needs `graph_cut_boost_backends.h`)
  boost_adjacency_list,
  /// the same on a compressed sparse row graph (faster to build; needs
  /// `graph_cut_boost_backends.h` when `SPECTRALSEG_USE_MAXFLOW` is defined)
  boost_compressed_sparse_row,
  /// Kolmogorov's MaxFlow code (GPL); available when
  /// `SPECTRALSEG_USE_MAXFLOW` is defined before including this header:
  /// version 3 (Debian's `libmaxflow-dev`, its headers) with
  /// `SPECTRALSEG_HAS_LIBMAXFLOW`, else version 2.2, shipped with CGAL's
  /// Surface_mesh_segmentation (the same cuts, slower on large meshes);
  /// fastest, and may give other (equally minimal) cuts than Boost's
  maxflow
};

/// \ingroup PkgSpectralSegRefinement
/// \brief Parameters of the graph-cut boundary enhancement: the thesis's
/// values by default, `banded()` for those of `segment_k_way()`.
struct Graph_cut_options
{
  /// weight \f$\mu\f$ of the smoothness term
  double smoothness = 0.3;
  /// strength \f$\nu\f$ of the logarithmic mapping of angular weights
  double angular_mapping = 10.;
  /// angular weight \f$\epsilon\f$ of convex folds
  double convex_weight = 0.001;
  /// divide edge lengths by the mean dual-edge length instead of the
  /// longest one (the thesis): on real meshes the longest edge is often many
  /// times the typical one, which leaves the smoothness term without effect
  bool normalize_by_mean_edge = false;
  /// leave out of the max-flow problems the faces whose data term alone
  /// decides their label: a face whose current label is cheaper than every
  /// other by more than the sum of its smoothness costs keeps it in every
  /// expansion move, so fixing it changes no move's optimum. Off: every face
  /// is a variable (slower on large meshes; for checking)
  bool fix_decided_faces = true;
  /// 0 (the thesis): every face may change label. Positive: only the faces
  /// within this many times the square root of their segment's area of the
  /// segment's boundary (geodesic distance between face centres over the
  /// dual graph), and in the half of the segment nearest that boundary,
  /// may; the others keep their label, so the cut moves boundaries locally
  /// and no segment disappears
  double band_width = 0.;
  /// the most sweeps of expansion moves (each label's move in turn, a
  /// label's move again only when labels near it changed since); 0 (the
  /// thesis): until a whole sweep lowers the energy no more
  std::size_t sweeps = 0;
  /// max-flow implementation: MaxFlow when available (the fastest), else
  /// Boost on compressed sparse rows
#ifdef SPECTRALSEG_USE_MAXFLOW
  Graph_cut_backend backend = Graph_cut_backend::maxflow;
#else
  Graph_cut_backend backend = Graph_cut_backend::boost_compressed_sparse_row;
#endif

  /// The graph cut of `segment_k_way()` by default (our addition): edge
  /// lengths over the mean edge length, \f$\mu = 10\f$, and a band of
  /// 0.4 (each face within 0.4 times the square root of its segment's area
  /// of the boundary, and in the half of the segment nearest its boundary,
  /// may change label). The smoothness term then matters: boundaries
  /// shorten and settle on concave creases, within reach of where the
  /// clustering put them, and no segment can vanish. One sweep of moves:
  /// the later ones lower the energy by a few thousandths at most and take
  /// two fifths of the time (doc/benchmarks.md).
  static Graph_cut_options banded()
  {
    Graph_cut_options o;
    o.smoothness = 10.;
    o.normalize_by_mean_edge = true;
    o.band_width = 0.4;
    o.sweeps = 1;
    return o;
  }
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// A Boost max-flow backend: runs the alpha expansion of `problem` from `l`
// on the given number of threads.
typedef void (*Boost_max_flow_backend)(const Potts_problem& problem, std::vector<std::size_t>& l, unsigned threads,
                                       std::size_t sweeps);

// The Boost backends, registered by graph_cut_boost_backends.h when a
// program includes it (null otherwise): [0] adjacency list, [1] compressed
// sparse rows. A function-local static, so that every translation unit
// sees the same table and no inline function depends on what was included.
inline Boost_max_flow_backend* boost_max_flow_backends()
{
  static Boost_max_flow_backend table[2] = {nullptr, nullptr};
  return table;
}

// The area of each segment, indexed by label.
SPECTRALSEG_INLINE std::vector<double> segment_areas(const Dual_graph& graph, const std::vector<int>& labels)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  int count = 0;
  for(int l : labels)
    count = std::max(count, l + 1);
  std::vector<double> area(std::size_t(count), 0.);
  for(std::size_t f = 0; f < labels.size(); ++f)
    area[std::size_t(labels[f])] += graph.geometry().areas[f];
  return area;
}
#else
;
#endif

// The shortest distances over the dual graph (geodesic edge lengths) from
// the faces of `sources`, whose `distance` is set to 0: a face is reached
// only from a face of its own segment and only when `admit(face,
// new_distance)` says so (admit is asked before the distance is lowered,
// maybe several times per face). By buckets of the mean edge length
// (internal::bucket_shortest_paths(), in `room`): Dijkstra's distances.
template <typename Admit>
void distances_within_segments(const Dual_graph& graph, const std::vector<int>& labels,
                               std::vector<double>& distance, const std::vector<Dual_graph::size_type>& sources,
                               double mean_length, const Admit& admit,
                               SpectralSeg::internal::Shortest_path_buckets<Dual_graph::size_type>& room)
{
  std::vector<std::pair<double, Dual_graph::size_type>> queued;
  queued.reserve(sources.size());
  for(const Dual_graph::size_type f : sources)
    queued.emplace_back(0., f);
  SpectralSeg::internal::bucket_shortest_paths<Dual_graph::size_type>(
    [&](Dual_graph::size_type f, const auto& fn) {
      graph.for_each_neighbour(f, [&](Dual_graph::size_type g, Dual_graph::size_type e) {
        if(labels[g] == labels[f])
          fn(g, graph.edge(e).geodesic_length);
      });
    },
    mean_length, distance, queued, admit, &room);
}

// The mean geodesic length of the dual graph's edges (1 without edges).
SPECTRALSEG_INLINE double mean_geodesic_length(const Dual_graph& graph)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  double sum = 0.;
  for(const Dual_graph::Edge& e : graph.edges())
    sum += e.geodesic_length;
  return sum > 0. && std::isfinite(sum) ? sum / double(graph.edges().size()) : 1.;
}
#else
;
#endif

// The faces of each segment, in face order: the faces of label l are
// face[first[l]] .. face[first[l + 1] - 1].
struct Segment_faces
{
  std::vector<std::size_t> first;
  std::vector<Dual_graph::size_type> face;

  Segment_faces(const std::vector<int>& labels, std::size_t count) : first(count + 1, 0), face(labels.size())
  {
    for(int l : labels)
      ++first[std::size_t(l) + 1];
    for(std::size_t l = 0; l < count; ++l)
      first[l + 1] += first[l];
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for(std::size_t f = 0; f < labels.size(); ++f)
      face[next[std::size_t(labels[f])]++] = Dual_graph::size_type(f);
  }
};

// 1 for the faces within `width` times the square root of their segment's
// area of the segment's boundary (geodesic distance between face centres
// over the dual graph, from the faces on the boundary) and in the half of
// the segment nearest it, 0 for the others. The segments are independent
// (a face is only reached from its own segment): one task each, on
// `threads` threads, with the same result.
SPECTRALSEG_INLINE std::vector<char> boundary_band(const Dual_graph& graph, const std::vector<int>& labels,
                                                   double width, unsigned threads = 1)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = graph.number_of_faces();
  const std::vector<double> area = segment_areas(graph, labels);
  const Segment_faces segments(labels, area.size());
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<char> out(n, 0);
  const double mean_length = mean_geodesic_length(graph);
  SpectralSeg::internal::parallel_range(0, area.size(), threads, [&](std::size_t l) {
    std::vector<Dual_graph::size_type> sources;
    for(std::size_t i = segments.first[l]; i < segments.first[l + 1]; ++i)
    {
      const Dual_graph::size_type f = segments.face[i];
      bool boundary = false;
      graph.for_each_neighbour(f, [&](Dual_graph::size_type g, Dual_graph::size_type) {
        boundary = boundary || labels[g] != labels[f];
      });
      if(boundary)
      {
        distance[f] = 0.;
        sources.push_back(f);
      }
    }
    SpectralSeg::internal::Shortest_path_buckets<Dual_graph::size_type> room;
    distances_within_segments(
      graph, labels, distance, sources, mean_length, [](Dual_graph::size_type, double) { return true; }, room);
    double deepest = 0.;
    for(std::size_t i = segments.first[l]; i < segments.first[l + 1]; ++i)
      if(distance[segments.face[i]] < std::numeric_limits<double>::infinity())
        deepest = std::max(deepest, distance[segments.face[i]]);
    // the half of each segment nearest its boundary at most: every segment
    // keeps a core; strictly nearer than half the deepest face: a segment
    // whose faces all touch its boundary (a tiny mesh) stays as it is
    const double reach = width * std::sqrt(area[l]);
    for(std::size_t i = segments.first[l]; i < segments.first[l + 1]; ++i)
    {
      const Dual_graph::size_type f = segments.face[i];
      out[f] = distance[f] <= reach && distance[f] < 0.5 * deepest ? 1 : 0;
    }
  });
  return out;
}
#else
;
#endif

// For the faces of `in_band`, the other labels each may take: those of the
// segments whose boundary with the face's segment lies within `width` times
// the square root of that segment's area (geodesic distance over the dual
// graph, through band faces of the same segment). Compressed rows: the
// labels of face f are reachable[offset[f]] .. reachable[offset[f + 1] - 1],
// ascending.
struct Band_labels
{
  std::vector<std::size_t> offset;
  std::vector<int> reachable;
};

// One task per segment on `threads` threads (a face is only reached from
// its own segment), with the same result.
SPECTRALSEG_INLINE Band_labels band_labels(const Dual_graph& graph, const std::vector<int>& labels,
                                           const std::vector<char>& in_band, double width, unsigned threads = 1)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = graph.number_of_faces();
  const std::vector<double> area = segment_areas(graph, labels);
  const Segment_faces segments(labels, area.size());
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  // (face, label it may take), per segment
  std::vector<std::vector<std::pair<Dual_graph::size_type, int>>> pairs(area.size());
  const double mean_length = mean_geodesic_length(graph);
  SpectralSeg::internal::parallel_range(0, area.size(), threads, [&](std::size_t l) {
    // the segment's band faces on its boundary, as (label across, face)
    std::vector<std::pair<int, Dual_graph::size_type>> sources;
    for(std::size_t i = segments.first[l]; i < segments.first[l + 1]; ++i)
    {
      const Dual_graph::size_type f = segments.face[i];
      if(in_band[f])
        graph.for_each_neighbour(f, [&](Dual_graph::size_type g, Dual_graph::size_type) {
          if(labels[g] != labels[f])
            sources.emplace_back(labels[g], f);
        });
    }
    std::sort(sources.begin(), sources.end());
    sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
    const double reach = width * std::sqrt(area[l]);
    std::vector<Dual_graph::size_type> touched, from;
    SpectralSeg::internal::Shortest_path_buckets<Dual_graph::size_type> room;
    for(std::size_t begin = 0; begin < sources.size();)
    {
      const int across = sources[begin].first;
      std::size_t end = begin;
      from.clear();
      for(; end < sources.size() && sources[end].first == across; ++end)
      {
        distance[sources[end].second] = 0.;
        touched.push_back(sources[end].second);
        from.push_back(sources[end].second);
      }
      distances_within_segments(graph, labels, distance, from, mean_length,
                                [&](Dual_graph::size_type g, double d) {
                                  if(!in_band[g] || d > reach)
                                    return false;
                                  if(distance[g] == std::numeric_limits<double>::infinity())
                                    touched.push_back(g);
                                  return true;
                                },
                                room);
      // every face reached lies within the reach: it may take `across`
      for(Dual_graph::size_type f : touched)
      {
        pairs[l].emplace_back(f, across);
        distance[f] = std::numeric_limits<double>::infinity();
      }
      touched.clear();
      begin = end;
    }
  });
  // Each face's pairs come from its segment's task, label after label,
  // ascending: a stable counting sort by face puts them in (face, label)
  // order in linear time (a sort took 1% of a 832,000-face segmentation).
  Band_labels out;
  out.offset.assign(n + 1, 0);
  for(const auto& segment_pairs : pairs)
    for(const auto& p : segment_pairs)
      ++out.offset[p.first + 1];
  for(std::size_t f = 0; f < n; ++f)
    out.offset[f + 1] += out.offset[f];
  out.reachable.resize(out.offset[n]);
  for(const auto& segment_pairs : pairs)
    for(const auto& p : segment_pairs) // offset[f] walks to offset[f + 1] ...
      out.reachable[out.offset[p.first]++] = p.second;
  for(std::size_t f = n; f > 0; --f) // ... and is moved back
    out.offset[f] = out.offset[f - 1];
  out.offset[0] = 0;
  return out;
}
#else
;
#endif

SPECTRALSEG_INLINE void run_boost_max_flow_backend(Graph_cut_backend backend, const Potts_problem& problem,
                                                   std::vector<std::size_t>& l, unsigned threads, std::size_t sweeps)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Boost_max_flow_backend run =
    boost_max_flow_backends()[backend == Graph_cut_backend::boost_adjacency_list ? 0 : 1];
  if(run == nullptr)
    throw Invalid_input("graph cut: the Boost max-flow backends need "
                        "#include <SpectralSeg/Refinement/graph_cut_boost_backends.h> in the program");
  run(problem, l, threads, sweeps);
}
#else
;
#endif

// The max-flow problem of graph_cut_boundaries(): its variables (the faces
// whose data term does not decide their label) and their Potts problem.
// Made apart from the moves, so that a caller can release the embedding
// (and this function its per-face scratch) before the moves run.
struct Graph_cut_problem
{
  Potts_problem problem;
  std::vector<Dual_graph::size_type> face_of_variable;
};

// graph_cut_boundaries() up to the moves: checks the input and makes the
// problem (none when there are fewer than two proxies or no variable).
SPECTRALSEG_INLINE Graph_cut_problem graph_cut_problem(const Dual_graph& graph, const Eigen::MatrixXd& embedding,
                                                       const Eigen::MatrixXd& proxies, const std::vector<int>& labels,
                                                       const Graph_cut_options& options, unsigned threads = 1)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Graph_cut_problem out;
  const std::size_t n = graph.number_of_faces();
  const std::size_t k = static_cast<std::size_t>(proxies.rows());
  if(labels.size() != n || static_cast<std::size_t>(embedding.rows()) != n)
    throw Invalid_input("graph cut: one label and one embedding row per face are needed");
  if(!(options.band_width >= 0.) || !std::isfinite(options.band_width))
    throw Invalid_input("graph cut: the band width must be finite and non-negative");
  if(k < 2)
    return out;
  for(int l : labels) // before the band, which indexes its arrays by label
    if(l < 0 || std::size_t(l) >= k)
      throw Invalid_input("graph cut: a label is outside [0, number of proxies)");

  // Smoothness term per dual edge, and its sum around each face.
  const Metrics::Angular_weight angular(options.convex_weight);
  double longest = graph.longest_edge_length() > 0 ? graph.longest_edge_length() : 1.;
  if(options.normalize_by_mean_edge && graph.number_of_edges() > 0)
  {
    double sum = 0.;
    for(const Dual_graph::Edge& e : graph.edges())
      sum += e.length;
    longest = sum > 0 ? sum / double(graph.number_of_edges()) : longest;
  }
  const double log_norm = std::log(options.angular_mapping + 1.);
  std::vector<double> edge_costs(graph.number_of_edges());
  SpectralSeg::internal::parallel_range(0, edge_costs.size(), threads, [&](std::size_t i) {
    const Dual_graph::Edge& e = graph.edge(Dual_graph::size_type(i));
    const double mapped = log_norm > 0 ? std::log(options.angular_mapping * angular.weight(e) + 1.) / log_norm : 0.;
    edge_costs[i] = options.smoothness * (e.length / longest) * std::max(0., 1. - mapped);
  });
  std::vector<double> smoothness_around(n, 0.);
  for(std::size_t i = 0; i < edge_costs.size(); ++i)
  {
    smoothness_around[graph.edge(Dual_graph::size_type(i)).face[0]] += edge_costs[i];
    smoothness_around[graph.edge(Dual_graph::size_type(i)).face[1]] += edge_costs[i];
  }

  // The band: faces far from their segment's boundary keep their label.
  // Each band face may only take the labels of the segments whose boundary
  // is within the band's reach, so that an expansion move is a problem over
  // the faces near its label's segment, not over the whole band.
  std::vector<char> in_band(n, 1);
  Band_labels reach;
  if(options.band_width > 0.)
  {
    in_band = boundary_band(graph, labels, options.band_width, threads);
    reach = band_labels(graph, labels, in_band, options.band_width, threads);
  }
  const double unreachable = std::numeric_limits<double>::infinity();

  // Data term of each face; the faces it does not decide become the
  // variables of the problem, in face order.
  const double scale = std::max(1e-300, (proxies.rowwise() - proxies.colwise().mean()).norm());
  const Dual_graph::size_type none = Dual_graph::size_type(-1);
  std::vector<Dual_graph::size_type> variable(n, none);
  Potts_problem& problem = out.problem;
  problem.labels = k;
  std::vector<Dual_graph::size_type>& face_of_variable = out.face_of_variable;
  const Eigen::Index dims = embedding.cols();
  if(proxies.cols() != dims)
    throw Invalid_input("graph cut: the proxies and the embedding must have the same number of columns");
  std::vector<double> proxy(k * static_cast<std::size_t>(dims));
  for(std::size_t c = 0; c < k; ++c)
    for(Eigen::Index j = 0; j < dims; ++j)
      proxy[c * std::size_t(dims) + std::size_t(j)] = proxies(Eigen::Index(c), j);
  // The faces in chunks, one task each: a chunk's variables and their
  // finite terms, appended to the problem chunk after chunk (the problem
  // one pass over the faces makes).
  struct Chunk
  {
    std::vector<Dual_graph::size_type> face;
    Potts_problem terms;
  };
  const std::size_t chunks = std::min<std::size_t>(n, 16 * std::max(1u, threads));
  std::vector<Chunk> chunk(chunks);
  SpectralSeg::internal::parallel_range(0, chunks, threads, [&](std::size_t c) {
    std::vector<double> face_cost(k), within_reach, row(static_cast<std::size_t>(dims));
    Chunk& out_chunk = chunk[c];
    for(std::size_t f = c * n / chunks; f < (c + 1) * n / chunks; ++f)
    {
      if(!in_band[f])
        continue;
      // the face's row read once (the embedding is stored column after column)
      for(Eigen::Index j = 0; j < dims; ++j)
        row[std::size_t(j)] = embedding(Eigen::Index(f), j);
      double total = 0.;
      for(std::size_t l = 0; l < k; ++l)
      {
        // the squared norm summed coordinate after coordinate, as Eigen does
        // for a row of a column-major matrix
        const double* q = proxy.data() + l * std::size_t(dims);
        double squared = 0.;
        if(dims > 0)
        {
          squared = (row[0] - q[0]) * (row[0] - q[0]);
          for(std::size_t j = 1; j < std::size_t(dims); ++j)
            squared += (row[j] - q[j]) * (row[j] - q[j]);
        }
        const double d = std::max(std::sqrt(squared), 1e-12 * scale);
        face_cost[l] = 1. / d;
        total += face_cost[l];
      }
      for(std::size_t l = 0; l < k; ++l)
        face_cost[l] = -std::log(face_cost[l] / total);
      const std::size_t own = std::size_t(labels[f]);
      if(options.band_width > 0.)
      {
        // only the own label and those within reach
        within_reach.assign(k, unreachable);
        within_reach[own] = face_cost[own];
        for(std::size_t i = reach.offset[f]; i < reach.offset[f + 1]; ++i)
          within_reach[std::size_t(reach.reachable[i])] = face_cost[std::size_t(reach.reachable[i])];
        face_cost.swap(within_reach);
      }
      bool decided = options.fix_decided_faces;
      for(std::size_t l = 0; l < k && decided; ++l)
        if(l != own && face_cost[l] - face_cost[own] <= smoothness_around[f])
          decided = false;
      if(decided)
        continue;
      out_chunk.face.push_back(Dual_graph::size_type(f));
      out_chunk.terms.add_vertex(face_cost);
    }
  });
  std::size_t variables = 0, terms = 0;
  for(const Chunk& c : chunk)
  {
    variables += c.face.size();
    terms += c.terms.label.size();
  }
  face_of_variable.reserve(variables);
  problem.first.reserve(variables + 1);
  problem.label.reserve(terms);
  problem.cost.reserve(terms);
  for(Chunk& c : chunk)
  {
    const std::size_t base = problem.label.size();
    for(std::size_t i = 0; i < c.face.size(); ++i)
    {
      variable[c.face[i]] = Dual_graph::size_type(face_of_variable.size());
      face_of_variable.push_back(c.face[i]);
      problem.first.push_back(base + c.terms.first[i + 1]);
    }
    problem.label.insert(problem.label.end(), c.terms.label.begin(), c.terms.label.end());
    problem.cost.insert(problem.cost.end(), c.terms.cost.begin(), c.terms.cost.end());
    problem.vertices += c.face.size();
    c = Chunk(); // its memory back before the next is copied
  }
  if(problem.vertices == 0)
    return out;

  // Edges between two variables stay; an edge to a fixed face costs its
  // weight for every label but the fixed face's.
  std::size_t variable_edges = 0;
  for(const Dual_graph::Edge& e : graph.edges())
    variable_edges += variable[e.face[0]] != none && variable[e.face[1]] != none;
  problem.edges.reserve(variable_edges);
  problem.weights.reserve(variable_edges);
  for(std::size_t i = 0; i < graph.edges().size(); ++i)
  {
    const Dual_graph::Edge& e = graph.edges()[i];
    const std::size_t a = variable[e.face[0]], b = variable[e.face[1]];
    if(a != none && b != none)
    {
      problem.edges.emplace_back(a, b);
      problem.weights.push_back(edge_costs[i]);
    }
    else if(a != none || b != none)
    {
      const std::size_t v = a != none ? a : b;
      const std::size_t fixed_label = std::size_t(labels[a != none ? e.face[1] : e.face[0]]);
      for(std::size_t t = problem.first[v]; t < problem.first[v + 1]; ++t)
        if(problem.label[t] != fixed_label)
          problem.cost[t] += edge_costs[i];
    }
  }

  return out;
}
#else
;
#endif

// Runs the alpha expansion of `cut` (made by graph_cut_problem() for
// `labels`) on `threads` threads (the same result on any number) and
// writes its labels of the variables into `labels`.
SPECTRALSEG_INLINE void solve_graph_cut(const Graph_cut_problem& cut, std::vector<int>& labels,
                                        const Graph_cut_options& options, unsigned threads = 1)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Potts_problem& problem = cut.problem;
  if(problem.vertices == 0)
    return;
  std::vector<std::size_t> l(problem.vertices);
  for(std::size_t v = 0; v < problem.vertices; ++v)
    l[v] = std::size_t(labels[cut.face_of_variable[v]]);
  if(options.backend == Graph_cut_backend::maxflow)
  {
#ifdef SPECTRALSEG_USE_MAXFLOW
    alpha_expansion<Maxflow_impl>(problem, l, threads, options.sweeps);
#else
    throw Invalid_input("graph cut: the MaxFlow backend needs SPECTRALSEG_USE_MAXFLOW (GPL code)");
#endif
  }
  else
    run_boost_max_flow_backend(options.backend, problem, l, threads, options.sweeps);
  for(std::size_t v = 0; v < problem.vertices; ++v)
    labels[cut.face_of_variable[v]] = static_cast<int>(l[v]);
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegRefinement
/// \brief Relabels the faces by minimising
/// \f$E = \sum_f h_1(f, p_f) + \mu \sum_{(f,g)} h_2(f, g)\f$ with alpha expansion.
///
/// The data term of face \f$f\f$ for the segment with proxy \f$p\f$ is
/// \f$h_1 = -\log\frac{1/d(f,p)}{\sum_q 1/d(f,q)}\f$, \f$d\f$ the Euclidean
/// distance in the embedding between the face and the proxies (the K-means
/// centroids). Across a pair of adjacent faces with different labels, the
/// smoothness term is \f$h_2 = \frac{l(e)}{l_{max}}\left(1 -
/// \frac{\log(\nu a(e) + 1)}{\log(\nu + 1)}\right)\f$, with \f$l(e)\f$ the
/// shared edge length and \f$a(e)\f$ its angular weight: short boundaries
/// along concave creases are cheap.
///
/// Expansion moves for every label are repeated until a whole sweep lowers
/// the energy no more, or for `Graph_cut_options::sweeps` sweeps; a move is
/// kept only when the energy of its labelling, evaluated exactly, is lower.
/// Faces whose data term alone decides their label
/// (`Graph_cut_options::fix_decided_faces`) are left out of the max-flow
/// problems, which then only hold the faces near the boundaries.
/// With `Graph_cut_options::band_width` positive, only the faces in a band
/// along the boundaries may change label (our addition, the default of
/// `segment_k_way()` through `Graph_cut_options::banded()`).
/// Deterministic.
///
/// \param graph the dual graph
/// \param embedding one row per face
/// \param proxies one row per segment
/// \param labels the labels to refine (in `[0, proxies.rows())`), replaced by the result
/// \param options \f$\mu\f$, \f$\nu\f$ and the backend
SPECTRALSEG_INLINE void graph_cut_boundaries(const Dual_graph& graph, const Eigen::MatrixXd& embedding,
                                             const Eigen::MatrixXd& proxies, std::vector<int>& labels,
                                             const Graph_cut_options& options = Graph_cut_options())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  // the problem's scratch (per face and per edge) is released before the moves
  internal::solve_graph_cut(internal::graph_cut_problem(graph, embedding, proxies, labels, options), labels, options);
}
#else
;
#endif

} // namespace Refinement
} // namespace SpectralSeg

#ifndef SPECTRALSEG_USE_MAXFLOW
#include <SpectralSeg/Refinement/graph_cut_boost_backends.h> // the default backend
#include <SpectralSeg/internal/separate_compilation.h>
#endif

#endif
