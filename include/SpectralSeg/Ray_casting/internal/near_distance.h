// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The distance under which the ray casters count no hit.
#ifndef SPECTRALSEG_RAY_CASTING_INTERNAL_NEAR_DISTANCE_H
#define SPECTRALSEG_RAY_CASTING_INTERNAL_NEAR_DISTANCE_H

namespace SpectralSeg {
namespace Ray_casting {
/// \cond SKIP_IN_MANUAL
namespace internal {

// Hits closer than this fraction of the mesh's bounding-box diagonal do not
// count. Far below any face of a mesh a float can hold (10^-7 is the
// relative precision of a float coordinate), it keeps a ray that leaves a
// flat region from entering every bounding box that touches its origin:
// the boxes of a flat fan all contain the origins of its rays, and a ray
// that leaves the plane only crosses them at distance 0.
constexpr double near_distance_fraction = 1e-7;

} // namespace internal
/// \endcond
} // namespace Ray_casting
} // namespace SpectralSeg

#endif // SPECTRALSEG_RAY_CASTING_INTERNAL_NEAR_DISTANCE_H
