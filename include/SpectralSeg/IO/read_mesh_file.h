// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_mesh_file.h
/// \brief Reading OFF, OBJ, PLY and STL files into a checked, repaired triangle mesh.
#ifndef SPECTRALSEG_IO_READ_MESH_FILE_H
#define SPECTRALSEG_IO_READ_MESH_FILE_H

#include <SpectralSeg/IO/Mesh_file_report.h>
#include <SpectralSeg/exceptions.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cerrno>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <unordered_map>
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

// Whether the text of a file holds a token that C++ streams read as a
// non-finite number; used to explain why a reader failed.
inline bool file_mentions_non_finite(const std::string& path)
{
  std::ifstream in(path);
  std::string token;
  while(in >> token)
  {
    std::string t = token;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if(t.front() == '-' || t.front() == '+')
      t.erase(0, 1);
    if(t == "nan" || t == "inf" || t == "infinity" || t.rfind("nan(", 0) == 0 || t == "-nan")
      return true;
  }
  return false;
}

// Triangulates one polygon (given by positions) with CGAL's minimum-area
// polyline triangulation; falls back to a fan if that fails.
template <typename Point>
std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<Point>& polygon)
{
  std::vector<std::array<std::size_t, 3>> out;
  std::vector<CGAL::Triple<int, int, int>> triples;
  try
  {
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polygon, std::back_inserter(triples));
  }
  catch(const CGAL::Failure_exception&)
  {
    triples.clear();
  }
  if(triples.size() + 2 == polygon.size())
  {
    for(const auto& t : triples)
      out.push_back({std::size_t(t.first), std::size_t(t.second), std::size_t(t.third)});
    return out;
  }
  for(std::size_t i = 1; i + 1 < polygon.size(); ++i)
    out.push_back({0, i, i + 1});
  return out;
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
///         cannot be parsed
/// \throws Invalid_input if it holds a non-finite coordinate or no usable face
template <typename Point>
Mesh_file_report read_mesh_file(const std::string& path, CGAL::Surface_mesh<Point>& mesh)
{
  Mesh_file_report report;
  report.path = path;
  mesh.clear();

  {
    std::ifstream probe(path, std::ios::binary);
    if(!probe)
      throw Io_error("cannot open '" + path + "': " + std::strerror(errno));
    probe.seekg(0, std::ios::end);
    if(probe.tellg() <= 0)
      throw Io_error("'" + path + "' is empty");
  }
  const std::string ext = internal::lowercase_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
    throw Io_error("'" + path + "': unknown mesh format '" + ext + "' (use .off, .obj, .ply or .stl)");

  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  try
  {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons);
  }
  catch(const std::exception&)
  {
    ok = false;
  }
  if(!ok)
  {
    if(internal::file_mentions_non_finite(path))
      throw Invalid_input("'" + path + "' holds a non-finite coordinate (NaN or infinity)");
    throw Io_error("cannot parse '" + path + "' as " + ext + " (malformed or truncated file)");
  }
  report.input_vertices = points.size();
  report.input_faces = polygons.size();
  if(polygons.empty())
    throw Invalid_input("'" + path + "' holds no face");
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(CGAL::to_double(points[v][c])))
        throw Invalid_input("'" + path + "': vertex " + std::to_string(v) +
                            " has a non-finite coordinate (NaN or infinity)");

  // Merge vertices with identical coordinates.
  std::vector<std::size_t> weld(points.size());
  {
    std::map<std::tuple<double, double, double>, std::size_t> first;
    std::vector<Point> unique;
    for(std::size_t v = 0; v < points.size(); ++v)
    {
      const auto key = std::make_tuple(CGAL::to_double(points[v].x()), CGAL::to_double(points[v].y()),
                                       CGAL::to_double(points[v].z()));
      auto it = first.emplace(key, unique.size());
      if(it.second)
        unique.push_back(points[v]);
      weld[v] = it.first->second;
    }
    report.merged_vertices = points.size() - unique.size();
    points.swap(unique);
  }

  // Clean, triangulate and deduplicate the faces, recording where each goes.
  std::vector<std::vector<std::size_t>> triangles;
  std::vector<std::size_t> input_face_of_triangle;
  std::vector<std::size_t> first_triangle(polygons.size(), Mesh_file_report::no_face);
  std::map<std::vector<std::size_t>, std::size_t> seen; // sorted vertices -> input face
  std::vector<std::size_t> duplicate_of(polygons.size(), Mesh_file_report::no_face);
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    std::vector<std::size_t> poly;
    for(std::size_t v : polygons[p])
    {
      if(v >= weld.size())
        throw Io_error("'" + path + "': face " + std::to_string(p) + " refers to a missing vertex");
      const std::size_t w = weld[v];
      if(poly.empty() || poly.back() != w)
        poly.push_back(w);
    }
    while(poly.size() > 1 && poly.front() == poly.back())
      poly.pop_back();
    std::vector<std::size_t> key = poly;
    std::sort(key.begin(), key.end());
    if(poly.size() < 3 || std::adjacent_find(key.begin(), key.end()) != key.end())
    {
      ++report.invalid_faces;
      continue;
    }
    auto it = seen.emplace(key, p);
    if(!it.second)
    {
      ++report.duplicate_faces;
      duplicate_of[p] = it.first->second;
      continue;
    }
    first_triangle[p] = triangles.size();
    if(poly.size() == 3)
    {
      triangles.push_back(poly);
      input_face_of_triangle.push_back(p);
      continue;
    }
    ++report.non_triangle_faces;
    std::vector<Point> positions;
    for(std::size_t v : poly)
      positions.push_back(points[v]);
    for(const auto& t : internal::triangulate_polygon(positions))
    {
      ++report.triangles_from_polygons;
      triangles.push_back({poly[t[0]], poly[t[1]], poly[t[2]]});
      input_face_of_triangle.push_back(p);
    }
  }
  if(triangles.empty())
    throw Invalid_input("'" + path + "' holds no usable face (every face has fewer than three distinct vertices)");
  // Non-manifold edges of the welded soup: edges with more than two faces.
  {
    std::unordered_map<std::uint64_t, unsigned> count;
    for(const auto& t : triangles)
      for(int i = 0; i < 3; ++i)
      {
        std::uint64_t a = t[i], b = t[(i + 1) % 3];
        if(a > b)
          std::swap(a, b);
        ++count[(a << 32) | b];
      }
    for(const auto& c : count)
      if(c.second > 2)
        ++report.non_manifold_edges;
  }

  const std::size_t points_before = points.size();
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, triangles);
  report.split_vertices = points.size() - points_before;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  if(num_faces(mesh) != triangles.size())
    throw Invalid_input("'" + path + "': the faces could not be assembled into a mesh");

  // Surface_mesh numbers faces in insertion order: triangle t is face t.
  report.face_of_input_face.assign(polygons.size(), Mesh_file_report::no_face);
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    if(first_triangle[p] != Mesh_file_report::no_face)
      report.face_of_input_face[p] = first_triangle[p];
    else if(duplicate_of[p] != Mesh_file_report::no_face)
      report.face_of_input_face[p] = first_triangle[duplicate_of[p]];
  }
  report.input_face_of_face = input_face_of_triangle;

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
