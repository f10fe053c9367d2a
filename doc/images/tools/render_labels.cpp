// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Renders a label file (one label per face of the mesh file, in file order)
// with views chosen on the command line, for meshes that the default views
// (front +Z, side +X, back -Z, +Y up) show badly. Not built by CMake: used
// once to make pictures of the manual (see README.md).
//
// usage: render_labels MESH LABELS OUT.png  dx dy dz ux uy uz  [dx dy dz ux uy uz ...]
//   each view: viewing direction (from the camera into the scene), then the up vector
//
// build: g++ -std=c++17 -O2 -I include -I /usr/include/eigen3 doc/images/tools/render_labels.cpp \
//            -o render_labels -lpng -lgmp -lmpfr
#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/Rendering/render_png.h>
#include <SpectralSeg/evaluation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

int main(int argc, char** argv)
{
  if(argc < 10 || (argc - 4) % 6 != 0)
  {
    std::cerr << "usage: render_labels MESH LABELS OUT.png dx dy dz ux uy uz [...]\n";
    return 1;
  }
  CGAL::Surface_mesh<K::Point_3> mesh;
  const SpectralSeg::IO::Mesh_file_report report = SpectralSeg::IO::read_mesh_file(argv[1], mesh);
  const SpectralSeg::Dual_graph graph = SpectralSeg::make_dual_graph(mesh);
  const std::vector<int> file_labels = SpectralSeg::Evaluation::read_labels(argv[2]);
  std::vector<int> labels(graph.number_of_faces());
  for(std::size_t f = 0; f < labels.size(); ++f)
    labels[f] = file_labels.at(report.input_face_of_face[f]);

  namespace R = SpectralSeg::Rendering;
  R::Render_options options;
  options.views.clear();
  for(int i = 4; i + 5 < argc; i += 6)
    options.views.push_back({"view",
                             {std::atof(argv[i]), std::atof(argv[i + 1]), std::atof(argv[i + 2])},
                             {std::atof(argv[i + 3]), std::atof(argv[i + 4]), std::atof(argv[i + 5])}});
  const SpectralSeg::Mesh_geometry& g = graph.geometry();
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  for(const auto& p : g.points)
    points.push_back({p.x(), p.y(), p.z()});
  for(const auto& t : g.triangles)
    triangles.push_back({t[0], t[1], t[2]});
  R::render_face_labels_png(argv[3], points, triangles, labels, options);
  std::cout << argv[3] << "\n";
  return 0;
}
