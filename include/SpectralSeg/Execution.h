// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Execution.h
/// \brief Thread count and progress reporting shared by every long computation.
#ifndef SPECTRALSEG_EXECUTION_H
#define SPECTRALSEG_EXECUTION_H

#include <SpectralSeg/exceptions.h>

#include <functional>
#include <string>
#include <thread>

#ifdef SPECTRALSEG_HAS_TBB
#include <tbb/info.h>
#endif

namespace SpectralSeg {

/// \ingroup PkgSpectralSegCore
/// \brief Signature of a progress callback.
///
/// It is called from the thread that started the computation, never from a
/// worker thread, with the name of the running stage and the fraction of that
/// stage already done (in `[0, 1]`). Returning `false` cancels the
/// computation, which then throws `Operation_cancelled`.
using Progress_callback = std::function<bool(const std::string& stage, double fraction)>;

/// \ingroup PkgSpectralSegCore
/// \brief How a computation runs: how many threads, and whom to tell about
/// progress. Algorithms build it from the named parameters
/// `number_of_threads` and `progress_callback`; metric policies receive it.
///
/// Results never depend on the number of threads.
class Execution
{
public:
  /// \param threads number of threads; `0` means all hardware threads
  /// \param progress optional progress callback
  explicit Execution(unsigned threads = 0, Progress_callback progress = {})
    : threads_(resolve(threads)), progress_(std::move(progress))
  {}

  /// the number of threads to use (at least 1)
  unsigned threads() const { return threads_; }

  /// reports progress; throws `Operation_cancelled` if the callback asks to stop
  void report(const std::string& stage, double fraction) const
  {
    if(progress_ && !progress_(stage, fraction < 0 ? 0. : (fraction > 1 ? 1. : fraction)))
      throw Operation_cancelled(stage);
  }

  /// whether a progress callback is set
  bool has_progress() const { return static_cast<bool>(progress_); }

private:
  static unsigned resolve(unsigned requested)
  {
    if(requested > 0)
      return requested;
#ifdef SPECTRALSEG_HAS_TBB
    const int n = tbb::info::default_concurrency();
    return n > 0 ? static_cast<unsigned>(n) : 1u;
#else
    const unsigned n = std::thread::hardware_concurrency();
    return n > 0 ? n : 1u;
#endif
  }

  unsigned threads_;
  Progress_callback progress_;
};

} // namespace SpectralSeg

#endif // SPECTRALSEG_EXECUTION_H
