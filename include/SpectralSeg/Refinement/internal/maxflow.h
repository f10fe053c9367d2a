// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file maxflow.h
/// \brief Kolmogorov's MaxFlow code (GPL) as a max-flow backend of the
/// alpha expansion: version 3 from Debian's libmaxflow-dev when
/// `SPECTRALSEG_HAS_LIBMAXFLOW` is defined, else version 2.2, shipped with
/// CGAL's Surface_mesh_segmentation.
#ifndef SPECTRALSEG_REFINEMENT_INTERNAL_MAXFLOW_H
#define SPECTRALSEG_REFINEMENT_INTERNAL_MAXFLOW_H

#include <algorithm>
#include <cstddef>
#include <limits>
#include <memory>
#include <new>
#include <vector>

#ifdef SPECTRALSEG_HAS_LIBMAXFLOW
// Version 3 (Debian's libmaxflow-dev), its template code included here so
// that the library needs no linking: nodes and arcs in two arrays, no
// conversion of linked blocks before each max flow.
#ifndef MAXFLOW_INCLUDE_TEMPLATE_IMPLEMENTATION
#define MAXFLOW_INCLUDE_TEMPLATE_IMPLEMENTATION
#endif
#include <maxflow.h>
#else
#include <CGAL/license/Surface_mesh_segmentation.h>

// the C headers graph.h includes, first, so that they stay out of namespace MaxFlow
#include <stdio.h>
#include <stdlib.h>

// As CGAL/boost/graph/Alpha_expansion_MaxFlow_tag.h does (the guards of
// graph.h make the two compatible in one program).
#ifndef DOXYGEN_RUNNING
namespace MaxFlow {
#include <CGAL/Surface_mesh_segmentation/internal/auxiliary/graph.h>
}
#endif
#endif

namespace SpectralSeg {
namespace Refinement {
/// \cond SKIP_IN_MANUAL
namespace internal {

#ifdef SPECTRALSEG_HAS_LIBMAXFLOW
// Kolmogorov's MaxFlow 3 with the interface of CGAL's
// Alpha_expansion_*_impl classes, and reserve(): one object serves move
// after move, its arrays made once at the size of the largest move (growing
// them while a graph is built would copy them and touch twice the memory).
// The same cuts as the version 2.2 that CGAL ships: the same algorithm,
// and a vertex that either side could take goes to the sink in both.
class Maxflow_impl
{
  typedef maxflow::Graph<double, double, double> Graph;

public:
  typedef Graph::node_id Vertex_descriptor;

  // An empty graph with room for `vertices` vertices and `edges` edges.
  void reserve(std::size_t vertices, std::size_t edges)
  {
    const std::size_t most = std::size_t(std::numeric_limits<int>::max()) / 2;
    if(vertices > most || edges > most)
      throw std::bad_alloc(); // MaxFlow counts in int
    if(!graph || vertices > vertex_room || edges > edge_room)
    {
      graph.reset(); // the old arrays go before the new ones come
      vertex_room = std::max(vertices, vertex_room);
      edge_room = std::max(edges, edge_room);
      // MaxFlow calls this when malloc fails (and exits when it returns)
      graph.reset(new Graph(int(vertex_room), int(edge_room), [](const char*) { throw std::bad_alloc(); }));
    }
    else
      graph->reset();
  }
  void clear_graph() { reserve(0, 0); }
  Vertex_descriptor add_vertex() { return graph->add_node(); }
  void add_tweight(Vertex_descriptor v, double w1, double w2) { graph->add_tweights(v, w1, w2); }
  void init_vertices() {}
  double max_flow() { return graph->maxflow(); }
  void add_edge(Vertex_descriptor v1, Vertex_descriptor v2, double w1, double w2) { graph->add_edge(v1, v2, w1, w2); }

  template <typename VertexLabelMap, typename InputVertexDescriptor>
  void update(VertexLabelMap vertex_label_map, const std::vector<Vertex_descriptor>& inserted_vertices,
              InputVertexDescriptor vd, std::size_t vertex_i, std::size_t alpha)
  {
    if(get(vertex_label_map, vd) != alpha && graph->what_segment(inserted_vertices[vertex_i], Graph::SINK) == Graph::SINK)
      put(vertex_label_map, vd, alpha);
  }

private:
  std::unique_ptr<Graph> graph;
  std::size_t vertex_room = 0, edge_room = 0;
};
#else
// CGAL::Alpha_expansion_MaxFlow_impl (version 2.2 of MaxFlow), call for
// call, without the header that declares it:
// CGAL/boost/graph/Alpha_expansion_MaxFlow_tag.h includes
// alpha_expansion_graphcut.h and with it Boost's max-flow, adjacency list
// and CGAL's named parameters, which weigh on a k-way translation unit's
// peak compile memory (doc/benchmarks.md, "Compile time").
class Maxflow_impl
{
public:
  typedef MaxFlow::Graph::node_id Vertex_descriptor;

  void clear_graph() { graph.clear(); }
  Vertex_descriptor add_vertex() { return graph.add_node(); }
  void add_tweight(Vertex_descriptor& v, double w1, double w2) { graph.add_tweights(v, w1, w2); }
  void init_vertices() {}
  double max_flow() { return graph.maxflow(); }
  void add_edge(Vertex_descriptor& v1, Vertex_descriptor& v2, double w1, double w2) { graph.add_edge(v1, v2, w1, w2); }

  template <typename VertexLabelMap, typename InputVertexDescriptor>
  void update(VertexLabelMap vertex_label_map, const std::vector<Vertex_descriptor>& inserted_vertices,
              InputVertexDescriptor vd, std::size_t vertex_i, std::size_t alpha)
  {
    if(get(vertex_label_map, vd) != alpha && graph.what_segment(inserted_vertices[vertex_i]) == MaxFlow::Graph::SINK)
      put(vertex_label_map, vd, alpha);
  }

private:
  MaxFlow::Graph graph;
};
#endif

} // namespace internal
/// \endcond
} // namespace Refinement
} // namespace SpectralSeg

#endif // SPECTRALSEG_REFINEMENT_INTERNAL_MAXFLOW_H
