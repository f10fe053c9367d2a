// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Shape_descriptor.h
/// \brief Shape descriptors for retrieval: histograms of distances between
/// faces under a metric (thesis 3.6), their chi-square distance, rankings and
/// retrieval scores. The dual-graph stage; `shape_retrieval.h` has the
/// mesh-level entry point.
#ifndef SPECTRALSEG_RETRIEVAL_SHAPE_DESCRIPTOR_H
#define SPECTRALSEG_RETRIEVAL_SHAPE_DESCRIPTOR_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Sampling/farthest_point_samples.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Retrieval {

/// \ingroup PkgSpectralSegRetrieval
/// \brief The Euclidean distance between face centroids: with it, the shape
/// descriptor is the D2 shape distribution of Osada et al. (the thesis's
/// baseline in 3.6). It is not a `DualEdgeWeight`: only the descriptor
/// functions accept it as their `metric`.
struct Euclidean_distance
{
  /// `"euclidean"`
  std::string name() const { return "euclidean"; }
};

/// \ingroup PkgSpectralSegRetrieval
/// \brief The part-aware metric with the thesis's retrieval coefficients
/// (3.6): \f$\alpha = 0.02\f$, \f$\beta = 0\f$, \f$\gamma = 0.98\f$, VSI
/// dominating; the default metric of `shape_descriptor()`.
template <typename RayCaster = Ray_casting::Default_ray_caster>
Metrics::Part_aware_weight<RayCaster> retrieval_metric(const Metrics::VSI_options& vsi = Metrics::VSI_options())
{
  return Metrics::Part_aware_weight<RayCaster>(0.02, 0., 0.98, vsi);
}

/// \ingroup PkgSpectralSegRetrieval
/// \brief Parameters of a shape descriptor.
struct Descriptor_options
{
  /// number of histogram bins
  std::size_t bins = 64;
  /// number of source faces (farthest-point samples); at most the number of faces
  std::size_t sources = 32;
  /// the histogram covers distances from 0 to `range` times the mean
  /// distance; longer distances count in the last bin
  double range = 4.;

  /// \throws Invalid_input unless `bins` >= 2, `sources` >= 1 and `range` > 0 is finite
  void check() const
  {
    if(bins < 2 || bins > 100000)
      throw Invalid_input("shape descriptor: the number of bins must be from 2 to 100000, not " + std::to_string(bins));
    if(sources < 1)
      throw Invalid_input("shape descriptor: at least one source face is needed");
    if(!(range > 0.) || !std::isfinite(range))
      throw Invalid_input("shape descriptor: the range must be a positive number of mean distances");
  }
};

/// \ingroup PkgSpectralSegRetrieval
/// \brief A shape descriptor: the distribution of the distances between
/// two faces of the surface, both taken with probability proportional to
/// their area, the distances divided by their mean.
///
/// Dividing by the mean makes it independent of the mesh's scale; weighting
/// by area makes it (nearly) independent of the tessellation.
struct Shape_descriptor
{
  /// name of the metric (`"part-aware"`, `"geodesic"`, `"euclidean"`, ...)
  std::string metric;
  /// the fraction of (area-weighted) face pairs in each bin; adds up to 1
  std::vector<double> histogram;
  /// bin `i` covers distances in \f$[i, i+1) \cdot range / bins\f$ mean distances
  double range = 4.;
  /// the mean distance, in the metric's units (mesh units for geodesic and euclidean)
  double mean_distance = 0.;
  /// number of source faces used
  std::size_t sources = 0;
};

/// \ingroup PkgSpectralSegRetrieval
/// \brief The chi-square distance between two descriptors,
/// \f$\frac12 \sum_i (a_i - b_i)^2 / (a_i + b_i)\f$ over the bins where
/// \f$a_i + b_i > 0\f$: 0 for equal histograms, 1 for histograms with
/// disjoint supports, symmetric.
/// \throws Invalid_input if the descriptors differ in metric, number of bins or range
SPECTRALSEG_INLINE double chi_square_distance(const Shape_descriptor& a, const Shape_descriptor& b)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(a.metric != b.metric)
    throw Invalid_input("chi_square_distance: a '" + a.metric + "' descriptor cannot be compared to a '" + b.metric +
                        "' one");
  if(a.histogram.size() != b.histogram.size() || a.range != b.range)
    throw Invalid_input("chi_square_distance: the descriptors have different bins (" +
                        std::to_string(a.histogram.size()) + " up to " + std::to_string(a.range) + " against " +
                        std::to_string(b.histogram.size()) + " up to " + std::to_string(b.range) + ")");
  double d = 0.;
  for(std::size_t i = 0; i < a.histogram.size(); ++i)
  {
    const double s = a.histogram[i] + b.histogram[i];
    if(s > 0.)
      d += (a.histogram[i] - b.histogram[i]) * (a.histogram[i] - b.histogram[i]) / s;
  }
  return 0.5 * d;
}
#else
;
#endif

/// \ingroup PkgSpectralSegRetrieval
/// \brief One entry of a ranking: a database position and its distance to the query.
struct Ranked_shape
{
  /// position of the shape in the database
  std::size_t index;
  /// its chi-square distance to the query
  double distance;
};

/// \ingroup PkgSpectralSegRetrieval
/// \brief Ranks `database` by chi-square distance to `query`, nearest first;
/// equal distances keep the database order.
/// \throws Invalid_input if a descriptor cannot be compared to the query
SPECTRALSEG_INLINE std::vector<Ranked_shape> rank_shapes(const Shape_descriptor& query,
                                                         const std::vector<Shape_descriptor>& database)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<Ranked_shape> r;
  r.reserve(database.size());
  for(std::size_t i = 0; i < database.size(); ++i)
    r.push_back({i, chi_square_distance(query, database[i])});
  std::stable_sort(r.begin(), r.end(), [](const Ranked_shape& x, const Ranked_shape& y) { return x.distance < y.distance; });
  return r;
}
#else
;
#endif

/// \ingroup PkgSpectralSegRetrieval
/// \brief Retrieval scores of a database queried with each of its shapes
/// in turn (the query itself left out), averaged over the queries.
struct Retrieval_scores
{
  /// fraction of queries whose nearest shape is in the query's class
  double nearest_neighbor = 0.;
  /// mean fraction of the query's class (itself excluded, \f$C-1\f$ shapes)
  /// found among the \f$C-1\f$ nearest shapes
  double first_tier = 0.;
  /// the same among the \f$2(C-1)\f$ nearest shapes
  double second_tier = 0.;
  /// number of queries (shapes whose class has at least two members)
  std::size_t queries = 0;
};

/// \ingroup PkgSpectralSegRetrieval
/// \brief Nearest neighbour, first tier and second tier (the Princeton Shape
/// Benchmark's measures) of the symmetric matrix `distance` of all pairs of
/// shapes, for the classes `category`. Ties go to the smaller index. Shapes
/// alone in their class are not queried.
/// \throws Invalid_input if the sizes do not match
SPECTRALSEG_INLINE Retrieval_scores retrieval_scores(const std::vector<std::vector<double>>& distance,
                                                     const std::vector<std::string>& category)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = category.size();
  if(distance.size() != n)
    throw Invalid_input("retrieval_scores: " + std::to_string(distance.size()) + " rows for " + std::to_string(n) +
                        " shapes");
  Retrieval_scores s;
  for(std::size_t q = 0; q < n; ++q)
  {
    if(distance[q].size() != n)
      throw Invalid_input("retrieval_scores: row " + std::to_string(q) + " has " +
                          std::to_string(distance[q].size()) + " entries for " + std::to_string(n) + " shapes");
    const std::size_t relevant = static_cast<std::size_t>(std::count(category.begin(), category.end(), category[q])) - 1;
    if(relevant == 0)
      continue;
    std::vector<std::size_t> order;
    for(std::size_t i = 0; i < n; ++i)
      if(i != q)
        order.push_back(i);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return distance[q][a] < distance[q][b]; });
    auto hits = [&](std::size_t top) {
      std::size_t h = 0;
      for(std::size_t i = 0; i < std::min(top, order.size()); ++i)
        h += category[order[i]] == category[q] ? 1 : 0;
      return double(h);
    };
    s.nearest_neighbor += hits(1);
    s.first_tier += hits(relevant) / double(relevant);
    s.second_tier += hits(2 * relevant) / double(relevant);
    ++s.queries;
  }
  if(s.queries > 0)
  {
    s.nearest_neighbor /= double(s.queries);
    s.first_tier /= double(s.queries);
    s.second_tier /= double(s.queries);
  }
  return s;
}
#else
;
#endif

/// \cond SKIP_IN_MANUAL
namespace internal {

// Farthest-point samples under the geodesic metric and the fraction of the
// surface area nearest to each (its weight): stratified, area-weighted sources.
struct Descriptor_sources
{
  std::vector<Dual_graph::size_type> faces;
  std::vector<double> weight;
};

SPECTRALSEG_INLINE Descriptor_sources descriptor_sources(const Dual_graph& graph, std::size_t count,
                                                         const Execution& exec)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::vector<double>& area = graph.geometry().areas;
  const Weighted_dual_graph geodesic(graph, Metrics::Geodesic_weight()(graph));
  Sampling::Farthest_point_options fo;
  fo.max_hops = 4;
  const Sampling::Farthest_point_samples fps =
    Sampling::farthest_point_samples(geodesic, std::min<std::size_t>(count, graph.number_of_faces()), fo, exec);
  Descriptor_sources s;
  s.faces = fps.faces;
  s.weight.assign(s.faces.size(), 0.);
  double total = 0.;
  for(std::size_t f = 0; f < area.size(); ++f)
    if(fps.nearest_sample[f] < s.weight.size())
    {
      s.weight[fps.nearest_sample[f]] += area[f];
      total += area[f];
    }
  if(!(total > 0.))
    throw Invalid_input("shape descriptor: the mesh has no area");
  for(double& w : s.weight)
    w /= total;
  return s;
}
#else
;
#endif

// The descriptor from the distances of each source to every face:
// row(source, out) fills out[f] (float, +inf when unreachable).
template <typename Row>
Shape_descriptor descriptor_from_rows(const Dual_graph& graph, const Descriptor_sources& src, const Row& row,
                                      const std::string& metric, const Descriptor_options& o, const Execution& exec)
{
  const std::vector<double>& area = graph.geometry().areas;
  const std::size_t n = area.size(), m = src.faces.size();
  std::vector<std::vector<float>> rows(m);
  std::vector<double> row_sum(m, 0.), row_area(m, 0.);
  ::SpectralSeg::internal::parallel_for(m, exec, "descriptor distances", [&](std::size_t i) {
    rows[i].resize(n);
    row(src.faces[i], rows[i]);
    for(std::size_t f = 0; f < n; ++f)
      if(std::isfinite(rows[i][f]))
      {
        row_sum[i] += area[f] * double(rows[i][f]);
        row_area[i] += area[f];
      }
  });
  double sum = 0., weight = 0.; // in source order: the same whatever the threads
  for(std::size_t i = 0; i < m; ++i)
  {
    sum += src.weight[i] * row_sum[i];
    weight += src.weight[i] * row_area[i];
  }
  Shape_descriptor d;
  d.metric = metric;
  d.range = o.range;
  d.sources = m;
  d.mean_distance = weight > 0. ? sum / weight : 0.;
  if(!(d.mean_distance > 0.) || !std::isfinite(d.mean_distance))
    throw Invalid_input("shape descriptor: all distances are zero under the " + metric + " metric");
  // Linear binning: a distance between two bin centres is shared between them.
  const double scale = double(o.bins) / (o.range * d.mean_distance);
  std::vector<std::vector<double>> partial(m);
  ::SpectralSeg::internal::parallel_for(m, exec, "descriptor histogram", [&](std::size_t i) {
    std::vector<double>& h = partial[i];
    h.assign(o.bins, 0.);
    for(std::size_t f = 0; f < n; ++f)
    {
      if(!std::isfinite(rows[i][f]))
        continue;
      const double x = double(rows[i][f]) * scale - 0.5;
      if(x <= 0.)
        h.front() += area[f];
      else if(x >= double(o.bins - 1))
        h.back() += area[f];
      else
      {
        const std::size_t b = static_cast<std::size_t>(x);
        const double t = x - double(b);
        h[b] += (1. - t) * area[f];
        h[b + 1] += t * area[f];
      }
    }
    std::vector<float>().swap(rows[i]);
  });
  d.histogram.assign(o.bins, 0.);
  for(std::size_t i = 0; i < m; ++i)
    for(std::size_t b = 0; b < o.bins; ++b)
      d.histogram[b] += src.weight[i] * partial[i][b];
  const double total = std::accumulate(d.histogram.begin(), d.histogram.end(), 0.);
  for(double& v : d.histogram)
    v /= total;
  return d;
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegRetrieval
/// \brief The shape descriptor of a weighted dual graph: the distribution
/// of the shortest-path distances between faces (thesis 3.6).
///
/// Sources: `options.sources` farthest-point samples under the geodesic
/// metric (whatever the weights), each standing for the faces nearest to
/// it and weighted by their area, so that sources cover the surface evenly
/// and count as much as the area they stand for. From each source, one
/// Dijkstra run reaches every face; each face counts with its area. The
/// distances are divided by their (area-weighted) mean and binned linearly
/// into `options.bins` bins up to `options.range` mean distances.
/// Unreachable pairs (faces in other components) are left out.
///
/// Deterministic: the sources do not depend on a random draw, and the
/// sums run in a fixed order whatever the number of threads.
///
/// \param weighted the dual graph with its weights
/// \param metric the name stored in the descriptor
/// \param options bins, sources, range
/// \param exec threads and progress
/// \throws Invalid_input for invalid options, a mesh without area or all distances zero
SPECTRALSEG_INLINE Shape_descriptor shape_descriptor(const Weighted_dual_graph& weighted, const std::string& metric,
                                                     const Descriptor_options& options = Descriptor_options(),
                                                     const Execution& exec = Execution())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  options.check();
  const internal::Descriptor_sources src = internal::descriptor_sources(weighted.graph(), options.sources, exec);
  return internal::descriptor_from_rows(
    weighted.graph(), src,
    [&](Dual_graph::size_type s, std::vector<float>& out) {
      const std::vector<double> d = weighted.distances(s);
      std::copy(d.begin(), d.end(), out.begin());
    },
    metric, options, exec);
}
#else
;
#endif

/// \ingroup PkgSpectralSegRetrieval
/// \brief The D2 descriptor of a dual graph: as the other overload, with
/// the Euclidean distances between face centroids.
SPECTRALSEG_INLINE Shape_descriptor shape_descriptor(const Dual_graph& graph, Euclidean_distance metric,
                                                     const Descriptor_options& options = Descriptor_options(),
                                                     const Execution& exec = Execution())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  options.check();
  const internal::Descriptor_sources src = internal::descriptor_sources(graph, options.sources, exec);
  const std::vector<Eigen::Vector3d>& c = graph.geometry().centroids;
  return internal::descriptor_from_rows(
    graph, src,
    [&](Dual_graph::size_type s, std::vector<float>& out) {
      for(std::size_t f = 0; f < c.size(); ++f)
        out[f] = static_cast<float>((c[f] - c[s]).norm());
    },
    metric.name(), options, exec);
}
#else
;
#endif

} // namespace Retrieval
} // namespace SpectralSeg

#endif // SPECTRALSEG_RETRIEVAL_SHAPE_DESCRIPTOR_H
