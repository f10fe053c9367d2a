// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Two ways to plug a user-defined metric into SpectralSeg, on a CGAL::Polyhedron_3:
//  - a function of one dual edge, wrapped by Metrics::make_per_edge_weight;
//  - a full policy class modelling the DualEdgeWeight concept.
// Both then mix with the library's metrics in a Blend.
//
// usage: custom_metric [mesh.off]
#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Blend.h>
#include <SpectralSeg/Metrics/Per_edge_weight.h>
#include <SpectralSeg/face_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <boost/property_map/property_map.hpp>

#include <map>

#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;

// A policy class: the weight of a dual edge is the number of mesh edges
// crossed (1), so distances count face hops. Any class with name() and this
// call operator models DualEdgeWeight.
struct Hop_count
{
  std::string name() const { return "hops"; }
  std::vector<double> operator()(const SpectralSeg::Dual_graph& g, const SpectralSeg::Execution&) const
  {
    return std::vector<double>(g.number_of_edges(), 1.);
  }
};

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : SPECTRALSEG_DATA_DIR "/elephant.off";
  Polyhedron mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << path << std::endl;
    return 1;
  }
  namespace M = SpectralSeg::Metrics;

  // A per-edge function: the length of the shared edge relative to the longest one.
  const auto edge_length = M::make_per_edge_weight(
    [](const SpectralSeg::Dual_graph& g, const SpectralSeg::Dual_graph::Edge& e) {
      return e.length / g.longest_edge_length();
    },
    "edge-length");
  const auto metric = M::make_blend(edge_length, 0.2, Hop_count(), 0.3, M::Angular_weight(), 0.5);

  // Polyhedron_3 has no internal face index: the library numbers faces in
  // iteration order; results go to any writable property map.
  typedef boost::graph_traits<Polyhedron>::face_descriptor face_descriptor;
  std::map<face_descriptor, double> distances;
  const face_descriptor source = *faces(mesh).begin();
  SpectralSeg::face_distances(mesh, source, boost::make_assoc_property_map(distances),
                              SpectralSeg::parameters::metric(metric));

  double largest = 0;
  for(const auto& fd : distances)
    largest = std::max(largest, fd.second);
  std::cout << metric.name() << "\n"
            << distances.size() << " faces; largest distance from the first face: " << largest << std::endl;
  return 0;
}
