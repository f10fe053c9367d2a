// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file k_way_segmentation.h
/// \brief Segmentation of a triangle mesh into k parts by spectral clustering
/// of the part-aware metric (thesis ch. 4 and 5): the mesh-level entry
/// points, and every header of the k-way segmentation.
#ifndef SPECTRALSEG_K_WAY_SEGMENTATION_H
#define SPECTRALSEG_K_WAY_SEGMENTATION_H

#include <SpectralSeg/K_way_options.h>
#include <SpectralSeg/Kernels/Exponential_kernel.h>
#include <SpectralSeg/Kernels/Gaussian_kernel.h>
#include <SpectralSeg/choose_number_of_segments.h>
#include <SpectralSeg/face_distances.h>
#include <SpectralSeg/internal/mesh_parameters.h>
#include <SpectralSeg/named_parameters.h>
#include <SpectralSeg/segment_k_way.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>

namespace SpectralSeg {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The k-way options of the named parameters: `k_way_options` first, then
// each individual parameter that is given replaces the field it names.
template <typename NamedParameters>
auto k_way_options_from(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto base = choose_parameter(get_parameter(np, SpectralSeg::internal_np::k_way_options), K_way_options());
  auto o = base.with_kernel(choose_parameter(get_parameter(np, SpectralSeg::internal_np::kernel), base.kernel));
  o.embedding.method = choose_parameter(get_parameter(np, SpectralSeg::internal_np::embedding_method), o.embedding.method);
  o.embedding.samples = choose_parameter(get_parameter(np, SpectralSeg::internal_np::number_of_nystrom_samples), o.embedding.samples);
  o.embedding.sampling = choose_parameter(get_parameter(np, SpectralSeg::internal_np::sampling_method), o.embedding.sampling);
  o.embedding.seed = static_cast<unsigned int>(
    choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), o.embedding.seed));
  o.boundary_enhancement =
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::boundary_enhancement), o.boundary_enhancement);
  return o;
}

template <typename TriangleMesh, typename SegmentMap, typename NamedParameters>
void put_labels(const TriangleMesh& tm, const std::vector<int>& labels, SegmentMap segments, const NamedParameters& np)
{
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  typedef typename boost::property_traits<SegmentMap>::value_type Label;
  for(auto f : faces(tm))
    put(segments, f, static_cast<Label>(labels[get(fim, f)]));
}

// The `number_of_parts` named parameter (0 when not given).
// \throws Invalid_input if it is given as 0
template <typename NamedParameters>
std::size_t number_of_parts_from(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::size_t none = static_cast<std::size_t>(-1);
  const std::size_t parts = choose_parameter(get_parameter(np, SpectralSeg::internal_np::number_of_parts), none);
  if(parts == none)
    return 0;
  if(parts == 0)
    throw Invalid_input("automatic segmentation: the number of parts must be at least 1");
  return parts;
}

// Moves `h` to where the `part_hierarchy` named parameter points, if given.
template <typename NamedParameters>
void put_hierarchy(Part_hierarchy&& h, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Part_hierarchy* out =
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::part_hierarchy), static_cast<Part_hierarchy*>(nullptr));
  if(out)
    *out = std::move(h);
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegKWay
/// \brief Segments a triangle mesh into `k` parts by spectral clustering of
/// the part-aware metric, and returns the number of segments.
///
/// Builds the dual graph, weighs it with the metric and runs
/// `segment_k_way()` on it; see there for the stages.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         with triangle faces oriented outward
/// \tparam SegmentMap a model of `WritablePropertyMap` with the face
///         descriptor as key type and an integer type as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param k the number of segments wanted
/// \param segments receives the segment of each face, in `[0, returned value)`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{metric}
///     \cgalParamDescription{the weights of the dual edges (thesis, ch. 3)}
///     \cgalParamType{a model of `DualEdgeWeight`}
///     \cgalParamDefault{`Metrics::Part_aware_weight<>()`, the part-aware metric (thesis 3.5)}
///   \cgalParamNEnd
///   \cgalParamNBegin{kernel}
///     \cgalParamDescription{turns distances into affinities (thesis 4.2.3); replaces `k_way_options.kernel`}
///     \cgalParamType{a model of `AffinityKernel`}
///     \cgalParamDefault{the kernel of `k_way_options`: `Kernels::Exponential_kernel()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{embedding_method}
///     \cgalParamDescription{`automatic` (exact up to `Embedding_options::exact_face_limit` faces, Nyström above), `exact` (thesis 4.2) or `nystrom` (thesis 5.2); replaces `k_way_options.embedding.method`}
///     \cgalParamType{`Embedding::Method`}
///     \cgalParamDefault{`Embedding::Method::automatic`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_nystrom_samples}
///     \cgalParamDescription{Nyström samples; 0 means one more than the embedding's dimensions (thesis 5.3: \f$l = k + 1\f$); replaces `k_way_options.embedding.samples`}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{sampling_method}
///     \cgalParamDescription{how the Nyström samples are chosen: farthest-point (thesis fig. 5.3) or Gamma-sampling (thesis 5.4); replaces `k_way_options.embedding.sampling`}
///     \cgalParamType{`Embedding::Sampling_method`}
///     \cgalParamDefault{`Embedding::Sampling_method::farthest_point`}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{seed of the sampling's random start face and of the Gamma candidates; replaces `k_way_options.embedding.seed`}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_enhancement}
///     \cgalParamDescription{whether the graph cut refines the boundaries (thesis 4.3.3); replaces `k_way_options.boundary_enhancement`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{k_way_options}
///     \cgalParamDescription{every parameter of the k-way method (graph-cut \f$\mu\f$ and \f$\nu\f$, extra clusters, K-means rounds, ...). Precedence: the individual parameters above, when given, replace the fields they name; every other field comes from here}
///     \cgalParamType{`Basic_K_way_options<AffinityKernel>`, e.g. `K_way_options`}
///     \cgalParamDefault{`K_way_options()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads of the parallel stages; 0 means all hardware threads. The result does not depend on it}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called with each stage's name and done fraction; returning `false` cancels (`Operation_cancelled`)}
///     \cgalParamType{`SpectralSeg::Progress_callback`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
///     \cgalParamDescription{the vertex positions and the numbering of vertices and faces, as for `extract_mesh_geometry()`}
///     \cgalParamType{property maps as for `extract_mesh_geometry()`}
///     \cgalParamDefault{the mesh's internal maps}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// The output does not depend on the number of threads.
/// \throws Invalid_input for `k` = 0 or larger than the number of faces, a
///         non-triangle face or a non-finite coordinate
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename TriangleMesh, typename SegmentMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t k_way_segmentation(const TriangleMesh& tm, std::size_t k, SegmentMap segments,
                               const NamedParameters& np = parameters::default_values())
{
  const internal::Weighted_mesh_graph g(tm, np);
  auto o = internal::k_way_options_from(np);
  o.keep_embedding_coordinates = false; // only the labels are returned: less memory
  const K_way_result r = segment_k_way(g.weighted, k, o, g.exec);
  internal::put_labels(tm, r.labels, segments, np);
  return r.number_of_segments;
}

/// \ingroup PkgSpectralSegKWay
/// \brief Segments a triangle mesh into a number of parts it chooses itself,
/// between 2 and `max_number_of_segments`, and returns that number (the rule
/// of `segment_k_way_automatic()`, our addition; the thesis takes k from the
/// user).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         with triangle faces oriented outward
/// \tparam SegmentMap a model of `WritablePropertyMap` with the face
///         descriptor as key type and an integer type as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param segments receives the segment of each face, in `[0, returned value)`
/// \param np an optional sequence of named parameters: those of
///        `k_way_segmentation()` (where `k_way_options.extra_clusters` and
///        `k_way_options.merge_strength_limit` are replaced by the rule's
///        values) and the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{max_number_of_segments}
///     \cgalParamDescription{the largest number of segments considered, at least 2 (`K_way_automatic_options::max_k`)}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{20}
///   \cgalParamNEnd
///   \cgalParamNBegin{min_boundary_contrast}
///     \cgalParamDescription{merging stops once the weakest boundary's mean concave angle reaches this many times the mesh's mean concave angle (`K_way_automatic_options::min_boundary_contrast`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{3}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_parts}
///     \cgalParamDescription{when given, the answer has this many parts (or as many as the over-segmentation has, if fewer): the merge hierarchy cut there instead of where the rule stops (`K_way_automatic_options::parts`)}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{none: the rule decides}
///   \cgalParamNEnd
///   \cgalParamNBegin{part_hierarchy}
///     \cgalParamDescription{receives the merges from the over-segmentation down to one part per connected component (`K_way_result::hierarchy`)}
///     \cgalParamType{`Part_hierarchy*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input if `max_number_of_segments` is below 2, for a
///         non-triangle face or a non-finite coordinate
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename TriangleMesh, typename SegmentMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t k_way_segmentation_automatic(const TriangleMesh& tm, SegmentMap segments,
                                         const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const internal::Weighted_mesh_graph g(tm, np);
  const auto k_way = internal::k_way_options_from(np);
  Basic_K_way_automatic_options<typename std::decay_t<decltype(k_way)>::Kernel_type> o;
  o.k_way = k_way;
  o.k_way.keep_embedding_coordinates = false; // only the labels and the hierarchy are returned
  o.max_k = choose_parameter(get_parameter(np, SpectralSeg::internal_np::max_number_of_segments), o.max_k);
  o.min_boundary_contrast =
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::min_boundary_contrast), o.min_boundary_contrast);
  o.parts = internal::number_of_parts_from(np);
  K_way_result r = segment_k_way_automatic(g.weighted, o, g.exec);
  internal::put_labels(tm, r.labels, segments, np);
  internal::put_hierarchy(std::move(r.hierarchy), np);
  return r.number_of_segments;
}

/// \ingroup PkgSpectralSegKWay
/// \brief The spectral embedding of the faces of `tm` in `dimensions`
/// dimensions (thesis 4.2, 5.2), for users who run their own clustering.
/// Rows follow the face index map.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         with triangle faces oriented outward
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param dimensions the number of columns wanted (fewer if eigenvalues are
///        not positive: `Spectral_embedding::dropped_dimensions`)
/// \param np an optional sequence of named parameters: `metric`, `kernel`,
///        `embedding_method`, `number_of_nystrom_samples`,
///        `sampling_method`, `random_seed`, `k_way_options` (its `kernel`
///        and `embedding` fields), `number_of_threads`, `progress_callback`
///        and the mesh maps, as for `k_way_segmentation()`
///
/// \throws Invalid_input for more dimensions or samples than faces, a
///         non-triangle face or a non-finite coordinate
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Embedding::Spectral_embedding spectral_embedding(const TriangleMesh& tm, std::size_t dimensions,
                                                 const NamedParameters& np = parameters::default_values())
{
  const internal::Weighted_mesh_graph g(tm, np);
  const auto o = internal::k_way_options_from(np);
  return internal::embed(g.weighted, dimensions, o.kernel, o.embedding, g.exec);
}

} // namespace SpectralSeg

#endif // SPECTRALSEG_K_WAY_SEGMENTATION_H
