// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file smooth_contour.h
/// \brief Smoothing a contour with truncated Fourier descriptors (thesis 6.2.3).
#ifndef SPECTRALSEG_SEGMENTABILITY_SMOOTH_CONTOUR_H
#define SPECTRALSEG_SEGMENTABILITY_SMOOTH_CONTOUR_H

#include <SpectralSeg/Segmentability/Contour.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <cmath>
#include <complex>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \cond SKIP_IN_MANUAL
namespace internal {

// Mean distance between corresponding points of two contours of equal size.
SPECTRALSEG_INLINE double mean_distance(const Contour& a, const Contour& b)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(a.empty())
    return 0.;
  double sum = 0.;
  for(std::size_t k = 0; k < a.size(); ++k)
    sum += (a[k] - b[k]).norm();
  return sum / double(a.size());
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegSegmentability
/// \brief Smooths a closed contour by keeping only its lowest frequencies
/// (truncated Fourier descriptors).
///
/// The vertices are read as complex numbers \f$z_k = x_k + i\,y_k\f$ and
/// their discrete Fourier transform is taken. Frequencies are kept in the
/// order \f$0, \pm 1, \pm 2, \ldots\f$, one pair at a time, until the mean
/// distance between the reconstructed points and the original ones is below
/// `relative_error` times the *scale* of the contour, defined here as the
/// length of the diagonal of its bounding box (well defined even for a
/// contour of zero area). With all frequencies kept the reconstruction is
/// exact, so the loop always ends.
///
/// The coefficients are computed one at a time by a direct sum with a
/// table of the \f$n\f$-th roots of unity, so the cost is \f$O(n\,m)\f$ for
/// \f$n\f$ points and \f$m\f$ kept frequencies (at most \f$O(n^2)\f$).
///
/// \param c the contour, typically from `trace_outer_contour()`
/// \param relative_error the tolerance, relative to the scale (the thesis
///        uses 0.5 %)
/// \return a contour with as many points as `c`, point \f$k\f$ the smoothed
///         position of `c[k]`, made counter-clockwise if the smoothing
///         turned it around (then in reverse order); `c` itself if it has
///         fewer than three points or all its points are equal
/// \throws Invalid_input if a coordinate is not finite or `relative_error`
///         is negative or not finite
SPECTRALSEG_INLINE Contour smooth_contour(const Contour& c, double relative_error = 0.005)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_finite(c, "smooth_contour");
  if(!(relative_error >= 0.) || !std::isfinite(relative_error))
    throw Invalid_input("smooth_contour: the relative error must be finite and non-negative, got " +
                        std::to_string(relative_error));
  const std::size_t n = c.size();
  const double scale = internal::bounding_box_diagonal(c);
  if(n < 3 || !(scale > 0.))
    return c;
  const double tolerance = relative_error * scale;

  typedef std::complex<double> Complex;
  const double two_pi = 6.283185307179586476925286766559;
  std::vector<Complex> root(n); // root[k] = exp(2 pi i k / n)
  for(std::size_t k = 0; k < n; ++k)
    root[k] = std::polar(1., two_pi * double(k) / double(n));
  std::vector<Complex> z(n), sum(n, Complex(0., 0.));
  for(std::size_t k = 0; k < n; ++k)
    z[k] = Complex(c[k].x(), c[k].y());

  Contour smoothed(n);
  auto add_frequency = [&](std::size_t m) {
    Complex coefficient(0., 0.);
    for(std::size_t k = 0; k < n; ++k)
      coefficient += z[k] * std::conj(root[(m * k) % n]);
    coefficient /= double(n);
    for(std::size_t k = 0; k < n; ++k)
      sum[k] += coefficient * root[(m * k) % n];
  };
  auto update = [&]() {
    for(std::size_t k = 0; k < n; ++k)
      smoothed[k] = Eigen::Vector2d(sum[k].real(), sum[k].imag());
    return internal::mean_distance(smoothed, c);
  };

  add_frequency(0);
  double error = update();
  for(std::size_t m = 1; 2 * m <= n && error >= tolerance; ++m)
  {
    add_frequency(m);
    if(n - m != m)
      add_frequency(n - m); // frequency -m
    error = update();
  }
  if(error >= tolerance)
    smoothed = c; // only rounding errors stood in the way; all frequencies give c back
  internal::make_counterclockwise(smoothed);
  return smoothed;
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_SMOOTH_CONTOUR_H
