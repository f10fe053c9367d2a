// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Exponential_kernel.h
/// \brief The exponential affinity kernel (thesis 4.2.1 and 4.2.3), the default.
#ifndef SPECTRALSEG_KERNELS_EXPONENTIAL_KERNEL_H
#define SPECTRALSEG_KERNELS_EXPONENTIAL_KERNEL_H

#include <cmath>
#include <string>

namespace SpectralSeg {
namespace Kernels {

/// \ingroup PkgSpectralSegKernels
/// \brief Affinity \f$W_{ij} = e^{-G_{ij} / (2\sigma^2)}\f$ of two faces at
/// distance \f$G_{ij}\f$, with the kernel width \f$\sigma\f$ set to the
/// square root of the mean distance.
///
/// \cgalModels `AffinityKernel`
struct Exponential_kernel
{
  /// `"exponential"`
  std::string name() const { return "exponential"; }
  /// \f$\sigma = \sqrt{\bar G}\f$ for the mean distance \f$\bar G\f$
  double width(double mean_distance) const { return std::sqrt(mean_distance); }
  /// the affinity of two faces at distance `distance`
  double operator()(double distance, double width) const { return std::exp(-distance / (2. * width * width)); }
};

} // namespace Kernels
} // namespace SpectralSeg

#endif
