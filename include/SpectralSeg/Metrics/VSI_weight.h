// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file VSI_weight.h
/// \brief The VSI (volumetric shape image) edge weight of the dual graph (thesis 3.4).
#ifndef SPECTRALSEG_METRICS_VSI_WEIGHT_H
#define SPECTRALSEG_METRICS_VSI_WEIGHT_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Metrics/VSI/Reference_points.h>
#include <SpectralSeg/Metrics/VSI/Shape_images.h>
#include <SpectralSeg/Ray_casting/AABB_ray_caster.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Metrics {

/// \ingroup PkgSpectralSegVSI
/// \brief All parameters of the VSI metric.
struct VSI_options
{
  /// reference points (16 rays in an 80-degree cone, smoothing)
  VSI::Reference_point_options reference;
  /// shape images (50 antipodal ray pairs, 1% of the faces sampled)
  VSI::Shape_image_options images;

  /// the thesis's construction: every face casts its cone for its
  /// reference point, however many there are
  /// (`reference.max_measured_faces` = 0)
  static VSI_options thesis()
  {
    VSI_options o;
    o.reference.max_measured_faces = 0;
    return o;
  }
};

/// \ingroup PkgSpectralSegVSI
/// \brief Everything the VSI metric computes, for inspection and pictures.
struct VSI_result
{
  VSI::Reference_points reference_points; ///< one point per face
  VSI::Shape_images images;               ///< one image per face
  std::vector<double> weights;            ///< one weight per dual edge
  std::size_t filled_weights = 0;         ///< weights taken from neighbouring edges (no common measured pair)
};

/// \ingroup PkgSpectralSegVSI
/// \brief The VSI edge weights from the shape images: the image difference
/// (`VSI::image_difference()`) of the two faces of each dual edge.
///
/// An edge whose faces share no measured ray pair (open meshes, where rays
/// escape) takes the mean weight of the computable edges around its two
/// faces, repeatedly, so that no `NaN` reaches a distance; with no
/// computable edge at all, every weight is 0. `filled` receives the number
/// of such edges.
SPECTRALSEG_INLINE std::vector<double> vsi_edge_weights(const Dual_graph& graph, const VSI::Shape_images& images,
                                                        const Execution& exec = Execution(),
                                                        std::size_t* filled = nullptr)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t ne = graph.number_of_edges();
  const std::size_t m = static_cast<std::size_t>(images.reaches.cols());
  std::vector<double> w(ne);
  ::SpectralSeg::internal::parallel_for(ne, exec, "vsi weights", [&](std::size_t e) {
    const Dual_graph::Edge& edge = graph.edge(static_cast<Dual_graph::size_type>(e));
    w[e] = VSI::image_difference(images.reaches.row(edge.face[0]).data(), images.reaches.row(edge.face[1]).data(), m);
  });
  std::size_t missing = 0;
  for(double v : w)
    missing += std::isnan(v) ? 1 : 0;
  if(filled)
    *filled = missing;
  while(missing > 0)
  {
    std::vector<std::pair<std::size_t, double>> updates;
    for(std::size_t e = 0; e < ne; ++e)
    {
      if(!std::isnan(w[e]))
        continue;
      double sum = 0.;
      int count = 0;
      for(Dual_graph::size_type f : graph.edge(static_cast<Dual_graph::size_type>(e)).face)
        graph.for_each_neighbour(f, [&](Dual_graph::size_type, Dual_graph::size_type g) {
          if(!std::isnan(w[g]))
          {
            sum += w[g];
            ++count;
          }
        });
      if(count > 0)
        updates.emplace_back(e, sum / count);
    }
    if(updates.empty())
    {
      for(double& v : w)
        if(std::isnan(v))
          v = 0.;
      break;
    }
    for(const auto& u : updates)
      w[u.first] = u.second;
    missing -= updates.size();
  }
  return w;
}
#else
;
#endif

/// \ingroup PkgSpectralSegVSI
/// \brief The thickness of the shape at each face: the larger of its
/// reference point's ball diameter (`VSI::Reference_points::diameters`) and
/// half its median chord (`VSI::median_reaches()`); `NaN` where neither is
/// known.
///
/// Across a convex part neither exceeds the part's thickness: the ball
/// fits inside it, and the median chord from the middle of a part is at
/// most twice its thickness (a plate's). On a smooth surface the ball is
/// the larger and gives the thickness. A rough surface (hair, plates,
/// noise) shrinks the ball to the size of its bumps but shortens only the
/// chords that run along it, so half the median chord is the larger there.
SPECTRALSEG_INLINE std::vector<double> vsi_face_thickness(const VSI_result& vsi, const Execution& exec = Execution())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<double> thickness = VSI::median_reaches(vsi.images, exec);
  const std::vector<double>& ball = vsi.reference_points.diameters;
  for(std::size_t f = 0; f < thickness.size(); ++f)
  {
    const double half_chord = 0.5 * thickness[f];
    const double diameter = f < ball.size() ? ball[f] : std::numeric_limits<double>::quiet_NaN();
    thickness[f] = std::isnan(half_chord) ? diameter : std::isnan(diameter) ? half_chord : std::max(diameter, half_chord);
  }
  return thickness;
}
#else
;
#endif

/// \ingroup PkgSpectralSegVSI
/// \brief Runs the whole VSI pipeline: reference points, shape images, edge weights.
template <typename RayCaster>
VSI_result compute_vsi(const Dual_graph& graph, const RayCaster& caster, const VSI_options& options = VSI_options(),
                       const Execution& exec = Execution())
{
  VSI_result r;
  r.reference_points = VSI::compute_reference_points(graph, caster, options.reference, exec);
  r.images = VSI::compute_shape_images(r.reference_points.points, caster, options.images, exec);
  r.weights = vsi_edge_weights(graph, r.images, exec, &r.filled_weights);
  return r;
}

/// \cond SKIP_IN_MANUAL
#if SPECTRALSEG_DEFAULT_INSTANCES
SPECTRALSEG_INSTANTIATE VSI_result compute_vsi<Ray_casting::AABB_ray_caster>(
  const Dual_graph&, const Ray_casting::AABB_ray_caster&, const VSI_options&, const Execution&);
#endif
/// \endcond

/// \ingroup PkgSpectralSegVSI
/// \brief The VSI distance, which makes the borders between parts expensive
/// to cross: each face is mapped to a reference point inside the shape, the
/// visible reach of the volume around that point is sampled along fixed
/// directions (its volumetric shape image), and a dual edge weighs the
/// difference between the images of its two faces.
///
/// Inside a part the images change slowly; across a part boundary the
/// visible volume changes abruptly. See `compute_vsi()` for the steps and
/// `VSI_options` for the parameters.
///
/// \tparam RayCaster a model of `RayCaster`: `Ray_casting::AABB_ray_caster`
///         (default) or `Ray_casting::Embree_ray_caster`
///
/// \cgalModels `DualEdgeWeight`
template <typename RayCaster = Ray_casting::AABB_ray_caster>
class VSI_weight
{
public:
  /// \param options the parameters of the reference points and shape images
  explicit VSI_weight(const VSI_options& options = VSI_options()) : options_(options) {}

  /// the parameters
  const VSI_options& options() const { return options_; }

  /// the name used by the command-line tool and in reports
  std::string name() const { return "vsi"; }

  /// one weight per dual edge of `graph`
  std::vector<double> operator()(const Dual_graph& graph, const Execution& exec = Execution()) const
  {
    return (*this)(graph, exec, nullptr);
  }

  /// one weight per dual edge of `graph`; with `face_thickness`, the
  /// thickness of the shape at each face goes there (`vsi_face_thickness()`,
  /// see `Metrics::metric_values()`)
  std::vector<double> operator()(const Dual_graph& graph, const Execution& exec,
                                 std::vector<double>* face_thickness) const
  {
    exec.report("ray casting setup", 0.);
    const RayCaster caster(graph.geometry());
    exec.report("ray casting setup", 1.);
    VSI_result r = compute_vsi(graph, caster, options_, exec);
    if(face_thickness)
      *face_thickness = vsi_face_thickness(r, exec);
    return std::move(r.weights);
  }

private:
  VSI_options options_;
};

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_VSI_WEIGHT_H
