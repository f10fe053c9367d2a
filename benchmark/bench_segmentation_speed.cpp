// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// End-to-end segmentation time and peak memory of one configuration, for
// the speed table (run each configuration in its own process so that the
// peak memory is its own; see benchmark/run_speed_benchmark.sh).
//
// usage: bench_segmentation_speed MESH METHOD [k=10] [subdivisions=0] [threads=0]
//   METHOD: spectralseg (AABB ray casting), spectralseg-embree, cgal-sdf
// Prints one markdown table row:
// | method | mesh | faces | threads | k | segments | metric s | segmentation s | total s | peak MB |
#include "subdivide.h"

#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/k_way_segmentation.h>
#ifdef SPECTRALSEG_HAS_EMBREE
#include <SpectralSeg/Ray_casting/Embree_ray_caster.h>
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <set>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
double peak_megabytes()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.;
}
template <typename RayCaster>
std::size_t run_spectralseg(const Mesh& mesh, std::size_t k, unsigned threads, double& t_metric, double& t_seg)
{
  const SpectralSeg::Execution exec(threads);
  auto t0 = std::chrono::steady_clock::now();
  const SpectralSeg::Dual_graph g = SpectralSeg::make_dual_graph(mesh);
  const std::vector<double> w = SpectralSeg::Metrics::Part_aware_weight<RayCaster>()(g, exec);
  t_metric = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const SpectralSeg::Weighted_dual_graph wg(g, w);
  const SpectralSeg::K_way_result r = SpectralSeg::segment_k_way(wg, k, SpectralSeg::Kernels::Exponential_kernel(),
                                                                 SpectralSeg::K_way_options(), exec);
  t_seg = seconds_since(t0);
  return r.number_of_segments;
}
} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::fprintf(stderr, "usage: %s MESH spectralseg|spectralseg-embree|cgal-sdf [k=10] [subdivisions=0] [threads=0]\n", argv[0]);
    return 1;
  }
  const std::string path = argv[1], method = argv[2];
  const std::size_t k = argc > 3 ? std::stoul(argv[3]) : 10;
  const int levels = argc > 4 ? std::stoi(argv[4]) : 0;
  const unsigned threads = argc > 5 ? static_cast<unsigned>(std::stoul(argv[5])) : 0u;
  Mesh mesh;
  SpectralSeg::IO::read_mesh_file(path, mesh);
  for(int i = 0; i < levels; ++i)
    mesh = spectralseg_bench::midpoint_subdivision(mesh);

  double t_metric = 0, t_seg = 0;
  std::size_t segments = 0;
  unsigned used = SpectralSeg::Execution(threads).threads();
  if(method == "cgal-sdf")
  {
    used = 1;
    auto sdf = mesh.add_property_map<Mesh::Face_index, double>("f:sdf").first;
    auto seg = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:seg").first;
    auto t0 = std::chrono::steady_clock::now();
    CGAL::sdf_values(mesh, sdf);
    t_metric = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    segments = CGAL::segmentation_from_sdf_values(mesh, sdf, seg, k);
    t_seg = seconds_since(t0);
  }
#ifdef SPECTRALSEG_HAS_EMBREE
  else if(method == "spectralseg-embree")
    segments = run_spectralseg<SpectralSeg::Ray_casting::Embree_ray_caster>(mesh, k, threads, t_metric, t_seg);
#endif
  else if(method == "spectralseg")
    segments = run_spectralseg<SpectralSeg::Ray_casting::AABB_ray_caster>(mesh, k, threads, t_metric, t_seg);
  else
  {
    std::fprintf(stderr, "unknown method %s\n", method.c_str());
    return 1;
  }
  const std::string name = path.substr(path.find_last_of("/\\") + 1) + (levels ? " x" + std::to_string(1 << (2 * levels)) : "");
  std::printf("| %s | %s | %zu | %u | %zu | %zu | %.2f | %.2f | %.2f | %.0f |\n", method.c_str(), name.c_str(),
              std::size_t(num_faces(mesh)), used, k, segments, t_metric, t_seg, t_metric + t_seg, peak_megabytes());
  return 0;
}
