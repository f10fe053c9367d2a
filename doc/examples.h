// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Documentation only: the example programs, shown in full in the manual's
// "Examples" pages. No code includes this file.

/// \example distance_field.cpp
/// Distances from one face of a `CGAL::Surface_mesh` under the geodesic, the
/// angular and the default part-aware metric, computed by
/// `SpectralSeg::face_distances()` into face property maps, and the farthest
/// face under each. Usage: `distance_field [mesh.off] [source_face]`.

/// \example custom_metric.cpp
/// Two ways to write a metric: a function of one dual edge wrapped by
/// `SpectralSeg::Metrics::make_per_edge_weight()`, and a class modelling
/// `DualEdgeWeight`; both are blended with the angular metric and used on a
/// `CGAL::Polyhedron_3`. Usage: `custom_metric [mesh.off]`.

/// \example part_aware_sampling.cpp
/// Max-min (farthest-point) sampling of faces under the part-aware metric
/// with `SpectralSeg::Sampling::farthest_point_samples()`, on a
/// `SpectralSeg::Weighted_dual_graph` built once; every face is then coloured
/// by its nearest sample and the picture is written as a PNG file with
/// `SpectralSeg::Rendering::render_face_labels_png()`. Usage:
/// `part_aware_sampling [mesh.off] [samples=8] [out.png]`.

/// \example k_way_segmentation.cpp
/// k-way segmentation of a `CGAL::Surface_mesh` with the defaults, segment
/// areas, a coloured PLY (`SpectralSeg::IO::write_segmented_mesh()`), and the
/// spectral embedding clustered by hand.

/// \example automatic_segmentation.cpp
/// Automatic segmentation of a `CGAL::Polyhedron_3` by recursive salient
/// cuts (thesis ch. 6) with `SpectralSeg::automatic_segmentation()`: the
/// number of parts, the `SpectralSeg::Part_hierarchy` printed level by level
/// (test, score and salience of each cut), and the hierarchy replayed to 3
/// parts. Usage: `automatic_segmentation [mesh.off]`.
