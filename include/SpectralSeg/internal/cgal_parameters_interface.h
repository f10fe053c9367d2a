// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The one place that reads CGAL's internal list of named parameters.
//
// Expands, for every named parameter CGAL declares, one of the includer's
// macros (define them before including this file; it has no include guard):
//   SPECTRALSEG_CGAL_NP(Tag, function)       the value is stored by copy
//   SPECTRALSEG_CGAL_NP_CREF(Tag, function)  stored as std::cref (CGAL 6)
//   SPECTRALSEG_CGAL_NP_REF(Tag, function)   stored as std::ref  (CGAL 6)
//
// CGAL 5.5 (Debian 12, the version this package is built and tested with)
// lists every parameter in CGAL/STL_Extension/internal/parameters_interface.h
// with the single macro CGAL_add_named_parameter. CGAL 6 keeps the file at
// that path but also uses CGAL_add_named_parameter_with_compatibility,
// ..._with_compatibility_cref_only, ..._with_compatibility_ref_only and
// CGAL_add_extra_named_parameter_with_compatibility, and moves a few
// mesh-specific parameters into internal/mesh_parameters_interface.h (those
// are not offered by SpectralSeg's chains; start a CGAL chain for them).
// All five macros are defined here, so both layouts expand; CI builds the
// package against CGAL 5.5 and 6.0.1 (scripts/test.sh).
#include <CGAL/version.h>

#if CGAL_VERSION_NR < 1050500000
#error "SpectralSeg needs CGAL 5.5 or later"
#endif

#define CGAL_add_named_parameter(X, Y, Z) SPECTRALSEG_CGAL_NP(X, Z)
#define CGAL_add_named_parameter_with_compatibility(X, Y, Z) SPECTRALSEG_CGAL_NP(X, Z)
#define CGAL_add_named_parameter_with_compatibility_cref_only(X, Y, Z) SPECTRALSEG_CGAL_NP_CREF(X, Z)
#define CGAL_add_named_parameter_with_compatibility_ref_only(X, Y, Z) SPECTRALSEG_CGAL_NP_REF(X, Z)
#define CGAL_add_extra_named_parameter_with_compatibility(X, Y, Z) SPECTRALSEG_CGAL_NP(X, Z)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#undef CGAL_add_named_parameter_with_compatibility
#undef CGAL_add_named_parameter_with_compatibility_cref_only
#undef CGAL_add_named_parameter_with_compatibility_ref_only
#undef CGAL_add_extra_named_parameter_with_compatibility
