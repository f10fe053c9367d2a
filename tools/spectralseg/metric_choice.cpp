// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The metrics of --metric: their ray-casting backends are compiled here.
#include "metric_choice.h"

#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Metrics/VSI_weight.h>
#ifdef SPECTRALSEG_HAS_EMBREE
#include <SpectralSeg/Ray_casting/Embree_ray_caster.h>
#endif

namespace spectralseg_cli {

template <typename RayCaster>
SpectralSeg::Metrics::Any_weight make_vsi_metric(const Metric_options& o)
{
  using namespace SpectralSeg::Metrics;
  VSI_options vsi;
  vsi.images.sample_fraction = o.vsi_fraction;
  if(o.name == "vsi")
    return VSI_weight<RayCaster>(vsi);
  const double gamma = o.weights.size() > 2 ? o.weights[2] : 0.;
  return Part_aware_weight<RayCaster>(o.weights.at(0), o.weights.at(1), gamma, vsi, 0.001,
                                      o.normalization == "max" ? Normalization::maximum() : Normalization::quantile(0.99));
}

SpectralSeg::Metrics::Any_weight make_metric(const Metric_options& o)
{
  using namespace SpectralSeg::Metrics;
  if(o.name == "geodesic")
    return Geodesic_weight();
  if(o.name == "angular")
    return Angular_weight();
#ifdef SPECTRALSEG_HAS_EMBREE
  if(o.ray_caster == "embree")
    return make_vsi_metric<SpectralSeg::Ray_casting::Embree_ray_caster>(o);
#endif
  return make_vsi_metric<SpectralSeg::Ray_casting::AABB_ray_caster>(o);
}

} // namespace spectralseg_cli
