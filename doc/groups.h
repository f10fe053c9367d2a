// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Documentation only: the groups (modules) of the reference manual and the
// namespaces. No code includes this file.

/// \defgroup PkgSpectralSegRef SpectralSeg reference
/// \brief Every public class, function and concept of SpectralSeg, by topic.
///
/// The user manual (the main page) explains how the pieces fit together.

/// \defgroup PkgSpectralSegConcepts Concepts
/// \ingroup PkgSpectralSegRef
/// \brief What a user-supplied type must provide to be used by the library.
///
/// Concepts are documented as classes, as in CGAL; they do not exist in the
/// code.

/// \defgroup PkgSpectralSegCore Core: mesh geometry, dual graph, execution, errors
/// \ingroup PkgSpectralSegRef
/// \brief The dual graph of a triangle mesh and the types shared by all
/// algorithms.
///
/// `make_dual_graph()` copies the geometry of any CGAL `FaceListGraph`
/// (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`, an OpenMesh mesh, ...) into a
/// `Mesh_geometry` and builds the `Dual_graph`: one node per face, one edge
/// per pair of faces sharing a mesh edge, with the geometry of every dual edge
/// computed once. `Execution` carries the thread count and the progress
/// callback; every exception the library throws derives from `Error`.
///
/// Headers: `<SpectralSeg/Mesh_geometry.h>`, `<SpectralSeg/Dual_graph.h>`,
/// `<SpectralSeg/Execution.h>`, `<SpectralSeg/exceptions.h>`, `<SpectralSeg/version.h>`
/// (the version macros).

/// \defgroup PkgSpectralSegMetrics Dual-edge metrics
/// \ingroup PkgSpectralSegRef
/// \brief Models of the `DualEdgeWeight` concept: policies that give every
/// dual edge a weight, so that shortest paths in the dual graph measure a
/// distance between faces.
///
/// All metric policies live in the namespace `SpectralSeg::Metrics`:
/// - `Part_aware_weight`: the library's default, a blend of the geodesic,
///   angular and VSI weights with the thesis's coefficients (0.01, 0.195,
///   0.795), each component normalised by its 99th percentile;
///   `Part_aware_weight<>::thesis()` normalises by the maximum instead;
/// - `Geodesic_weight`: the centroid-to-centroid path length across the
///   shared edge (approximate geodesic distance);
/// - `Angular_weight`: the normal angle across concave folds, a small
///   constant across convex ones;
/// - `VSI_weight`: the difference of the volumetric shape images of the two
///   faces (the stages are in \ref PkgSpectralSegVSI);
/// - `Blend`: a convex combination of normalised metrics;
/// - `Per_edge_weight`: any function of one dual edge;
/// - `Any_weight`: a metric chosen at run time.
///
/// `check_weights()`, `normalize_weights()` and `Normalization` are the
/// helpers the library uses to validate and normalise weight vectors.
///
/// Headers: `<SpectralSeg/Metrics/*.h>`.

/// \defgroup PkgSpectralSegDistances Distances between faces
/// \ingroup PkgSpectralSegRef
/// \brief Shortest-path (Dijkstra) distances in the weighted dual graph.
///
/// `face_distances()` is the one-call entry point on a mesh: it builds the
/// dual graph, evaluates the metric and writes distances into a face
/// property map. `Weighted_dual_graph` keeps a weighted graph for repeated
/// queries, including many rows of the face-to-face distance matrix in
/// parallel (`Weighted_dual_graph::distance_rows()`).
///
/// Headers: `<SpectralSeg/face_distances.h>`,
/// `<SpectralSeg/Weighted_dual_graph.h>`.

/// \defgroup PkgSpectralSegIO Reading meshes, writing per-face values and segmented meshes
/// \ingroup PkgSpectralSegRef
/// \brief Reading OFF, OBJ, PLY and STL files with checks and repairs,
/// writing per-face results in the order of the faces of the file, and
/// writing meshes with one colour per face.
///
/// Label files (one integer per face, as in the Princeton Segmentation
/// Benchmark) are read and written by `Evaluation::read_labels()` and
/// `Evaluation::write_labels()` (\ref PkgSpectralSegEvaluation).
///
/// `write_segmented_mesh()` and `write_segment_parts()` write segmented
/// meshes that other programs show in colour (PLY with coloured vertices
/// and the labels, OBJ with one material per segment, one file per part;
/// \ref ss_outputs).
///
/// Headers: `<SpectralSeg/IO/read_mesh_file.h>`,
/// `<SpectralSeg/IO/Mesh_file_report.h>`,
/// `<SpectralSeg/IO/write_face_values.h>`,
/// `<SpectralSeg/IO/write_colored_mesh.h>`,
/// `<SpectralSeg/IO/write_segmented_mesh.h>`,
/// `<SpectralSeg/IO/write_segment_parts.h>`,
/// `<SpectralSeg/IO/Mesh_output_format.h>`.

/// \defgroup PkgSpectralSegNamedParameters Named parameters
/// \ingroup PkgSpectralSegRef
/// \brief SpectralSeg's named parameters, which extend CGAL's.
///
/// Optional arguments are passed as a chain of named parameters, as in CGAL's
/// Polygon Mesh Processing package:
/// \code
/// namespace P = SpectralSeg::parameters;
/// SpectralSeg::face_distances(mesh, source, distance_map,
///                             P::metric(SpectralSeg::Metrics::Angular_weight())
///                              .number_of_threads(4)
///                              .vertex_point_map(vpm));
/// \endcode
///
/// A chain can mix SpectralSeg's and CGAL's parameters if it starts with a
/// function of `SpectralSeg::parameters` (every CGAL parameter, such as
/// `vertex_point_map` or `face_index_map`, is available there too). A chain
/// that starts in `CGAL::parameters` can only continue with CGAL's own
/// parameters.
///
/// The parameters SpectralSeg adds:
///
/// <table>
/// <tr><th>Parameter</th><th>Type</th><th>Meaning</th><th>Default</th><th>Read by</th></tr>
/// <tr><td>`metric`</td><td>a model of `DualEdgeWeight`</td>
///     <td>the weight of each dual edge</td>
///     <td>`Metrics::Part_aware_weight<>()`</td>
///     <td>`face_distances()`, `k_way_segmentation()`, `spectral_embedding()`,
///         `shape_descriptor()` (which also takes `Retrieval::Euclidean_distance`)</td></tr>
/// <tr><td>`descriptor_options`</td><td>`Retrieval::Descriptor_options`</td>
///     <td>bins, source faces and range of a shape descriptor</td>
///     <td>64 bins, 32 sources, 4 mean distances</td>
///     <td>`shape_descriptor()`</td></tr>
/// <tr><td>`nearest_source_map`</td>
///     <td>a writable property map, key: face descriptor, value: `std::size_t`</td>
///     <td>receives, for each face, the position in the source range of the
///         nearest source, or `Nearest_source_distances::unreachable`</td>
///     <td>not written</td>
///     <td>`face_distances()`</td></tr>
/// <tr><td>`number_of_threads`</td><td>`unsigned int`</td>
///     <td>threads used by parallel stages; `0` means all hardware threads
///         (results do not depend on it)</td>
///     <td>`0`</td>
///     <td>all</td></tr>
/// <tr><td>`progress_callback`</td><td>`Progress_callback`</td>
///     <td>called with the stage name and the fraction done; returning
///         `false` cancels the computation (`Operation_cancelled`)</td>
///     <td>none</td>
///     <td>all</td></tr>
/// <tr><td>`kernel`</td><td>a model of `AffinityKernel`</td>
///     <td>turns distances into affinities</td>
///     <td>`Kernels::Exponential_kernel()`</td>
///     <td>`k_way_segmentation()`, `spectral_embedding()`</td></tr>
/// <tr><td>`embedding_method`</td><td>`Embedding::Method`</td>
///     <td>`automatic` (exact up to `Embedding_options::exact_face_limit`
///         = 2,000 faces, Nyström above), `exact` or `nystrom`</td>
///     <td>`Embedding::Method::automatic`</td>
///     <td>`k_way_segmentation()`, `spectral_embedding()`</td></tr>
/// <tr><td>`number_of_nystrom_samples`</td><td>`std::size_t`</td>
///     <td>number of Nyström samples; `0` means the number of dimensions
///         plus one</td>
///     <td>`0` (that is, \f$k + 1\f$)</td>
///     <td>`k_way_segmentation()`, `spectral_embedding()`</td></tr>
/// <tr><td>`sampling_method`</td><td>`Embedding::Sampling_method`</td>
///     <td>how the Nyström samples are chosen: `farthest_point` or
///         `gamma`</td>
///     <td>`Embedding::Sampling_method::farthest_point`</td>
///     <td>`k_way_segmentation()`, `spectral_embedding()`</td></tr>
/// <tr><td>`boundary_enhancement`</td><td>`bool`</td>
///     <td>whether the K-means labels are refined by the graph cut</td>
///     <td>`true`</td>
///     <td>`k_way_segmentation()`</td></tr>
/// <tr><td>`k_way_options`</td><td>`Basic_K_way_options` (the whole set of
///         k-way options, the kernel included)</td>
///     <td>every k-way option; an individual parameter above, when
///         given, replaces the field it names</td>
///     <td>`K_way_options()`</td>
///     <td>`k_way_segmentation()`, `spectral_embedding()`</td></tr>
/// <tr><td>`max_number_of_segments`</td><td>`std::size_t`</td>
///     <td>the largest number of segments considered</td>
///     <td>20</td>
///     <td>`k_way_segmentation_automatic()`</td></tr>
/// <tr><td>`min_boundary_contrast`</td><td>`double`</td>
///     <td>merging stops once the weakest boundary's mean concave angle
///         reaches this many times the mesh's mean concave angle</td>
///     <td>3</td>
///     <td>`k_way_segmentation_automatic()`</td></tr>
/// </table>
///
/// The CGAL parameters read by SpectralSeg's functions are
/// `vertex_point_map`, `vertex_index_map` and `face_index_map` (see
/// `extract_mesh_geometry()`), and, for `k_way_segmentation()` and
/// `spectral_embedding()`, `random_seed` (an `unsigned int`, default 0: the
/// seed of the random start face of the farthest-point sampling and of the
/// candidates of Gamma-sampling).
///
/// Header: `<SpectralSeg/named_parameters.h>`.

/// \defgroup PkgSpectralSegRendering Pictures (PNG rendering)
/// \ingroup PkgSpectralSegRef
/// \brief A headless software renderer that draws per-face fields and labels
/// into PNG files, for checking results without a viewer.
///
/// It needs libpng: link with the CMake target `SpectralSeg::Rendering`.
/// Everything lives in the namespace `SpectralSeg::Rendering`.
///
/// Headers: `<SpectralSeg/Rendering/render_png.h>` (entry points),
/// `<SpectralSeg/Rendering/render_mesh_geometry.h>` (the same for a `Mesh_geometry`),
/// `<SpectralSeg/Rendering/Color_map.h>`, `<SpectralSeg/Rendering/Image.h>`,
/// `<SpectralSeg/Rendering/Software_rasterizer.h>`,
/// `<SpectralSeg/Rendering/write_png.h>`.

/// \defgroup PkgSpectralSegRayCasting Ray casting
/// \ingroup PkgSpectralSegRef
/// \brief Backends that find the first triangle hit by a ray, for the VSI
/// metric, which looks at the volume enclosed by the surface.
///
/// Both are models of the `RayCaster` concept and live in the namespace
/// `SpectralSeg::Ray_casting`:
/// - `AABB_ray_caster`: a CGAL AABB tree in double precision, always
///   available, the default;
/// - `Embree_ray_caster`: Intel Embree 3 in single precision, much faster;
///   available when `SPECTRALSEG_HAS_EMBREE` is defined (the CMake option
///   `SPECTRALSEG_WITH_EMBREE`).
///
/// Headers: `<SpectralSeg/Ray_casting/AABB_ray_caster.h>`,
/// `<SpectralSeg/Ray_casting/Embree_ray_caster.h>`.

/// \defgroup PkgSpectralSegVSI VSI metric
/// \ingroup PkgSpectralSegMetrics
/// \brief The stages of the volumetric shape image metric: a reference
/// point inside the shape for every face, the shape image seen from it, and
/// the difference of the images across each dual edge.
///
/// `Metrics::VSI_weight` runs them all; `Metrics::compute_vsi()` does the
/// same and also returns the reference points and the images, for
/// inspection. The parameters are gathered in `Metrics::VSI_options`.
///
/// Headers: `<SpectralSeg/Metrics/VSI_weight.h>`,
/// `<SpectralSeg/Metrics/VSI/Reference_points.h>`,
/// `<SpectralSeg/Metrics/VSI/Shape_images.h>`,
/// `<SpectralSeg/Metrics/VSI/ray_directions.h>`.

/// \defgroup PkgSpectralSegSampling Sampling faces
/// \ingroup PkgSpectralSegRef
/// \brief Max-min (farthest-point) sampling of faces under any dual-graph
/// metric: the Nyström samples of the k-way segmentation, and a way to see
/// how a metric separates the parts of a mesh.
///
/// Header: `<SpectralSeg/Sampling/farthest_point_samples.h>`.

/// \defgroup PkgSpectralSegRetrieval Shape retrieval
/// \ingroup PkgSpectralSegRef
/// \brief Shape descriptors from the distribution of distances between faces
/// under a metric (part-aware, geodesic or Euclidean, thesis 3.6), their
/// chi-square distance, rankings and retrieval scores (doc/retrieval.md).
///
/// Headers: `<SpectralSeg/shape_retrieval.h>` (mesh level),
/// `<SpectralSeg/Retrieval/Shape_descriptor.h>` (dual-graph level).

/// \defgroup PkgSpectralSegRegistration Registration of spectral embeddings
/// \ingroup PkgSpectralSegRef
/// \brief Rigid (or similarity) alignment of two spectral embeddings
/// (`spectral_embedding()`) by closest points from every axis sign flip,
/// for registration with a metric (thesis 3.6; doc/retrieval.md).
///
/// Header: `<SpectralSeg/Registration/align_embeddings.h>`.

/// \defgroup PkgSpectralSegKWay k-way segmentation
/// \ingroup PkgSpectralSegRef
/// \brief Segmentation of a mesh into a given number of parts by spectral
/// clustering.
///
/// `k_way_segmentation()` and `k_way_segmentation_automatic()` are the
/// entry points on a mesh, with named parameters; `segment_k_way()` and
/// `segment_k_way_automatic()` work on a `Weighted_dual_graph` with one
/// options struct (`K_way_options`, `K_way_automatic_options`) and return
/// every intermediate result (`K_way_result`); `spectral_embedding()` stops after
/// the embedding, for users who cluster the faces themselves. The stages are
/// documented in \ref PkgSpectralSegKernels, \ref PkgSpectralSegEmbedding,
/// \ref PkgSpectralSegClustering and \ref PkgSpectralSegRefinement.
///
/// Header: `<SpectralSeg/k_way_segmentation.h>`.

/// \defgroup PkgSpectralSegKernels Affinity kernels
/// \ingroup PkgSpectralSegKWay
/// \brief Models of the `AffinityKernel` concept, which turn distances
/// between faces into affinities: `Kernels::Exponential_kernel` (the
/// default) and `Kernels::Gaussian_kernel`.
///
/// Headers: `<SpectralSeg/Kernels/Exponential_kernel.h>`,
/// `<SpectralSeg/Kernels/Gaussian_kernel.h>`.

/// \defgroup PkgSpectralSegEmbedding Spectral embedding
/// \ingroup PkgSpectralSegKWay
/// \brief The coordinates of every face in the space spanned by the leading
/// eigenvectors of the affinity matrix: exactly from all pairwise distances
/// (`Embedding::exact_spectral_embedding()`), or from a few sampled rows by
/// the Nyström method (`Embedding::nystrom_spectral_embedding()`), with the
/// sampling quality measure `Embedding::nystrom_gamma()`.
///
/// Headers: `<SpectralSeg/Embedding/Spectral_embedding.h>`,
/// `<SpectralSeg/Embedding/exact_spectral_embedding.h>`,
/// `<SpectralSeg/Embedding/nystrom_spectral_embedding.h>`.

/// \defgroup PkgSpectralSegClustering Clustering
/// \ingroup PkgSpectralSegKWay
/// \brief Lloyd's K-means on the rows of the embedding, with max-min
/// seeding (`Clustering::kmeans()`, `Clustering::max_min_seeds()`).
///
/// Header: `<SpectralSeg/Clustering/Kmeans.h>`.

/// \defgroup PkgSpectralSegRefinement Refinement of segments
/// \ingroup PkgSpectralSegKWay
/// \brief Boundary enhancement by an alpha-expansion graph cut
/// (`Refinement::graph_cut_boundaries()`), and the last step of every
/// segmentation: one connected region per segment
/// (`Refinement::make_segments_connected()`).
///
/// Headers: `<SpectralSeg/Refinement/graph_cut_boundaries.h>`,
/// `<SpectralSeg/Refinement/connected_segments.h>`.

/// \defgroup PkgSpectralSegEvaluation Evaluation
/// \ingroup PkgSpectralSegRef
/// \brief The scores of the Princeton Segmentation Benchmark (Rand index
/// error, global and local consistency errors, Hamming distance, cut
/// discrepancy) of a segmentation against ground-truth segmentations, and
/// reading and writing label files.
///
/// Everything lives in the namespace `SpectralSeg::Evaluation`.
///
/// Header: `<SpectralSeg/evaluation.h>`.

/// \brief Everything in SpectralSeg: the dual graph, distances and the
/// k-way segmentation, and (in sub-namespaces) metric policies, ray casting,
/// the stages of the segmentation, evaluation, file input/output and
/// rendering.
namespace SpectralSeg {

/// \ingroup PkgSpectralSegMetrics
/// \brief Metric policies: models of `DualEdgeWeight`, and weight helpers.
namespace Metrics {

/// \ingroup PkgSpectralSegVSI
/// \brief The stages of the volumetric shape image metric.
namespace VSI {}

} // namespace Metrics

/// \ingroup PkgSpectralSegRayCasting
/// \brief Ray-casting backends: models of `RayCaster`.
namespace Ray_casting {}

/// \ingroup PkgSpectralSegSampling
/// \brief Choosing faces spread over a mesh.
namespace Sampling {}

/// \ingroup PkgSpectralSegKernels
/// \brief Affinity kernels: models of `AffinityKernel`.
namespace Kernels {}

/// \ingroup PkgSpectralSegEmbedding
/// \brief Spectral embeddings of the faces, exact or by the Nyström method.
namespace Embedding {}

/// \ingroup PkgSpectralSegClustering
/// \brief K-means in the spectral embedding.
namespace Clustering {}

/// \ingroup PkgSpectralSegRefinement
/// \brief Refinement of segmentations: graph-cut boundaries, connected segments.
namespace Refinement {}

/// \ingroup PkgSpectralSegEvaluation
/// \brief Scores of segmentations against ground truths, label files.
namespace Evaluation {}

/// \ingroup PkgSpectralSegIO
/// \brief Reading mesh files with repairs, writing per-face values and
/// coloured meshes.
namespace IO {}

/// \ingroup PkgSpectralSegRendering
/// \brief Colour maps, images, a software rasteriser and PNG output.
namespace Rendering {}

} // namespace SpectralSeg

/// \defgroup PkgSpectralSegSegmentability Segmentability
/// \ingroup PkgSpectralSegRef
/// \brief The 2D contour analysis of the segmentability test of the
/// automatic segmentation (thesis 6.2.3, 6.2.4 and 6.3.3): whether the
/// outline of a 2D projection of a mesh piece is concave enough to cut it.
///
/// All of it works on plain 2D points and lives in the namespace
/// `SpectralSeg::Segmentability`. The stages, in order:
/// - `trace_outer_contour()`: draws the projected triangles on a raster and
///   traces the outer boundary of the drawing;
/// - `smooth_contour()`: removes the pixel staircase with truncated Fourier
///   descriptors;
/// - `simplify_contour()`: keeps the 50 most relevant vertices (discrete
///   curve evolution), giving the contour \f$\zeta\f$;
/// - `convexity()` and `segmentability_score()`: \f$S = 1 - C\f$, where
///   the convexity \f$C\f$ combines an area ratio and a perimeter ratio;
/// - `inner_distances()` and `multidimensional_scaling()`: the contour
///   re-embedded by its inner distances, \f$\zeta^*\f$, whose score does
///   not suffer from a bent shape;
/// - `integrated_bending_scores()` and `bending_samples()`: two contour
///   vertices on different parts, the seeds of the cut.
///
/// `analyse_contour()` runs the stages up to the scores in one call and
/// returns every intermediate result (`Contour_analysis`).
///
/// Headers: `<SpectralSeg/Segmentability/Contour_analysis.h>` (all of the
/// above), `<SpectralSeg/Segmentability/Contour.h>`,
/// `<SpectralSeg/Segmentability/trace_outer_contour.h>`,
/// `<SpectralSeg/Segmentability/smooth_contour.h>`,
/// `<SpectralSeg/Segmentability/simplify_contour.h>`,
/// `<SpectralSeg/Segmentability/convexity.h>`,
/// `<SpectralSeg/Segmentability/inner_distances.h>`,
/// `<SpectralSeg/Segmentability/multidimensional_scaling.h>`,
/// `<SpectralSeg/Segmentability/integrated_bending_score.h>`.

namespace SpectralSeg {
/// \ingroup PkgSpectralSegSegmentability
/// \brief The 2D contour analysis of the segmentability test.
namespace Segmentability {}
} // namespace SpectralSeg

/// \defgroup PkgSpectralSegAutomatic Automatic segmentation
/// \ingroup PkgSpectralSegRef
/// \brief Segmentation into as many parts as the shape has (thesis ch. 6):
/// `segment_automatically()` on a dual graph, `automatic_segmentation()` on a
/// mesh; pieces (`Mesh_piece`) are tested (\ref PkgSpectralSegSegmentability),
/// cut at their most salient place (\ref PkgSpectralSegSalientCut,
/// \ref PkgSpectralSegSalience), and the cuts kept in a `Part_hierarchy`.

/// \defgroup PkgSpectralSegSalience Salience terms
/// \ingroup PkgSpectralSegAutomatic
/// \brief Part salience (thesis 6.4): the terms (`Salience::Size_term`,
/// `Salience::Boundary_strength_term`, `Salience::Protrusion_term`), their
/// weighted sum `Salience::Weighted_salience`, and the search state they read.

/// \defgroup PkgSpectralSegSalientCut Salient cut
/// \ingroup PkgSpectralSegAutomatic
/// \brief The face sequence of a piece (thesis 6.3) and the search for the
/// most salient cut along it (thesis 6.4.2).

/// \namespace SpectralSeg::Salience
/// \brief Part salience: terms and their weighted sum.

/// \namespace SpectralSeg::Salient_cut
/// \brief Face sequences and the salient-cut search.
