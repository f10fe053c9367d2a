// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file repair_polygon_soup.h
/// \brief The repairs of `read_mesh_file()`, one function per step: welding
/// identical vertices, cleaning, deduplicating and triangulating faces,
/// counting non-manifold edges.
#ifndef SPECTRALSEG_IO_INTERNAL_REPAIR_POLYGON_SOUP_H
#define SPECTRALSEG_IO_INTERNAL_REPAIR_POLYGON_SOUP_H

#include <SpectralSeg/IO/Mesh_file_report.h>
#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/exceptions.h>

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <map>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// Merges the points with identical coordinates: returns, for each point of
// the soup, its index among the merged points, which replace `points`.
inline std::vector<std::size_t> weld_identical_vertices(std::vector<std::array<double, 3>>& points)
{
  std::vector<std::size_t> weld(points.size());
  std::map<std::array<double, 3>, std::size_t> first;
  std::vector<std::array<double, 3>> unique;
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    auto it = first.emplace(points[v], unique.size());
    if(it.second)
      unique.push_back(points[v]);
    weld[v] = it.first->second;
  }
  points.swap(unique);
  return weld;
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

// The triangles of the cleaned soup and where each face of the file went.
struct Clean_triangles
{
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::size_t> input_face_of_triangle;
  std::vector<std::size_t> first_triangle; // per file face, or no_face
  std::vector<std::size_t> duplicate_of;   // per file face: the face it repeats, or no_face
};

// Maps faces to welded vertices, drops faces with fewer than three
// distinct vertices and repeats of an earlier face's vertex set, and
// triangulates polygons; counts each in `report`.
template <typename Point>
Clean_triangles clean_and_triangulate_faces(const Polygon_soup& soup, const std::vector<std::size_t>& weld,
                                            Mesh_file_report& report)
{
  const std::size_t faces = soup.number_of_faces();
  Clean_triangles out;
  out.first_triangle.assign(faces, Mesh_file_report::no_face);
  out.duplicate_of.assign(faces, Mesh_file_report::no_face);
  out.triangles.reserve(faces);
  out.input_face_of_triangle.reserve(faces);
  std::map<std::vector<std::size_t>, std::size_t> seen; // sorted vertices -> file face
  std::vector<std::size_t> poly;
  for(std::size_t p = 0; p < faces; ++p)
  {
    poly.clear();
    for(std::size_t i = 0; i < soup.face_size(p); ++i)
    {
      const std::size_t w = weld[soup.face(p)[i]];
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
    auto it = seen.emplace(std::move(key), p);
    if(!it.second)
    {
      ++report.duplicate_faces;
      out.duplicate_of[p] = it.first->second;
      continue;
    }
    out.first_triangle[p] = out.triangles.size();
    if(poly.size() == 3)
    {
      out.triangles.push_back({poly[0], poly[1], poly[2]});
      out.input_face_of_triangle.push_back(p);
      continue;
    }
    ++report.non_triangle_faces;
    std::vector<Point> positions;
    for(std::size_t v : poly)
      positions.push_back(Point(soup.points[v][0], soup.points[v][1], soup.points[v][2]));
    for(const auto& t : triangulate_polygon(positions))
    {
      ++report.triangles_from_polygons;
      out.triangles.push_back({poly[t[0]], poly[t[1]], poly[t[2]]});
      out.input_face_of_triangle.push_back(p);
    }
  }
  return out;
}

// Edges of the triangles shared by more than two of them.
inline std::size_t count_non_manifold_edges(const std::vector<std::array<std::size_t, 3>>& triangles)
{
  std::unordered_map<std::uint64_t, unsigned> count;
  count.reserve(3 * triangles.size() / 2);
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i)
    {
      std::uint64_t a = t[std::size_t(i)], b = t[std::size_t((i + 1) % 3)];
      if(a > b)
        std::swap(a, b);
      ++count[(a << 32) | b];
    }
  std::size_t n = 0;
  for(const auto& c : count)
    n += c.second > 2 ? 1 : 0;
  return n;
}

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_REPAIR_POLYGON_SOUP_H
