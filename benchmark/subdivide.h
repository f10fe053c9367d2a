// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// 1-to-4 midpoint subdivision for the benchmarks: the shape is unchanged,
// the face count grows fourfold.
#ifndef SPECTRALSEG_BENCHMARK_SUBDIVIDE_H
#define SPECTRALSEG_BENCHMARK_SUBDIVIDE_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <map>
#include <utility>
#include <vector>

namespace spectralseg_bench {

// Splits each triangle into four at its edge midpoints. Faces of the result
// are numbered 4f .. 4f+3 for face f of the input.
template <typename Point>
CGAL::Surface_mesh<Point> midpoint_subdivision(const CGAL::Surface_mesh<Point>& m)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  std::vector<Point> points(m.points().begin(), m.points().end());
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
  auto mid = [&](std::size_t a, std::size_t b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = midpoint.find(key);
    if(it != midpoint.end())
      return it->second;
    points.push_back(CGAL::midpoint(points[a], points[b]));
    midpoint.emplace(key, points.size() - 1);
    return points.size() - 1;
  };
  std::vector<std::vector<std::size_t>> faces;
  faces.reserve(4 * num_faces(m));
  for(typename Mesh::Face_index f : m.faces())
  {
    std::vector<std::size_t> v;
    for(typename Mesh::Vertex_index u : vertices_around_face(m.halfedge(f), m))
      v.push_back(u);
    const std::size_t ab = mid(v[0], v[1]), bc = mid(v[1], v[2]), ca = mid(v[2], v[0]);
    faces.push_back({v[0], ab, ca});
    faces.push_back({ab, v[1], bc});
    faces.push_back({ca, bc, v[2]});
    faces.push_back({ab, bc, ca});
  }
  Mesh out;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, out);
  return out;
}

} // namespace spectralseg_bench

#endif
