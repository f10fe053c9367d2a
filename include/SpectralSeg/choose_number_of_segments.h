// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file choose_number_of_segments.h
/// \brief A number of segments read from the spectrum of the affinity matrix.
#ifndef SPECTRALSEG_CHOOSE_NUMBER_OF_SEGMENTS_H
#define SPECTRALSEG_CHOOSE_NUMBER_OF_SEGMENTS_H

#include <SpectralSeg/Embedding/Spectral_embedding.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <cstddef>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegKWay
/// \brief Estimates a number of segments from the spectrum of the affinity
/// matrix.
///
/// With \f$\lambda_1 \ge \lambda_2 \ge \dots\f$ the leading eigenvalues
/// of the affinity matrix (\f$\lambda_1\f$ is the one dropped for
/// centring, \f$\lambda_2\f$ the largest kept one), each part of a shape
/// contributes a large eigenvalue. The rule counts the eigenvalues after the
/// first that reach `threshold` times \f$\lambda_2\f$, adds one for the
/// first, and clamps the result to \f$[2, k_{max}]\f$ (our rule; the
/// thesis takes k from the user). `segment_k_way_automatic()` does not use
/// it (doc/benchmarks.md compares the two).
SPECTRALSEG_INLINE std::size_t choose_number_of_segments(const Embedding::Spectral_embedding& e, std::size_t max_k,
                                                         double threshold = 0.3)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::size_t count = 0;
  const double lambda2 = e.eigenvalues.size() > 0 ? e.eigenvalues(0) : 0.;
  for(Eigen::Index i = 0; i < e.eigenvalues.size(); ++i)
    if(e.eigenvalues(i) >= threshold * lambda2)
      ++count;
  return std::max<std::size_t>(2, std::min(max_k, count + 1));
}
#else
;
#endif

} // namespace SpectralSeg

#endif // SPECTRALSEG_CHOOSE_NUMBER_OF_SEGMENTS_H
