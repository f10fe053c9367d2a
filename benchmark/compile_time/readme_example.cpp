// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The README's usage example as a user's whole translation unit, for the
// compile-time measurement of doc/benchmarks.md ("Compile time"):
// benchmark/compile_time/measure.sh builds it with the flags CMake gives
// a target that links SpectralSeg::SpectralSeg.
//
// usage: readme_example mesh.off
#include <SpectralSeg/k_way_segmentation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <fstream>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index face_descriptor;

int main(int argc, char** argv)
{
  Mesh mesh;
  std::ifstream in(argc > 1 ? argv[1] : "data/elephant.off");
  if(!(in >> mesh))
    return 1;
  auto segment = mesh.add_property_map<face_descriptor, std::size_t>("f:segment").first;
  std::size_t n = SpectralSeg::k_way_segmentation(mesh, 6, segment,
                      SpectralSeg::parameters::number_of_threads(0));
  std::cout << n << " segments\n";
  return 0;
}
