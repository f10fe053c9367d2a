// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// End-to-end segmentation time, per stage, and peak memory of one
// configuration, for the speed table. Run each configuration in its own
// process so that the peak memory is its own; benchmark/run_speed_benchmark.sh
// runs the whole table.
//
// usage: bench_segmentation_speed MESH METHOD [--k 10] [--faces N | --subdivisions L]
//                                 [--threads 0] [--tsv] [--header] [--trace]
//        bench_segmentation_speed --methods
//   METHOD        spectralseg (k-way, AABB ray casting), spectralseg-embree, auto-contrast (the default
//                 automatic method, default ray caster), auto-salient (the thesis's ch. 6 salient cuts)
//                 (k-way, Embree ray casting; only if built with Embree),
//                 cgal-sdf (CGAL::sdf_values + CGAL::segmentation_from_sdf_values,
//                 single-threaded), or faces (print the face count of the
//                 prepared mesh and exit)
//   --k K         number of segments (default 10)
//   --faces N     resize the mesh to about N faces first: if N is below the
//                 face count, decimate by edge collapse (CGAL
//                 Surface_mesh_simplification, Lindstrom-Turk) to at most about
//                 N faces; if above, apply 1-to-4 midpoint subdivision until the
//                 mesh has at least N faces
//   --subdivisions L  apply L 1-to-4 midpoint subdivisions (default 0)
//   --threads T   SpectralSeg threads, 0 = all hardware threads (default 0)
//   --tsv         print a tab-separated row instead of a markdown row
//   --header      print the column names (markdown or TSV) before the row
//   --trace       print every progress report (seconds, stage, fraction) to stderr
//   --methods     list the methods this build supports, one per line
//
// Columns: method, mesh, faces, threads, k, segments, then seconds of
//   metric       SpectralSeg: dual graph + part-aware edge weights (geodesic,
//                angular, VSI: ray casting setup, reference points, shape
//                images, VSI weights); CGAL: sdf_values
//   sampling     farthest-point sampling of the Nyström samples, up to the
//                start of the last "distance rows" stage (empty when the
//                exact embedding is used: up to 2,000 faces); when the
//                sampling keeps its Dijkstra rows (the default), up to the
//                start of "eigen-solve", rows and affinities included
//   distances    the distance rows of the samples (all faces for the exact
//                embedding) and their conversion into affinities, up to the
//                start of "eigen-solve"; empty when the sampling kept its rows
//   eigen-solve  eigen-solve and Nyström extension, up to the start of K-means
//   clustering   K-means + connected segments + merge (K_way_result::timings);
//                CGAL: segmentation_from_sdf_values (soft clustering and graph
//                cut in one call, which cannot be split)
//   cut          graph-cut boundary enhancement; empty for CGAL (included
//                in clustering)
//   total        wall clock of everything above (the stage columns add up to
//                it, up to a few milliseconds, except with several k-way
//                candidates: their stage times are summed, and their merges
//                and graph cuts run side by side)
// and the peak resident memory in MB during the segmentation (VmHWM, reset
// after the mesh is prepared, so that it counts the mesh but not its
// subdivision or decimation; ru_maxrss of the whole process if the reset is
// not possible). The stage boundaries are read from the library's progress
// reports (SpectralSeg::Execution), with the time of each report.
#include "decimate.h"
#include "subdivide.h"
#include "timing.h"

#include <SpectralSeg/automatic_segmentation.h>
#include <SpectralSeg/segment_hybrid.h>
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
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

using spectralseg_bench::seconds_since;

// Resets the peak resident set size of this process (Linux 4.0 and later),
// after giving the freed heap back to the system.
bool reset_peak_memory()
{
#ifdef __GLIBC__
  malloc_trim(0);
#endif
#ifdef __linux__
  std::ofstream f("/proc/self/clear_refs");
  f << "5";
  f.close();
  return static_cast<bool>(f);
#else
  return false;
#endif
}

// VmHWM (peak resident set size since the last reset) in MB, or the whole
// process's ru_maxrss if it cannot be read.
double peak_megabytes()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.compare(0, 6, "VmHWM:") == 0)
    {
      std::istringstream in(line.substr(6));
      double kb = 0;
      if(in >> kb)
        return kb / 1024.;
    }
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.;
}

// The progress reports of one run, timed from the construction of the clock.
class Stage_clock
{
public:
  explicit Stage_clock(bool trace) : trace_(trace), origin_(std::chrono::steady_clock::now()) {}

  SpectralSeg::Progress_callback callback()
  {
    return [this](const std::string& stage, double fraction) {
      const double t = now();
      events_.push_back(Event{t, stage, fraction});
      if(trace_)
        std::fprintf(stderr, "%10.4f s  %-28s %.2f\n", t, stage.c_str(), fraction);
      return true;
    };
  }

  double now() const { return seconds_since(origin_); }

  // time of the first report of `stage` at or after `after`, or -1
  double first(const std::string& stage, double after) const
  {
    for(const Event& e : events_)
      if(e.time >= after && e.stage == stage)
        return e.time;
    return -1.;
  }

  // time of the last start (fraction 0) of `stage` in [after, before], or -1
  double last_start(const std::string& stage, double after, double before) const
  {
    double t = -1.;
    for(const Event& e : events_)
      if(e.time >= after && e.time <= before && e.stage == stage && e.fraction == 0.)
        t = e.time;
    return t;
  }

private:
  struct Event
  {
    double time;
    std::string stage;
    double fraction;
  };
  bool trace_;
  std::chrono::steady_clock::time_point origin_;
  std::vector<Event> events_;
};

// Seconds per stage of one run; -1 means "not applicable" (an empty column).
struct Run
{
  unsigned threads = 1;
  std::size_t segments = 0;
  double metric = -1, sampling = -1, distances = -1, eigen_solve = -1, clustering = -1, cut = -1, total = -1;
};

template <typename RayCaster>
Run run_spectralseg(const Mesh& mesh, std::size_t k, unsigned threads, bool trace)
{
  Stage_clock clock(trace);
  const SpectralSeg::Execution exec(threads, clock.callback());
  Run r;
  r.threads = exec.threads();
  const double t0 = clock.now();
  const SpectralSeg::Dual_graph g = SpectralSeg::make_dual_graph(mesh);
  const std::vector<double> w = SpectralSeg::Metrics::Part_aware_weight<RayCaster>()(g, exec);
  const SpectralSeg::Weighted_dual_graph wg(g, w);
  const double t1 = clock.now();
  const SpectralSeg::K_way_result kr = SpectralSeg::segment_k_way(wg, k, SpectralSeg::K_way_options(), exec);
  const double t2 = clock.now();
  r.segments = kr.number_of_segments;
  r.metric = t1 - t0;
  r.total = t2 - t0;

  // the embedding runs from t1 to the start of K-means
  const double kmeans = clock.first("k-means", t1);
  const double eigen = clock.first("eigen-solve", t1);
  const double rows = eigen < 0 ? -1. : clock.last_start("distance rows", t1, eigen);
  const bool sampled = clock.first("farthest point sampling", t1) >= 0 || clock.first("gamma sampling", t1) >= 0;
  if(kmeans >= 0 && eigen >= 0 && rows >= 0)
  {
    if(sampled)
      r.sampling = rows - t1;
    r.distances = eigen - (sampled ? rows : t1);
    r.eigen_solve = kmeans - eigen;
  }
  else if(kmeans >= 0 && eigen >= 0 && sampled)
  {
    // the farthest-point sampling kept its Dijkstra rows: no separate
    // distance-row stage, the sampling column holds both
    r.sampling = eigen - t1;
    r.eigen_solve = kmeans - eigen;
  }
  for(const auto& stage : kr.timings)
  {
    if(stage.first == "graph cut")
      r.cut = (r.cut < 0 ? 0. : r.cut) + stage.second;
    else if(stage.first == "k-means" || stage.first == "connected segments" || stage.first == "merge")
      r.clustering = (r.clustering < 0 ? 0. : r.clustering) + stage.second;
  }
  return r;
}

// The automatic methods: contrast merge (the default, part-aware metric) or
// the thesis's salient cuts (no part-aware metric).
Run run_automatic(const Mesh& mesh, bool salient, unsigned threads)
{
  const SpectralSeg::Execution exec(threads);
  Run r;
  r.threads = exec.threads();
  const auto t0 = std::chrono::steady_clock::now();
  const SpectralSeg::Dual_graph g = SpectralSeg::make_dual_graph(mesh);
  if(salient)
  {
    const auto a = SpectralSeg::segment_automatically(g, SpectralSeg::sequence_weights(g, exec),
                                                      SpectralSeg::Automatic_segmentation_options<>(), exec);
    r.segments = a.number_of_segments;
    r.clustering = seconds_since(t0);
  }
  else
  {
    const std::vector<double> w = SpectralSeg::Metrics::Part_aware_weight<>()(g, exec);
    const SpectralSeg::Weighted_dual_graph wg(g, w);
    r.metric = seconds_since(t0);
    const auto t1 = std::chrono::steady_clock::now();
    const SpectralSeg::K_way_result kr = SpectralSeg::segment_hybrid(wg, SpectralSeg::Hybrid_options(), exec);
    r.segments = kr.number_of_segments;
    r.clustering = seconds_since(t1);
  }
  r.total = seconds_since(t0);
  return r;
}

Run run_cgal_sdf(Mesh& mesh, std::size_t k)
{
  Run r;
  auto sdf = mesh.add_property_map<Mesh::Face_index, double>("f:sdf").first;
  auto seg = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:seg").first;
  const auto t0 = std::chrono::steady_clock::now();
  CGAL::sdf_values(mesh, sdf);
  r.metric = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  r.segments = CGAL::segmentation_from_sdf_values(mesh, sdf, seg, k);
  r.clustering = seconds_since(t1);
  r.total = seconds_since(t0);
  return r;
}

std::string seconds_field(double s)
{
  if(s < 0)
    return "";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", s);
  return buffer;
}

int usage(const char* program)
{
  std::fprintf(stderr,
               "usage: %s MESH spectralseg|spectralseg-embree|auto-contrast|auto-salient|cgal-sdf|faces [--k 10] [--faces N | --subdivisions L]\n"
               "       [--threads 0] [--tsv] [--header] [--trace]\n"
               "       %s --methods\n",
               program, program);
  return 1;
}

} // namespace

int main(int argc, char** argv)
{
  const std::vector<std::string> args(argv + 1, argv + argc);
#ifdef __GLIBC__
  // the allocator setting of the spectralseg tool (tools/spectralseg/main.cpp),
  // for every method, CGAL's included
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_ARENA_MAX, int(std::max(1u, std::thread::hardware_concurrency())));
#endif
  if(args.size() == 1 && args[0] == "--methods")
  {
    std::printf("spectralseg\n");
#ifdef SPECTRALSEG_HAS_EMBREE
    std::printf("spectralseg-embree\n");
#endif
    std::printf("cgal-sdf\n");
    return 0;
  }
  if(args.size() < 2)
    return usage(argv[0]);
  const std::string path = args[0], method = args[1];
  std::size_t k = 10, target_faces = 0;
  int levels = 0;
  unsigned threads = 0;
  bool tsv = false, header = false, trace = false;
  try
  {
    for(std::size_t i = 2; i < args.size(); ++i)
    {
      const std::string& a = args[i];
      auto next = [&]() -> std::string {
        if(i + 1 >= args.size())
          throw std::runtime_error("missing value after " + a);
        return args[++i];
      };
      if(a == "--k")
        k = std::stoul(next());
      else if(a == "--faces")
        target_faces = std::stoul(next());
      else if(a == "--subdivisions")
        levels = std::stoi(next());
      else if(a == "--threads")
        threads = static_cast<unsigned>(std::stoul(next()));
      else if(a == "--tsv")
        tsv = true;
      else if(a == "--header")
        header = true;
      else if(a == "--trace")
        trace = true;
      else
        throw std::runtime_error("unknown option " + a);
    }
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "%s\n", e.what());
    return usage(argv[0]);
  }
  if(target_faces > 0 && levels > 0)
  {
    std::fprintf(stderr, "--faces and --subdivisions exclude each other\n");
    return 1;
  }

  Mesh mesh;
  try
  {
    SpectralSeg::IO::read_mesh_file(path, mesh);
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  std::string name = path.substr(path.find_last_of("/\\") + 1);
  if(target_faces > 0 && target_faces < num_faces(mesh))
  {
    spectralseg_bench::decimate(mesh, target_faces);
    name += " decimated";
  }
  else if(target_faces > 0)
    while(num_faces(mesh) < target_faces)
    {
      mesh = spectralseg_bench::midpoint_subdivision(mesh);
      ++levels;
    }
  else
    for(int i = 0; i < levels; ++i)
      mesh = spectralseg_bench::midpoint_subdivision(mesh);
  if(levels > 0)
    name += " x" + std::to_string(std::size_t(1) << (2 * levels));
  if(method == "faces")
  {
    std::printf("%zu\n", std::size_t(num_faces(mesh)));
    return 0;
  }

  if(!reset_peak_memory())
    std::fprintf(stderr, "warning: cannot reset the peak memory; peak MB includes the mesh preparation\n");
  Run r;
  try
  {
    if(method == "cgal-sdf")
      r = run_cgal_sdf(mesh, k);
#ifdef SPECTRALSEG_HAS_EMBREE
    else if(method == "spectralseg-embree")
      r = run_spectralseg<SpectralSeg::Ray_casting::Embree_ray_caster>(mesh, k, threads, trace);
#endif
    else if(method == "spectralseg")
      r = run_spectralseg<SpectralSeg::Ray_casting::AABB_ray_caster>(mesh, k, threads, trace);
    else if(method == "auto-contrast" || method == "auto-salient")
      r = run_automatic(mesh, method == "auto-salient", threads);
    else
    {
      std::fprintf(stderr, "unknown method %s (see --methods)\n", method.c_str());
      return 1;
    }
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "%s on %s: %s\n", method.c_str(), name.c_str(), e.what());
    return 1;
  }
  const double peak = peak_megabytes();

  const std::vector<std::string> columns = {"method", "mesh", "faces", "threads", "k", "segments", "metric s",
                                            "sampling s", "distances s", "eigen-solve s", "clustering s", "cut s",
                                            "total s", "peak MB"};
  char peak_text[32];
  std::snprintf(peak_text, sizeof peak_text, "%.0f", peak);
  const std::vector<std::string> fields = {method, name, std::to_string(num_faces(mesh)), std::to_string(r.threads),
                                           std::to_string(k), std::to_string(r.segments), seconds_field(r.metric),
                                           seconds_field(r.sampling), seconds_field(r.distances),
                                           seconds_field(r.eigen_solve), seconds_field(r.clustering),
                                           seconds_field(r.cut), seconds_field(r.total), peak_text};
  auto print_row = [tsv](const std::vector<std::string>& row) {
    std::string line = tsv ? "" : "|";
    for(std::size_t i = 0; i < row.size(); ++i)
      line += tsv ? (i ? "\t" : "") + row[i] : " " + row[i] + " |";
    std::printf("%s\n", line.c_str());
  };
  if(header)
  {
    print_row(columns);
    if(!tsv)
    {
      std::string rule = "|---|---|";
      for(std::size_t i = 2; i < columns.size(); ++i)
        rule += "---:|";
      std::printf("%s\n", rule.c_str());
    }
  }
  print_row(fields);
  return 0;
}
