// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file separate_compilation.h
/// \brief Header-only or separately compiled: the two macros that decide
/// where the library's non-template functions are compiled.
#ifndef SPECTRALSEG_INTERNAL_SEPARATE_COMPILATION_H
#define SPECTRALSEG_INTERNAL_SEPARATE_COMPILATION_H

/// \cond SKIP_IN_MANUAL
// Header-only (the default): every function is defined inline in its header.
//
// With SPECTRALSEG_SEPARATE_COMPILATION defined, the non-template functions
// whose bodies instantiate the eigensolvers, K-means, the graph cut and
// chapter 6's tests are only declared in the headers, and defined once in
// src/spectralseg_compiled.cpp (CMake target SpectralSeg::Compiled), which
// defines SPECTRALSEG_COMPILING_LIBRARY as well. Results are the same either
// way; a program made of many translation units compiles much less.
//
// SPECTRALSEG_HEADER_CHECK_OWN_BODIES (the header self-containment test
// only, GCC and Clang): the bodies of the header the translation unit
// includes, and only declarations from the headers that one includes, whose
// bodies are checked in their own units; the default instances (below) are
// declared, so that their lines are checked too.
//
// With SPECTRALSEG_SEPARATE_COMPILATION, the method templates that programs
// call with the default policies (the exponential kernel or the
// command line's run-time kernel, the thesis's salience, both ray casters,
// the point type of `Epick`) are instantiated once as well, in
// src/spectralseg_instances.cpp (which defines
// SPECTRALSEG_COMPILING_INSTANCES): SPECTRALSEG_DEFAULT_INSTANCES is 1, and
// a header writes `SPECTRALSEG_INSTANTIATE` before such an instantiation,
// an explicit instantiation definition (`template`) in that source and a
// declaration (`extern template`) everywhere else. The two sources let the
// library compile on two cores.
#if defined(SPECTRALSEG_HEADER_CHECK_OWN_BODIES) && defined(__INCLUDE_LEVEL__)
#  define SPECTRALSEG_INLINE
#  define SPECTRALSEG_DEFINE_FUNCTIONS (__INCLUDE_LEVEL__ == 1)
#  define SPECTRALSEG_DEFAULT_INSTANCES 1
#  define SPECTRALSEG_INSTANTIATE extern template
#elif defined(SPECTRALSEG_SEPARATE_COMPILATION)
#  define SPECTRALSEG_INLINE
#  define SPECTRALSEG_DEFAULT_INSTANCES 1
#  if defined(SPECTRALSEG_COMPILING_LIBRARY)
#    define SPECTRALSEG_DEFINE_FUNCTIONS 1
#  else
#    define SPECTRALSEG_DEFINE_FUNCTIONS 0
#  endif
#  if defined(SPECTRALSEG_COMPILING_INSTANCES)
#    define SPECTRALSEG_INSTANTIATE template
#  else
#    define SPECTRALSEG_INSTANTIATE extern template
#  endif
#else
#  define SPECTRALSEG_INLINE inline
#  define SPECTRALSEG_DEFINE_FUNCTIONS 1
#  define SPECTRALSEG_DEFAULT_INSTANCES 0
#endif
/// \endcond

#endif // SPECTRALSEG_INTERNAL_SEPARATE_COMPILATION_H
