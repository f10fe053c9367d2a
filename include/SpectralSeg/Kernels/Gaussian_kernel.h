// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Gaussian_kernel.h
/// \brief The Gaussian affinity kernel, the alternative to the exponential one.
#ifndef SPECTRALSEG_KERNELS_GAUSSIAN_KERNEL_H
#define SPECTRALSEG_KERNELS_GAUSSIAN_KERNEL_H

#include <cmath>
#include <string>

namespace SpectralSeg {
namespace Kernels {

/// \ingroup PkgSpectralSegKernels
/// \brief Affinity \f$W_{ij} = e^{-G_{ij}^2 / (2\sigma^2)}\f$, with the
/// kernel width \f$\sigma\f$ set to the mean distance \f$\bar G\f$ (so that,
/// as for the exponential kernel, a face at the mean distance has affinity
/// \f$e^{-1/2}\f$).
///
/// \cgalModels `AffinityKernel`
struct Gaussian_kernel
{
  /// `"gaussian"`
  std::string name() const { return "gaussian"; }
  /// \f$\sigma = \bar G\f$
  double width(double mean_distance) const { return mean_distance; }
  /// the affinity of two faces at distance `distance`
  double operator()(double distance, double width) const
  {
    return std::exp(-distance * distance / (2. * width * width));
  }
};

} // namespace Kernels
} // namespace SpectralSeg

#endif
