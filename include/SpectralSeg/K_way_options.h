// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file K_way_options.h
/// \brief The options and the result of the k-way segmentation.
#ifndef SPECTRALSEG_K_WAY_OPTIONS_H
#define SPECTRALSEG_K_WAY_OPTIONS_H

#include <SpectralSeg/Clustering/Kmeans.h>
#include <SpectralSeg/Embedding/Spectral_embedding.h>
#include <SpectralSeg/Embedding/nystrom_spectral_embedding.h>
#include <SpectralSeg/Kernels/Exponential_kernel.h>
#include <SpectralSeg/Part_hierarchy.h>
#include <SpectralSeg/Refinement/graph_cut_boundaries.h>

#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegKWay
/// \brief Parameters of `segment_k_way()` (thesis ch. 4 and 5), the affinity
/// kernel included. Use the alias `K_way_options` for the default kernel.
///
/// \tparam AffinityKernel a model of `AffinityKernel`
template <typename AffinityKernel = Kernels::Exponential_kernel>
struct Basic_K_way_options
{
  /// the kernel type
  typedef AffinityKernel Kernel_type;
  /// the affinity kernel (thesis 4.2.3)
  AffinityKernel kernel = AffinityKernel();
  /// exact or Nyström embedding, samples, seed (thesis 4.2, 5.2)
  Embedding::Embedding_options embedding;
  /// whether the K-means labels are refined by the graph cut (thesis 4.3.3)
  bool boundary_enhancement = true;
  /// \f$\mu\f$, \f$\nu\f$, band and max-flow backend of the graph cut;
  /// by default `Refinement::Graph_cut_options::banded()` (our addition: a
  /// stronger smoothness term acting in a band around the boundaries), the
  /// thesis's values with `Refinement::Graph_cut_options()`
  Refinement::Graph_cut_options graph_cut = Refinement::Graph_cut_options::banded();
  /// bound on K-means rounds
  std::size_t kmeans_iterations = 100;
  /// on meshes of more faces than this, K-means first runs on every
  /// \f$\lceil n / \f$`kmeans_sample_limit`\f$\rceil\f$-th face, then on
  /// all of them from the centroids found (`Clustering::kmeans()`; our
  /// addition, fewer rounds over all the faces); 0: on all of them from
  /// the seeds
  std::size_t kmeans_sample_limit = 100000;
  /// Nyström path: seed K-means with the first `k` sample faces (the
  /// thesis, 5.5); if false, with max-min seeds in the embedding, as the
  /// exact path does
  bool seed_with_samples = true;
  /// over-segment and merge (our addition): the embedding and K-means use
  /// `k + extra_clusters` clusters, then the adjacent segments whose
  /// boundary has the smallest mean concave dihedral angle are merged until
  /// `k` are left (`Refinement::merge_weakest_boundaries()` with
  /// `Refinement::concave_angle_weights()`). K-means splits large bodies
  /// into pieces of similar spread and leaves small parts (fins, horns,
  /// fingers) unsplit; the extra clusters take those small parts and the
  /// merge joins the body pieces across their smooth seams. 0 gives the
  /// thesis's method (`thesis()`). See also `alternative_extra_clusters`.
  std::size_t extra_clusters = 2;
  /// choice of the over-segmentation (our addition): each of these numbers
  /// of extra clusters is tried as well as `extra_clusters` (K-means, merge
  /// and graph cut each time; the Nyström samples and their distance rows
  /// are computed once for all), and the result with the lowest
  /// `Refinement::concave_normalized_cut()` is kept. How many clusters it
  /// takes to give each small part its own depends on the shape; the
  /// normalized cut prefers the result whose boundaries follow concave
  /// creases. Default {8}: two over-segmentations, 2 and 8 extra clusters.
  /// Empty: `extra_clusters` only, at the cost of one segmentation.
  std::vector<std::size_t> alternative_extra_clusters{8};
  /// with several over-segmentations to choose from (our addition): those
  /// of `extra_clusters` and `alternative_extra_clusters` that make fewer
  /// than this many K-means clusters (\f$k\f$ + extra) are not tried,
  /// unless none would be left (then the one of the most clusters is).
  /// With \f$k\f$ 2 or 3, \f$k\f$ + 2 clusters are too few to give a
  /// part its own: they divide the largest body by its extent (a cube
  /// into halves under its peg, a cup's wall lengthwise), and the
  /// normalized cut, which favours segments of similar size, then keeps
  /// that candidate. Default 6 (\f$k\f$ + 2 is tried from \f$k\f$ = 4
  /// on); 0: every candidate is tried
  std::size_t min_candidate_clusters = 6;
  /// the contrast merge as one more over-segmentation to choose from (our
  /// addition): when positive, the mesh is also over-segmented into this
  /// many K-means clusters (at least `k`), split along concave creases and
  /// merged by contrast down to `k` segments, as `segment_hybrid()` does
  /// with as many clusters and one over-segmentation
  /// (`Hybrid_options::over_segmentations` = 1; its merge hierarchy cut at
  /// `k` parts), then
  /// refined by the graph cut; it is kept when its
  /// `Refinement::concave_normalized_cut()` is the lowest. The two merge
  /// orders fail on different shapes: the concave strength keeps a part
  /// whose junction is a crease, the contrast (concavity, metric and neck
  /// ratio) one that meets the body along a short loop without a crease.
  /// Default 20, `segment_hybrid()`'s; 0: not tried (the thesis's method)
  std::size_t contrast_merge_clusters = 20;
  /// the concavity scale \f$s\f$ (radians) of the normalized cut that
  /// chooses the over-segmentation
  double cut_angle_scale = 0.1;
  /// merging also stops when every boundary's mean concave angle (radians)
  /// is at least this
  double merge_strength_limit = std::numeric_limits<double>::infinity();
  /// segments smaller than this fraction of the mesh area are merged
  /// first, whatever their boundary: without it the sharp crease around an
  /// ear keeps the ear while the smooth hip joint merges the leg into the
  /// body
  double merge_min_area_fraction = 0.005;
  /// the merge's boundary strength is multiplied by the area fraction of
  /// the pair's smaller segment to this power (our addition;
  /// `Refinement::merge_weakest_boundaries()`): of two boundaries about as
  /// strong, the one around the smaller part is merged first; 0: the
  /// strength alone
  double merge_size_exponent = 0.1;
  /// the merge's boundary strength is multiplied by the embedding-separation
  /// factor with this scale (our addition; `Refinement::Embedding_separation`):
  /// pieces of one body, which overlap in the spectral embedding, are merged
  /// before a part is joined to the body. Its exponent follows the kind of
  /// mesh: 1 where the folds are mostly blunt (scanned and sculpted shapes,
  /// `Refinement::sharp_crease_share()` at most 0.3), 0 where they are mostly
  /// sharp (machine parts, at least 0.6, whose patches the crease split and
  /// the concave strength already tell apart), linear in between. 0 turns
  /// it off.
  double merge_separation_scale = 2.;
  /// with extra clusters, and in the contrast merge (`segment_hybrid()`)
  /// (our addition): before the merge, each K-means cluster is split along the closed loops of concave creases of at least
  /// this dihedral angle, in degrees (`Refinement::crease_regions()`), so
  /// that a part bounded by a crease all around (a shaft in a housing, a
  /// knob on a lid) is not shared with its neighbour; 0 turns it off
  double crease_angle = 30.;
  /// in the merges of extra clusters and in the contrast merge (our
  /// addition): a boundary whose mean concave dihedral angle is below this,
  /// in degrees, is a flat seam: with no fold along it, it is no evidence of
  /// a part boundary, so flat seams are merged before every other boundary
  /// (after the segments under `merge_min_area_fraction`), the one between
  /// the two largest segments first. A rod cut into bands by K-means
  /// then keeps its middle whole and its ends apart, instead of three bands
  /// of a third each. 0 turns it off
  double flat_seam_angle = 0.5;
  /// whether the result keeps its embedding's coordinates
  /// (`K_way_result::embedding`, one row per face, the largest array of the
  /// result). Without them (our addition, for callers that only need the
  /// labels, such as `spectralseg segment` and `k_way_segmentation()`),
  /// `segment_k_way()` and `segment_k_way_automatic()` release each
  /// over-segmentation's coordinates as soon as its graph cut has its data
  /// terms, before the next one's embedding is made, instead of keeping
  /// every candidate's until the best is known: 832,000 faces, 2 threads,
  /// heap peak 927 -> 668 MB (doc/benchmarks.md). The labels are the same;
  /// the result's `embedding.coordinates` is then empty (its samples,
  /// kernel width and the other fields are kept).
  bool keep_embedding_coordinates = true;

  /// whether each candidate over-segmentation's final labels are kept in
  /// `K_way_result::candidates` (one label vector per candidate), so that
  /// every candidate, not only the kept one, can be looked at or scored;
  /// off by default (the labels cost memory)
  bool keep_candidate_labels = false;

  /// the thesis's k-way method: K-means with exactly `k` clusters, the
  /// thesis's graph cut, no crease split
  static Basic_K_way_options thesis()
  {
    Basic_K_way_options o;
    o.extra_clusters = 0;
    o.alternative_extra_clusters.clear();
    o.contrast_merge_clusters = 0;
    o.graph_cut = Refinement::Graph_cut_options();
    o.crease_angle = 0.;
    o.flat_seam_angle = 0.;
    o.merge_size_exponent = 0.;
    o.merge_separation_scale = 0.;
    return o;
  }

  /// the same options with another kernel
  template <typename OtherKernel>
  Basic_K_way_options<OtherKernel> with_kernel(const OtherKernel& other) const
  {
    Basic_K_way_options<OtherKernel> o;
    o.kernel = other;
    o.embedding = embedding;
    o.boundary_enhancement = boundary_enhancement;
    o.graph_cut = graph_cut;
    o.kmeans_iterations = kmeans_iterations;
    o.kmeans_sample_limit = kmeans_sample_limit;
    o.seed_with_samples = seed_with_samples;
    o.extra_clusters = extra_clusters;
    o.alternative_extra_clusters = alternative_extra_clusters;
    o.min_candidate_clusters = min_candidate_clusters;
    o.contrast_merge_clusters = contrast_merge_clusters;
    o.cut_angle_scale = cut_angle_scale;
    o.merge_strength_limit = merge_strength_limit;
    o.merge_min_area_fraction = merge_min_area_fraction;
    o.merge_size_exponent = merge_size_exponent;
    o.merge_separation_scale = merge_separation_scale;
    o.crease_angle = crease_angle;
    o.flat_seam_angle = flat_seam_angle;
    o.keep_embedding_coordinates = keep_embedding_coordinates;
    o.keep_candidate_labels = keep_candidate_labels;
    return o;
  }
};

/// \ingroup PkgSpectralSegKWay
/// \brief The k-way options with the exponential kernel, the default.
typedef Basic_K_way_options<Kernels::Exponential_kernel> K_way_options;

/// \ingroup PkgSpectralSegKWay
/// \brief Parameters of `segment_k_way_automatic()`: the k-way options and
/// the rule that chooses the number of segments (our addition).
///
/// \tparam AffinityKernel a model of `AffinityKernel`
template <typename AffinityKernel = Kernels::Exponential_kernel>
struct Basic_K_way_automatic_options
{
  /// the options of the k-way segmentation the rule runs;
  /// `extra_clusters` and `merge_strength_limit` are replaced by the rule's
  /// values
  Basic_K_way_options<AffinityKernel> k_way;
  /// the largest number of segments; at least 2
  std::size_t max_k = 20;
  /// merging stops once the weakest boundary's mean concave angle reaches
  /// this many times the mesh's mean concave angle
  double min_boundary_contrast = 3.;
  /// when positive, the answer has this many parts (or as many as the
  /// over-segmentation has, if fewer): the merge hierarchy
  /// (`K_way_result::hierarchy`) cut at that number instead of where
  /// `min_boundary_contrast` stops the merge, then the graph cut; 0 (the
  /// default): the rule decides
  std::size_t parts = 0;
};

/// \ingroup PkgSpectralSegKWay
/// \brief The automatic k-way options with the exponential kernel, the
/// default.
typedef Basic_K_way_automatic_options<Kernels::Exponential_kernel> K_way_automatic_options;

/// \ingroup PkgSpectralSegKWay
/// \brief One over-segmentation that `segment_k_way()` tried when it had
/// several candidates (`K_way_options::alternative_extra_clusters`,
/// `K_way_options::contrast_merge_clusters`), and how its choice saw it.
struct K_way_candidate
{
  /// its number of extra clusters (K-means clusters minus `k`)
  std::size_t extra_clusters = 0;
  /// whether it is the contrast merge's
  bool contrast_merge = false;
  /// `Refinement::concave_normalized_cut()` of the segments the graph cut
  /// started from (after the merge; the K-means clusters on a mesh whose
  /// components outnumber them)
  double normalized_cut_before_graph_cut = 0.;
  /// `Refinement::concave_normalized_cut()` of its final labels: the
  /// candidate with the lowest is kept
  double normalized_cut = 0.;
  /// whether it is the one kept
  bool kept = false;
  /// its number of segments
  std::size_t number_of_segments = 0;
  /// its final labels, with `K_way_options::keep_candidate_labels` (else
  /// empty)
  std::vector<int> labels;
};

/// \ingroup PkgSpectralSegKWay
/// \brief What `segment_k_way()` and `segment_k_way_automatic()` produce.
struct K_way_result
{
  /// one segment per face, in `[0, number_of_segments)`, each segment one
  /// connected region, numbered by their smallest face
  std::vector<int> labels;
  /// number of segments: `k`, or more on a mesh with more connected
  /// components than `k`, or fewer if a cluster vanished
  std::size_t number_of_segments = 0;
  /// the spectral embedding the clusters were found in
  Embedding::Spectral_embedding embedding;
  /// K-means result, before the graph cut
  Clustering::Kmeans_result clusters;
  /// the number of extra clusters of the kept over-segmentation (see
  /// `K_way_options::alternative_extra_clusters`)
  std::size_t extra_clusters = 0;
  /// whether the kept over-segmentation is the contrast merge's
  /// (`K_way_options::contrast_merge_clusters`)
  bool contrast_merge = false;
  /// its `Refinement::concave_normalized_cut()` when several were tried,
  /// else 0
  double normalized_cut = 0.;
  /// the merges from the over-segmentation down to one segment per
  /// connected component, the answer's first (`Part_hierarchy`; empty when
  /// nothing was merged, as with `extra_clusters` 0)
  Part_hierarchy hierarchy;
  /// every over-segmentation tried, in the order tried, when there were
  /// several (else empty)
  std::vector<K_way_candidate> candidates;
  /// seconds spent in each stage, in order
  std::vector<std::pair<std::string, double>> timings;
};

} // namespace SpectralSeg

#endif // SPECTRALSEG_K_WAY_OPTIONS_H
