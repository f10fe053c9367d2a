// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Dual_graph.h
/// \brief The dual graph of a triangle mesh, with per-edge geometry.
#ifndef SPECTRALSEG_DUAL_GRAPH_H
#define SPECTRALSEG_DUAL_GRAPH_H

#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/internal/contact_adjacencies.h>
#include <SpectralSeg/internal/execution_from.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>
#include <SpectralSeg/named_parameters.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace SpectralSeg {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The fold between two faces with unit normals n0, n1 and centroids c0, c1:
// the angle between the normals (0 when either normal is undefined, that is
// not of unit length) and whether the fold is concave, each face rising
// above the other's tangent plane: (n0 - n1).(c1 - c0) > 0, with a
// tolerance that keeps flat pairs convex.
struct Fold
{
  double angle = 0.;
  bool concave = false;
};

inline Fold fold_between(const Eigen::Vector3d& n0, const Eigen::Vector3d& n1, const Eigen::Vector3d& c0,
                         const Eigen::Vector3d& c1)
{
  Fold out;
  if(!(n0.squaredNorm() > 0.5 && n1.squaredNorm() > 0.5))
    return out;
  out.angle = std::acos(std::max(-1., std::min(1., n0.dot(n1))));
  out.concave = (n0 - n1).dot(c1 - c0) > 1e-12 * (c1 - c0).norm();
  return out;
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegCore
/// \brief The dual graph of a triangle mesh: one node per face, one edge per
/// pair of faces that share a mesh edge.
///
/// The adjacency is stored in compressed sparse rows as a Boost
/// `compressed_sparse_row_graph` (each dual edge appears once in each
/// direction), so that Boost Graph Library algorithms run on it directly.
/// The geometry of each dual edge is computed once: the length of the shared
/// mesh edge, the centroid-to-midpoint path length used by the geodesic
/// metric, the angle between the two face normals, and whether the fold is
/// concave. Mesh edges on a border have no dual edge.
///
/// Nodes are numbered by the face index map of the mesh the graph was built
/// from; dual edges are numbered in the order of that mesh's edges.
class Dual_graph
{
public:
  /// node (face) and dual-edge index type
  typedef std::uint32_t size_type;

  /// geometry of one dual edge
  struct Edge
  {
    /// the two faces; the shared mesh edge runs from `vertex[0]` to
    /// `vertex[1]` in the orientation of `face[0]`
    size_type face[2];
    /// the two vertices of the shared mesh edge
    size_type vertex[2];
    /// length of the shared mesh edge
    double length;
    /// \f$\|c_0 - m\| + \|c_1 - m\|\f$, with \f$c_i\f$ the face centroids
    /// and \f$m\f$ the midpoint of the shared edge (thesis eq. 3.1)
    double geodesic_length;
    /// angle between the two face normals, in \f$[0, \pi]\f$
    double normal_angle;
    /// whether the two faces form a concave (valley) fold, judged with
    /// outward normals; a flat pair is not concave
    bool concave;
    /// a contact between parts that touch without sharing a mesh edge
    /// (`vertex[0]` and `vertex[1]` are two vertices at the same position,
    /// see `make_dual_graph()`); its `length` is nominal: the mean edge
    /// length of the two faces
    bool contact;
  };

  /// bundled property of a CSR arc: the dual edge it belongs to
  struct Arc
  {
    size_type dual_edge; ///< index of the dual edge in `edges()`
  };

  /// the Boost CSR graph type
  typedef boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, Arc,
                                             boost::no_property, size_type, size_type>
    Csr;

  /// one face adjacency: faces `f0`, `f1` sharing the mesh edge `v0 -> v1`
  /// (oriented as in `f0`)
  struct Adjacency
  {
    size_type f0; ///< first face
    size_type f1; ///< second face
    size_type v0; ///< first vertex of the shared edge, in the orientation of `f0`
    size_type v1; ///< second vertex of the shared edge
    /// 0 for a shared mesh edge; for a contact (`v0` and `v1` two vertices
    /// at the same position) the nominal length of the dual edge, positive
    double contact_length = 0.;
  };

  Dual_graph() = default;

  /// Builds the graph from a mesh geometry and its face adjacencies, on
  /// `threads` threads (0: all hardware threads; the graph does not depend
  /// on it). Degenerate faces receive the normal of their neighbours here.
  Dual_graph(Mesh_geometry geometry, const std::vector<Adjacency>& adjacencies,
             std::size_t number_of_border_edges = 0, unsigned threads = 1)
    : geometry_(std::move(geometry)), border_edges_(number_of_border_edges)
  {
    build(adjacencies, Execution(threads).threads());
  }

  /// the geometry the graph was built from
  const Mesh_geometry& geometry() const { return geometry_; }
  /// number of nodes (faces)
  size_type number_of_faces() const { return static_cast<size_type>(geometry_.number_of_faces()); }
  /// number of dual edges
  size_type number_of_edges() const { return static_cast<size_type>(edges_.size()); }
  /// the geometry of dual edge `e`
  const Edge& edge(size_type e) const { return edges_[e]; }
  /// all dual edges
  const std::vector<Edge>& edges() const { return edges_; }
  /// the Boost CSR graph
  const Csr& csr() const { return csr_; }
  /// number of mesh edges with a single incident face
  std::size_t number_of_border_edges() const { return border_edges_; }
  /// length of the longest shared mesh edge (0 if there is no dual edge)
  double longest_edge_length() const { return longest_edge_; }

  /// number of connected components of the dual graph
  size_type number_of_components() const { return components_; }
  /// the connected component of each face, numbered from 0 by smallest face index
  const std::vector<size_type>& component_of_faces() const { return component_; }

  /// number of neighbours of face `f`
  size_type degree(size_type f) const { return static_cast<size_type>(out_degree(f, csr_)); }

  /// calls `fn(neighbour_face, dual_edge)` for each neighbour of `f`
  template <typename Fn>
  void for_each_neighbour(size_type f, const Fn& fn) const
  {
    for(auto e : boost::make_iterator_range(out_edges(f, csr_)))
      fn(static_cast<size_type>(target(e, csr_)), csr_[e].dual_edge);
  }

private:
  void build(const std::vector<Adjacency>& adjacencies, unsigned threads);

  // Degenerate faces take the area-weighted mean normal of their neighbours
  // with a defined normal; repeated so that runs of degenerate faces fill in.
  void fill_degenerate_normals();

  void compute_edge_geometry(unsigned threads);

  void compute_components();

  Mesh_geometry geometry_;
  std::vector<Edge> edges_;
  Csr csr_;
  std::size_t border_edges_ = 0;
  double longest_edge_ = 0.;
  std::vector<size_type> component_;
  size_type components_ = 0;
};

#if SPECTRALSEG_DEFINE_FUNCTIONS
SPECTRALSEG_INLINE void Dual_graph::build(const std::vector<Adjacency>& adjacencies, unsigned threads)
{
  const std::size_t nf = geometry_.number_of_faces();
  edges_.clear();
  edges_.reserve(adjacencies.size());
  // the arcs (both directions of each edge) in the order of (source,
  // target, edge): counted per source face, then each face's few arcs
  // sorted (a counting sort, linear in the number of edges)
  std::vector<std::size_t> first(nf + 1, 0);
  for(const Adjacency& a : adjacencies)
  {
    if(a.f0 >= nf || a.f1 >= nf || a.f0 == a.f1)
      throw Invalid_input("invalid face adjacency (" + std::to_string(a.f0) + ", " + std::to_string(a.f1) + ")");
    Edge edge;
    edge.face[0] = a.f0;
    edge.face[1] = a.f1;
    edge.vertex[0] = a.v0;
    edge.vertex[1] = a.v1;
    edge.contact = a.contact_length > 0.;
    edge.length = a.contact_length;
    edges_.push_back(edge);
    ++first[a.f0 + 1];
    ++first[a.f1 + 1];
  }
  for(std::size_t f = 0; f < nf; ++f)
    first[f + 1] += first[f];
  std::vector<std::pair<size_type, size_type>> arcs(first[nf]); // (target, edge), then (source, target)
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for(size_type e = 0; e < static_cast<size_type>(edges_.size()); ++e)
    {
      arcs[next[edges_[e].face[0]]++] = {edges_[e].face[1], e};
      arcs[next[edges_[e].face[1]]++] = {edges_[e].face[0], e};
    }
  }
  std::vector<Arc> arc_props(arcs.size());
  internal::parallel_range(0, nf, threads, [&](std::size_t f) {
    std::sort(arcs.begin() + std::ptrdiff_t(first[f]), arcs.begin() + std::ptrdiff_t(first[f + 1]));
    for(std::size_t i = first[f]; i < first[f + 1]; ++i)
    {
      arc_props[i] = Arc{arcs[i].second};
      arcs[i] = {static_cast<size_type>(f), arcs[i].first};
    }
  });
  csr_ = Csr(boost::edges_are_sorted, arcs.begin(), arcs.end(), arc_props.begin(),
             static_cast<size_type>(nf));

  fill_degenerate_normals();
  compute_edge_geometry(threads);
  compute_components();
}

SPECTRALSEG_INLINE void Dual_graph::fill_degenerate_normals()
{
  std::vector<size_type> pending;
  for(size_type f = 0; f < number_of_faces(); ++f)
    if(geometry_.degenerate[f])
      pending.push_back(f);
  while(!pending.empty())
  {
    std::vector<std::pair<size_type, Eigen::Vector3d>> filled;
    std::vector<size_type> still;
    for(size_type f : pending)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for_each_neighbour(f, [&](size_type g, size_type) {
        sum += (geometry_.areas[g] > 0 ? geometry_.areas[g] : 1.) * geometry_.normals[g];
      });
      const double len = sum.norm();
      if(len > 0 && std::isfinite(len))
        filled.emplace_back(f, sum / len);
      else
        still.push_back(f);
    }
    if(filled.empty())
      break; // isolated degenerate faces keep a zero normal
    for(const auto& fn : filled)
      geometry_.normals[fn.first] = fn.second;
    pending.swap(still);
  }
}

SPECTRALSEG_INLINE void Dual_graph::compute_edge_geometry(unsigned threads)
{
  internal::parallel_range(0, edges_.size(), threads, [&](std::size_t i) {
    Edge& e = edges_[i];
    const Eigen::Vector3d& p = geometry_.points[e.vertex[0]];
    const Eigen::Vector3d& q = geometry_.points[e.vertex[1]];
    const Eigen::Vector3d& c0 = geometry_.centroids[e.face[0]];
    const Eigen::Vector3d& c1 = geometry_.centroids[e.face[1]];
    const Eigen::Vector3d& n0 = geometry_.normals[e.face[0]];
    const Eigen::Vector3d& n1 = geometry_.normals[e.face[1]];
    const Eigen::Vector3d m = 0.5 * (p + q);
    if(!e.contact)
      e.length = (q - p).norm();
    e.geodesic_length = (c0 - m).norm() + (c1 - m).norm();
    const internal::Fold fold = internal::fold_between(n0, n1, c0, c1);
    e.normal_angle = fold.angle;
    e.concave = fold.concave;
  });
  longest_edge_ = 0.;
  for(const Edge& e : edges_)
    longest_edge_ = std::max(longest_edge_, e.length);
}

SPECTRALSEG_INLINE void Dual_graph::compute_components()
{
  const size_type nf = number_of_faces();
  const size_type unset = static_cast<size_type>(-1);
  component_.assign(nf, unset);
  components_ = 0;
  std::vector<size_type> stack;
  for(size_type s = 0; s < nf; ++s)
  {
    if(component_[s] != unset)
      continue;
    component_[s] = components_;
    stack.push_back(s);
    while(!stack.empty())
    {
      const size_type f = stack.back();
      stack.pop_back();
      for_each_neighbour(f, [&](size_type g, size_type) {
        if(component_[g] == unset)
        {
          component_[g] = components_;
          stack.push_back(g);
        }
      });
    }
    ++components_;
  }
}
#endif

/// \ingroup PkgSpectralSegCore
/// \brief Builds the dual graph of a triangle mesh.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         whose faces are triangles, with outward-oriented faces (concavity
///         is judged with the face normals)
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// Parts that touch or nearly touch without sharing a mesh edge are joined:
/// when two vertices at most `contact_distance` apart belong to faces of
/// different connected components (what splitting non-manifold edges or
/// vertices, an unwelded export or a model assembled from separate pieces
/// leaves), the nearest two of their incident faces get a contact edge
/// (`Dual_graph::Edge::contact`), whose geometry is that of a shared edge of
/// nominal length at the vertices' midpoint. Specks still apart (parts with
/// less than `speck_area_fraction` of the area) are then linked, smallest
/// first, to the nearest other part by one contact between their nearest
/// vertices, so that they join the part they lie against instead of taking
/// a segment each. Larger parts that do not touch stay apart: each is at
/// least one segment. A mesh of one connected component gets no contact. `connect_touching_parts(false)` keeps only the mesh
/// edges, as in the thesis.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
///     \cgalParamDescription{the vertex positions and the numbering of vertices and faces, as for `extract_mesh_geometry()`}
///     \cgalParamType{property maps as for `extract_mesh_geometry()`}
///     \cgalParamDefault{the mesh's internal maps}
///   \cgalParamNEnd
///   \cgalParamNBegin{connect_touching_parts}
///     \cgalParamDescription{whether faces of different connected components that touch at a vertex position are joined by contact edges}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{contact_distance}
///     \cgalParamDescription{how far apart two vertices of different components may be to join them, as a fraction of the diagonal of the mesh's bounding box}
///     \cgalParamType{`double`, finite, at least 0}
///     \cgalParamDefault{0.005}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads of the graph's construction; 0 means all hardware threads. The graph does not depend on it}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{speck_area_fraction}
///     \cgalParamDescription{parts with less than this fraction of the mesh's area that touch nothing are linked to the nearest other part (0: none)}
///     \cgalParamType{`double`, in [0, 1]}
///     \cgalParamDefault{0.01}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input if a face is not a triangle or a coordinate is not finite.
template <typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Dual_graph make_dual_graph(const TriangleMesh& tm,
                           const NamedParameters& np = parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  Mesh_geometry geometry = extract_mesh_geometry(tm, np);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);

  std::vector<Dual_graph::Adjacency> adjacencies;
  adjacencies.reserve(num_edges(tm));
  std::size_t border = 0;
  for(typename GT::edge_descriptor e : edges(tm))
  {
    const typename GT::halfedge_descriptor h = halfedge(e, tm);
    const typename GT::face_descriptor f0 = face(h, tm);
    const typename GT::face_descriptor f1 = face(opposite(h, tm), tm);
    if(f0 == GT::null_face() || f1 == GT::null_face())
    {
      ++border;
      continue;
    }
    adjacencies.push_back({static_cast<Dual_graph::size_type>(get(fim, f0)),
                           static_cast<Dual_graph::size_type>(get(fim, f1)),
                           static_cast<Dual_graph::size_type>(get(vim, source(h, tm))),
                           static_cast<Dual_graph::size_type>(get(vim, target(h, tm)))});
  }
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double gap_fraction = choose_parameter(get_parameter(np, internal_np::contact_distance), 0.005);
  if(!(gap_fraction >= 0.) || !std::isfinite(gap_fraction))
    throw Invalid_input("make_dual_graph: contact_distance must be finite and not negative");
  if(choose_parameter(get_parameter(np, internal_np::connect_touching_parts), true))
  {
    const double gap = gap_fraction * geometry.bbox_diagonal;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    pairs.reserve(adjacencies.size());
    for(const Dual_graph::Adjacency& a : adjacencies)
      pairs.emplace_back(a.f0, a.f1);
    const double speck = choose_parameter(get_parameter(np, internal_np::speck_area_fraction), 0.01);
    if(!(speck >= 0.) || !(speck <= 1.))
      throw Invalid_input("make_dual_graph: speck_area_fraction must be in [0, 1]");
    for(const internal::Contact& c : internal::contact_adjacencies(geometry, pairs, gap, speck))
    {
      Dual_graph::Adjacency a{c.f0, c.f1, c.v0, c.v1};
      a.contact_length = c.length > 0. ? c.length : 1e-300;
      adjacencies.push_back(a);
    }
  }
  return Dual_graph(std::move(geometry), adjacencies, border, internal::execution_from(np).threads());
}

} // namespace SpectralSeg

#endif // SPECTRALSEG_DUAL_GRAPH_H
