// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Weighted_dual_graph.h
/// \brief `Weighted_dual_graph`: shortest-path distances on the dual graph weighted by a metric.
#ifndef SPECTRALSEG_WEIGHTED_DUAL_GRAPH_H
#define SPECTRALSEG_WEIGHTED_DUAL_GRAPH_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Metrics/metric_values.h>
#include <SpectralSeg/Metrics/normalize_weights.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/bucket_shortest_paths.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/range/iterator_range.hpp>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegDistances
/// \brief Distances from a set of source faces, with the nearest source of each face.
struct Nearest_source_distances
{
  /// value of `nearest_source` for a face that no source reaches
  static constexpr std::size_t unreachable = static_cast<std::size_t>(-1);
  /// distance of each face to its nearest source; `+infinity` if unreachable
  std::vector<double> distance;
  /// position, in the source list, of each face's nearest source; `unreachable` if none
  std::vector<std::size_t> nearest_source;
};

/// \ingroup PkgSpectralSegDistances
/// \brief A dual graph with one weight per dual edge, ready for repeated
/// shortest-path queries.
///
/// Faces in another connected component than every source are unreachable:
/// their distance is `+infinity` (`std::numeric_limits<double>::infinity()`).
/// Queries are independent and const, so they can run concurrently.
///
/// The distances are Dijkstra's, bit for bit. The single-source queries,
/// `distance_rows()` and `add_source()` reach them by buckets of the mean
/// edge weight (delta-stepping on one thread, about a third of the time of
/// Boost's Dijkstra on a mesh); the query with nearest sources runs Boost's
/// Dijkstra, whose order decides which of two equally near sources wins.
class Weighted_dual_graph
{
public:
  /// face index type
  typedef Dual_graph::size_type size_type;

  /// \param graph the dual graph
  /// \pre `graph` outlives this object
  /// \param weights one finite, non-negative weight per dual edge
  /// \throws Invalid_input if the weights are not valid
  Weighted_dual_graph(const Dual_graph& graph, std::vector<double> weights);

  /// A metric's weights with the faces' thickness where the metric reports
  /// it (`Metrics::metric_values()`); the contrast merge of
  /// `segment_hybrid()` reads the thickness.
  /// \param graph the dual graph
  /// \pre `graph` outlives this object
  /// \param values one finite, non-negative weight per dual edge, and no
  ///        thickness or one per face, each positive or `NaN` (unknown)
  /// \throws Invalid_input if the weights or the thickness are not valid
  Weighted_dual_graph(const Dual_graph& graph, Metrics::Metric_values values);

  /// a temporary graph would dangle: keep the graph alive while this object is used
  Weighted_dual_graph(Dual_graph&&, std::vector<double>) = delete;
  /// a temporary graph would dangle: keep the graph alive while this object is used
  Weighted_dual_graph(Dual_graph&&, Metrics::Metric_values) = delete;

  /// the dual graph
  const Dual_graph& graph() const { return graph_; }

  /// the weight of each dual edge, indexed like `Dual_graph::edges()`
  const std::vector<double>& weights() const { return weights_; }

  /// empty, or the thickness of the shape at each face (`NaN` where
  /// unknown), as reported by the metric (`Metrics::Metric_values`)
  const std::vector<double>& face_thickness() const { return face_thickness_; }

  /// distances from one source face
  std::vector<double> distances(size_type source) const
  {
    std::vector<double> d;
    run(std::vector<size_type>(1, source), d, nullptr);
    return d;
  }

  /// distances to the nearest of several source faces (at least one); when
  /// two sources are equally near, the one that reaches the face first in
  /// Dijkstra's order wins, which is deterministic
  Nearest_source_distances distances(const std::vector<size_type>& sources) const
  {
    Nearest_source_distances out;
    run(sources, out.distance, &out.nearest_source);
    return out;
  }

  /// Row `i` of the result holds the distances from `sources[i]` to every
  /// face. Rows are computed in parallel, each by one shortest-path run, so
  /// the result does not depend on the number of threads.
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>
  distance_rows(const std::vector<size_type>& sources, const Execution& exec = Execution()) const;

  /// Adds a source to nearest-source distances: wherever `source` is
  /// closer than `distance[f]`, lowers `distance[f]` to its distance from
  /// `source` and sets `nearest[f] = label`. Only the faces that get closer
  /// are visited (a shortest-path run bounded by `distance`), so adding a source
  /// among i well-spread ones visits about 1/i of the faces; the distances
  /// are those of `distances()` from all the sources. A face at distance 0
  /// from an earlier source keeps it.
  /// \throws Invalid_input if `source` is out of range or `distance` or
  /// `nearest` does not have one entry per face
  void add_source(size_type source, std::size_t label, std::vector<double>& distance,
                  std::vector<std::size_t>& nearest) const;

private:
  // One shortest-path run from `sources`; records the nearest source only
  // when `nearest` is given (Dijkstra's order decides its ties), else runs
  // by buckets (the same distances, faster).
  void run(const std::vector<size_type>& sources, std::vector<double>& distance,
           std::vector<std::size_t>* nearest) const;

  // the arcs of a face, for bucket_shortest_paths()
  auto arcs() const
  {
    return [this](size_type f, const auto& fn) {
      const Dual_graph::Csr& g = graph_.csr();
      for(auto e : boost::make_iterator_range(out_edges(f, g)))
        fn(size_type(target(e, g)), arc_weights_[get(boost::edge_index, g, e)]);
    };
  }

  struct Nearest_recorder
  {
    typedef boost::on_edge_relaxed event_filter;
    std::vector<std::size_t>* nearest;
    template <typename Edge, typename Graph>
    void operator()(Edge e, const Graph& g) const
    {
      (*nearest)[target(e, g)] = (*nearest)[source(e, g)];
    }
  };

  const Dual_graph& graph_;
  std::vector<double> weights_;
  std::vector<double> face_thickness_;
  std::vector<double> arc_weights_;
  double bucket_width_ = 1.; // of bucket_shortest_paths(): the mean weight
};

#if SPECTRALSEG_DEFINE_FUNCTIONS
SPECTRALSEG_INLINE Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>
Weighted_dual_graph::distance_rows(const std::vector<size_type>& sources, const Execution& exec) const
{
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows(
    static_cast<Eigen::Index>(sources.size()), static_cast<Eigen::Index>(graph_.number_of_faces()));
  internal::parallel_for(sources.size(), exec, "distance rows", [&](std::size_t i) {
    const std::vector<double> d = distances(sources[i]);
    rows.row(static_cast<Eigen::Index>(i)) = Eigen::Map<const Eigen::RowVectorXd>(d.data(), static_cast<Eigen::Index>(d.size()));
  });
  return rows;
}

SPECTRALSEG_INLINE void Weighted_dual_graph::add_source(size_type source, std::size_t label, std::vector<double>& distance,
                                                        std::vector<std::size_t>& nearest) const
{
  const std::size_t n = graph_.number_of_faces();
  if(source >= n)
    throw Invalid_input("add_source: source face " + std::to_string(source) + " is out of range (the mesh has " +
                        std::to_string(n) + " faces)");
  if(distance.size() != n || nearest.size() != n)
    throw Invalid_input("add_source: " + std::to_string(distance.size()) + " distances and " +
                        std::to_string(nearest.size()) + " nearest sources for " + std::to_string(n) + " faces");
  if(!(distance[source] > 0.))
    return;
  distance[source] = 0.;
  nearest[source] = label;
  internal::bucket_shortest_paths<size_type>(arcs(), bucket_width_, distance, {std::make_pair(0., source)},
                                             [&](size_type f, double) {
                                               nearest[f] = label;
                                               return true;
                                             });
}

SPECTRALSEG_INLINE void Weighted_dual_graph::run(const std::vector<size_type>& sources, std::vector<double>& distance,
                                                 std::vector<std::size_t>* nearest) const
{
  const Dual_graph::Csr& g = graph_.csr();
  const std::size_t n = graph_.number_of_faces();
  if(sources.empty())
    throw Invalid_input("distances: no source face given");
  for(size_type s : sources)
    if(s >= n)
      throw Invalid_input("distances: source face " + std::to_string(s) + " is out of range (the mesh has " +
                          std::to_string(n) + " faces)");
  distance.assign(n, std::numeric_limits<double>::infinity());
  const auto index = get(boost::vertex_index, g);
  const auto weight = boost::make_iterator_property_map(arc_weights_.begin(), get(boost::edge_index, g));
  const auto dmap = boost::make_iterator_property_map(distance.begin(), index);
  const double inf = std::numeric_limits<double>::infinity();
  if(nearest)
  {
    nearest->assign(n, Nearest_source_distances::unreachable);
    for(std::size_t i = sources.size(); i-- > 0;) // the first listed source wins a duplicate
      (*nearest)[sources[i]] = i;
    boost::dijkstra_shortest_paths(g, sources.begin(), sources.end(), boost::dummy_property_map(), dmap, weight,
                                   index, std::less<double>(), boost::closed_plus<double>(inf), inf, 0.,
                                   boost::make_dijkstra_visitor(Nearest_recorder{nearest}));
  }
  else
  {
    std::vector<std::pair<double, size_type>> queued;
    for(size_type s : sources)
    {
      distance[s] = 0.;
      queued.emplace_back(0., s);
    }
    internal::bucket_shortest_paths(arcs(), bucket_width_, distance, queued,
                                    [](size_type, double) { return true; });
  }
}

SPECTRALSEG_INLINE Weighted_dual_graph::Weighted_dual_graph(const Dual_graph& graph, std::vector<double> weights)
  : graph_(graph), weights_(std::move(weights)), arc_weights_(num_edges(graph.csr()))
{
  Metrics::check_weights(graph, weights_);
  const Dual_graph::Csr& g = graph.csr();
  for(auto e : boost::make_iterator_range(boost::edges(g)))
    arc_weights_[get(boost::edge_index, g, e)] = weights_[g[e].dual_edge];
  double sum = 0.;
  for(double w : weights_)
    sum += w;
  if(sum > 0. && std::isfinite(sum))
    bucket_width_ = sum / double(weights_.size());
}

SPECTRALSEG_INLINE Weighted_dual_graph::Weighted_dual_graph(const Dual_graph& graph, Metrics::Metric_values values)
  : Weighted_dual_graph(graph, std::move(values.weights))
{
  if(!values.face_thickness.empty())
  {
    if(values.face_thickness.size() != graph.number_of_faces())
      throw Invalid_input("face thickness: " + std::to_string(values.face_thickness.size()) + " values for " +
                          std::to_string(graph.number_of_faces()) + " faces");
    for(double t : values.face_thickness)
      if(!(std::isnan(t) || (t > 0. && std::isfinite(t))))
        throw Invalid_input("face thickness: a value is neither positive and finite nor NaN (unknown)");
  }
  face_thickness_ = std::move(values.face_thickness);
}
#endif

} // namespace SpectralSeg

#endif // SPECTRALSEG_WEIGHTED_DUAL_GRAPH_H
