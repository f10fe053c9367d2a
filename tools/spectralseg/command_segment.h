// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg segment MESH --k K ...
#ifndef SPECTRALSEG_TOOLS_COMMAND_SEGMENT_H
#define SPECTRALSEG_TOOLS_COMMAND_SEGMENT_H

#include "Argument_checks.h"
#include "Mesh_outputs.h"
#include "Work_limits.h"
#include "metric_choice.h"
#include "salient_cut_segmentation.h"

#include <SpectralSeg/K_way_options.h>
#include <SpectralSeg/segment_hybrid.h>
#include <SpectralSeg/k_way_segmentation.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace spectralseg_cli {

struct Segment_options
{
  std::string mesh;
  std::string k;
  std::size_t max_k = 20;
  Metric_options metric;
  std::string kernel = "exponential";
  std::string sampling = "auto";
  std::size_t samples = 0;
  bool no_graph_cut = false;
  std::string graph_cut_backend = "default";
  unsigned threads = 0;
  unsigned seed = 0;
  std::size_t extra_clusters = SpectralSeg::K_way_options().extra_clusters;
  std::vector<std::size_t> alternative_extra_clusters = SpectralSeg::K_way_options().alternative_extra_clusters;
  std::string graph_cut = "banded";
  double crease_angle = SpectralSeg::K_way_options().crease_angle;
  double merge_size_exponent = SpectralSeg::K_way_options().merge_size_exponent;
  double merge_separation = SpectralSeg::K_way_options().merge_separation_scale;
  double min_boundary_contrast = 0.; // 0: the method's default (contrast-merge 4, concave-merge 3)
  double neck_scale = SpectralSeg::Hybrid_options().neck_scale;
  std::string labels, out_mesh, png, json;
  bool binary = false;   // PLY outputs in binary
  std::string parts_dir; // one PLY file per segment
  Salient_cut_options salient;
  const CLI::App* cli = nullptr; // the parsed subcommand, to tell the options given (null: none)
};

// The options of the method, all but the input and the outputs: shared by
// `segment` and `batch`.
inline void add_segment_method_options(CLI::App* cmd, Segment_options& o)
{
  cmd->add_option("--k", o.k,
                  "number of segments: a positive integer, or 'auto' to let --auto-method choose it")
    ->required();
  cmd->add_option("--max-k", o.max_k, "largest k considered by --k auto")->capture_default_str()->check(Count(2, max_clusters));
  cmd->add_option("--min-boundary-contrast", o.min_boundary_contrast,
                  "--k auto, contrast-merge and concave-merge: segments are merged while their boundary's contrast "
                  "to the whole mesh is below this (default 4 for contrast-merge, 3 for concave-merge)")
    ->check(Finite_range(0., 1e6));
  cmd->add_option("--neck-scale", o.neck_scale,
                  "--k auto, contrast-merge: a boundary's metric contrast is multiplied by its neck ratio (the "
                  "square root of the smaller segment's area over the boundary's length) over this, so that limbs "
                  "stay and slices of a body merge (0: off)")
    ->capture_default_str()
    ->check(Finite_range(0., 1e6));
  add_metric_options(*cmd, o.metric);
  cmd->add_option("--kernel", o.kernel, "affinity kernel")
    ->check(CLI::IsMember({"exponential", "gaussian"}))
    ->capture_default_str();
  cmd->add_option("--sampling", o.sampling,
                  "embedding: exact (full matrix), nystrom (farthest-point samples), gamma (Nyström with Gamma-sampling) or auto (exact up to 2000 faces, nystrom above)")
    ->check(CLI::IsMember({"auto", "exact", "nystrom", "gamma"}))
    ->capture_default_str();
  cmd->add_option("--samples", o.samples, "Nyström samples (default: one more than the K-means clusters)")->check(Count(0, max_samples));
  cmd->add_flag("--no-graph-cut", o.no_graph_cut, "skip the graph-cut boundary enhancement");
  cmd->add_option("--graph-cut", o.graph_cut,
                  "graph-cut settings: banded (a strong smoothness term acting near the boundaries) or thesis "
                  "(the thesis's weak smoothness term, every face free)")
    ->check(CLI::IsMember({"banded", "thesis"}))
    ->capture_default_str();
  cmd->add_option("--crease-angle", o.crease_angle,
                  "with extra clusters: split the K-means clusters along closed loops of concave creases of at least "
                  "this many degrees before merging (0: off)")
    ->capture_default_str()
    ->check(Finite_range(0., 180.));
  cmd->add_option("--merge-size-exponent", o.merge_size_exponent,
                  "with extra clusters: the merge multiplies a boundary's strength by the area fraction of the "
                  "smaller of its two segments to this power, so that small parts go before large ones (0: off)")
    ->capture_default_str()
    ->check(Finite_range(0., 10.));
  cmd->add_option("--merge-separation", o.merge_separation,
                  "with extra clusters, on meshes whose folds are mostly blunt: the merge weakens the boundary "
                  "between two segments that overlap in the spectral embedding (pieces of one body), in proportion "
                  "while their separation is below this scale (0: off)")
    ->capture_default_str()
    ->check(Finite_range(0., 1e6));
  cmd->add_option("--graph-cut-backend", o.graph_cut_backend,
                  "max-flow code of the graph cut: maxflow (fastest, GPL), boost-csr or boost-list (LGPL)")
    ->check(CLI::IsMember({"default", "maxflow", "boost-csr", "boost-list"}))
    ->capture_default_str();
  cmd->add_option("--threads", o.threads, "threads (0 = all); the labels do not depend on it")->check(Count(0, 4096));
  cmd->add_option("--seed", o.seed, "seed of the sampling's start face")->capture_default_str()->check(Count(0, UINT32_MAX));
  cmd->add_option("--extra-clusters", o.extra_clusters,
                  "K-means makes k + N clusters, then the segments with the weakest (least concave) boundaries "
                  "are merged until k are left (0, with --alternative-extra-clusters none: the thesis's method)")->capture_default_str()->check(Count(0, max_clusters));
  const CLI::Validator count = Count(0, max_clusters);
  cmd
    ->add_option_function<std::vector<std::string>>(
      "--alternative-extra-clusters",
      [&o](const std::vector<std::string>& items) {
        o.alternative_extra_clusters.clear();
        for(const std::string& item : items)
          if(item == "none" && items.size() > 1)
            throw CLI::ValidationError("--alternative-extra-clusters", "'none' cannot be combined with numbers");
          else if(item != "none")
            o.alternative_extra_clusters.push_back(std::stoul(item)); // checked below
      },
      "other numbers of extra clusters to try besides --extra-clusters (comma-separated, default 8): each is a "
      "whole segmentation, and the one whose boundaries best follow concave creases (lowest concave normalized "
      "cut) is kept; 'none': one segmentation only, about 20% faster")
    ->delimiter(',')
    ->check(CLI::Validator(
      [count](std::string& text) { return text == "none" ? std::string() : count(text); },
      "INT in [0, " + std::to_string(max_clusters) + "] or 'none'"));
  add_salient_cut_options(*cmd, o.salient);
}

inline void add_segment_command(CLI::App& app, Segment_options& o)
{
  CLI::App* cmd = app.add_subcommand("segment", "Segment a mesh into k parts by spectral clustering (k-way), or into as many parts as it has (--k auto)");
  o.cli = cmd;
  cmd->add_option("MESH", o.mesh, "mesh file (.off, .obj, .ply, .stl)")->required();
  add_segment_method_options(cmd, o);
  cmd->add_option("--labels", o.labels, "output: one segment label per face of the file, in file order")->required();
  add_mesh_output_options(*cmd, o.out_mesh, o.binary, o.parts_dir);
  cmd->add_option("--png", o.png, "output: picture of the segments");
  cmd->add_option("--json", o.json,
                  "output: report with the stage timings, segments and their areas ('-': on standard output, "
                  "which then carries nothing else)");
}

// The options given that the method asked for does not use, each with the
// reason: refused (exit code 2), not ignored.
std::vector<std::string> inapplicable_segment_options(const Segment_options& o);

// The value of --k: a number of segments, or 0 for 'auto'.
// \throws Usage_error if it is neither
std::size_t parse_k(const std::string& text);

// spectralseg segment: returns the exit code.
int run_segment(const Segment_options& o, Progress_printer& out);

} // namespace spectralseg_cli

#endif
