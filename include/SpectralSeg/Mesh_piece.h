// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Mesh_piece.h
/// \brief A connected set of faces of a mesh, with its own vertex and face
/// numbering: what the automatic segmentation tests and cuts.
#ifndef SPECTRALSEG_MESH_PIECE_H
#define SPECTRALSEG_MESH_PIECE_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegAutomatic
/// \brief A set of faces of a mesh, renumbered from 0, with the vertices,
/// triangles and face adjacencies that lie inside it.
///
/// Local face `i` is the mesh face `faces[i]`; local vertex `v` is the mesh
/// vertex `vertices[v]`. Only the dual edges whose two faces are in the piece
/// are kept (`edges`); the piece's adjacency is stored in compressed rows
/// (`neighbours(f)`). Building a piece costs time proportional to its size
/// (plus one pass over scratch arrays of the mesh's size).
class Mesh_piece
{
public:
  /// local index type
  typedef std::uint32_t size_type;

  /// a dual edge inside the piece
  struct Edge
  {
    size_type face[2];      ///< the two local faces
    size_type vertex[2];    ///< the two local vertices of the shared mesh edge
    size_type dual_edge;    ///< the dual edge in the mesh's `Dual_graph`
  };

  /// one neighbour of a local face
  struct Neighbour
  {
    size_type face; ///< the neighbouring local face
    size_type edge; ///< the local edge (index in `edges()`) between them
  };

  Mesh_piece() = default;

  /// Builds the piece made of the mesh faces `faces` (each at most once).
  /// \pre every face index is below `graph.number_of_faces()`
  /// \throws Invalid_input if a face is out of range or listed twice
  Mesh_piece(const Dual_graph& graph, std::vector<size_type> faces) : graph_(&graph), faces_(std::move(faces))
  {
    const Mesh_geometry& g = graph.geometry();
    const size_type none = std::numeric_limits<size_type>::max();
    std::vector<size_type> local_face(g.number_of_faces(), none);
    for(size_type i = 0; i < faces_.size(); ++i)
    {
      const size_type f = faces_[i];
      if(f >= g.number_of_faces() || local_face[f] != none)
        throw Invalid_input("Mesh_piece: face " + std::to_string(f) + " is out of range or listed twice");
      local_face[f] = i;
    }
    std::vector<size_type> local_vertex(g.number_of_vertices(), none);
    triangles_.resize(faces_.size());
    area_ = 0.;
    for(size_type i = 0; i < faces_.size(); ++i)
    {
      const auto& t = g.triangles[faces_[i]];
      for(int c = 0; c < 3; ++c)
      {
        size_type& lv = local_vertex[t[c]];
        if(lv == none)
        {
          lv = static_cast<size_type>(vertices_.size());
          vertices_.push_back(t[c]);
        }
        triangles_[i][c] = lv;
      }
      area_ += g.areas[faces_[i]];
    }
    // local dual edges, in the order of their first face then of the mesh's arcs
    offsets_.assign(faces_.size() + 1, 0);
    for(size_type i = 0; i < faces_.size(); ++i)
      graph.for_each_neighbour(faces_[i], [&](Dual_graph::size_type nb, Dual_graph::size_type e) {
        const size_type j = local_face[nb];
        if(j == none)
        {
          const Dual_graph::Edge& de = graph.edge(e);
          if(!de.contact) // a cut edge: kept for longest_cut_loop()
            cut_edges_.push_back(Edge{{i, i}, {local_vertex[de.vertex[0]], local_vertex[de.vertex[1]]}, e});
          return;
        }
        ++offsets_[i + 1];
        if(i < j)
        {
          const Dual_graph::Edge& de = graph.edge(e);
          edges_.push_back(Edge{{i, j}, {local_vertex[de.vertex[0]], local_vertex[de.vertex[1]]}, e});
        }
      });
    for(size_type i = 0; i < faces_.size(); ++i)
      offsets_[i + 1] += offsets_[i];
    adjacency_.resize(offsets_.back());
    std::vector<size_type> fill(offsets_.begin(), offsets_.end() - 1);
    for(size_type e = 0; e < edges_.size(); ++e)
    {
      const Edge& ed = edges_[e];
      adjacency_[fill[ed.face[0]]++] = Neighbour{ed.face[1], e};
      adjacency_[fill[ed.face[1]]++] = Neighbour{ed.face[0], e};
    }
  }

  /// the dual graph of the whole mesh
  const Dual_graph& graph() const { return *graph_; }
  /// the geometry of the whole mesh
  const Mesh_geometry& geometry() const { return graph_->geometry(); }
  /// mesh face of each local face
  const std::vector<size_type>& faces() const { return faces_; }
  /// mesh vertex of each local vertex
  const std::vector<size_type>& vertices() const { return vertices_; }
  /// local vertex triples of each local face
  const std::vector<std::array<size_type, 3>>& triangles() const { return triangles_; }
  /// the dual edges inside the piece
  const std::vector<Edge>& edges() const { return edges_; }
  /// number of local faces
  size_type number_of_faces() const { return static_cast<size_type>(faces_.size()); }
  /// number of local vertices
  size_type number_of_vertices() const { return static_cast<size_type>(vertices_.size()); }
  /// total area of the piece
  double area() const { return area_; }
  /// area of local face `f`
  double face_area(size_type f) const { return geometry().areas[faces_[f]]; }
  /// position of local vertex `v`
  const Eigen::Vector3d& point(size_type v) const { return geometry().points[vertices_[v]]; }
  /// length of the mesh edge shared across local edge `e`
  double edge_length(size_type e) const { return graph_->edge(edges_[e].dual_edge).length; }

  /// the neighbours of local face `f` inside the piece
  std::pair<const Neighbour*, const Neighbour*> neighbours(size_type f) const
  {
    return {adjacency_.data() + offsets_[f], adjacency_.data() + offsets_[f + 1]};
  }

  /// the undirected mesh edges of the piece's triangles, as sorted pairs of
  /// local vertices, each once (border edges included)
  std::vector<std::pair<size_type, size_type>> vertex_edges() const
  {
    std::vector<std::pair<size_type, size_type>> e;
    e.reserve(3 * triangles_.size());
    for(const auto& t : triangles_)
      for(int c = 0; c < 3; ++c)
      {
        size_type a = t[c], b = t[(c + 1) % 3];
        if(a == b)
          continue;
        if(b < a)
          std::swap(a, b);
        e.emplace_back(a, b);
      }
    std::sort(e.begin(), e.end());
    e.erase(std::unique(e.begin(), e.end()), e.end());
    return e;
  }

  /// the connected components of the piece (through its dual edges), one
  /// label per local face, numbered from 0 in order of their smallest local
  /// face; returns the number of components
  size_type components(std::vector<size_type>& component) const
  {
    const size_type none = std::numeric_limits<size_type>::max();
    component.assign(faces_.size(), none);
    size_type count = 0;
    std::vector<size_type> stack;
    for(size_type s = 0; s < faces_.size(); ++s)
    {
      if(component[s] != none)
        continue;
      component[s] = count;
      stack.push_back(s);
      while(!stack.empty())
      {
        const size_type f = stack.back();
        stack.pop_back();
        const auto range = neighbours(f);
        for(const Neighbour* n = range.first; n != range.second; ++n)
          if(component[n->face] == none)
          {
            component[n->face] = count;
            stack.push_back(n->face);
          }
      }
      ++count;
    }
    return count;
  }

  /// the number of handles of the piece's surface: its genus, from the
  /// Euler characteristic of its triangles, \f$\chi = V - E + F = 2c - 2g -
  /// b\f$ with \f$c\f$ the components (faces joined by a shared edge) and
  /// \f$b\f$ the border loops (border edges joined by a shared vertex).
  /// 0 for a disc, a sphere, a tube or a sphere with holes cut in it; 1 for
  /// a cup with its handle, or a torus. Non-manifold edges and vertices make
  /// the count approximate (never below 0)
  std::size_t genus() const
  {
    // each triangle's edges as (sorted vertex pair, face), sorted
    std::vector<std::pair<std::pair<size_type, size_type>, size_type>> sides;
    sides.reserve(3 * triangles_.size());
    for(size_type f = 0; f < triangles_.size(); ++f)
      for(int c = 0; c < 3; ++c)
      {
        size_type a = triangles_[f][c], b = triangles_[f][(c + 1) % 3];
        if(a == b)
          continue;
        if(b < a)
          std::swap(a, b);
        sides.push_back({{a, b}, f});
      }
    std::sort(sides.begin(), sides.end());
    std::vector<size_type> face_root = singletons(triangles_.size()), vertex_root = singletons(vertices_.size());
    long long edges = 0, components = static_cast<long long>(triangles_.size()), border_loops = 0;
    std::vector<unsigned char> on_border(vertices_.size(), 0);
    for(std::size_t i = 0; i < sides.size();)
    {
      std::size_t j = i + 1;
      while(j < sides.size() && sides[j].first == sides[i].first)
      {
        if(join(face_root, sides[i].second, sides[j].second))
          --components;
        ++j;
      }
      ++edges;
      if(j - i == 1) // a border edge
      {
        const size_type a = sides[i].first.first, b = sides[i].first.second;
        for(size_type v : {a, b})
          if(!on_border[v])
          {
            on_border[v] = 1;
            ++border_loops; // a loop per border vertex, less one per join
          }
        if(join(vertex_root, a, b))
          --border_loops;
      }
      i = j;
    }
    const long long euler =
        static_cast<long long>(vertices_.size()) - edges + static_cast<long long>(triangles_.size());
    const long long twice_genus = 2 * components - border_loops - euler;
    return twice_genus > 0 ? std::size_t(twice_genus / 2) : 0;
  }

  /// the length of the piece's longest cut loop: the mesh edges it shares
  /// with faces outside it (where cuts separated it from the rest of its
  /// component; the mesh's own border and contacts between parts do not
  /// count), joined into loops by shared vertices. 0 for a whole
  /// component. A piece that sticks out of the surface it was cut from has
  /// more area than the flat disc its cut loop bounds (any surface spanning
  /// a planar circle does); a patch cut out of a surface by a ragged or
  /// elongated loop has less.
  double longest_cut_loop() const
  {
    std::vector<size_type> root = singletons(vertices_.size());
    for(const Edge& c : cut_edges_)
      join(root, c.vertex[0], c.vertex[1]);
    std::vector<double> loop(root.size(), 0.);
    double longest = 0.;
    for(const Edge& c : cut_edges_)
    {
      double& l = loop[find(root, c.vertex[0])];
      l += graph_->edge(c.dual_edge).length;
      longest = std::max(longest, l);
    }
    return longest;
  }

private:
  // union-find over local indices (genus(), longest_cut_loop())
  static std::vector<size_type> singletons(std::size_t n)
  {
    std::vector<size_type> root(n);
    for(size_type i = 0; i < root.size(); ++i)
      root[i] = i;
    return root;
  }
  static size_type find(std::vector<size_type>& root, size_type x)
  {
    while(root[x] != x)
      x = root[x] = root[root[x]];
    return x;
  }
  static bool join(std::vector<size_type>& root, size_type a, size_type b)
  {
    a = find(root, a);
    b = find(root, b);
    if(a == b)
      return false;
    root[std::max(a, b)] = std::min(a, b);
    return true;
  }

  const Dual_graph* graph_ = nullptr;
  std::vector<size_type> faces_;
  std::vector<size_type> vertices_;
  std::vector<std::array<size_type, 3>> triangles_;
  std::vector<Edge> edges_;
  std::vector<Edge> cut_edges_; // to faces outside the piece (face[1] unused)
  std::vector<size_type> offsets_;
  std::vector<Neighbour> adjacency_;
  double area_ = 0.;
};

} // namespace SpectralSeg

#endif // SPECTRALSEG_MESH_PIECE_H
