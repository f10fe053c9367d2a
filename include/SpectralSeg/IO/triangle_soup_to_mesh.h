// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file triangle_soup_to_mesh.h
/// \brief A checked, repaired triangle mesh from arrays of points and
/// triangles, with the repairs of `read_mesh_file()`.
#ifndef SPECTRALSEG_IO_TRIANGLE_SOUP_TO_MESH_H
#define SPECTRALSEG_IO_TRIANGLE_SOUP_TO_MESH_H

#include <SpectralSeg/IO/Mesh_file_report.h>
#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/oriented_manifold_soup_to_mesh.h>
#include <SpectralSeg/IO/internal/repair_polygon_soup.h>
#include <SpectralSeg/IO/internal/spatial_order.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/execution_from.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The repairs of read_mesh_file() on the soup of a file (or of arrays):
// `name` names the soup in the messages ("'path'"), `triangulate` splits
// polygons into triangles (see clean_and_triangulate_faces()). Fills every
// field of the report but `path`. Its sorts run on `threads` threads (the
// same mesh on any number).
template <typename Point, typename Triangulate>
Mesh_file_report polygon_soup_to_mesh(Polygon_soup& soup, const std::string& name, CGAL::Surface_mesh<Point>& mesh,
                                      const Triangulate& triangulate, unsigned threads = 1)
{
  Mesh_file_report report;
  mesh.clear();
  report.input_vertices = soup.points.size();
  report.input_faces = soup.number_of_faces();
  report.ignored_elements = soup.ignored_elements;
  if(soup.number_of_faces() == 0)
    throw Invalid_input(name + " holds no face");

  const std::vector<std::size_t> weld = weld_identical_vertices(soup.points, threads);
  report.merged_vertices = report.input_vertices - soup.points.size();
  Clean_triangles clean = clean_and_triangulate_faces<Point>(soup, weld, report, triangulate, threads);
  if(clean.triangles.empty())
    throw Invalid_input(name + " holds no usable face (every face has fewer than three distinct vertices)");
  const std::size_t distinct = report.input_faces - report.invalid_faces - report.duplicate_faces;
  if(report.duplicate_faces > distinct)
    throw Invalid_input(name + ": " + std::to_string(report.duplicate_faces) + " of its " +
                        std::to_string(report.input_faces) + " faces repeat another face, leaving only " +
                        std::to_string(distinct) +
                        " distinct faces: the file is mostly copies of the same faces, not a surface");
  // an oriented manifold soup (the usual file) has no non-manifold edge and
  // needs no orientation pass
  const bool oriented_manifold = is_oriented_manifold_soup(soup.points.size(), clean.triangles, threads);
  report.non_manifold_edges = oriented_manifold ? 0 : count_non_manifold_edges(clean.triangles);

  // vertices no kept face uses are left out:
  // CGAL counts an isolated vertex as an invalid polygon mesh, and a stray
  // point would widen the bounding box that framing and scales are taken from
  std::vector<std::array<std::size_t, 3>>& triangles = clean.triangles;
  std::vector<std::size_t> new_index(soup.points.size(), 0);
  for(const std::array<std::size_t, 3>& t : triangles)
    for(const std::size_t v : t)
      new_index[v] = 1;
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(std::size_t v = 0; v < soup.points.size(); ++v)
    if(new_index[v] != 0)
    {
      new_index[v] = points.size();
      points.push_back(Point(soup.points[v][0], soup.points[v][1], soup.points[v][2]));
    }
  for(std::array<std::size_t, 3>& t : triangles)
    for(std::size_t& v : t)
      v = new_index[v];
  report.unused_vertices = soup.points.size() - points.size();
  const std::size_t points_before = points.size();
  if(!oriented_manifold)
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, triangles);
  report.split_vertices = points.size() - points_before;
  // vertices and faces along Hilbert curves: neighbours in the mesh become
  // neighbours in memory, and the file's order stops mattering
  const std::vector<std::size_t> new_triangle = sort_along_hilbert_curve(points, triangles, threads);
  // CGAL's construction is quadratic in a vertex's degree; the mesh it
  // would make is made directly when the soup allows it (always, unless
  // orienting it failed)
  if(oriented_manifold || is_oriented_manifold_soup(points.size(), triangles, threads))
    oriented_manifold_soup_to_mesh(points, triangles, mesh, threads);
  else
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  if(num_faces(mesh) != triangles.size())
    throw Invalid_input(name + ": the faces could not be assembled into a mesh");

  // Surface_mesh numbers faces in insertion order: triangle t is face t.
  report.face_of_input_face.assign(report.input_faces, Mesh_file_report::no_face);
  for(std::size_t p = 0; p < report.input_faces; ++p)
  {
    if(clean.first_triangle[p] != Mesh_file_report::no_face)
      report.face_of_input_face[p] = new_triangle[clean.first_triangle[p]];
    else if(clean.duplicate_of[p] != Mesh_file_report::no_face)
      report.face_of_input_face[p] = new_triangle[clean.first_triangle[clean.duplicate_of[p]]];
  }
  report.input_face_of_face.assign(triangles.size(), 0);
  for(std::size_t t = 0; t < triangles.size(); ++t)
    report.input_face_of_face[new_triangle[t]] = clean.input_face_of_triangle[t];

  report.closed = CGAL::is_closed(mesh);
  if(report.closed)
  {
    try
    {
      CGAL::Polygon_mesh_processing::orient(mesh, CGAL::parameters::outward_orientation(true));
    }
    catch(const CGAL::Failure_exception&)
    {
      report.warnings.push_back("could not orient the closed mesh outward (degenerate geometry); "
                                "the file's orientation is kept");
    }
  }
  report.finish();
  return report;
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegIO
/// \brief Builds a `CGAL::Surface_mesh` from a triangle soup given as
/// arrays (as numpy, trimesh, Open3D or libigl hold a mesh), checked and
/// repaired exactly as `read_mesh_file()` repairs a file's faces.
///
/// The repairs (identical vertices welded, triangles with fewer than three
/// distinct vertices and repeated triangles dropped, vertices no triangle
/// uses left out, non-manifold edges and
/// vertices split, consistent orientation, closed meshes oriented outward)
/// are counted in the returned report, with a warning each;
/// `Mesh_file_report::face_of_input_face` maps each triangle of
/// `triangles` to the mesh face that carries its values, so that
/// `values_in_input_order()` gives per-face results in the order of
/// `triangles`. `Mesh_file_report::path` is left empty.
///
/// \tparam Point a CGAL point type
/// \tparam NamedParameters a sequence of named parameters
/// \param points the vertex coordinates
/// \param triangles three indices into `points` per triangle
/// \param mesh receives the mesh (cleared first), its vertices and faces
///        along Hilbert curves as in `read_mesh_file()`; its face `f` comes
///        from triangle `report.input_face_of_face[f]`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads of the sorts (welding, repeated triangles, the Hilbert order); 0 means all hardware threads. The mesh does not depend on it}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input if a coordinate is not finite, an index is not
///         below `points.size()`, there is no triangle, no usable triangle,
///         or more repeated triangles than distinct ones
template <typename Point, typename NamedParameters = parameters::Default_named_parameters>
Mesh_file_report triangle_soup_to_mesh(const std::vector<std::array<double, 3>>& points,
                                       const std::vector<std::array<std::size_t, 3>>& triangles,
                                       CGAL::Surface_mesh<Point>& mesh,
                                       const NamedParameters& np = parameters::default_values())
{
  mesh.clear();
  internal::Polygon_soup soup;
  soup.points = points;
  for(std::size_t v = 0; v < points.size(); ++v)
    for(double c : points[v])
      if(!std::isfinite(c))
        throw Invalid_input("the triangle soup: vertex " + std::to_string(v) + " has a non-finite coordinate");
  soup.corners.reserve(3 * triangles.size());
  soup.face_begin.reserve(triangles.size() + 1);
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    for(std::size_t v : triangles[t])
    {
      if(v >= points.size())
        throw Invalid_input("the triangle soup: triangle " + std::to_string(t) + " has vertex index " +
                            std::to_string(v) + ", but there are " + std::to_string(points.size()) + " vertices");
      soup.corners.push_back(v);
    }
    soup.end_face();
  }
  // Triangles need no triangulation: after welding they have three
  // distinct vertices or are dropped.
  const auto no_polygons = [](const std::vector<Point>&) { return std::vector<std::array<std::size_t, 3>>(); };
  return internal::polygon_soup_to_mesh(soup, "the triangle soup", mesh, no_polygons,
                                        SpectralSeg::internal::execution_from(np).threads());
}

/// \cond SKIP_IN_MANUAL
#if SPECTRALSEG_DEFAULT_INSTANCES
SPECTRALSEG_INSTANTIATE Mesh_file_report triangle_soup_to_mesh<CGAL::Epick::Point_3>(
  const std::vector<std::array<double, 3>>&, const std::vector<std::array<std::size_t, 3>>&,
  CGAL::Surface_mesh<CGAL::Epick::Point_3>&, const parameters::Default_named_parameters&);
#endif
/// \endcond

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_TRIANGLE_SOUP_TO_MESH_H
