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
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <future>
#include <mutex>
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
  /// distances from `faces[i]` to every face (one Dijkstra run per sample,
  /// on the other threads as soon as the sample is chosen, while the
  /// sampling goes on); empty otherwise
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
  /// also compute the distance row of every sample
  /// (`Farthest_point_samples::distance_rows`, what the Nyström embedding
  /// needs): `count` times the number of faces doubles
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
/// Each new sample updates the distances to the nearest sample with
/// `Weighted_dual_graph::add_source()`, which only visits the faces it
/// brings closer. The samples of a smaller `count` are the first ones of a
/// larger `count`.
///
/// \param graph the weighted dual graph
/// \param count number of samples (at most the number of faces)
/// \param options the start face, the bound on the diameter search, whether
///        to compute the samples' distance rows
/// \param exec progress reporting
/// \throws Invalid_input if `count` is 0 or exceeds the number of faces, or `start` is out of range
SPECTRALSEG_INLINE Farthest_point_samples farthest_point_samples(const Weighted_dual_graph& graph, std::size_t count,
                                                                 const Farthest_point_options& options,
                                                                 const Execution& exec = Execution())
#if SPECTRALSEG_DEFINE_FUNCTIONS
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
  out.faces.push_back(a);
  out.distance = row_a; // to the nearest sample
  out.nearest_sample.assign(n, 0);
  if(count > 1 && b != a)
  {
    out.faces.push_back(b);
    if(!have_row_b)
      row_b = graph.distances(b);
    for(std::size_t f = 0; f < n; ++f)
      if(row_b[f] < out.distance[f]) // the first sample on ties
      {
        out.distance[f] = row_b[f];
        out.nearest_sample[f] = 1;
      }
  }
  else
    row_b.clear();
  // With distance rows and several threads, the rows of the samples are
  // made by other threads as soon as each sample is chosen, while this one
  // goes on choosing (each row depends on its sample only); this thread
  // joins them when the samples are chosen.
  const bool rows = options.keep_distance_rows;
  if(rows)
  {
    out.faces.reserve(count); // read by the other threads: never reallocated
    out.distance_rows.resize(count);
    out.distance_rows[0] = std::move(row_a);
    if(!row_b.empty())
      out.distance_rows[1] = std::move(row_b);
  }
  std::atomic<std::size_t> chosen(out.faces.size()), next_row(0);
  std::atomic<bool> stop(false);
  std::mutex mutex;
  std::condition_variable more;
  // the rows not yet made, in order; waits for a sample not yet chosen
  // (this thread reports progress, which may throw to cancel)
  const auto make_rows = [&](bool report) {
    for(std::size_t i = next_row++; i < count && !stop.load(); i = next_row++)
    {
      {
        std::unique_lock<std::mutex> lock(mutex);
        more.wait(lock, [&] { return chosen.load() > i || stop.load(); });
      }
      if(stop.load())
        return;
      if(out.distance_rows[i].empty())
        out.distance_rows[i] = graph.distances(out.faces[i]);
      if(report)
        exec.report("distance rows", double(i + 1) / double(count));
    }
  };
  // wakes the threads waiting for a sample (stop: for good)
  const auto publish = [&](bool end) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      chosen = out.faces.size();
      stop = end;
    }
    more.notify_all();
  };
  std::vector<std::future<void>> helpers;
  if(rows)
    for(unsigned t = 1; t < exec.threads() && t < count; ++t)
      helpers.push_back(std::async(std::launch::async, make_rows, false));
  try
  {
    // Each further sample lowers the distances where it is closer: a
    // Dijkstra run bounded by them, over the new sample's region only.
    while(out.faces.size() < count)
    {
      exec.report("farthest point sampling", double(out.faces.size()) / double(count));
      const Dual_graph::size_type next = farthest(out.distance);
      if(out.distance[next] == 0.) // every face is already a sample or at distance 0 of one
      {
        for(std::size_t f = 0; f < n && out.faces.size() < count; ++f)
          if(std::find(out.faces.begin(), out.faces.end(), f) == out.faces.end())
            out.faces.push_back(static_cast<Dual_graph::size_type>(f));
        break;
      }
      out.faces.push_back(next);
      if(rows)
        publish(false);
      graph.add_source(next, out.faces.size() - 1, out.distance, out.nearest_sample);
    }
    exec.report("farthest point sampling", 1.);
    if(rows)
    {
      publish(false); // every sample is chosen (the loop fills up to `count`)
      exec.report("distance rows", 0.);
      make_rows(true);
      for(auto& h : helpers)
        h.get();
      exec.report("distance rows", 1.);
    }
  }
  catch(...)
  {
    publish(true);
    for(auto& h : helpers)
      if(h.valid())
        h.wait();
    throw;
  }
  return out;
}
#else
;
#endif

/// \ingroup PkgSpectralSegSampling
/// \brief `farthest_point_samples()` from face `start`, with at most
/// `max_hops` hops of the diameter search.
SPECTRALSEG_INLINE Farthest_point_samples farthest_point_samples(const Weighted_dual_graph& graph, std::size_t count,
                                                                 Dual_graph::size_type start = 0,
                                                                 std::size_t max_hops = 10,
                                                                 const Execution& exec = Execution())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Farthest_point_options options;
  options.start = start;
  options.max_hops = max_hops;
  return farthest_point_samples(graph, count, options, exec);
}
#else
;
#endif

} // namespace Sampling
} // namespace SpectralSeg

#endif // SPECTRALSEG_SAMPLING_FARTHEST_POINT_SAMPLES_H
