// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file shape_retrieval.h
/// \brief Shape retrieval with the part-aware metric (thesis 3.6): the
/// mesh-level shape descriptor, and every header of retrieval.
#ifndef SPECTRALSEG_SHAPE_RETRIEVAL_H
#define SPECTRALSEG_SHAPE_RETRIEVAL_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Retrieval/Shape_descriptor.h>
#include <SpectralSeg/internal/mesh_parameters.h>
#include <SpectralSeg/named_parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegRetrieval
/// \brief Computes the shape descriptor of a triangle mesh: the histogram
/// of the distances between its faces under a metric, divided by their mean
/// (thesis 3.6; see `Retrieval::shape_descriptor()` for the sampling).
/// Compare descriptors with `Retrieval::chi_square_distance()`, rank them
/// with `Retrieval::rank_shapes()`.
///
/// The descriptor does not depend on the mesh's position, scale or face
/// order (up to the choice of the first farthest-point sample) and little
/// on its tessellation; the part-aware metric's shape images use fixed ray
/// directions, so a rotation changes its descriptor slightly (the user
/// manual's retrieval page has the measured tolerances).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         with triangle faces oriented outward
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{metric}
///     \cgalParamDescription{the distance between faces: a model of `DualEdgeWeight` (shortest paths in the dual graph), or `Retrieval::Euclidean_distance()` for the D2 descriptor}
///     \cgalParamType{a model of `DualEdgeWeight` or `Retrieval::Euclidean_distance`}
///     \cgalParamDefault{`Retrieval::retrieval_metric()`: part-aware with \f$\alpha = 0.02\f$, \f$\beta = 0\f$, \f$\gamma = 0.98\f$ (thesis 3.6)}
///   \cgalParamNEnd
///   \cgalParamNBegin{descriptor_options}
///     \cgalParamDescription{number of bins, number of source faces, range of the histogram}
///     \cgalParamType{`Retrieval::Descriptor_options`}
///     \cgalParamDefault{`Retrieval::Descriptor_options()`: 64 bins, 32 sources, 4 mean distances}
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
/// \throws Invalid_input for a non-triangle face, a non-finite coordinate,
///         invalid descriptor options, a mesh without area or a metric
///         that returns invalid weights
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Retrieval::Shape_descriptor shape_descriptor(const TriangleMesh& tm,
                                             const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Execution exec = internal::execution_from(np);
  const auto metric = choose_parameter(get_parameter(np, SpectralSeg::internal_np::metric), Retrieval::retrieval_metric());
  const Retrieval::Descriptor_options options =
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::descriptor_options), Retrieval::Descriptor_options());
  options.check();
  const Dual_graph graph = make_dual_graph(tm, np);
  if constexpr(std::is_same<std::decay_t<decltype(metric)>, Retrieval::Euclidean_distance>::value)
    return Retrieval::shape_descriptor(graph, metric, options, exec);
  else
  {
    const Weighted_dual_graph weighted(graph, internal::metric_weights(metric, graph, exec));
    return Retrieval::shape_descriptor(weighted, metric.name(), options, exec);
  }
}

} // namespace SpectralSeg

#endif // SPECTRALSEG_SHAPE_RETRIEVAL_H
