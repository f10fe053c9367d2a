// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shape retrieval (thesis 3.6): the shape descriptor of each mesh, the
// histogram of the distances between its faces divided by their mean, under
// the part-aware metric (the thesis's retrieval coefficients), the geodesic
// metric and the Euclidean distance (D2); then every other mesh ranked by
// chi-square distance to the first one.
//
// usage: shape_retrieval query.off other1.off [other2.off ...]
#include <SpectralSeg/shape_retrieval.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace P = SpectralSeg::parameters;
using namespace SpectralSeg::Retrieval;

int main(int argc, char** argv)
{
  std::vector<std::string> paths(argv + 1, argv + argc);
  if(paths.size() < 2)
    paths = {SPECTRALSEG_DATA_DIR "/elephant.off", SPECTRALSEG_DATA_DIR "/camel.off",
             SPECTRALSEG_DATA_DIR "/human_man.off"};
  std::vector<Mesh> meshes(paths.size());
  for(std::size_t i = 0; i < paths.size(); ++i)
    if(!CGAL::IO::read_polygon_mesh(paths[i], meshes[i]) || !CGAL::is_triangle_mesh(meshes[i]))
    {
      std::cerr << "cannot read a triangle mesh from " << paths[i] << std::endl;
      return 1;
    }

  for(const std::string metric : {"part-aware", "geodesic", "euclidean"})
  {
    std::vector<Shape_descriptor> d;
    for(const Mesh& m : meshes)
    {
      if(metric == "part-aware") // the default metric: alpha 0.02, beta 0, gamma 0.98
        d.push_back(SpectralSeg::shape_descriptor(m));
      else if(metric == "geodesic")
        d.push_back(SpectralSeg::shape_descriptor(m, P::metric(SpectralSeg::Metrics::Geodesic_weight())));
      else // D2
        d.push_back(SpectralSeg::shape_descriptor(m, P::metric(Euclidean_distance())));
    }
    const std::vector<Shape_descriptor> others(d.begin() + 1, d.end());
    std::cout << metric << " ranking for " << paths[0] << ":\n";
    for(const Ranked_shape& r : rank_shapes(d[0], others))
      std::cout << "  " << r.distance << "  " << paths[r.index + 1] << "\n";
  }
  return 0;
}
