// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// --metric and --weights options of the command-line tool.
#ifndef SPECTRALSEG_TOOLS_METRIC_CHOICE_H
#define SPECTRALSEG_TOOLS_METRIC_CHOICE_H

#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Any_weight.h>
#include <SpectralSeg/Metrics/Blend.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace spectralseg_cli {

struct Metric_options
{
  std::string name = "blend";
  std::vector<double> weights{0.01, 0.99};
};

inline void add_metric_options(CLI::App& cmd, Metric_options& o)
{
  cmd.add_option("--metric", o.name, "dual-graph metric")
    ->check(CLI::IsMember({"geodesic", "angular", "blend"}))
    ->capture_default_str();
  cmd.add_option("--weights", o.weights,
                 "blend coefficients: geodesic,angular (each component normalised to [0,1] first)")
    ->delimiter(',')
    ->expected(2)
    ->capture_default_str();
}

inline SpectralSeg::Metrics::Any_weight make_metric(const Metric_options& o)
{
  using namespace SpectralSeg::Metrics;
  if(o.name == "geodesic")
    return Geodesic_weight();
  if(o.name == "angular")
    return Angular_weight();
  return Blend<Geodesic_weight, Angular_weight>({o.weights.at(0), o.weights.at(1)}, Geodesic_weight(),
                                                Angular_weight());
}

} // namespace spectralseg_cli

#endif
