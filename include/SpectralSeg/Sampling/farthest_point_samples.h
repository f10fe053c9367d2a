// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file farthest_point_samples.h
/// \brief Max-min (farthest-point) sampling of faces under a dual-graph metric
/// (thesis 3.6 and fig. 5.3).
#ifndef SPECTRALSEG_SAMPLING_FARTHEST_POINT_SAMPLES_H
#define SPECTRALSEG_SAMPLING_FARTHEST_POINT_SAMPLES_H

#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace SpectralSeg {
namespace Sampling {

/// \ingroup PkgSpectralSegSampling
/// \brief Faces chosen by max-min sampling, with the distances that chose them.
struct Farthest_point_samples
{
  /// the sampled faces, in the order they were chosen
  std::vector<Dual_graph::size_type> faces;
  /// distance of each face to its nearest sample (after the last sample)
  std::vector<double> distance;
  /// for each face, the position in `faces` of its nearest sample
  std::vector<std::size_t> nearest_sample;
  /// with `Farthest_point_options::keep_distance_rows`: row `i` holds the
  /// distances from `faces[i]` to every face (the Dijkstra runs the sampling
  /// made anyway); empty otherwise
  std::vector<std::vector<double>> distance_rows;
};

/// \ingroup PkgSpectralSegSampling
/// \brief Parameters of `farthest_point_samples()`.
struct Farthest_point_options
{
  /// the face the diameter search starts from
  Dual_graph::size_type start = 0;
  /// bound on the hops of the diameter search
  std::size_t max_hops = 10;
  /// keep the distance row of every sample (`Farthest_point_samples::distance_rows`):
  /// `count` times the number of faces doubles, saving the Nyström embedding
  /// one Dijkstra run per sample
  bool keep_distance_rows = false;
};

/// \ingroup PkgSpectralSegSampling
/// \brief Chooses `count` faces spread as far apart as possible under the
/// metric of `graph`.
///
/// The first two samples are the ends of an approximate diameter: starting
/// from `start`, hop to the farthest face until the farthest face of the
/// farthest face is the previous one (at most `max_hops` hops). Each further
/// sample is the face farthest from all samples chosen so far (max-min).
/// Faces in another connected component than every sample are infinitely
/// far, so each component receives a sample before any component gets a
/// second one. Ties go to the smallest face index: the result is deterministic.
///
/// \param graph the weighted dual graph
/// \param count number of samples (at most the number of faces)
/// \param options the start face, the bound on the diameter search, whether
///        to keep the samples' distance rows
/// \param exec progress reporting
/// \throws Invalid_input if `count` is 0 or exceeds the number of faces, or `start` is out of range
inline Farthest_point_samples farthest_point_samples(const Weighted_dual_graph& graph, std::size_t count,
                                                     const Farthest_point_options& options,
                                                     const Execution& exec = Execution())
{
  const std::size_t n = graph.graph().number_of_faces();
  const Dual_graph::size_type start = options.start;
  if(count == 0 || count > n)
    throw Invalid_input("farthest_point_samples: cannot choose " + std::to_string(count) + " samples among " +
                        std::to_string(n) + " faces");
  if(start >= n)
    throw Invalid_input("farthest_point_samples: start face " + std::to_string(start) + " is out of range");

  auto farthest = [n](const std::vector<double>& d) {
    Dual_graph::size_type best = 0;
    for(std::size_t f = 1; f < n; ++f)
      if(d[f] > d[best])
        best = static_cast<Dual_graph::size_type>(f);
    return best;
  };

  // Diameter search: a -> farthest(a) = b -> farthest(b) = c ...; stop when c == a.
  Dual_graph::size_type a = start;
  std::vector<double> row_a = graph.distances(a), row_b;
  Dual_graph::size_type b = farthest(row_a);
  bool have_row_b = false;
  for(std::size_t hop = 0; hop < options.max_hops; ++hop)
  {
    row_b = graph.distances(b);
    have_row_b = true;
    const Dual_graph::size_type c = farthest(row_b);
    if(c == a)
      break;
    a = b;
    b = c;
    row_a.swap(row_b);
    have_row_b = false;
  }

  Farthest_point_samples out;
  std::vector<std::vector<double>> rows; // of out.faces, in order
  out.faces.push_back(a);
  rows.push_back(std::move(row_a));
  if(count > 1 && b != a)
  {
    out.faces.push_back(b);
    rows.push_back(have_row_b ? std::move(row_b) : graph.distances(b));
  }
  // distance to the nearest sample, the first one on ties
  std::vector<double> nearest = rows[0];
  for(std::size_t i = 1; i < rows.size(); ++i)
    for(std::size_t f = 0; f < n; ++f)
      nearest[f] = std::min(nearest[f], rows[i][f]);
  while(out.faces.size() < count)
  {
    exec.report("farthest point sampling", double(out.faces.size()) / double(count));
    const Dual_graph::size_type next = farthest(nearest);
    if(nearest[next] == 0.) // every face is already a sample or at distance 0 of one
    {
      for(std::size_t f = 0; f < n && out.faces.size() < count; ++f)
        if(std::find(out.faces.begin(), out.faces.end(), f) == out.faces.end())
        {
          out.faces.push_back(static_cast<Dual_graph::size_type>(f));
          rows.push_back(options.keep_distance_rows ? graph.distances(static_cast<Dual_graph::size_type>(f))
                                                    : std::vector<double>(n, 0.));
        }
      break;
    }
    out.faces.push_back(next);
    // one more Dijkstra from the new sample, merged into the nearest distances
    rows.push_back(graph.distances(next));
    const std::vector<double>& dn = rows.back();
    for(std::size_t f = 0; f < n; ++f)
      nearest[f] = std::min(nearest[f], dn[f]);
    if(!options.keep_distance_rows)
      rows.back() = std::vector<double>();
  }
  exec.report("farthest point sampling", 1.);
  // Nearest sample of each face: from the kept rows, the first sample in
  // order at the minimum distance; else one multi-source Dijkstra run.
  out.distance = std::move(nearest);
  out.nearest_sample.assign(n, 0);
  if(options.keep_distance_rows)
  {
    for(std::size_t f = 0; f < n; ++f)
      for(std::size_t i = 0; i < rows.size(); ++i)
        if(rows[i][f] == out.distance[f])
        {
          out.nearest_sample[f] = i;
          break;
        }
    out.distance_rows = std::move(rows);
  }
  else
  {
    const Nearest_source_distances d = graph.distances(out.faces);
    out.nearest_sample = d.nearest_source;
  }
  return out;
}

/// \ingroup PkgSpectralSegSampling
/// \brief `farthest_point_samples()` from face `start`, with at most
/// `max_hops` hops of the diameter search.
inline Farthest_point_samples farthest_point_samples(const Weighted_dual_graph& graph, std::size_t count,
                                                     Dual_graph::size_type start = 0, std::size_t max_hops = 10,
                                                     const Execution& exec = Execution())
{
  Farthest_point_options options;
  options.start = start;
  options.max_hops = max_hops;
  return farthest_point_samples(graph, count, options, exec);
}

} // namespace Sampling
} // namespace SpectralSeg

#endif // SPECTRALSEG_SAMPLING_FARTHEST_POINT_SAMPLES_H
