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
/// \param start the face the diameter search starts from
/// \param max_hops bound on the diameter search
/// \param exec progress reporting
/// \throws Invalid_input if `count` is 0 or exceeds the number of faces, or `start` is out of range
inline Farthest_point_samples farthest_point_samples(const Weighted_dual_graph& graph, std::size_t count,
                                                     Dual_graph::size_type start = 0, std::size_t max_hops = 10,
                                                     const Execution& exec = Execution())
{
  const std::size_t n = graph.graph().number_of_faces();
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
  Dual_graph::size_type b = farthest(graph.distances(a));
  for(std::size_t hop = 0; hop < max_hops; ++hop)
  {
    const Dual_graph::size_type c = farthest(graph.distances(b));
    if(c == a)
      break;
    a = b;
    b = c;
  }

  Farthest_point_samples out;
  out.faces.push_back(a);
  if(count > 1 && b != a)
    out.faces.push_back(b);
  Nearest_source_distances d = graph.distances(out.faces);
  while(out.faces.size() < count)
  {
    exec.report("farthest point sampling", double(out.faces.size()) / double(count));
    const Dual_graph::size_type next = farthest(d.distance);
    if(d.distance[next] == 0.) // every face is already a sample or at distance 0 of one
    {
      for(std::size_t f = 0; f < n && out.faces.size() < count; ++f)
        if(std::find(out.faces.begin(), out.faces.end(), f) == out.faces.end())
          out.faces.push_back(static_cast<Dual_graph::size_type>(f));
      break;
    }
    out.faces.push_back(next);
    // one more Dijkstra from the new sample, merged into the nearest distances
    const std::vector<double> dn = graph.distances(next);
    for(std::size_t f = 0; f < n; ++f)
      if(dn[f] < d.distance[f])
      {
        d.distance[f] = dn[f];
        d.nearest_source[f] = out.faces.size() - 1;
      }
  }
  exec.report("farthest point sampling", 1.);
  d = graph.distances(out.faces);
  out.distance = std::move(d.distance);
  out.nearest_sample = std::move(d.nearest_source);
  return out;
}

} // namespace Sampling
} // namespace SpectralSeg

#endif // SPECTRALSEG_SAMPLING_FARTHEST_POINT_SAMPLES_H
