// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Automatic segmentation of a CGAL::Polyhedron_3 by recursive salient cuts
// (thesis ch. 6): the number of parts is found by the segmentability test,
// the cuts are kept in a hierarchy, printed here level by level, and the
// parts go into a face property map; then the same with the thesis's face
// sequence.
//
// usage: automatic_segmentation [mesh.off]
#include <SpectralSeg/automatic_segmentation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/property_map/vector_property_map.hpp>

#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3> Polyhedron;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : SPECTRALSEG_DATA_DIR "/human_man.off";
  Polyhedron mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << path << std::endl;
    return 1;
  }
  CGAL::set_halfedgeds_items_id(mesh);

  // the parts, one per face, in a property map indexed by the face ids
  const auto fim = get(CGAL::face_index, mesh);
  boost::vector_property_map<int, decltype(fim)> part(fim);
  SpectralSeg::Part_hierarchy hierarchy;
  namespace P = SpectralSeg::parameters;
  const std::size_t parts = SpectralSeg::automatic_segmentation(
    mesh, part,
    P::automatic_method(SpectralSeg::Automatic_method::salient_cuts)
      .segmentability_threshold(0.1) // eta, the thesis's default
      .part_hierarchy(&hierarchy));

  std::cout << path << ": " << num_faces(mesh) << " faces, " << parts << " parts after "
            << hierarchy.number_of_cuts() << " cuts\n";
  // the hierarchy, one level per line: the pieces at each depth
  for(std::size_t depth = 0;; ++depth)
  {
    std::cout << "depth " << depth << ":";
    bool deeper = false;
    for(const SpectralSeg::Part_node& n : hierarchy.nodes)
      if(n.depth == depth)
      {
        std::cout << " [" << n.faces.size() << " faces";
        if(!n.is_leaf())
          std::cout << ", cut after test " << SpectralSeg::Segmentability::test_name(n.test) << " (score "
                    << n.score << ", salience " << n.cut_salience << ")";
        std::cout << "]";
        deeper = deeper || !n.is_leaf();
      }
    std::cout << "\n";
    if(!deeper)
      break;
  }
  // the same partition, replayed with the first two cuts only
  const std::vector<int> leaves = hierarchy.labels(), three = hierarchy.labels_with_parts(3);
  std::size_t agree = 0;
  for(auto f : faces(mesh))
    agree += (leaves[get(fim, f)] == get(part, f));
  std::cout << "labels of the property map agree with the hierarchy on " << agree << " of " << num_faces(mesh)
            << " faces; with 3 parts, face 0 is in part " << three[0] << "\n";
  // the thesis's face sequence (the distance difference) instead of our
  // concavity-aware harmonic field: every other setting unchanged
  SpectralSeg::Automatic_segmentation_options<> options;
  options.sequence = SpectralSeg::Automatic_segmentation_options<>::Sequence::distance_difference;
  const std::size_t thesis_sequence = SpectralSeg::automatic_segmentation(
    mesh, part, P::automatic_method(SpectralSeg::Automatic_method::salient_cuts).automatic_options(options));
  std::cout << "with the thesis's face sequence: " << thesis_sequence << " parts\n";
  return agree == num_faces(mesh) ? 0 : 1;
}
