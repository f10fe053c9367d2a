// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file ray_directions.h
/// \brief The fixed ray patterns of the VSI metric: a cone of rays around a
/// normal, and antipodal pairs of directions spread over the sphere.
#ifndef SPECTRALSEG_METRICS_VSI_RAY_DIRECTIONS_H
#define SPECTRALSEG_METRICS_VSI_RAY_DIRECTIONS_H

#include <SpectralSeg/internal/separate_compilation.h>
#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <vector>

namespace SpectralSeg {
namespace Metrics {
namespace VSI {

/// \ingroup PkgSpectralSegVSI
/// \brief `count` unit directions inside a cone of full opening angle
/// `opening_angle` (radians) around the +z axis: the first is the axis
/// itself, the others follow a golden-angle spiral, evenly spread in solid
/// angle, the last one on the cone's rim. Rotate them with `rotate_to()`.
SPECTRALSEG_INLINE std::vector<Eigen::Vector3d> cone_directions(std::size_t count, double opening_angle)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<Eigen::Vector3d> d;
  if(count == 0)
    return d;
  d.emplace_back(0., 0., 1.);
  const double golden = CGAL_PI * (3. - std::sqrt(5.));
  const double cos_rim = std::cos(0.5 * opening_angle);
  for(std::size_t j = 1; j < count; ++j)
  {
    const double z = 1. - (1. - cos_rim) * double(j) / double(count - 1);
    const double r = std::sqrt(std::max(0., 1. - z * z));
    const double phi = golden * double(j);
    d.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return d;
}
#else
;
#endif

/// \ingroup PkgSpectralSegVSI
/// \brief Rotates directions given around +z so that +z maps to the unit vector `axis`.
SPECTRALSEG_INLINE void rotate_to(const Eigen::Vector3d& axis, const std::vector<Eigen::Vector3d>& local,
                                  std::vector<Eigen::Vector3d>& out)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Eigen::Vector3d w = axis.normalized();
  const Eigen::Vector3d helper = std::abs(w.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = w.cross(helper).normalized();
  const Eigen::Vector3d v = w.cross(u);
  out.resize(local.size());
  for(std::size_t i = 0; i < local.size(); ++i)
    out[i] = local[i].x() * u + local[i].y() * v + local[i].z() * w;
}
#else
;
#endif

/// \ingroup PkgSpectralSegVSI
/// \brief `2 * pairs` fixed global unit directions, stored as antipodal
/// pairs (`d[2k+1] == -d[2k]`). The first of each pair follows a
/// Fibonacci spiral on the upper half-sphere, so that together they cover
/// the whole sphere evenly.
SPECTRALSEG_INLINE std::vector<Eigen::Vector3d> antipodal_directions(std::size_t pairs)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<Eigen::Vector3d> d;
  const double golden = CGAL_PI * (3. - std::sqrt(5.));
  for(std::size_t k = 0; k < pairs; ++k)
  {
    const double z = (double(k) + 0.5) / double(pairs);
    const double r = std::sqrt(std::max(0., 1. - z * z));
    const double phi = golden * (double(k) + 0.5);
    const Eigen::Vector3d a(r * std::cos(phi), r * std::sin(phi), z);
    d.push_back(a);
    d.push_back(-a);
  }
  return d;
}
#else
;
#endif

} // namespace VSI
} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_VSI_RAY_DIRECTIONS_H
