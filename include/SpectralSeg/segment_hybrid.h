// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file segment_hybrid.h
/// \brief Automatic segmentation by over-segmenting in the spectral embedding
/// and merging across the boundaries that are weak by both concavity and the
/// part-aware metric (our addition).
#ifndef SPECTRALSEG_SEGMENT_HYBRID_H
#define SPECTRALSEG_SEGMENT_HYBRID_H

#include <SpectralSeg/Clustering/Kmeans.h>
#include <SpectralSeg/K_way_options.h>
#include <SpectralSeg/Kernels/Any_kernel.h>
#include <SpectralSeg/Refinement/connected_segments.h>
#include <SpectralSeg/Refinement/crease_regions.h>
#include <SpectralSeg/Refinement/graph_cut_boundaries.h>
#include <SpectralSeg/Refinement/merge_segments.h>
#include <SpectralSeg/Refinement/sharp_crease_share.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/Stage_timer.h>
#include <SpectralSeg/internal/merge_by_contrast.h>
#include <SpectralSeg/internal/most_typical_merge.h>
#include <SpectralSeg/internal/separate_compilation.h>
#include <SpectralSeg/segment_k_way.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegAutomatic
/// \brief Parameters of `segment_hybrid()`.
///
/// \tparam AffinityKernel a model of `AffinityKernel`
template <typename AffinityKernel = Kernels::Exponential_kernel>
struct Basic_hybrid_options
{
  /// the embedding, K-means and graph-cut settings, the affinity kernel,
  /// `merge_min_area_fraction` (0.005 by default: segments under 0.5% of the
  /// area are merged first, whatever their boundary),
  /// `merge_separation_scale` (the merge order's embedding-separation
  /// factor, as in `segment_k_way()`; 0: none) and `crease_angle` (the
  /// clusters are split along closed loops of concave creases of at least
  /// this many degrees before the merge, as in `segment_k_way()`; 0: no
  /// split, the contrast merge until 2026-11-25), `flat_seam_angle` (as in
  /// `segment_k_way()`); `extra_clusters`,
  /// `alternative_extra_clusters`, `contrast_merge_clusters`,
  /// `merge_strength_limit` and `merge_size_exponent` are not used
  Basic_K_way_options<AffinityKernel> k_way;
  /// the number of K-means clusters of the over-segmentation (default 20);
  /// at least 2
  std::size_t clusters = 20;
  /// merging never goes below this many segments (default 2); at least 1
  std::size_t min_segments = 2;
  /// merging stops once the weakest boundary's contrast reaches this
  /// (default 4): the contrast of a boundary is the geometric mean of its
  /// concave contrast (its mean concave dihedral angle over the mesh's) and
  /// its metric contrast (its mean dual-edge weight over the mesh's), all
  /// means weighted by edge length; finite and positive
  double min_boundary_contrast = 4.;
  /// the neck ratio's scale (default 0.4; 0: no neck factor, the contrast
  /// merge until 2026-11-25): the metric contrast of a boundary is
  /// multiplied by its neck ratio \f$\sqrt{a}/\ell\f$ over this, where
  /// \f$a\f$ is the area of the smaller of the two segments and \f$\ell\f$
  /// the boundary's length. A limb or a handle meets the rest along a short
  /// loop for its area (a large ratio: kept), a slice of a body along a long
  /// one (a small ratio: merged). With the neck factor comes the slice
  /// factor: where the boundary is longer than the loop \f$o\f$ along
  /// which the two segments together meet the others, it cuts through one
  /// part (a head into face and back), and the metric contrast is also
  /// multiplied by \f$(o/\ell)^2\f$. Neither ratio depends on the mesh's
  /// scale or resolution. At least 0
  double neck_scale = internal::default_neck_scale;
  /// the resolution at which the concave contrast is measured (default
  /// 50,000 faces; 0: every mesh at its own, the contrast merge until
  /// 2026-11-27): on a mesh with more faces, the concave angles are those
  /// of `Refinement::concave_angle_weights(graph, reference_faces)`, judged
  /// on face normals averaged over about the face spacing of a mesh of this
  /// many faces. On a finer copy of a surface a smooth fold turns by smaller
  /// angles across each edge while a sharp crease keeps its angle, so
  /// without it the same shape is cut into more parts the finer its mesh
  /// (doc/benchmarks.md). Meshes with at most this many faces are not
  /// affected
  std::size_t reference_faces = internal::default_reference_faces;
  /// how many over-segmentations vote (default 10: with the default 20
  /// clusters, every even number of clusters from 20 down to 2; at least 1;
  /// 1: one, the contrast merge until 2026-11-27; 5 until 2026-12-04): with
  /// more than one, the K-means clusters are also joined by Ward's rule
  /// into 2, 4, ... fewer clusters (at least 2), K-means is run again from
  /// each joined set, every over-segmentation is merged by contrast, and
  /// the one whose answer is closest to the others' (least summed
  /// area-weighted Rand distance, the medoid) is kept: an answer that only
  /// some granularities of the clusters give is not taken. With `parts`,
  /// only an over-segmentation of at least `parts` clusters is kept (all
  /// vote). It scores better on psb-dev and moves fewer models when the
  /// metric is perturbed (doc/benchmarks.md), for more K-means runs and
  /// merges
  std::size_t over_segmentations = 10;
  /// when positive, the answer has this many parts (or as many as the
  /// over-segmentation has, if fewer): the merge hierarchy
  /// (`K_way_result::hierarchy`) cut at that number instead of where
  /// `min_boundary_contrast` stops the merge; 0 (the default): the limit
  /// decides
  std::size_t parts = 0;
};

/// \ingroup PkgSpectralSegAutomatic
/// \brief The options of `segment_hybrid()` with the exponential kernel, the
/// default.
typedef Basic_hybrid_options<Kernels::Exponential_kernel> Hybrid_options;


/// \ingroup PkgSpectralSegAutomatic
/// \brief Segments the faces of a weighted dual graph into a number of parts
/// it chooses itself (our addition; it builds on the k-way method of thesis
/// ch. 4 and 5).
///
/// 1. spectral embedding in `options.clusters` dimensions (exact for small
///    meshes, Nyström for large ones, `options.k_way.embedding`) and
///    K-means into `options.clusters` clusters, as in `segment_k_way()`;
///    the clusters are split along the closed loops of concave creases of at
///    least `options.k_way.crease_angle` (`Refinement::crease_regions()`, as
///    in `segment_k_way()`: a part bounded by a crease all around, such as a
///    knob on a box, is then never half of a cluster that also covers some
///    of the box) and made connected regions;
/// 2. segments under `options.k_way.merge_min_area_fraction` of the area are
///    merged into a neighbour, smallest first;
/// 3. the two adjacent segments whose boundary has the lowest contrast are
///    merged, for as long as that contrast is below
///    `options.min_boundary_contrast` and more than `options.min_segments`
///    are left. On meshes whose folds are mostly blunt the pairs are taken
///    in the order of their contrast times the embedding-separation factor
///    of `segment_k_way()` (`options.k_way.merge_separation_scale`,
///    `Refinement::Embedding_separation`), so that pieces of one body go
///    before a part; the limit applies to the contrast alone. The contrast of a boundary is the geometric mean of two
///    ratios, both means weighted by edge length: its mean concave dihedral
///    angle over the mesh's (parts meet at concave creases) and its mean
///    dual-edge weight (`graph.weights()`, the part-aware metric in the
///    usual pipeline) over the mesh's (parts differ in thickness, which the
///    volumetric term of the metric sees), the second multiplied by the
///    boundary's neck ratio (`options.neck_scale`: parts are protrusions,
///    which meet the rest along a short loop for their area, while K-means
///    also slices bodies along long ones) and, when the graph has the faces'
///    thickness (`Weighted_dual_graph::face_thickness()`, which the
///    part-aware metric reports through `Metrics::metric_values()`), by the
///    square root of the ratio of the two segments' area-weighted mean
///    thicknesses, the thicker over the thinner (a tail fin, a leg or a
///    head that meets a thicker body without a crease is a part; the
///    ratio is free of units). A boundary is kept only when
///    both say it separates parts, so K-means' cuts through smooth bodies and
///    through creased but uniform regions are both undone. The ratios are
///    relative to the mesh or free of units, so the limit does not depend
///    on scale; on meshes of more than `options.reference_faces` faces the
///    concave angles are measured at that resolution
///    (`Refinement::concave_angle_weights()`), so that a finer copy of a
///    shape is not cut into more parts;
/// 4. graph-cut boundary enhancement on the merged segments, their mean
///    embedding as proxies (optional, `options.k_way.boundary_enhancement`;
///    skipped when connected components leave more segments than clusters),
///    and every segment made one connected region.
///
/// On a mesh without concave edges every boundary has contrast 0 and the
/// merge goes down to `options.min_segments`. Segments with no neighbour
/// (whole connected components) are never merged. The result is
/// deterministic and does not depend on the number of threads.
///
/// \tparam AffinityKernel a model of `AffinityKernel`
/// \param graph the dual graph weighted by a metric
/// \param options the parameters
/// \param exec threads and progress callback
/// \throws Invalid_input if `options.clusters` is below 2,
///         `options.min_segments` is 0, `options.min_boundary_contrast`
///         is not finite and positive,
///         `options.k_way.merge_separation_scale` is negative or not a
///         number, `options.neck_scale` is negative or not finite,
///         `options.k_way.crease_angle` is not a number,
///         `options.k_way.flat_seam_angle` is not in [0, 180), or
///         `options.over_segmentations` is 0
/// \throws Error if the affinity matrix has no positive eigenvalue after the first
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename AffinityKernel = Kernels::Exponential_kernel>
K_way_result segment_hybrid(const Weighted_dual_graph& graph,
                            const Basic_hybrid_options<AffinityKernel>& options = Basic_hybrid_options<AffinityKernel>(),
                            const Execution& exec = Execution())
{
  if(options.clusters < 2)
    throw Invalid_input("hybrid segmentation: the number of clusters must be at least 2");
  if(options.min_segments < 1)
    throw Invalid_input("hybrid segmentation: the smallest number of segments must be at least 1");
  if(!std::isfinite(options.min_boundary_contrast) || !(options.min_boundary_contrast > 0.))
    throw Invalid_input("hybrid segmentation: the boundary contrast limit must be finite and positive");
  if(!(options.k_way.merge_separation_scale >= 0.))
    throw Invalid_input("hybrid segmentation: the merge separation scale must be a number of at least 0");
  if(!(options.neck_scale >= 0.) || !std::isfinite(options.neck_scale))
    throw Invalid_input("hybrid segmentation: the neck scale must be a finite number of at least 0");
  if(std::isnan(options.k_way.crease_angle))
    throw Invalid_input("hybrid segmentation: the crease angle is not a number");
  if(!(options.k_way.flat_seam_angle >= 0. && options.k_way.flat_seam_angle < 180.))
    throw Invalid_input("hybrid segmentation: the flat seam angle must be a number of degrees in [0, 180)");
  if(options.over_segmentations < 1)
    throw Invalid_input("hybrid segmentation: at least one over-segmentation is needed");
  const std::size_t n = graph.graph().number_of_faces();
  K_way_result r;
  internal::Stage_timer lap(r.timings);
  if(n < 3)
  {
    r.labels.assign(n, 0);
    r.number_of_segments = Refinement::make_segments_connected(graph.graph(), r.labels);
    return r;
  }
  const std::size_t clusters = std::min(options.clusters, n - 1);
  // the merges' crease regions and concave angles depend on the mesh only:
  // made on another thread while this one embeds (whose diameter search
  // runs on one)
  const bool early = exec.threads() > 1;
  std::future<internal::Contrast_merge_shared> made;
  if(early)
    made = std::async(std::launch::async, [&graph, &options] {
      return internal::contrast_merge_shared(graph, options.k_way, options.reference_faces);
    });
  r.embedding = internal::embed(graph, clusters, options.k_way.kernel, options.k_way.embedding, exec);
  lap("embedding");
  if(r.embedding.coordinates.cols() == 0)
    throw Error("hybrid segmentation: the affinity matrix has no positive eigenvalue after the first");
  exec.report("k-means", 0.);
  std::vector<std::size_t> seeds;
  if(!r.embedding.exact && options.k_way.seed_with_samples)
    for(std::size_t i = 0; i < clusters && i < r.embedding.samples.size(); ++i)
      seeds.push_back(r.embedding.samples[i]);
  r.clusters = Clustering::kmeans(r.embedding.coordinates, clusters, seeds, options.k_way.kmeans_iterations, exec,
                                 options.k_way.kmeans_sample_limit);
  exec.report("k-means", 1.);
  lap("k-means");
  const internal::Contrast_merge_shared shared = early ? made.get() : internal::Contrast_merge_shared();
  std::size_t m = internal::merge_most_typical_over_segmentation(
    graph, options.k_way, clusters, options.over_segmentations, options.min_segments, options.min_boundary_contrast,
    options.neck_scale, options.reference_faces, options.parts, r, exec,
    early ? &shared : nullptr);
  if(options.parts > 0)
  {
    r.labels = r.hierarchy.labels_with_parts(options.parts);
    m = r.labels.empty() ? 0 : std::size_t(*std::max_element(r.labels.begin(), r.labels.end()) + 1);
  }
  lap("merge");
  internal::graph_cut_merged(graph, m, clusters, options.k_way, r, exec, &lap);
  return r;
}

/// \cond SKIP_IN_MANUAL
#if SPECTRALSEG_DEFAULT_INSTANCES
SPECTRALSEG_INSTANTIATE K_way_result segment_hybrid<Kernels::Exponential_kernel>(
  const Weighted_dual_graph&, const Basic_hybrid_options<Kernels::Exponential_kernel>&, const Execution&);
SPECTRALSEG_INSTANTIATE K_way_result segment_hybrid<Kernels::Any_kernel>(
  const Weighted_dual_graph&, const Basic_hybrid_options<Kernels::Any_kernel>&, const Execution&);
#endif
/// \endcond

} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENT_HYBRID_H
