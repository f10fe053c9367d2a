// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library's non-template functions, compiled once for the programs of a
// build with SPECTRALSEG_SEPARATE_COMPILATION (the CMake target
// SpectralSeg_compiled; include/SpectralSeg/internal/separate_compilation.h).
// Every header that declares such functions is included here; the default
// instances are in src/spectralseg_instances.cpp.
#ifndef SPECTRALSEG_SEPARATE_COMPILATION
#error "src/spectralseg_compiled.cpp is compiled with SPECTRALSEG_SEPARATE_COMPILATION (CMake target SpectralSeg_compiled)"
#endif
#ifndef SPECTRALSEG_COMPILING_LIBRARY
#define SPECTRALSEG_COMPILING_LIBRARY
#endif

#include <SpectralSeg/Clustering/Kmeans.h>
#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Embedding/exact_spectral_embedding.h>
#include <SpectralSeg/Embedding/internal/affinity.h>
#include <SpectralSeg/Embedding/nystrom_spectral_embedding.h>
#include <SpectralSeg/IO/internal/read_obj.h>
#include <SpectralSeg/IO/internal/read_off.h>
#include <SpectralSeg/IO/internal/read_ply.h>
#include <SpectralSeg/IO/internal/read_polygon_soup.h>
#include <SpectralSeg/IO/internal/read_stl.h>
#include <SpectralSeg/IO/internal/repair_polygon_soup.h>
#include <SpectralSeg/IO/internal/spatial_order.h>
#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/Metrics/VSI/Shape_images.h>
#include <SpectralSeg/Metrics/VSI/ray_directions.h>
#include <SpectralSeg/Metrics/VSI/spread_samples.h>
#include <SpectralSeg/Metrics/VSI_weight.h>
#include <SpectralSeg/Metrics/normalize_weights.h>
#include <SpectralSeg/Ray_casting/AABB_ray_caster.h>
#include <SpectralSeg/Ray_casting/Embree_ray_caster.h>
#include <SpectralSeg/Refinement/concave_normalized_cut.h>
#include <SpectralSeg/Refinement/connected_segments.h>
#include <SpectralSeg/Refinement/crease_regions.h>
#include <SpectralSeg/Refinement/graph_cut_boundaries.h>
#include <SpectralSeg/Refinement/merge_segments.h>
#include <SpectralSeg/Refinement/morphological_closing.h>
#include <SpectralSeg/Refinement/sharp_crease_share.h>
#include <SpectralSeg/Registration/align_embeddings.h>
#include <SpectralSeg/Retrieval/Shape_descriptor.h>
#include <SpectralSeg/Salient_cut/face_sequence.h>
#include <SpectralSeg/Sampling/farthest_point_samples.h>
#include <SpectralSeg/Segmentability/Contour_analysis.h>
#include <SpectralSeg/Segmentability/convexity.h>
#include <SpectralSeg/Segmentability/inner_distances.h>
#include <SpectralSeg/Segmentability/integrated_bending_score.h>
#include <SpectralSeg/Segmentability/multidimensional_scaling.h>
#include <SpectralSeg/Segmentability/principal_curvatures.h>
#include <SpectralSeg/Segmentability/segmentability.h>
#include <SpectralSeg/Segmentability/simplify_contour.h>
#include <SpectralSeg/Segmentability/smooth_contour.h>
#include <SpectralSeg/Segmentability/spectral_projection.h>
#include <SpectralSeg/Segmentability/trace_outer_contour.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/automatic_segmentation.h>
#include <SpectralSeg/choose_number_of_segments.h>
#include <SpectralSeg/evaluation.h>
#include <SpectralSeg/internal/Point_neighbours.h>
#include <SpectralSeg/internal/contact_adjacencies.h>
#include <SpectralSeg/internal/merge_by_contrast.h>
#include <SpectralSeg/internal/most_typical_merge.h>
#include <SpectralSeg/segment_k_way.h>
