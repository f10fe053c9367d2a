// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Test.h
/// \brief The segmentability tests, named.
#ifndef SPECTRALSEG_SEGMENTABILITY_TEST_H
#define SPECTRALSEG_SEGMENTABILITY_TEST_H

#include <string>

namespace SpectralSeg {
namespace Segmentability {

/// \ingroup PkgSpectralSegSegmentability
/// \brief The four tests, in the order they are tried.
enum class Test
{
  structure = 0,            ///< contour of the L projection
  structure_normalized = 1, ///< the same contour re-embedded by MDS of its inner distances
  geometry = 2,             ///< contour of the M projection
  geometry_normalized = 3,  ///< the same contour re-embedded by MDS of its inner distances
  none = 4                  ///< no test passed: the piece is a final part
};

/// \ingroup PkgSpectralSegSegmentability
/// \brief The name of a test: `"L"`, `"L-MDS"`, `"M"`, `"M-MDS"` or `"none"`.
inline std::string test_name(Test t)
{
  static const char* names[] = {"L", "L-MDS", "M", "M-MDS", "none"};
  return names[static_cast<int>(t)];
}

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_TEST_H
