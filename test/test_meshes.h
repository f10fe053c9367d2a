// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Small meshes built in the tests, with known geometry.
#ifndef SPECTRALSEG_TEST_MESHES_H
#define SPECTRALSEG_TEST_MESHES_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <map>
#include <set>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace test_meshes {

constexpr double pi = 3.14159265358979323846;

struct Soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;
  std::vector<int> face_part; // optional: the known part of each face
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

// The closed surface of a union of unit voxels (given as integer cells),
// each exposed voxel side split into s x s squares of two triangles,
// outward oriented. Cells must not touch along an edge or a vertex only.
inline Soup voxel_union(const std::vector<std::array<int, 3>>& cells, int s, const std::vector<int>& cell_part = {})
{
  std::set<std::array<int, 3>> filled(cells.begin(), cells.end());
  std::map<std::array<long, 3>, std::size_t> vertex;
  Soup out;
  auto vid = [&](std::array<long, 3> p) {
    auto it = vertex.emplace(p, out.points.size());
    if(it.second)
      out.points.push_back({double(p[0]) / s, double(p[1]) / s, double(p[2]) / s});
    return it.first->second;
  };
  for(const auto& c : cells)
    for(int axis = 0; axis < 3; ++axis)
      for(int side = 0; side < 2; ++side)
      {
        std::array<int, 3> nb = c;
        nb[axis] += side ? 1 : -1;
        if(filled.count(nb))
          continue;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for(int i = 0; i < s; ++i)
          for(int j = 0; j < s; ++j)
          {
            auto corner = [&](int di, int dj) {
              std::array<long, 3> p{long(c[0]) * s, long(c[1]) * s, long(c[2]) * s};
              p[axis] += side ? s : 0;
              p[u] += i + di;
              p[v] += j + dj;
              return vid(p);
            };
            const std::size_t a = corner(0, 0), b = corner(1, 0), cc = corner(1, 1), d = corner(0, 1);
            // (u, v, axis) is right-handed: u x v = +axis
            if(!cell_part.empty())
            {
              const int part = cell_part[std::size_t(&c - cells.data())];
              out.face_part.push_back(part);
              out.face_part.push_back(part);
            }
            if(side)
            {
              out.faces.push_back({a, b, cc});
              out.faces.push_back({a, cc, d});
            }
            else
            {
              out.faces.push_back({a, cc, b});
              out.faces.push_back({a, d, cc});
            }
          }
      }
  return out;
}

// A T: a horizontal bar of 12 x 2 x 2 cells on top of a vertical stem of
// 2 x 2 x 6 cells, joined at the bar's middle.
inline Soup t_shape(int s)
{
  std::vector<std::array<int, 3>> cells;
  for(int x = 0; x < 12; ++x)
    for(int y = 0; y < 2; ++y)
      for(int z = 6; z < 8; ++z)
        cells.push_back({x, y, z});
  for(int x = 5; x < 7; ++x)
    for(int y = 0; y < 2; ++y)
      for(int z = 0; z < 6; ++z)
        cells.push_back({x, y, z});
  return voxel_union(cells, s);
}

// Appends the cells of the block [0, nx) x [0, ny) x [0, nz), as part 0.
inline void add_block(int nx, int ny, int nz, std::vector<std::array<int, 3>>& cells, std::vector<int>& part)
{
  for(int x = 0; x < nx; ++x)
    for(int y = 0; y < ny; ++y)
      for(int z = 0; z < nz; ++z)
      {
        cells.push_back({x, y, z});
        part.push_back(0);
      }
}

// A body (a 4 x 4 x 4 block of cells, part 0) with four limbs of 6 x 2 x 2
// cells along +x, -x, +y and -y (parts 1 to 4): a shape with five known parts.
inline Soup star(int s)
{
  std::vector<std::array<int, 3>> cells;
  std::vector<int> part;
  add_block(4, 4, 4, cells, part);
  for(int t = 0; t < 6; ++t)
    for(int a = 1; a < 3; ++a)
      for(int z = 1; z < 3; ++z)
      {
        cells.push_back({4 + t, a, z});
        part.push_back(1);
        cells.push_back({-1 - t, a, z});
        part.push_back(2);
        cells.push_back({a, 4 + t, z});
        part.push_back(3);
        cells.push_back({a, -1 - t, z});
        part.push_back(4);
      }
  return voxel_union(cells, s, part);
}

// A block of 4 x 4 x 8 cells (part 0) with one or two handles on its +x
// side (parts 1, 2): each an arch out 3 cells from the block between heights
// 1 and 6, around an opening of 2 x 4 cells, 2 cells thick (one handle) or
// 1 cell thick at y = 0 and y = 3 (two). Genus `handles`.
inline Soup block_with_handles(int s, int handles)
{
  std::vector<std::array<int, 3>> cells;
  std::vector<int> part;
  add_block(4, 4, 8, cells, part);
  std::set<std::array<int, 3>> arch;
  for(int h = 0; h < handles; ++h)
  {
    const int y0 = handles == 1 ? 1 : 3 * h, thickness = handles == 1 ? 2 : 1;
    for(int y = y0; y < y0 + thickness; ++y)
    {
      for(int x = 4; x < 7; ++x)
      {
        arch.insert({x, y, 1});
        arch.insert({x, y, 6});
      }
      for(int z = 1; z < 7; ++z)
        arch.insert({6, y, z});
    }
    for(const auto& c : arch)
    {
      cells.push_back(c);
      part.push_back(1 + h);
    }
    arch.clear();
  }
  return voxel_union(cells, s, part);
}

// A UV sphere of radius r centred at the origin.
inline Soup sphere(double r, std::size_t rings, std::size_t segments)
{
  Soup s;
  const double pi = 3.14159265358979323846;
  s.points.push_back({0., 0., r});
  for(std::size_t i = 1; i < rings; ++i)
  {
    const double th = pi * double(i) / double(rings);
    for(std::size_t j = 0; j < segments; ++j)
    {
      const double ph = 2. * pi * double(j) / double(segments);
      s.points.push_back({r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th)});
    }
  }
  s.points.push_back({0., 0., -r});
  const std::size_t south = s.points.size() - 1;
  auto at = [&](std::size_t i, std::size_t j) { return 1 + (i - 1) * segments + (j % segments); };
  for(std::size_t j = 0; j < segments; ++j)
    s.faces.push_back({0, at(1, j), at(1, j + 1)});
  for(std::size_t i = 1; i + 1 < rings; ++i)
    for(std::size_t j = 0; j < segments; ++j)
    {
      s.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  for(std::size_t j = 0; j < segments; ++j)
    s.faces.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
  return s;
}

} // namespace test_meshes

#endif
