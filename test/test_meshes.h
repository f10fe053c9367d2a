// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Small meshes built in the tests, with known geometry.
#ifndef SPECTRALSEG_TEST_MESHES_H
#define SPECTRALSEG_TEST_MESHES_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace test_meshes {

struct Soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;
};

// A strip of `squares` unit squares along x, each split by its diagonal
// (0,0)-(1,1) into a lower triangle (even face) and an upper one (odd face).
inline Soup square_strip(std::size_t squares)
{
  Soup s;
  for(std::size_t i = 0; i <= squares; ++i)
  {
    s.points.push_back({double(i), 0., 0.});
    s.points.push_back({double(i), 1., 0.});
  }
  for(std::size_t i = 0; i < squares; ++i)
  {
    const std::size_t a = 2 * i, b = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1; // (i,0) (i+1,0) (i+1,1) (i,1)
    s.faces.push_back({a, b, c});
    s.faces.push_back({a, c, d});
  }
  return s;
}

// A strip of `triangles` equilateral triangles of side 1 (alternately up and down).
inline Soup equilateral_strip(std::size_t triangles)
{
  Soup s;
  const double h = std::sqrt(3.) / 2.;
  const std::size_t bottom = triangles / 2 + 2, top = triangles / 2 + 2;
  for(std::size_t i = 0; i < bottom; ++i)
    s.points.push_back({double(i), 0., 0.});
  for(std::size_t i = 0; i < top; ++i)
    s.points.push_back({double(i) + 0.5, h, 0.});
  for(std::size_t t = 0; t < triangles; ++t)
  {
    const std::size_t i = t / 2;
    if(t % 2 == 0)
      s.faces.push_back({i, i + 1, bottom + i}); // up
    else
      s.faces.push_back({i + 1, bottom + i + 1, bottom + i}); // down
  }
  return s;
}

// Two triangles sharing the edge (0,0,0)-(0,1,0), the second one rotated about
// that edge so that the normals make the angle `angle` (radians). With
// `concave`, the fold is a valley seen from the side the normals point to.
inline Soup fold(double angle, bool concave)
{
  Soup s;
  s.points = {{0., 0., 0.}, {0., 1., 0.}, {-1., 0.5, 0.}};
  const double sign = concave ? 1. : -1.;
  s.points.push_back({std::cos(angle), 0.5, sign * std::sin(angle)});
  // first face in the plane z = 0 with normal +z; second shares edge 0-1
  s.faces = {{0, 1, 2}, {1, 0, 3}};
  return s;
}

// An axis-aligned box [0,sx]x[0,sy]x[0,sz] subdivided into n x n quads per
// face, triangulated, outward oriented.
inline Soup box(double sx, double sy, double sz, std::size_t n)
{
  Soup s;
  auto add_face = [&](std::array<double, 3> o, std::array<double, 3> u, std::array<double, 3> v) {
    const std::size_t base = s.points.size();
    for(std::size_t j = 0; j <= n; ++j)
      for(std::size_t i = 0; i <= n; ++i)
        s.points.push_back({o[0] + u[0] * i / n + v[0] * j / n, o[1] + u[1] * i / n + v[1] * j / n,
                            o[2] + u[2] * i / n + v[2] * j / n});
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i)
      {
        const std::size_t a = base + j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
        s.faces.push_back({a, b, c});
        s.faces.push_back({a, c, d});
      }
  };
  add_face({0, 0, 0}, {0, sy, 0}, {sx, 0, 0});   // z = 0, normal -z
  add_face({0, 0, sz}, {sx, 0, 0}, {0, sy, 0});  // z = sz, normal +z
  add_face({0, 0, 0}, {sx, 0, 0}, {0, 0, sz});   // y = 0, normal -y
  add_face({0, sy, 0}, {0, 0, sz}, {sx, 0, 0});  // y = sy, normal +y
  add_face({0, 0, 0}, {0, 0, sz}, {0, sy, 0});   // x = 0, normal -x
  add_face({sx, 0, 0}, {0, sy, 0}, {0, 0, sz});  // x = sx, normal +x
  return s;
}

// Builds a CGAL mesh (Surface_mesh, Polyhedron_3, ...) from a soup; the
// coincident points of `box` are merged by the caller's choice of soup.
template <typename Mesh>
Mesh to_mesh(const Soup& s)
{
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  std::vector<Point> points;
  for(const auto& p : s.points)
    points.emplace_back(p[0], p[1], p[2]);
  Mesh m;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, s.faces, m);
  return m;
}

// Merges coincident points (exact), as needed after `box`.
inline Soup welded(const Soup& in)
{
  Soup out;
  std::vector<std::size_t> map(in.points.size());
  for(std::size_t i = 0; i < in.points.size(); ++i)
  {
    std::size_t j = 0;
    for(; j < out.points.size(); ++j)
      if(out.points[j] == in.points[i])
        break;
    if(j == out.points.size())
      out.points.push_back(in.points[i]);
    map[i] = j;
  }
  for(const auto& f : in.faces)
  {
    std::vector<std::size_t> g;
    for(std::size_t v : f)
      g.push_back(map[v]);
    out.faces.push_back(g);
  }
  return out;
}

} // namespace test_meshes

#endif
