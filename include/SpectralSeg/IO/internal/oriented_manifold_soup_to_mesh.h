// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// A Surface_mesh made from an oriented manifold triangle soup in O(n log d).
#ifndef SPECTRALSEG_IO_INTERNAL_ORIENTED_MANIFOLD_SOUP_TO_MESH_H
#define SPECTRALSEG_IO_INTERNAL_ORIENTED_MANIFOLD_SOUP_TO_MESH_H

#include <SpectralSeg/internal/parallel_for.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// Makes `mesh` (cleared first) from `points` and `triangles`, a soup for
// which is_oriented_manifold_soup() holds (indices below 2^32), with the
// vertices, faces, edges and halfedges that CGAL's
// polygon_soup_to_polygon_mesh() makes with Euler::add_face(), in the same
// order: vertex v is point v, face t is triangle t, the edges are numbered
// in the order the triangles' corners first meet them, each edge's first
// halfedge runs the way that corner does, and a face's halfedge is the one
// that ends at its first vertex. Euler::add_face() walks around the
// triangle's vertices to find their edges and border halfedges, which is
// quadratic in a vertex's degree (42 s for a fan of 200,000 triangles
// around one vertex); here each corner finds its opposite corner by
// bisection among the corners leaving the same vertex. Each vertex's
// halfedge ends at it, and is a border halfedge on a border, as CGAL keeps
// them. The corners' sorts and their opposite corners are found on
// `threads` threads; the mesh does not depend on their number.
template <typename Point>
void oriented_manifold_soup_to_mesh(const std::vector<Point>& points,
                                    const std::vector<std::array<std::size_t, 3>>& triangles,
                                    CGAL::Surface_mesh<Point>& mesh, unsigned threads = 1)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Vertex_index Vertex;
  typedef typename Mesh::Halfedge_index Halfedge;
  typedef typename Mesh::Face_index Face;
  const std::size_t nv = points.size(), nt = triangles.size();
  const std::size_t none = std::size_t(-1);
  // corner c = 3 t + i runs from triangles[t][i] to triangles[t][(i + 1) % 3]
  const auto from = [&](std::size_t c) { return triangles[c / 3][c % 3]; };
  const auto to = [&](std::size_t c) { return triangles[c / 3][(c % 3 + 1) % 3]; };

  // the corners leaving each vertex, sorted by the vertex they reach
  std::vector<std::size_t> first(nv + 1, 0);
  for(std::size_t c = 0; c < 3 * nt; ++c)
    ++first[from(c) + 1];
  for(std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<std::pair<std::uint32_t, std::size_t>> leaving(3 * nt); // (reached vertex, corner)
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t c = 0; c < 3 * nt; ++c)
      leaving[fill[from(c)]++] = {std::uint32_t(to(c)), c};
  }
  ::SpectralSeg::internal::parallel_range(0, nv, threads, [&](std::size_t v) {
    std::sort(leaving.begin() + std::ptrdiff_t(first[v]), leaving.begin() + std::ptrdiff_t(first[v + 1]));
  });
  // the corner running the other way along c's edge, or none
  const auto opposite_corner = [&](std::size_t c) {
    const std::size_t b = to(c);
    const auto lo = leaving.begin() + std::ptrdiff_t(first[b]), hi = leaving.begin() + std::ptrdiff_t(first[b + 1]);
    const auto it = std::lower_bound(lo, hi, std::make_pair(std::uint32_t(from(c)), std::size_t(0)));
    return (it != hi && it->first == from(c)) ? it->second : none;
  };

  // halfedge 2 e runs as the corner that first meets edge e, 2 e + 1 back
  std::vector<std::size_t> opposite(3 * nt);
  ::SpectralSeg::internal::parallel_range(0, 3 * nt, threads,
                                          [&](std::size_t c) { opposite[c] = opposite_corner(c); });
  std::vector<std::size_t> halfedge_of(3 * nt, none);
  std::size_t edges = 0;
  for(std::size_t c = 0; c < 3 * nt; ++c)
    if(halfedge_of[c] == none)
    {
      halfedge_of[c] = 2 * edges;
      const std::size_t o = opposite[c];
      if(o != none)
        halfedge_of[o] = 2 * edges + 1;
      ++edges;
    }

  mesh.clear();
  mesh.reserve(typename Mesh::size_type(nv), typename Mesh::size_type(edges), typename Mesh::size_type(nt));
  for(const Point& p : points)
    mesh.add_vertex(p);
  for(std::size_t e = 0; e < edges; ++e)
    mesh.add_edge();
  for(std::size_t t = 0; t < nt; ++t)
    mesh.add_face();
  std::vector<std::uint8_t> inner(2 * edges, 0);
  for(std::size_t c = 0; c < 3 * nt; ++c)
  {
    const Halfedge h{typename Mesh::size_type(halfedge_of[c])};
    const std::size_t t = c / 3;
    inner[halfedge_of[c]] = 1;
    mesh.set_target(h, Vertex(typename Mesh::size_type(to(c))));
    mesh.set_face(h, Face(typename Mesh::size_type(t)));
    mesh.set_next(h, Halfedge(typename Mesh::size_type(halfedge_of[3 * t + (c % 3 + 1) % 3])));
    mesh.set_halfedge(Vertex(typename Mesh::size_type(to(c))), h);
    if(c % 3 == 2)
      mesh.set_halfedge(Face(typename Mesh::size_type(t)), h);
  }
  // border halfedges: each border vertex of a manifold has one leaving it
  std::vector<std::size_t> border_leaving(nv, none);
  for(std::size_t c = 0; c < 3 * nt; ++c)
  {
    const std::size_t o = halfedge_of[c] ^ 1;
    if(inner[o])
      continue;
    const Halfedge b{typename Mesh::size_type(o)};
    mesh.set_target(b, Vertex(typename Mesh::size_type(from(c))));
    mesh.set_face(b, Face()); // the null face
    border_leaving[to(c)] = o;
  }
  for(std::size_t c = 0; c < 3 * nt; ++c)
  {
    const std::size_t o = halfedge_of[c] ^ 1;
    if(inner[o])
      continue;
    const Halfedge b{typename Mesh::size_type(o)};
    mesh.set_next(b, Halfedge(typename Mesh::size_type(border_leaving[from(c)])));
    mesh.set_halfedge(Vertex(typename Mesh::size_type(from(c))), b);
  }
}

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_ORIENTED_MANIFOLD_SOUP_TO_MESH_H
