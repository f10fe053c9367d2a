// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file version.h
/// \brief The version of SpectralSeg: the one place it is written.
///
/// CMake reads the three numbers below for `project(SpectralSeg VERSION ...)`,
/// so the package version (`find_package(SpectralSeg 0.1)`), the reference
/// manual's number and `spectralseg --version` all come from here.
#ifndef SPECTRALSEG_VERSION_H
#define SPECTRALSEG_VERSION_H

/// \ingroup PkgSpectralSegCore
/// major version number
#define SPECTRALSEG_VERSION_MAJOR 0
/// \ingroup PkgSpectralSegCore
/// minor version number
#define SPECTRALSEG_VERSION_MINOR 1
/// \ingroup PkgSpectralSegCore
/// patch version number
#define SPECTRALSEG_VERSION_PATCH 0

/// \cond SKIP_IN_MANUAL
#define SPECTRALSEG_VERSION_STRINGIFY_(x) #x
#define SPECTRALSEG_VERSION_STRINGIFY(x) SPECTRALSEG_VERSION_STRINGIFY_(x)
/// \endcond

/// \ingroup PkgSpectralSegCore
/// the version as a string literal, `"MAJOR.MINOR.PATCH"`
#define SPECTRALSEG_VERSION_STRING                                                                        \
  SPECTRALSEG_VERSION_STRINGIFY(SPECTRALSEG_VERSION_MAJOR)                                                \
  "." SPECTRALSEG_VERSION_STRINGIFY(SPECTRALSEG_VERSION_MINOR) "." SPECTRALSEG_VERSION_STRINGIFY(         \
    SPECTRALSEG_VERSION_PATCH)

/// \ingroup PkgSpectralSegCore
/// the version as one number, `MAJOR * 10000 + MINOR * 100 + PATCH`, for `#if` tests
#define SPECTRALSEG_VERSION (SPECTRALSEG_VERSION_MAJOR * 10000 + SPECTRALSEG_VERSION_MINOR * 100 + SPECTRALSEG_VERSION_PATCH)

#endif // SPECTRALSEG_VERSION_H
