// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef SPECTRALSEG_INTERNAL_BUCKET_SHORTEST_PATHS_H
#define SPECTRALSEG_INTERNAL_BUCKET_SHORTEST_PATHS_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace internal {

// The memory of bucket_shortest_paths(): its ring of buckets, a bucket's
// vertices being relaxed, and the heap it may switch to; empty between
// runs, so that a task making many runs allocates once.
template <typename Vertex>
struct Shortest_path_buckets
{
  static constexpr std::size_t ring = 1024;
  std::vector<std::vector<std::pair<double, Vertex>>> bucket = std::vector<std::vector<std::pair<double, Vertex>>>(ring);
  std::vector<std::pair<double, Vertex>> work, heap; // heap: after a switch, ordered by std::greater
};

// Lowers `distance` to the shortest-path distances from the vertices of
// `queued` (each with the distance it now has in `distance`) over the arcs
// that `arcs(u, fn)` lists by calling `fn(v, w)` for each arc u -> v of
// weight w (finite, non-negative). Where an arc would lower `distance[v]`
// to d, `lower(v, d)` is asked first: it returns whether v may take d (and
// may note it); v is only reached through the arcs and the values it
// accepts.
//
// The vertices wait in buckets of distance `width` (Meyer and Sanders's
// delta-stepping, on one thread): a bucket's vertices are relaxed in turn,
// again whenever one of them gets closer, and the next bucket starts when
// this one is empty. On the dual graph of a mesh this does a third of the
// work of Dijkstra's heap (doc/benchmarks.md, session 68).
//
// The distances are those of Dijkstra's algorithm bit for bit, in any order
// of relaxation: each is the least, over the paths from a source, of the
// path's weights added one arc at a time in floating point (rounding is
// monotonic, so Dijkstra's algorithm finds that least value), and a vertex
// keeps being lowered here until no arc can lower it, which only that
// value allows. `lower(v, d)` may therefore be asked more often than in
// Dijkstra's run, but a vertex ends lower than it started exactly when
// Dijkstra's run would lower it (with a `lower` that only depends on v and
// on whether d is within a bound).
//
// A vertex past the last of the 1024 buckets kept at a time (an arc over a
// thousand times `width`), or relaxations past four per vertex of
// `distance`, send the waiting vertices to a heap, and the run ends as
// Dijkstra's: the same distances, and never much more work than Dijkstra's.
// `room`, when given, serves as the run's memory.
template <typename Vertex, typename Arcs, typename Lower>
void bucket_shortest_paths(const Arcs& arcs, double width, std::vector<double>& distance,
                           const std::vector<std::pair<double, Vertex>>& queued, const Lower& lower,
                           Shortest_path_buckets<Vertex>* room = nullptr)
{
  typedef std::pair<double, Vertex> Entry;
  constexpr std::size_t ring = Shortest_path_buckets<Vertex>::ring;
  if(queued.empty())
    return;
  const double inverse = width > 0. && std::isfinite(1. / width) ? 1. / width : 1.;
  std::optional<Shortest_path_buckets<Vertex>> own; // made only without `room`: 1,024 buckets
  Shortest_path_buckets<Vertex>& r = room ? *room : own.emplace();
  std::vector<std::vector<Entry>>& bucket = r.bucket;
  std::vector<Entry>& work = r.work;
  std::vector<Entry>& heap = r.heap;
  const std::greater<Entry> later;
  std::size_t pending = 0, budget = 4 * distance.size() + ring;
  double current = std::floor(queued.front().first * inverse);
  for(const Entry& e : queued)
    current = std::min(current, std::floor(e.first * inverse));
  bool buckets = true;
  const auto to_heap = [&] {
    buckets = false;
    for(std::vector<Entry>& b : bucket)
    {
      heap.insert(heap.end(), b.begin(), b.end());
      b.clear();
    }
    std::make_heap(heap.begin(), heap.end(), later);
  };
  const auto push = [&](double d, Vertex v) {
    if(buckets)
    {
      const double b = std::floor(d * inverse) - current; // >= 0: no distance lower than the bucket's
      if(b < double(ring))
      {
        bucket[(std::size_t(current) + std::size_t(b)) % ring].emplace_back(d, v);
        ++pending;
        return;
      }
      to_heap();
    }
    heap.emplace_back(d, v);
    std::push_heap(heap.begin(), heap.end(), later);
  };
  const auto relax = [&](double du, Vertex u) {
    arcs(u, [&](Vertex v, double w) {
      const double d = du + w;
      if(d < distance[v] && lower(v, d))
      {
        distance[v] = d;
        push(d, v);
      }
    });
  };
  if(!std::isfinite(current) || current >= 1e15) // beyond exact bucket numbers
    to_heap();
  for(const Entry& e : queued)
    push(e.first, e.second);
  while(buckets && pending > 0)
  {
    std::vector<Entry>& b = bucket[std::size_t(current) % ring];
    while(buckets && !b.empty())
    {
      work.swap(b);
      pending -= work.size();
      for(std::size_t i = 0; i < work.size(); ++i)
      {
        if(!buckets || budget == 0)
        {
          if(buckets)
            to_heap();
          for(; i < work.size(); ++i)
            push(work[i].first, work[i].second);
          break;
        }
        if(work[i].first != distance[work[i].second]) // lowered since it was queued
          continue;
        --budget;
        relax(work[i].first, work[i].second);
      }
      work.clear();
    }
    current += 1.;
  }
  while(!heap.empty())
  {
    std::pop_heap(heap.begin(), heap.end(), later);
    const Entry top = heap.back();
    heap.pop_back();
    if(top.first == distance[top.second])
      relax(top.first, top.second);
  }
}

} // namespace internal
} // namespace SpectralSeg

#endif // SPECTRALSEG_INTERNAL_BUCKET_SHORTEST_PATHS_H
