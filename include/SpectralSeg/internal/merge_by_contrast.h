// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file merge_by_contrast.h
/// \brief The contrast merge of `segment_hybrid()` (internal): over-segmented
/// clusters merged by concave and metric contrast, shared with the
/// contrast-merge candidate of `segment_k_way()`.
#ifndef SPECTRALSEG_INTERNAL_MERGE_BY_CONTRAST_H
#define SPECTRALSEG_INTERNAL_MERGE_BY_CONTRAST_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/K_way_options.h>
#include <SpectralSeg/Part_hierarchy.h>
#include <SpectralSeg/Refinement/connected_segments.h>
#include <SpectralSeg/Refinement/crease_regions.h>
#include <SpectralSeg/Refinement/merge_segments.h>
#include <SpectralSeg/Refinement/sharp_crease_share.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace SpectralSeg {
namespace internal {

// The neck ratio's scale of the contrast merge (Basic_hybrid_options::neck_scale).
constexpr double default_neck_scale = 0.4;

// The exponent of the contrast merge's thickness ratio: the metric contrast
// of a boundary is multiplied by the square root of the ratio of its two
// segments' mean thicknesses (Weighted_dual_graph::face_thickness()).
constexpr double thickness_exponent = 0.5;

// The reference resolution of the contrast merge's concave contrast
// (Basic_hybrid_options::reference_faces).
constexpr std::size_t default_reference_faces = 50000;

// The exponent of the merge's embedding-separation factor for a mesh whose
// sharp_crease_share() is `share` (see K_way_options::merge_separation_scale):
// 1 up to 0.3, 0 from 0.6, linear in between.
SPECTRALSEG_INLINE double separation_exponent(double share)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  return std::max(0., std::min(1., (0.6 - share) / 0.3));
}
#else
;
#endif

// Merges adjacent segments, weakest boundary first: segments under
// `small` area first (smallest first, whatever their boundary), then the
// pair with the lowest product of the two contrasts while their geometric
// mean (the boundary's contrast) is below `limit` and more than
// `min_segments` are left (with a positive
// `neck_scale` the metric contrast is multiplied by the pair's neck ratio
// over `neck_scale` and by its slice ratio squared); with
// `separation.coordinates` the pairs are taken in the order of that product
// times the embedding-separation factor (the limit still applies to the
// contrast alone). Labels renumbered by their smallest face; returns the
// number of segments; with `history`, every merge down to one segment per
// component is recorded there (Refinement::internal::merge_cheapest_boundaries()).
// The concave angles are those of Refinement::concave_angle_weights() at
// `reference_faces` (0: the mesh's own resolution), or `given_angles` when
// not null (those angles, made once for several merges). Boundaries whose
// mean concave angle is below `flat_angle` (radians) are flat seams
// (Refinement::internal::merge_cheapest_boundaries()). With
// `face_thickness` (one value per face, NaN where unknown), the metric
// contrast is also multiplied by the square root of the ratio of the two
// segments' mean thicknesses, the thicker over the thinner: a fin, a tail
// or a leg that meets a thicker body without a crease is a part.
SPECTRALSEG_INLINE std::size_t merge_by_contrast(
    const Dual_graph& graph, const std::vector<double>& weights, std::vector<int>& labels, std::size_t min_segments,
    double limit, double min_area_fraction,
    const Refinement::Embedding_separation& separation = Refinement::Embedding_separation(), double neck_scale = 0.,
    Refinement::internal::Merge_history* history = nullptr, std::size_t reference_faces = 0,
    const std::vector<double>* given_angles = nullptr, double flat_angle = 0.,
    const std::vector<double>* face_thickness = nullptr)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  // the concave angles at the reference resolution (the mesh's own up to it)
  const std::vector<double> own =
    given_angles ? std::vector<double>() : Refinement::concave_angle_weights(graph, reference_faces);
  const std::vector<double>& angles = given_angles ? *given_angles : own;
  // mesh means, weighted by edge length
  double length = 0., concave = 0., metric = 0.;
  for(std::size_t d = 0; d < graph.number_of_edges(); ++d)
  {
    const Dual_graph::Edge& e = graph.edge(static_cast<Dual_graph::size_type>(d));
    length += e.length;
    concave += e.length * angles[d];
    metric += e.length * weights[d];
  }
  const double mean_concave = length > 0. ? concave / length : 0.;
  const double mean_metric = length > 0. ? metric / length : 0.;
  double total_area = 0.;
  for(double a : graph.geometry().areas)
    total_area += a;
  // a flat or convex mesh (or a zero metric) gives no contrast: such
  // boundaries are weak
  return Refinement::internal::merge_cheapest_boundaries(
    graph, weights, labels, min_segments, min_area_fraction, limit,
    [&](const Refinement::internal::Segment_boundary& x, double smaller, double r, double outer, double thicker) {
      const double c = mean_concave > 0. ? x.concave / x.length / mean_concave : 0.;
      double m = mean_metric > 0. ? x.weight / x.length / mean_metric : 0.;
      if(neck_scale > 0.) // the neck ratio: large around a limb, small across a slice of a body
        m *= std::sqrt(smaller * total_area) / x.length / neck_scale;
      // the slice ratio: a boundary longer than the loop along which the
      // two segments together meet the others cuts through one part (a
      // head cut into face and back, a cup's body lengthwise)
      if(neck_scale > 0. && outer > 0. && outer < x.length)
        m *= (outer / x.length) * (outer / x.length);
      // the thickness ratio: a thin part meets a thick one
      m *= std::pow(thicker, thickness_exponent);
      // the order, not the limit, follows the separation (r is infinite
      // without coordinates)
      const double order = r < separation.scale ? c * m * std::pow(r / separation.scale, separation.exponent) : c * m;
      return Refinement::internal::Merge_cost{order, std::sqrt(c * m)};
    },
    separation.coordinates && separation.exponent > 0. && separation.coordinates->cols() > 0 ? separation.coordinates
                                                                                            : nullptr,
    history, &angles, flat_angle, face_thickness);
}
#else
;
#endif

// The embedding-separation factor of a merge on `coordinates` with
// `k_way`'s scale (none when the scale is 0), its exponent from the mesh's
// sharp-crease share.
template <typename AffinityKernel>
Refinement::Embedding_separation merge_separation(const Weighted_dual_graph& graph,
                                                  const Basic_K_way_options<AffinityKernel>& k_way,
                                                  const Eigen::MatrixXd& coordinates)
{
  Refinement::Embedding_separation separation;
  if(k_way.merge_separation_scale > 0.)
  {
    separation.coordinates = &coordinates;
    separation.scale = k_way.merge_separation_scale;
    separation.exponent = separation_exponent(Refinement::sharp_crease_share(graph.graph()));
  }
  return separation;
}

// K_way_options::flat_seam_angle in radians.
template <typename AffinityKernel>
double flat_seam_radians(const Basic_K_way_options<AffinityKernel>& k_way)
{
  return k_way.flat_seam_angle * boost::math::constants::pi<double>() / 180.;
}

// A merge's history into `*keep` (for hierarchy_from_merges() later), or
// without `keep` made into `r.hierarchy` now.
SPECTRALSEG_INLINE void keep_merges(const Weighted_dual_graph& graph, Refinement::internal::Merge_history&& history,
                                    K_way_result& r, Refinement::internal::Merge_history* keep)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(keep)
    *keep = std::move(history);
  else
    r.hierarchy = hierarchy_from_merges(history.labels, graph.graph().geometry().areas, history.steps, history.answer);
}
#else
;
#endif

// What the contrast merges of one mesh share: the regions bounded by
// closed loops of concave creases (empty when `k_way.crease_angle` finds
// fewer than two) and the concave angles at `reference_faces`.
struct Contrast_merge_shared
{
  std::vector<int> crease_region;
  std::vector<double> angles;
};

template <typename AffinityKernel>
Contrast_merge_shared contrast_merge_shared(const Weighted_dual_graph& graph,
                                            const Basic_K_way_options<AffinityKernel>& k_way,
                                            std::size_t reference_faces, unsigned threads = 1)
{
  Contrast_merge_shared s;
  if(k_way.crease_angle > 0.)
  {
    std::vector<int> region;
    if(Refinement::crease_regions(graph.graph(), k_way.crease_angle, region) > 1)
      s.crease_region = std::move(region);
  }
  s.angles = Refinement::concave_angle_weights(graph.graph(), reference_faces, threads);
  return s;
}

// The contrast merge of segment_hybrid() on `labels`, K-means clusters of
// the embedding `coordinates`: the clusters split along closed loops of
// concave creases (`k_way.crease_angle`), made connected and merged by
// contrast (merge_by_contrast(), with `k_way`'s minimum area fraction and
// separation scale); every merge down to one segment per component goes
// into `history`, whose answer is where `limit` or `min_segments` stops
// the merge, as are `labels`; its concave contrast measured at
// `reference_faces` (see merge_by_contrast()), with the crease regions and
// concave angles of `shared` (made by contrast_merge_shared() with the same
// settings). Returns the number of segments there. Reads nothing else, so
// that merges of several clusterings can run side by side.
template <typename AffinityKernel>
std::size_t merge_labels_by_contrast(const Weighted_dual_graph& graph,
                                     const Basic_K_way_options<AffinityKernel>& k_way, std::size_t min_segments,
                                     double limit, double neck_scale, std::size_t reference_faces,
                                     const Eigen::MatrixXd& coordinates, std::vector<int>& labels,
                                     Refinement::internal::Merge_history& history, const Contrast_merge_shared& shared)
{
  if(!shared.crease_region.empty())
    Refinement::split_along_regions(shared.crease_region, labels);
  Refinement::make_segments_connected(graph.graph(), labels);
  return merge_by_contrast(graph.graph(), graph.weights(), labels, min_segments, limit, k_way.merge_min_area_fraction,
                           merge_separation(graph, k_way, coordinates), neck_scale, &history, reference_faces,
                           &shared.angles, flat_seam_radians(k_way),
                           graph.face_thickness().empty() ? nullptr : &graph.face_thickness());
}

// merge_labels_by_contrast() on `r.labels`, the K-means clusters of
// `r.embedding`, with `shared` (or, without it, the crease regions and
// concave angles made here); the merges go into `r.hierarchy` (or, with
// `keep`, into `*keep`, for hierarchy_from_merges() later).
template <typename AffinityKernel>
std::size_t merge_clusters_by_contrast(const Weighted_dual_graph& graph,
                                       const Basic_K_way_options<AffinityKernel>& k_way, std::size_t min_segments,
                                       double limit, double neck_scale, std::size_t reference_faces,
                                       K_way_result& r, Refinement::internal::Merge_history* keep = nullptr,
                                       const Contrast_merge_shared* shared = nullptr)
{
  const Contrast_merge_shared own =
    shared ? Contrast_merge_shared() : contrast_merge_shared(graph, k_way, reference_faces);
  Refinement::internal::Merge_history history;
  const std::size_t m = merge_labels_by_contrast(graph, k_way, min_segments, limit, neck_scale, reference_faces,
                                                 r.embedding.coordinates, r.labels, history, shared ? *shared : own);
  keep_merges(graph, std::move(history), r, keep);
  return m;
}

} // namespace internal
} // namespace SpectralSeg
/// \endcond

#endif // SPECTRALSEG_INTERNAL_MERGE_BY_CONTRAST_H
