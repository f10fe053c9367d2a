// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Any_kernel.h
/// \brief An affinity kernel chosen at run time.
#ifndef SPECTRALSEG_KERNELS_ANY_KERNEL_H
#define SPECTRALSEG_KERNELS_ANY_KERNEL_H

#include <SpectralSeg/Kernels/Exponential_kernel.h>

#include <memory>
#include <string>
#include <utility>

namespace SpectralSeg {
namespace Kernels {

/// \ingroup PkgSpectralSegKernels
/// \brief Holds any model of `AffinityKernel`, for kernels chosen at run time
/// (a command-line option, a configuration file): the segmentation is then
/// compiled once, not once per kernel, and computes the same affinities as
/// with the wrapped kernel. The static kernels are preferred in code: this
/// wrapper costs one indirect call per affinity.
///
/// \cgalModels `AffinityKernel`
class Any_kernel
{
public:
  /// wraps `Exponential_kernel`, the default kernel
  Any_kernel() : Any_kernel(Exponential_kernel()) {}

  /// wraps `kernel`
  template <typename AffinityKernel>
  Any_kernel(AffinityKernel kernel) // NOLINT: implicit on purpose
    : holder_(std::make_shared<Holder<AffinityKernel>>(std::move(kernel)))
  {}

  /// the wrapped kernel's name
  std::string name() const { return holder_->name(); }
  /// the wrapped kernel's width for the mean distance `mean_distance`
  double width(double mean_distance) const { return holder_->width(mean_distance); }
  /// the wrapped kernel's affinity at `distance` for the width `width`
  double operator()(double distance, double width) const { return holder_->affinity(distance, width); }

private:
  struct Base
  {
    virtual ~Base() = default;
    virtual std::string name() const = 0;
    virtual double width(double) const = 0;
    virtual double affinity(double, double) const = 0;
  };
  template <typename K>
  struct Holder : Base
  {
    explicit Holder(K k) : kernel(std::move(k)) {}
    std::string name() const override { return kernel.name(); }
    double width(double mean_distance) const override { return kernel.width(mean_distance); }
    double affinity(double distance, double w) const override { return kernel(distance, w); }
    K kernel;
  };
  std::shared_ptr<const Base> holder_;
};

} // namespace Kernels
} // namespace SpectralSeg

#endif // SPECTRALSEG_KERNELS_ANY_KERNEL_H
