// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file named_parameters.h
/// \brief SpectralSeg's named parameters, an extension of CGAL's.
///
/// `SpectralSeg::parameters::metric(m).number_of_threads(2).vertex_point_map(vpm)`
/// builds one parameter pack that SpectralSeg functions and CGAL functions both
/// read. Chaining works from a SpectralSeg parameter to any parameter (ours or
/// CGAL's); a chain that starts with a CGAL parameter can only continue with
/// CGAL's parameters, so start with a SpectralSeg one (or with
/// `SpectralSeg::parameters::vertex_point_map`, which is re-exported here).
#ifndef SPECTRALSEG_NAMED_PARAMETERS_H
#define SPECTRALSEG_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <functional>

namespace SpectralSeg {

/// \cond SKIP_IN_MANUAL
namespace internal_np {
// One enum per SpectralSeg named parameter: X is the tag type, Y its value.
#define SPECTRALSEG_NAMED_PARAMETERS(P) \
  P(metric_t, metric)                   \
  P(number_of_threads_t, number_of_threads) \
  P(progress_callback_t, progress_callback) \
  P(nearest_source_map_t, nearest_source_map) \
  P(kernel_t, kernel)                   \
  P(embedding_method_t, embedding_method) \
  P(number_of_nystrom_samples_t, number_of_nystrom_samples) \
  P(sampling_method_t, sampling_method) \
  P(boundary_enhancement_t, boundary_enhancement) \
  P(k_way_options_t, k_way_options) \
  P(max_number_of_segments_t, max_number_of_segments) \
  P(min_boundary_contrast_t, min_boundary_contrast) \
  P(automatic_method_t, automatic_method) \
  P(automatic_options_t, automatic_options) \
  P(segmentability_threshold_t, segmentability_threshold) \
  P(structure_only_t, structure_only) \
  P(min_part_area_fraction_t, min_part_area_fraction) \
  P(part_hierarchy_t, part_hierarchy) \
  P(number_of_parts_t, number_of_parts) \
  P(connect_touching_parts_t, connect_touching_parts) \
  P(contact_distance_t, contact_distance) \
  P(speck_area_fraction_t, speck_area_fraction) \
  P(descriptor_options_t, descriptor_options)

#define SPECTRALSEG_DECLARE_TAG(X, Y) enum X { Y };
SPECTRALSEG_NAMED_PARAMETERS(SPECTRALSEG_DECLARE_TAG)
#undef SPECTRALSEG_DECLARE_TAG
} // namespace internal_np
/// \endcond

/// \ingroup PkgSpectralSegNamedParameters
/// \brief A CGAL named-parameter pack that can also be chained with
/// SpectralSeg's own parameters. Read it with `CGAL::parameters::get_parameter`
/// and `CGAL::parameters::choose_parameter`, as any CGAL pack.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// \cond SKIP_IN_MANUAL
  typedef CGAL::Named_function_parameters<T, Tag, Base> cgal_type;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : cgal_type() {}
  Named_function_parameters(const T& v) : cgal_type(v) {}
  Named_function_parameters(const T& v, const Base& b) : cgal_type(v, b) {}

#define SPECTRALSEG_CHAIN(X, Y)                                           \
  template <typename K>                                                   \
  Named_function_parameters<K, internal_np::X, self> Y(const K& k) const  \
  {                                                                       \
    return Named_function_parameters<K, internal_np::X, self>(k, *this);  \
  }
  SPECTRALSEG_NAMED_PARAMETERS(SPECTRALSEG_CHAIN)
#undef SPECTRALSEG_CHAIN

#define SPECTRALSEG_CGAL_NP(X, Z)                                                \
  template <typename K>                                                          \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const   \
  {                                                                              \
    return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this);   \
  }
#define SPECTRALSEG_CGAL_NP_CREF(X, Z)                                           \
  template <typename K>                                                          \
  Named_function_parameters<std::reference_wrapper<const K>, CGAL::internal_np::X, self> Z(const K& k) const \
  {                                                                              \
    return Named_function_parameters<std::reference_wrapper<const K>, CGAL::internal_np::X, self>(std::cref(k), *this); \
  }
#define SPECTRALSEG_CGAL_NP_REF(X, Z)                                            \
  template <typename K>                                                          \
  Named_function_parameters<std::reference_wrapper<K>, CGAL::internal_np::X, self> Z(K& k) const \
  {                                                                              \
    return Named_function_parameters<std::reference_wrapper<K>, CGAL::internal_np::X, self>(std::ref(k), *this); \
  }
#include <SpectralSeg/internal/cgal_parameters_interface.h>
#undef SPECTRALSEG_CGAL_NP
#undef SPECTRALSEG_CGAL_NP_CREF
#undef SPECTRALSEG_CGAL_NP_REF
  /// \endcond
};

/// \ingroup PkgSpectralSegNamedParameters
/// \brief Free functions that start a named-parameter chain.
namespace parameters {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::default_values;
using CGAL::parameters::Default_named_parameters;

/// \cond SKIP_IN_MANUAL
#define SPECTRALSEG_START(X, Y)                                  \
  template <typename K>                                          \
  Named_function_parameters<K, internal_np::X> Y(const K& k)     \
  {                                                              \
    return Named_function_parameters<K, internal_np::X>(k);      \
  }
SPECTRALSEG_NAMED_PARAMETERS(SPECTRALSEG_START)
#undef SPECTRALSEG_START

#define SPECTRALSEG_CGAL_NP(X, Z)                                 \
  template <typename K>                                           \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& k) \
  {                                                               \
    return Named_function_parameters<K, CGAL::internal_np::X>(k);  \
  }
#define SPECTRALSEG_CGAL_NP_CREF(X, Z)                            \
  template <typename K>                                           \
  Named_function_parameters<std::reference_wrapper<const K>, CGAL::internal_np::X> Z(const K& k) \
  {                                                               \
    return Named_function_parameters<std::reference_wrapper<const K>, CGAL::internal_np::X>(std::cref(k)); \
  }
#define SPECTRALSEG_CGAL_NP_REF(X, Z)                             \
  template <typename K>                                           \
  Named_function_parameters<std::reference_wrapper<K>, CGAL::internal_np::X> Z(K& k) \
  {                                                               \
    return Named_function_parameters<std::reference_wrapper<K>, CGAL::internal_np::X>(std::ref(k)); \
  }
#include <SpectralSeg/internal/cgal_parameters_interface.h>
#undef SPECTRALSEG_CGAL_NP
#undef SPECTRALSEG_CGAL_NP_CREF
#undef SPECTRALSEG_CGAL_NP_REF
/// \endcond

} // namespace parameters
} // namespace SpectralSeg

#endif // SPECTRALSEG_NAMED_PARAMETERS_H
