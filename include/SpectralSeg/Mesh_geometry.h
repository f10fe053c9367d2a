// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Mesh_geometry.h
/// \brief A compact, mesh-type-independent copy of a triangle mesh's geometry.
#ifndef SPECTRALSEG_MESH_GEOMETRY_H
#define SPECTRALSEG_MESH_GEOMETRY_H

#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>
#include <SpectralSeg/named_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegCore
/// \brief Indexed triangles, per-face centroids, unit normals and areas, in
/// double precision, in the order of the mesh's face index map.
///
/// Every algorithm of the library works on this copy, so that their inner
/// loops do not depend on the mesh type or on property-map look-ups. A face
/// whose area is zero or negligible (below \f$10^{-14}\f$ times the squared
/// bounding-box diagonal) is *degenerate*: its normal is not defined by its
/// own vertices, so it takes the normalised area-weighted mean of its
/// neighbours' normals (propagated across runs of degenerate faces), and it
/// keeps a zero normal only when no neighbour has one.
struct Mesh_geometry
{
  /// vertex positions, in the order of the vertex index map
  std::vector<Eigen::Vector3d> points;
  /// the three vertex indices of each face, in the face's orientation
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// face centroids
  std::vector<Eigen::Vector3d> centroids;
  /// unit face normals (see the class description for degenerate faces)
  std::vector<Eigen::Vector3d> normals;
  /// face areas
  std::vector<double> areas;
  /// 1 for a degenerate face, 0 otherwise
  std::vector<std::uint8_t> degenerate;
  /// length of the diagonal of the axis-aligned bounding box
  double bbox_diagonal = 0.;

  /// number of faces
  std::size_t number_of_faces() const { return triangles.size(); }
  /// number of vertices
  std::size_t number_of_vertices() const { return points.size(); }
  /// number of degenerate faces
  std::size_t number_of_degenerate_faces() const
  {
    std::size_t n = 0;
    for(std::uint8_t d : degenerate)
      n += d;
    return n;
  }

  /// Fills `centroids`, `normals`, `areas`, `degenerate` and `bbox_diagonal`
  /// from `points` and `triangles`; throws `Invalid_input` on a non-finite
  /// coordinate or an out-of-range vertex index. Degenerate faces get a zero
  /// normal here; `Dual_graph` then gives them their neighbours' normal.
  void compute_face_attributes();
};

#if SPECTRALSEG_DEFINE_FUNCTIONS
SPECTRALSEG_INLINE void Mesh_geometry::compute_face_attributes()
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    const Eigen::Vector3d& p = points[v];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Invalid_input("vertex " + std::to_string(v) + " has a non-finite coordinate (NaN or infinity)");
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bbox_diagonal = points.empty() ? 0. : (hi - lo).norm();
  const double area_tolerance = 1e-14 * bbox_diagonal * bbox_diagonal;

  const std::size_t nf = triangles.size();
  centroids.resize(nf);
  normals.resize(nf);
  areas.resize(nf);
  degenerate.assign(nf, 0);
  for(std::size_t f = 0; f < nf; ++f)
  {
    for(std::uint32_t v : triangles[f])
      if(v >= points.size())
        throw Invalid_input("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                            " but the mesh has " + std::to_string(points.size()) + " vertices");
    const Eigen::Vector3d& a = points[triangles[f][0]];
    const Eigen::Vector3d& b = points[triangles[f][1]];
    const Eigen::Vector3d& c = points[triangles[f][2]];
    centroids[f] = (a + b + c) / 3.;
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double twice_area = n.norm();
    areas[f] = 0.5 * twice_area;
    if(areas[f] <= area_tolerance || !(twice_area > 0))
    {
      degenerate[f] = 1;
      normals[f].setZero();
    }
    else
      normals[f] = n / twice_area;
  }
}
#endif

/// \ingroup PkgSpectralSegCore
/// \brief Copies the geometry of a triangle mesh into a `Mesh_geometry`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         whose faces are all triangles
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`, in any CGAL kernel (converted to `double`)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in `[0, num_vertices(tm))`: the order of `Mesh_geometry::points`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map (iteration order for meshes without internal indices)}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in `[0, num_faces(tm))`: the order of every per-face array}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map (iteration order for meshes without internal indices)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input if a face is not a triangle or a coordinate is not finite.
template <typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Mesh_geometry extract_mesh_geometry(const TriangleMesh& tm,
                                    const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);

  Mesh_geometry g;
  g.points.resize(num_vertices(tm));
  for(typename GT::vertex_descriptor v : vertices(tm))
  {
    const auto& p = get(vpm, v);
    g.points[get(vim, v)] = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                            CGAL::to_double(p.z()));
  }
  g.triangles.resize(num_faces(tm));
  for(typename GT::face_descriptor f : faces(tm))
  {
    const std::size_t fi = get(fim, f);
    const typename GT::halfedge_descriptor h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      throw Invalid_input("face " + std::to_string(fi) + " is not a triangle; triangulate the mesh first "
                          "(CGAL::Polygon_mesh_processing::triangulate_faces)");
    g.triangles[fi] = {static_cast<std::uint32_t>(get(vim, source(h, tm))),
                       static_cast<std::uint32_t>(get(vim, target(h, tm))),
                       static_cast<std::uint32_t>(get(vim, target(next(h, tm), tm)))};
  }
  g.compute_face_attributes();
  return g;
}

} // namespace SpectralSeg

#endif // SPECTRALSEG_MESH_GEOMETRY_H
