// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Part_aware_weight.h
/// \brief The part-aware metric: geodesic, angular and VSI weights blended (thesis 3.5).
#ifndef SPECTRALSEG_METRICS_PART_AWARE_WEIGHT_H
#define SPECTRALSEG_METRICS_PART_AWARE_WEIGHT_H

#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Blend.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Metrics/VSI_weight.h>
#include <SpectralSeg/internal/separate_compilation.h>
#ifdef SPECTRALSEG_HAS_EMBREE
#include <SpectralSeg/Ray_casting/Embree_ray_caster.h>
#endif

#include <string>

namespace SpectralSeg {
namespace Ray_casting {
#ifdef SPECTRALSEG_HAS_EMBREE
/// \ingroup PkgSpectralSegRayCasting
/// \brief The ray caster of the default metric: `Embree_ray_caster` when
/// the library is built with Embree (`SPECTRALSEG_HAS_EMBREE`, about 5 times
/// faster), `AABB_ray_caster` otherwise. The two agree up to float rounding
/// (Embree casts in single precision), so segmentations can differ on a few
/// faces.
typedef Embree_ray_caster Default_ray_caster;
#else
/// \ingroup PkgSpectralSegRayCasting
/// \brief The ray caster of the default metric: `Embree_ray_caster` when
/// the library is built with Embree (`SPECTRALSEG_HAS_EMBREE`), else
/// `AABB_ray_caster`, as here.
typedef AABB_ray_caster Default_ray_caster;
#endif
} // namespace Ray_casting

namespace Metrics {

/// \cond SKIP_IN_MANUAL
#if SPECTRALSEG_DEFAULT_INSTANCES && defined(SPECTRALSEG_HAS_EMBREE)
SPECTRALSEG_INSTANTIATE VSI_result compute_vsi<Ray_casting::Embree_ray_caster>(
  const Dual_graph&, const Ray_casting::Embree_ray_caster&, const VSI_options&, const Execution&);
#endif
/// \endcond

/// \ingroup PkgSpectralSegMetrics
/// \brief The library's default metric: a `Blend` of `Geodesic_weight`,
/// `Angular_weight` and `VSI_weight`, each normalised to \f$[0, 1]\f$, with
/// the thesis's segmentation coefficients \f$\alpha = 0.01\f$,
/// \f$\beta = 0.195\f$, \f$\gamma = 0.795\f$.
///
/// The components are normalised by their 99th percentile (clamped at 1),
/// not by their maximum as in the thesis (our change; doc/benchmarks.md has
/// its effect on segmentation quality). Pass `Normalization::maximum()` for
/// the thesis's exact metric.
///
/// \tparam RayCaster the ray-casting backend of the VSI component (default
///         `Ray_casting::Default_ray_caster`: Embree when available)
///
/// \cgalModels `DualEdgeWeight`
template <typename RayCaster = Ray_casting::Default_ray_caster>
class Part_aware_weight : public Blend<Geodesic_weight, Angular_weight, VSI_weight<RayCaster>>
{
  typedef Blend<Geodesic_weight, Angular_weight, VSI_weight<RayCaster>> Base;

public:
  /// \param alpha geodesic coefficient
  /// \param beta angular coefficient
  /// \param gamma VSI coefficient
  /// \param vsi parameters of the VSI component
  /// \param convex_weight angular weight of convex folds
  /// \param normalization how the components are brought into [0, 1]
  explicit Part_aware_weight(double alpha = 0.01, double beta = 0.195, double gamma = 0.795,
                             const VSI_options& vsi = VSI_options(), double convex_weight = 0.001,
                             const Normalization& normalization = Normalization::quantile(0.99))
    : Base({alpha, beta, gamma}, Geodesic_weight(), Angular_weight(convex_weight), VSI_weight<RayCaster>(vsi))
  {
    this->set_normalization(normalization);
  }

  /// the thesis's metric exactly: components normalised by their maximum,
  /// every face's reference point from its own cone (`VSI_options::thesis()`)
  static Part_aware_weight thesis(const VSI_options& vsi = VSI_options::thesis())
  {
    return Part_aware_weight(0.01, 0.195, 0.795, vsi, 0.001, Normalization::maximum());
  }

  /// `"part-aware"`
  std::string name() const { return "part-aware"; }
};

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_PART_AWARE_WEIGHT_H
