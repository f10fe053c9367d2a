// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg descriptor MESH --output FILE.json ...
// spectralseg rank QUERY FOLDER ...
// Shape retrieval (thesis 3.6): the shape descriptor of a mesh, and a folder
// of meshes ranked by chi-square distance to a query.
#ifndef SPECTRALSEG_TOOLS_COMMAND_RETRIEVAL_H
#define SPECTRALSEG_TOOLS_COMMAND_RETRIEVAL_H

#include "Argument_checks.h"
#include "Batch_inputs.h"
#include "Loaded_mesh.h"
#include "Progress_printer.h"
#include "metric_choice.h"

#include <SpectralSeg/IO/Atomic_output_file.h>
#include <SpectralSeg/Retrieval/Shape_descriptor.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace spectralseg_cli {

inline Metric_options retrieval_metric_options()
{
  Metric_options m;
  m.weights = {0.02, 0., 0.98};
  return m;
}

// The metric and descriptor options both commands share.
struct Descriptor_choice
{
  // --metric part-aware, geodesic or euclidean; the thesis's retrieval weights
  Metric_options metric = retrieval_metric_options();
  std::size_t bins = 64;
  std::size_t sources = 32;
  double range = 4.;
  unsigned threads = 0;
};

struct Descriptor_command_options
{
  std::string mesh;
  std::string output;
  Descriptor_choice choice;
  const CLI::App* cli = nullptr; // the parsed subcommand (null: none)
};

struct Rank_command_options
{
  std::string query;
  std::vector<std::string> folders;
  std::size_t top = 0;
  std::string output;
  Descriptor_choice choice;
  const CLI::App* cli = nullptr;
};

inline void add_descriptor_options(CLI::App& cmd, Descriptor_choice& c)
{
  Metric_options& o = c.metric;
#ifdef SPECTRALSEG_HAS_EMBREE
  const std::vector<std::string> casters{"aabb", "embree"};
#else
  const std::vector<std::string> casters{"aabb"};
#endif
  cmd.add_option("--metric", o.name,
                 "distance between faces: part-aware (shortest paths, geodesic+angular+VSI blend), geodesic "
                 "(shortest paths) or euclidean (straight lines between centroids: the D2 descriptor)")
    ->check(CLI::IsMember({"part-aware", "geodesic", "euclidean"}))
    ->capture_default_str();
  cmd.add_option_function<std::string>(
       "--weights",
       [&o](const std::string& text) { o.weights = parse_number_list("--weights", text, 3, 3, 1e6); },
       "part-aware coefficients geodesic,angular,vsi (the thesis's for retrieval by default; scaled to add up "
       "to 1)")
    ->type_name("A,B,C")
    ->default_str("0.02,0,0.98");
  cmd.add_option("--ray-caster", o.ray_caster, "ray-casting backend of the part-aware metric")
    ->check(CLI::IsMember(casters))
    ->capture_default_str();
  cmd.add_option("--normalization", o.normalization,
                 "how each part-aware component is scaled into [0,1]: p99 (the default) or max (the thesis)")
    ->check(CLI::IsMember({"p99", "max"}))
    ->capture_default_str();
  cmd.add_option("--vsi-fraction", o.vsi_fraction, "fraction of the faces whose shape image is ray-cast")
    ->check(Finite_range(0.0, 1.0))
    ->capture_default_str();
  cmd.add_option("--max-measured-faces", o.max_measured_faces,
                 "at most this many faces cast their cone of rays for their reference point (0: every face)")
    ->check(Count(0, 1000000000))
    ->capture_default_str();
  cmd.add_option("--bins", c.bins, "histogram bins")->check(Count(2, 100000))->capture_default_str();
  cmd.add_option("--sources", c.sources, "source faces (farthest-point samples, each weighted by its area share)")
    ->check(Count(1, 100000))
    ->capture_default_str();
  cmd.add_option("--range", c.range, "the histogram covers 0 to this many mean distances")
    ->check(Finite_range(1e-3, 1e3))
    ->capture_default_str();
  cmd.add_option("--threads", c.threads, "threads (0 = all)")->check(Count(0, 4096));
}

inline void refuse_inapplicable_descriptor_options(const CLI::App* cmd, const Descriptor_choice& o)
{
  std::vector<std::string> w;
  for(const char* option : {"--weights", "--normalization", "--ray-caster", "--vsi-fraction", "--max-measured-faces"})
    if(o.metric.name != "part-aware" && given(cmd, option))
      w.push_back(std::string(option) + " cannot be used here: it applies to --metric part-aware, not " +
                  o.metric.name);
  refuse_inapplicable_options(w);
}

inline SpectralSeg::Retrieval::Shape_descriptor describe_mesh(const Loaded_mesh& m, const Descriptor_choice& o,
                                                  Progress_printer& out)
{
  using namespace SpectralSeg;
  const Execution exec(o.threads, out.callback());
  Retrieval::Descriptor_options d;
  d.bins = o.bins;
  d.sources = o.sources;
  d.range = o.range;
  if(o.metric.name == "euclidean")
    return Retrieval::shape_descriptor(m.graph, Retrieval::Euclidean_distance(), d, exec);
  const Metrics::Any_weight metric = make_metric(o.metric);
  exec.report(metric.name() + " weights", 0.);
  const std::vector<double> weights = metric(m.graph, exec);
  exec.report(metric.name() + " weights", 1.);
  const Weighted_dual_graph weighted(m.graph, weights);
  return Retrieval::shape_descriptor(weighted, metric.name(), d, exec);
}

inline std::string descriptor_json(const SpectralSeg::Retrieval::Shape_descriptor& d, const std::string& mesh)
{
  nlohmann::ordered_json j;
  j["mesh"] = mesh;
  j["metric"] = d.metric;
  j["bins"] = d.histogram.size();
  j["range"] = d.range;
  j["sources"] = d.sources;
  j["mean_distance"] = d.mean_distance;
  j["histogram"] = d.histogram;
  return j.dump(1) + "\n";
}

inline void add_descriptor_command(CLI::App& app, Descriptor_command_options& o)
{
  CLI::App* cmd = app.add_subcommand(
    "descriptor", "Shape descriptor of a mesh for retrieval: histogram of the distances between faces, divided by "
                  "their mean (thesis 3.6), as JSON");
  o.cli = cmd;
  cmd->add_option("MESH", o.mesh, "mesh file (.off, .obj, .ply, .stl)")->required();
  cmd->add_option("--output", o.output, "output: the descriptor as JSON ('-': standard output)")->required();
  add_descriptor_options(*cmd, o.choice);
}

inline void add_rank_command(CLI::App& app, Rank_command_options& o)
{
  CLI::App* cmd = app.add_subcommand(
    "rank", "Rank the meshes of folders by the chi-square distance of their shape descriptors to a query mesh's");
  o.cli = cmd;
  cmd->add_option("QUERY", o.query, "query mesh file")->required();
  cmd->add_option("FOLDER", o.folders, "folders whose meshes (.off, .obj, .ply, .stl, not recursive) are ranked")
    ->required();
  cmd->add_option("--top", o.top, "print only the N nearest (0 = all)")->check(Count(0, 100000000));
  cmd->add_option("--output", o.output, "output: the ranking as TSV (default: standard output)");
  add_descriptor_options(*cmd, o.choice);
}

inline int run_descriptor(const Descriptor_command_options& o, Progress_printer& out)
{
  check_outputs({{"--output", o.output, true}});
  refuse_inapplicable_descriptor_options(o.cli, o.choice);
  const Loaded_mesh m(o.mesh, out, true, o.choice.threads);
  const std::string text = descriptor_json(describe_mesh(m, o.choice, out), o.mesh);
  if(o.output == "-")
    std::cout << text;
  else
  {
    SpectralSeg::IO::write_text_file(o.output, text);
    std::cout << "descriptor: " << o.output << "\n";
  }
  return 0;
}

inline int run_rank(const Rank_command_options& o, Progress_printer& out)
{
  namespace fs = std::filesystem;
  check_outputs({{"--output", o.output}});
  refuse_inapplicable_descriptor_options(o.cli, o.choice);
  std::vector<std::string> meshes;
  for(const std::string& folder : o.folders)
  {
    std::error_code ec;
    if(!fs::is_directory(folder, ec))
      throw SpectralSeg::Invalid_input("'" + folder + "' is not a folder");
    std::vector<std::string> here;
    for(const auto& e : fs::directory_iterator(folder, ec))
      if(e.is_regular_file(ec) && has_mesh_extension(e.path()))
        here.push_back(e.path().string());
    if(ec)
      throw SpectralSeg::Invalid_input("cannot list '" + folder + "': " + ec.message());
    std::sort(here.begin(), here.end());
    meshes.insert(meshes.end(), here.begin(), here.end());
  }
  if(meshes.empty())
    throw SpectralSeg::Invalid_input("no mesh file (.off, .obj, .ply, .stl) in the folders given");
  const SpectralSeg::Retrieval::Shape_descriptor query =
    describe_mesh(Loaded_mesh(o.query, out, true, o.choice.threads), o.choice, out);
  std::vector<SpectralSeg::Retrieval::Shape_descriptor> database;
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    out.message("mesh " + std::to_string(i + 1) + "/" + std::to_string(meshes.size()) + ": " + meshes[i]);
    database.push_back(
      describe_mesh(Loaded_mesh(meshes[i], out, true, o.choice.threads), o.choice, out));
  }
  const std::vector<SpectralSeg::Retrieval::Ranked_shape> ranking = SpectralSeg::Retrieval::rank_shapes(query, database);
  std::ostringstream text;
  text << "rank\tchi_square\tmesh\n";
  const std::size_t shown = o.top == 0 ? ranking.size() : std::min(o.top, ranking.size());
  for(std::size_t r = 0; r < shown; ++r)
    text << r + 1 << "\t" << ranking[r].distance << "\t" << meshes[ranking[r].index] << "\n";
  if(o.output.empty())
    std::cout << text.str();
  else
  {
    SpectralSeg::IO::write_text_file(o.output, text.str());
    std::cout << "ranking: " << o.output << "\n";
  }
  return 0;
}


} // namespace spectralseg_cli

#endif
