// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef SPECTRALSEG_EMBEDDING_INTERNAL_AFFINITY_H
#define SPECTRALSEG_EMBEDDING_INTERNAL_AFFINITY_H

#include <SpectralSeg/Execution.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <cmath>

namespace SpectralSeg {
namespace Embedding {
namespace internal {

typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Row_matrix;

// Mean of the finite entries of the first `rows` rows (distances to other
// components are infinite).
SPECTRALSEG_INLINE double mean_finite(const Row_matrix& g, Eigen::Index rows)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  double sum = 0.;
  std::size_t count = 0;
  for(Eigen::Index i = 0; i < rows; ++i)
  {
    double row = 0.;
    for(Eigen::Index j = 0; j < g.cols(); ++j)
      if(std::isfinite(g(i, j)))
      {
        row += g(i, j);
        ++count;
      }
    sum += row;
  }
  return count ? sum / double(count) : 0.;
}
#else
;
#endif

// The kernel width of the first `rows` distance rows of `g`: from the mean
// of their finite entries (1 when there is none, or it is 0).
template <typename Kernel>
double kernel_width(const Row_matrix& g, Eigen::Index rows, const Kernel& kernel)
{
  const double mean = mean_finite(g, rows);
  return mean > 0 ? kernel.width(mean) : 1.;
}

// The affinity of a distance: 0 across components (an infinite distance).
template <typename Kernel>
double affinity(double distance, const Kernel& kernel, double width)
{
  return std::isfinite(distance) ? kernel(distance, width) : 0.;
}

// Turns distances into affinities in place; returns the kernel width.
template <typename Kernel>
double distances_to_affinities(Row_matrix& g, const Kernel& kernel, const Execution& exec)
{
  const double width = kernel_width(g, g.rows(), kernel);
  ::SpectralSeg::internal::parallel_range(0, static_cast<std::size_t>(g.rows()), exec.threads(), [&](std::size_t i) {
    for(Eigen::Index j = 0; j < g.cols(); ++j)
      g(Eigen::Index(i), j) = affinity(g(Eigen::Index(i), j), kernel, width);
  });
  return width;
}

// Makes eigenvector signs deterministic: the entry of largest magnitude is positive.
template <typename Matrix>
void fix_signs(Matrix& vectors)
{
  for(Eigen::Index c = 0; c < vectors.cols(); ++c)
  {
    Eigen::Index arg = 0;
    vectors.col(c).cwiseAbs().maxCoeff(&arg);
    if(vectors(arg, c) < 0)
      vectors.col(c) = -vectors.col(c);
  }
}

} // namespace internal
} // namespace Embedding
} // namespace SpectralSeg

#endif
