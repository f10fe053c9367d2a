// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Times one single-source Dijkstra on the dual graph (geodesic weights) on a
// mesh and on its 1-to-4 midpoint subdivisions, and the dual-graph build.
//
// usage: bench_dijkstra MESH [levels=1] [repeats=10]
// Prints a markdown table: mesh, faces, dual-graph build, weights, Dijkstra
// (median of the repeats), all single-threaded.
#include "subdivide.h"
#include "timing.h"

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Weighted_dual_graph.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {
using spectralseg_bench::seconds;

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::fprintf(stderr, "usage: %s MESH [levels=1] [repeats=10]\n", argv[0]);
    return 1;
  }
  const std::string path = argv[1];
  const int levels = argc > 2 ? std::stoi(argv[2]) : 1;
  const int repeats = argc > 3 ? std::stoi(argv[3]) : 10;
  Mesh mesh;
  SpectralSeg::IO::read_mesh_file(path, mesh);

  std::printf("| mesh | faces | dual graph build (s) | geodesic weights (s) | one Dijkstra, median of %d (s) |\n", repeats);
  std::printf("|---|---:|---:|---:|---:|\n");
  for(int level = 0; level <= levels; ++level)
  {
    if(level > 0)
      mesh = spectralseg_bench::midpoint_subdivision(mesh);
    SpectralSeg::Dual_graph g;
    const double t_build = seconds([&] { g = SpectralSeg::make_dual_graph(mesh); });
    std::vector<double> w;
    const double t_weights = seconds([&] { w = SpectralSeg::Metrics::Geodesic_weight()(g); });
    const SpectralSeg::Weighted_dual_graph wg(g, w);
    std::vector<double> times;
    double checksum = 0;
    for(int r = 0; r < repeats; ++r)
    {
      const auto source = static_cast<SpectralSeg::Dual_graph::size_type>((r * 7919u) % g.number_of_faces());
      times.push_back(seconds([&] { checksum += wg.distances(source)[0]; }));
    }
    std::sort(times.begin(), times.end());
    std::printf("| %s%s | %u | %.4f | %.4f | %.4f |\n", path.substr(path.find_last_of("/\\") + 1).c_str(),
                level ? (" x" + std::to_string(1 << (2 * level))).c_str() : "", g.number_of_faces(), t_build,
                t_weights, times[times.size() / 2]);
    if(checksum < 0)
      std::printf("impossible\n");
  }
  return 0;
}
