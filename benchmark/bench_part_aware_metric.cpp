// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Times the part-aware edge weights (geodesic + angular + VSI) with each
// ray-casting backend against CGAL's sdf_values (25 rays per face, single
// thread) on the same mesh in the same run, for a mesh and its 1-to-4
// midpoint subdivisions.
//
// usage: bench_part_aware_metric MESH [levels=1] [threads=0 (all)]
#include "subdivide.h"
#include "timing.h"

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#ifdef SPECTRALSEG_HAS_EMBREE
#include <SpectralSeg/Ray_casting/Embree_ray_caster.h>
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <chrono>
#include <cstdio>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {
using spectralseg_bench::seconds;

template <typename RayCaster>
double time_part_aware(const SpectralSeg::Dual_graph& g, unsigned threads)
{
  std::vector<double> w;
  return seconds([&] { w = SpectralSeg::Metrics::Part_aware_weight<RayCaster>()(g, SpectralSeg::Execution(threads)); });
}
} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::fprintf(stderr, "usage: %s MESH [levels=1] [threads=0]\n", argv[0]);
    return 1;
  }
  const std::string path = argv[1];
  const int levels = argc > 2 ? std::stoi(argv[2]) : 1;
  const unsigned threads = argc > 3 ? static_cast<unsigned>(std::stoul(argv[3])) : 0u;
  Mesh mesh;
  SpectralSeg::IO::read_mesh_file(path, mesh);
  const std::string name = path.substr(path.find_last_of("/\\") + 1);
  const unsigned used = SpectralSeg::Execution(threads).threads();

  std::printf("| mesh | faces | threads | part-aware, AABB (s) | part-aware, Embree (s) | CGAL sdf_values, 1 thread (s) "
              "| AABB / sdf | Embree / sdf |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for(int level = 0; level <= levels; ++level)
  {
    if(level > 0)
      mesh = spectralseg_bench::midpoint_subdivision(mesh);
    const SpectralSeg::Dual_graph g = SpectralSeg::make_dual_graph(mesh);
    const double t_aabb = time_part_aware<SpectralSeg::Ray_casting::AABB_ray_caster>(g, threads);
    double t_embree = -1;
#ifdef SPECTRALSEG_HAS_EMBREE
    t_embree = time_part_aware<SpectralSeg::Ray_casting::Embree_ray_caster>(g, threads);
#endif
    auto sdf = mesh.add_property_map<Mesh::Face_index, double>("f:sdf").first;
    const double t_sdf = seconds([&] { CGAL::sdf_values(mesh, sdf); });
    mesh.remove_property_map(sdf);
    std::printf("| %s%s | %zu | %u | %.3f | %.3f | %.3f | %.3f | %.3f |\n", name.c_str(),
                level ? (" x" + std::to_string(1 << (2 * level))).c_str() : "", std::size_t(num_faces(mesh)), used, t_aabb, t_embree,
                t_sdf, t_aabb / t_sdf, t_embree / t_sdf);
    std::fflush(stdout);
  }
  return 0;
}
