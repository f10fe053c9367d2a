// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// --metric, --weights and VSI options of the command-line tool.
#ifndef SPECTRALSEG_TOOLS_METRIC_CHOICE_H
#define SPECTRALSEG_TOOLS_METRIC_CHOICE_H

#include <SpectralSeg/Metrics/Any_weight.h>

#include "Argument_checks.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace spectralseg_cli {

// VSI::Reference_point_options::max_measured_faces's default (checked in
// segmentation_methods.cpp)
constexpr std::size_t default_max_measured_faces = 100000;

struct Metric_options
{
  std::string name = "part-aware";
  std::vector<double> weights{0.01, 0.195, 0.795};
#ifdef SPECTRALSEG_HAS_EMBREE
  std::string ray_caster = "embree"; // the fastest backend when built
#else
  std::string ray_caster = "aabb";
#endif
  double vsi_fraction = 0.01;
  std::size_t max_measured_faces = default_max_measured_faces;
  std::string normalization = "p99";
};

inline void add_metric_options(CLI::App& cmd, Metric_options& o)
{
  cmd.add_option("--metric", o.name,
                 "dual-graph metric: part-aware (geodesic+angular+VSI blend), geodesic, angular or vsi; "
                 "'blend' is a synonym of part-aware")
    ->check(CLI::IsMember({"part-aware", "blend", "geodesic", "angular", "vsi"}))
    ->capture_default_str();
  cmd.add_option_function<std::string>(
       "--weights",
       [&o](const std::string& text) { o.weights = parse_number_list("--weights", text, 2, 3, 1e6); },
       "part-aware coefficients geodesic,angular[,vsi], each from 0 to 1e6, not all 0 (each component is "
       "normalised to [0,1] first; the coefficients are scaled to add up to 1)")
    ->type_name("A,B[,C]")
    ->default_str("0.01,0.195,0.795");
  std::vector<std::string> casters{"aabb"};
#ifdef SPECTRALSEG_HAS_EMBREE
  casters.push_back("embree");
#endif
  cmd.add_option("--ray-caster", o.ray_caster, "ray-casting backend of the VSI metric")
    ->check(CLI::IsMember(casters))
    ->capture_default_str();
  cmd.add_option("--normalization", o.normalization,
                 "how each metric component is scaled into [0,1] before blending: p99 (99th percentile, "
                 "clamped; the default) or max (the thesis)")
    ->check(CLI::IsMember({"p99", "max"}))
    ->capture_default_str();
  cmd.add_option("--vsi-fraction", o.vsi_fraction,
                 "fraction of the faces whose shape image is ray-cast (the rest are interpolated)")
    ->check(Finite_range(0.0, 1.0))
    ->capture_default_str();
  cmd.add_option("--max-measured-faces", o.max_measured_faces,
                 "at most this many faces, spread over the shape, cast their cone of rays for their reference "
                 "point; the others take their neighbours' depth (0: every face, the thesis)")
    ->check(Count(0, 1000000000))
    ->capture_default_str();
}

// The metric options given that the chosen --metric does not use.
inline std::vector<std::string> inapplicable_metric_options(const CLI::App* cmd, const Metric_options& o)
{
  std::vector<std::string> w;
  const bool part_aware = o.name == "part-aware" || o.name == "blend";
  for(const char* option : {"--weights", "--normalization"})
    if(!part_aware && given(cmd, option))
      w.push_back(std::string(option) + " cannot be used here: it applies to --metric part-aware, not " + o.name);
  for(const char* option : {"--ray-caster", "--vsi-fraction", "--max-measured-faces"})
    if((o.name == "geodesic" || o.name == "angular") && given(cmd, option))
      w.push_back(std::string(option) + " cannot be used here: --metric " + o.name + " casts no rays");
  return w;
}

// The metric the options name (defined in segmentation_methods.cpp, with
// the ray casters).
SpectralSeg::Metrics::Any_weight make_metric(const Metric_options& o);

} // namespace spectralseg_cli

#endif
