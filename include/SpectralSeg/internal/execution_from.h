// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The execution (threads and progress) that an entry point reads from its
// named parameters `number_of_threads` and `progress_callback`.
#ifndef SPECTRALSEG_INTERNAL_EXECUTION_FROM_H
#define SPECTRALSEG_INTERNAL_EXECUTION_FROM_H

#include <SpectralSeg/Execution.h>
#include <SpectralSeg/named_parameters.h>

namespace SpectralSeg {
namespace internal {

template <typename NamedParameters>
Execution execution_from(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const unsigned threads = static_cast<unsigned>(
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::number_of_threads), 0));
  Progress_callback progress =
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::progress_callback), Progress_callback());
  return Execution(threads, progress);
}

} // namespace internal
} // namespace SpectralSeg

#endif // SPECTRALSEG_INTERNAL_EXECUTION_FROM_H
