// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file face_distances.h
/// \brief Distances between the faces of a triangle mesh under a dual-graph metric.
#ifndef SPECTRALSEG_FACE_DISTANCES_H
#define SPECTRALSEG_FACE_DISTANCES_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/internal/mesh_parameters.h>
#include <SpectralSeg/named_parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <iterator>
#include <type_traits>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegDistances
/// \brief Computes the shortest-path distance, in the weighted dual graph,
/// from the nearest of `sources` to every face of `tm`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         with triangle faces oriented outward
/// \tparam FaceRange a range of `boost::graph_traits<TriangleMesh>::face_descriptor`
/// \tparam FaceDistanceMap a writable property map with the face descriptor
///         as key and `double` as value
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param sources the source faces (at least one)
/// \param distances receives each face's distance; `+infinity` for a face in
///        a connected component without a source
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{metric}
///     \cgalParamDescription{the weights of the dual edges (thesis, ch. 3)}
///     \cgalParamType{a model of `DualEdgeWeight`}
///     \cgalParamDefault{`Metrics::Part_aware_weight<>()`, the part-aware metric (thesis 3.5)}
///   \cgalParamNEnd
///   \cgalParamNBegin{nearest_source_map}
///     \cgalParamDescription{receives, for each face, the position in `sources` of its nearest source (`Nearest_source_distances::unreachable` if none); ties go to the source Dijkstra settles first}
///     \cgalParamType{a model of `WritablePropertyMap` with the face descriptor as key type and `std::size_t` as value type}
///     \cgalParamDefault{not written}
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
///         an empty source range or a metric that returns invalid weights
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename TriangleMesh, typename FaceRange, typename FaceDistanceMap,
          typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          , typename = std::enable_if_t<!std::is_convertible<
              FaceRange, typename boost::graph_traits<TriangleMesh>::face_descriptor>::value>
#endif
          >
void face_distances(const TriangleMesh& tm, const FaceRange& sources, FaceDistanceMap distances,
                    const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;

  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const internal::Weighted_mesh_graph g(tm, np);
  const Execution& exec = g.exec;
  const Weighted_dual_graph& weighted = g.weighted;

  std::vector<Dual_graph::size_type> source_ids;
  for(typename GT::face_descriptor f : sources)
    source_ids.push_back(static_cast<Dual_graph::size_type>(get(fim, f)));
  exec.report("dijkstra", 0.);
  const Nearest_source_distances result = weighted.distances(source_ids);
  exec.report("dijkstra", 1.);

  auto nearest = choose_parameter(get_parameter(np, SpectralSeg::internal_np::nearest_source_map),
                                  internal::No_nearest_source_map());
  for(typename GT::face_descriptor f : faces(tm))
  {
    const std::size_t i = get(fim, f);
    put(distances, f, result.distance[i]);
    if constexpr(!std::is_same<decltype(nearest), internal::No_nearest_source_map>::value)
      put(nearest, f, result.nearest_source[i]);
  }
}

/// \ingroup PkgSpectralSegDistances
/// \brief Single-source version of `face_distances()`: distances from
/// `source`, with the same named parameters.
template <typename TriangleMesh, typename FaceDistanceMap,
          typename NamedParameters = parameters::Default_named_parameters>
void face_distances(const TriangleMesh& tm,
                    typename boost::graph_traits<TriangleMesh>::face_descriptor source,
                    FaceDistanceMap distances, const NamedParameters& np = parameters::default_values())
{
  face_distances(tm, std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>(1, source),
                 distances, np);
}

} // namespace SpectralSeg

#endif // SPECTRALSEG_FACE_DISTANCES_H
