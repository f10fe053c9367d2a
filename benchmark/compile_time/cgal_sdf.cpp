// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reference of the compile-time measurement (doc/benchmarks.md,
// "Compile time"): CGAL's SDF segmentation of a Surface_mesh, as in CGAL's
// own example, in one translation unit.
//
// usage: cgal_sdf mesh.off
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

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
  auto sdf = mesh.add_property_map<face_descriptor, double>("f:sdf").first;
  CGAL::sdf_values(mesh, sdf);
  auto segment = mesh.add_property_map<face_descriptor, std::size_t>("f:segment").first;
  std::size_t n = CGAL::segmentation_from_sdf_values(mesh, sdf, segment);
  std::cout << n << " segments\n";
  return 0;
}
