// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_mesh_file.h
/// \brief Reading OFF, OBJ, PLY and STL files into a checked, repaired triangle mesh.
#ifndef SPECTRALSEG_IO_READ_MESH_FILE_H
#define SPECTRALSEG_IO_READ_MESH_FILE_H

#include <SpectralSeg/IO/Mesh_file_report.h>
#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/read_obj.h>
#include <SpectralSeg/IO/internal/read_off.h>
#include <SpectralSeg/IO/internal/read_ply.h>
#include <SpectralSeg/IO/internal/read_stl.h>
#include <SpectralSeg/IO/internal/repair_polygon_soup.h>
#include <SpectralSeg/exceptions.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

inline std::string lowercase_extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// The points and faces of a file, as the file gives them, by format.
inline Polygon_soup read_polygon_soup(const std::string& path)
{
  const std::string ext = lowercase_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
  {
    const File_bytes probe = read_file_bytes(path); // a missing file says so first
    throw Io_error("'" + path + "': unknown mesh format '" + ext + "' (use .off, .obj, .ply or .stl)");
  }
  const File_bytes file = read_file_bytes(path);
  Polygon_soup soup;
  if(ext == "off")
    read_off(file, soup);
  else if(ext == "obj")
    read_obj(file, soup);
  else if(ext == "ply")
    read_ply(file, soup);
  else
    read_stl(file, soup);
  return soup;
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegIO
/// \brief Reads a mesh file (OFF, OBJ, PLY or STL, by extension, in any
/// letter case), checks it and repairs what can be repaired without
/// changing the shape, into a `CGAL::Surface_mesh`.
///
/// Repairs, each counted in the report with a warning:
/// - vertices with exactly the same coordinates are merged (STL files and
///   unwelded exports store each triangle's corners separately);
/// - faces with more than three vertices are triangulated (minimum-area
///   triangulation of the polygon);
/// - faces with fewer than three distinct vertices are dropped;
/// - duplicate faces (the same vertex set) are dropped, keeping the first;
/// - non-manifold edges and vertices are split (CGAL's
///   `orient_polygon_soup()`), so faces across a non-manifold edge are not
///   adjacent;
/// - faces are oriented consistently, and, when the whole mesh is closed,
///   each component outward (an open mesh keeps the orientation the
///   consistent-orientation pass gives it; concavity depends on it).
///
/// Refused, with the line (or byte, or element) at fault: anything the
/// format does not allow (a malformed number, a fractional, negative or
/// overflowing index, an index past the vertices, an unknown statement or
/// property type), counts in the header that the file's size cannot hold
/// (checked before anything is allocated), data after the last announced
/// element, a non-finite coordinate (`Invalid_input`), faces of more than
/// `max_face_vertices` vertices, and a file in which the repeats of other
/// faces outnumber the distinct faces (`Invalid_input`). Legal content that
/// carries no face is skipped: OBJ texture coordinates, normals, groups,
/// materials, `l` and `p` elements (counted in `ignored_elements`); PLY
/// elements and properties other than the vertex coordinates and face
/// lists, whatever their types. The whole file is read into memory first.
///
/// Degenerate (zero-area) faces are kept and reported: the library handles
/// them (see `Mesh_geometry`). Open meshes and several connected components
/// are valid input.
///
/// `Mesh_file_report::face_of_input_face` maps each face of the file to the
/// mesh face that carries its values, so that per-face outputs can be
/// written in the file's face order with `write_face_values()`.
///
/// \tparam Point a CGAL point type
/// \throws Io_error if the file is missing, empty, of an unknown format or
///         malformed (the message names the line, byte or element)
/// \throws Invalid_input if it holds a non-finite coordinate, no usable face
///         or mostly repeated faces
template <typename Point>
Mesh_file_report read_mesh_file(const std::string& path, CGAL::Surface_mesh<Point>& mesh)
{
  Mesh_file_report report;
  report.path = path;
  mesh.clear();

  internal::Polygon_soup soup = internal::read_polygon_soup(path);
  report.input_vertices = soup.points.size();
  report.input_faces = soup.number_of_faces();
  report.ignored_elements = soup.ignored_elements;
  if(soup.number_of_faces() == 0)
    throw Invalid_input("'" + path + "' holds no face");

  const std::vector<std::size_t> weld = internal::weld_identical_vertices(soup.points);
  report.merged_vertices = report.input_vertices - soup.points.size();
  internal::Clean_triangles clean = internal::clean_and_triangulate_faces<Point>(soup, weld, report);
  if(clean.triangles.empty())
    throw Invalid_input("'" + path + "' holds no usable face (every face has fewer than three distinct vertices)");
  const std::size_t distinct = report.input_faces - report.invalid_faces - report.duplicate_faces;
  if(report.duplicate_faces > distinct)
    throw Invalid_input("'" + path + "': " + std::to_string(report.duplicate_faces) + " of its " +
                        std::to_string(report.input_faces) + " faces repeat another face, leaving only " +
                        std::to_string(distinct) +
                        " distinct faces: the file is mostly copies of the same faces, not a surface");
  // an oriented manifold soup (the usual file) has no non-manifold edge and
  // needs no orientation pass
  const bool oriented_manifold = internal::is_oriented_manifold_soup(soup.points.size(), clean.triangles);
  report.non_manifold_edges = oriented_manifold ? 0 : internal::count_non_manifold_edges(clean.triangles);

  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points)
    points.push_back(Point(p[0], p[1], p[2]));
  std::vector<std::array<std::size_t, 3>>& triangles = clean.triangles;
  const std::size_t points_before = points.size();
  if(!oriented_manifold)
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, triangles);
  report.split_vertices = points.size() - points_before;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  if(num_faces(mesh) != triangles.size())
    throw Invalid_input("'" + path + "': the faces could not be assembled into a mesh");

  // Surface_mesh numbers faces in insertion order: triangle t is face t.
  report.face_of_input_face.assign(report.input_faces, Mesh_file_report::no_face);
  for(std::size_t p = 0; p < report.input_faces; ++p)
  {
    if(clean.first_triangle[p] != Mesh_file_report::no_face)
      report.face_of_input_face[p] = clean.first_triangle[p];
    else if(clean.duplicate_of[p] != Mesh_file_report::no_face)
      report.face_of_input_face[p] = clean.first_triangle[clean.duplicate_of[p]];
  }
  report.input_face_of_face = std::move(clean.input_face_of_triangle);

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

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_READ_MESH_FILE_H
