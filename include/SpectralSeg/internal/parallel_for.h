// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef SPECTRALSEG_INTERNAL_PARALLEL_FOR_H
#define SPECTRALSEG_INTERNAL_PARALLEL_FOR_H

#include <SpectralSeg/Execution.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <memory>
#include <string>

#ifdef SPECTRALSEG_HAS_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>
#endif

namespace SpectralSeg {
namespace internal {

#ifdef SPECTRALSEG_HAS_TBB
// At most as many threads as TBB allows (more would only print a warning).
inline unsigned usable_threads(unsigned threads)
{
  return std::min<unsigned>(threads, static_cast<unsigned>(std::max(1, tbb::info::default_concurrency())));
}

// The calling thread's arena of `threads` threads, made on its first use and
// kept until the thread ends: making an arena costs about as much as a
// parallel loop over 50,000 faces, and K-means runs hundreds of such loops.
// One arena per thread count, none ever replaced, so that a body running
// in one can use another.
inline tbb::task_arena& thread_arena(unsigned threads)
{
  thread_local std::map<unsigned, std::unique_ptr<tbb::task_arena>> arenas;
  std::unique_ptr<tbb::task_arena>& arena = arenas[threads];
  if(!arena)
    arena.reset(new tbb::task_arena(static_cast<int>(threads)));
  return *arena;
}
#endif

// Runs body(i) for i in [begin, end) on exec.threads() threads. Each index is
// processed exactly once and bodies must write to disjoint outputs, so results
// never depend on the thread count.
template <typename Body>
void parallel_range(std::size_t begin, std::size_t end, unsigned threads, const Body& body)
{
  if(end <= begin)
    return;
#ifdef SPECTRALSEG_HAS_TBB
  threads = usable_threads(threads);
  if(threads > 1 && end - begin > 1)
  {
    thread_arena(threads).execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for(std::size_t i = r.begin(); i != r.end(); ++i)
                            body(i);
                        });
    });
    return;
  }
#else
  (void)threads;
#endif
  for(std::size_t i = begin; i != end; ++i)
    body(i);
}

// Sorts [first, last) by `less` on `threads` threads. `less` must be a
// strict total order on the values (no two of them equivalent): the sorted
// sequence is then the only one, whatever the algorithm and the number of
// threads.
template <typename Iterator, typename Less>
void parallel_sort(Iterator first, Iterator last, const Less& less, unsigned threads)
{
#ifdef SPECTRALSEG_HAS_TBB
  threads = usable_threads(threads);
  if(threads > 1)
  {
    thread_arena(threads).execute([&] { tbb::parallel_sort(first, last, less); });
    return;
  }
#else
  (void)threads;
#endif
  std::sort(first, last, less);
}

// Same as parallel_range over [0, n), cut into batches so that progress is
// reported (and cancellation checked) from the calling thread between batches.
template <typename Body>
void parallel_for(std::size_t n, const Execution& exec, const std::string& stage, const Body& body)
{
  exec.report(stage, 0.);
  if(n == 0)
    return;
  // at most 50 reports, and at least four indices per thread in a batch: with
  // fewer, a batch of one index (a few Dijkstra rows, say) would run on one
  // thread while the others wait
  const std::size_t batches = exec.has_progress() ? std::min<std::size_t>(n, 50) : 1;
  const std::size_t batch = std::max<std::size_t>((n + batches - 1) / batches, 4 * std::size_t(exec.threads()));
  for(std::size_t b = 0; b < n; b += batch)
  {
    const std::size_t e = std::min(n, b + batch);
    parallel_range(b, e, exec.threads(), body);
    exec.report(stage, double(e) / double(n));
  }
}

} // namespace internal
} // namespace SpectralSeg

#endif // SPECTRALSEG_INTERNAL_PARALLEL_FOR_H
