// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Retrieval benchmark (thesis 3.6) on a directory laid out like psb-dev
// (off/<id>.off and index.tsv with the columns id and category): the shape
// descriptor of every model under each metric, every model queried against
// all others by chi-square distance; prints nearest neighbour, first tier
// and second tier per metric.
//
// usage: bench_retrieval DIR [options]
//   --metrics part-aware,geodesic,euclidean   metrics to score (default: all three)
//   --threads N        threads (default 0: all)
//   --bins B --sources S --range R   descriptor options (default 64, 32, 4)
//   --invariance K     also: for the first K models, chi-square between the descriptor of the
//                      model and of the model scaled by 7.3, rotated (37 degrees about (1,2,3)),
//                      and 1-to-4 subdivided, per metric (median and maximum)
//   --markdown FILE    also write the table to this file
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/shape_retrieval.h>

#include "subdivide.h"
#include "timing.h"

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {
namespace fs = std::filesystem;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
using namespace SpectralSeg;

struct Options
{
  std::string dir;
  std::vector<std::string> metrics{"part-aware", "geodesic", "euclidean"};
  unsigned threads = 0;
  Retrieval::Descriptor_options descriptor;
  std::size_t invariance = 0;
  std::string markdown;
};

Retrieval::Shape_descriptor describe(const Mesh& m, const std::string& metric, const Options& o)
{
  namespace P = SpectralSeg::parameters;
  const auto np = P::descriptor_options(o.descriptor).number_of_threads(o.threads);
  if(metric == "part-aware")
    return shape_descriptor(m, np.metric(Retrieval::retrieval_metric()));
  if(metric == "geodesic")
    return shape_descriptor(m, np.metric(Metrics::Geodesic_weight()));
  if(metric == "euclidean")
    return shape_descriptor(m, np.metric(Retrieval::Euclidean_distance()));
  throw std::runtime_error("unknown metric " + metric);
}

std::vector<std::string> split(const std::string& s, char sep)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  for(std::string item; std::getline(ss, item, sep);)
    out.push_back(item);
  return out;
}

Mesh transformed(const Mesh& m, const K::Aff_transformation_3& t)
{
  Mesh r = m;
  CGAL::Polygon_mesh_processing::transform(t, r);
  return r;
}

K::Aff_transformation_3 rotation()
{
  const double a = 37. * 3.14159265358979323846 / 180., c = std::cos(a), s = std::sin(a);
  double x = 1, y = 2, z = 3;
  const double l = std::sqrt(x * x + y * y + z * z);
  x /= l, y /= l, z /= l;
  return K::Aff_transformation_3(c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s,
                                 y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s,
                                 z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c));
}

int run(int argc, char** argv)
{
  Options o;
  std::vector<std::string> args(argv + 1, argv + argc);
  for(std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    auto next = [&]() -> std::string {
      if(i + 1 >= args.size())
        throw std::runtime_error(a + " needs a value");
      return args[++i];
    };
    if(a == "--metrics")
      o.metrics = split(next(), ',');
    else if(a == "--threads")
      o.threads = static_cast<unsigned>(std::stoul(next()));
    else if(a == "--bins")
      o.descriptor.bins = std::stoul(next());
    else if(a == "--sources")
      o.descriptor.sources = std::stoul(next());
    else if(a == "--range")
      o.descriptor.range = std::stod(next());
    else if(a == "--invariance")
      o.invariance = std::stoul(next());
    else if(a == "--markdown")
      o.markdown = next();
    else if(!a.empty() && a[0] != '-' && o.dir.empty())
      o.dir = a;
    else
      throw std::runtime_error("unknown option " + a);
  }
  if(o.dir.empty())
  {
    std::fprintf(stderr, "usage: %s DIR [--metrics part-aware,geodesic,euclidean] [--threads N] [--bins B] "
                         "[--sources S] [--range R] [--invariance K] [--markdown FILE]\n", argv[0]);
    return 2;
  }
  std::ifstream index(fs::path(o.dir) / "index.tsv");
  if(!index)
  {
    std::fprintf(stderr, "no index.tsv in %s\n", o.dir.c_str());
    return 1;
  }
  std::vector<std::string> ids, categories;
  std::string line;
  std::getline(index, line); // header
  while(std::getline(index, line))
  {
    const auto f = split(line, '\t');
    ids.push_back(f.at(0));
    categories.push_back(f.at(1));
  }
  const std::size_t n = ids.size();
  std::vector<std::vector<Retrieval::Shape_descriptor>> d(o.metrics.size(), std::vector<Retrieval::Shape_descriptor>(n));
  std::vector<double> seconds(o.metrics.size(), 0.);
  std::vector<std::vector<double>> invariance(3 * o.metrics.size());
  for(std::size_t i = 0; i < n; ++i)
  {
    Mesh mesh;
    IO::read_mesh_file((fs::path(o.dir) / "off" / (ids[i] + ".off")).string(), mesh);
    for(std::size_t k = 0; k < o.metrics.size(); ++k)
    {
      const auto t0 = std::chrono::steady_clock::now();
      d[k][i] = describe(mesh, o.metrics[k], o);
      seconds[k] += spectralseg_bench::seconds_since(t0);
      if(i < o.invariance)
      {
        const Mesh variants[3] = {transformed(mesh, K::Aff_transformation_3(CGAL::SCALING, 7.3)),
                                  transformed(mesh, rotation()), spectralseg_bench::midpoint_subdivision(mesh)};
        for(int v = 0; v < 3; ++v)
          invariance[3 * k + v].push_back(Retrieval::chi_square_distance(d[k][i], describe(variants[v], o.metrics[k], o)));
      }
    }
    std::fprintf(stderr, "\r%zu/%zu models", i + 1, n);
  }
  std::fprintf(stderr, "\n");

  std::set<std::string> classes(categories.begin(), categories.end());
  std::ostringstream table;
  table << "| metric | models | categories | nearest neighbour | first tier | second tier | median chi-square same / other "
           "category | descriptor s/model |\n"
        << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  char buf[256];
  for(std::size_t k = 0; k < o.metrics.size(); ++k)
  {
    std::vector<std::vector<double>> dist(n, std::vector<double>(n, 0.));
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = 0; b < n; ++b)
        dist[a][b] = Retrieval::chi_square_distance(d[k][a], d[k][b]);
    const Retrieval::Retrieval_scores s = Retrieval::retrieval_scores(dist, categories);
    std::vector<double> same, other;
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = a + 1; b < n; ++b)
        (categories[a] == categories[b] ? same : other).push_back(dist[a][b]);
    auto median = [](std::vector<double> x) {
      std::sort(x.begin(), x.end());
      return x.empty() ? 0. : x[x.size() / 2];
    };
    std::snprintf(buf, sizeof buf, "| %s | %zu | %zu | %.3f | %.3f | %.3f | %.3f / %.3f | %.3f |\n",
                  o.metrics[k].c_str(), n, classes.size(), s.nearest_neighbor, s.first_tier, s.second_tier,
                  median(same), median(other), seconds[k] / double(n));
    table << buf;
  }
  if(o.invariance > 0)
  {
    table << "\n| metric | models | scale x7.3 median / max (model) | rotation median / max (model) | 1-to-4 subdivision "
             "median / max (model) |\n"
          << "|---|---:|---:|---:|---:|\n";
    for(std::size_t k = 0; k < o.metrics.size(); ++k)
    {
      table << "| " << o.metrics[k] << " | " << invariance[3 * k].size();
      for(int v = 0; v < 3; ++v)
      {
        const std::vector<double>& x = invariance[3 * k + v];
        std::vector<double> sorted = x;
        std::sort(sorted.begin(), sorted.end());
        const std::size_t worst = std::size_t(std::max_element(x.begin(), x.end()) - x.begin());
        std::snprintf(buf, sizeof buf, " | %.2g / %.2g (%s)", sorted[sorted.size() / 2], sorted.back(),
                      ids[worst].c_str());
        table << buf;
      }
      table << " |\n";
    }
  }
  std::cout << table.str();
  if(!o.markdown.empty())
    std::ofstream(o.markdown) << table.str();
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return run(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
