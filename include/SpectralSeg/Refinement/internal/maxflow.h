// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file maxflow.h
/// \brief Kolmogorov's MaxFlow code (shipped with CGAL's
/// Surface_mesh_segmentation, GPL) as a max-flow backend of the alpha
/// expansion.
#ifndef SPECTRALSEG_REFINEMENT_INTERNAL_MAXFLOW_H
#define SPECTRALSEG_REFINEMENT_INTERNAL_MAXFLOW_H

#include <CGAL/license/Surface_mesh_segmentation.h>

// the C headers graph.h includes, first, so that they stay out of namespace MaxFlow
#include <stdio.h>
#include <stdlib.h>

#include <cstddef>
#include <vector>

// As CGAL/boost/graph/Alpha_expansion_MaxFlow_tag.h does (the guards of
// graph.h make the two compatible in one program).
#ifndef DOXYGEN_RUNNING
namespace MaxFlow {
#include <CGAL/Surface_mesh_segmentation/internal/auxiliary/graph.h>
}
#endif

namespace SpectralSeg {
namespace Refinement {
/// \cond SKIP_IN_MANUAL
namespace internal {

// CGAL::Alpha_expansion_MaxFlow_impl, call for call, without the header
// that declares it: CGAL/boost/graph/Alpha_expansion_MaxFlow_tag.h includes
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

} // namespace internal
/// \endcond
} // namespace Refinement
} // namespace SpectralSeg

#endif // SPECTRALSEG_REFINEMENT_INTERNAL_MAXFLOW_H
