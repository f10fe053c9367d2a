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
/// `<SpectralSeg/Execution.h>`, `<SpectralSeg/exceptions.h>`.

/// \defgroup PkgSpectralSegMetrics Dual-edge metrics
/// \ingroup PkgSpectralSegRef
/// \brief Models of the `DualEdgeWeight` concept: policies that give every
/// dual edge a weight, so that shortest paths in the dual graph measure a
/// distance between faces.
///
/// All metric policies live in the namespace `SpectralSeg::Metrics`:
/// - `Geodesic_weight`: the centroid-to-centroid path length across the
///   shared edge (approximate geodesic distance);
/// - `Angular_weight`: the normal angle across concave folds, a small
///   constant across convex ones;
/// - `Blend`: a convex combination of normalised metrics;
/// - `Per_edge_weight`: any function of one dual edge;
/// - `Any_weight`: a metric chosen at run time.
///
/// `check_weights()` and `normalize_weights()` are the helpers the library
/// uses to validate and normalise weight vectors.
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
/// `<SpectralSeg/dual_graph_distances.h>`.

/// \defgroup PkgSpectralSegIO Reading meshes, writing per-face values
/// \ingroup PkgSpectralSegRef
/// \brief Reading OFF, OBJ, PLY and STL files with checks and repairs, and
/// writing per-face results in the order of the faces of the file.
///
/// Headers: `<SpectralSeg/IO/read_mesh_file.h>`,
/// `<SpectralSeg/IO/Mesh_file_report.h>`,
/// `<SpectralSeg/IO/write_face_values.h>`.

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
/// <tr><th>Parameter</th><th>Type</th><th>Meaning</th><th>Default</th></tr>
/// <tr><td>`metric`</td><td>a model of `DualEdgeWeight`</td>
///     <td>the weight of each dual edge</td>
///     <td>`Metrics::Geodesic_weight()`</td></tr>
/// <tr><td>`nearest_source_map`</td>
///     <td>a writable property map, key: face descriptor, value: `std::size_t`</td>
///     <td>receives, for each face, the position in the source range of the
///         nearest source, or `Nearest_source_distances::unreachable`</td>
///     <td>not written</td></tr>
/// <tr><td>`number_of_threads`</td><td>`unsigned int`</td>
///     <td>threads used by parallel stages; `0` means all hardware threads
///         (results do not depend on it)</td>
///     <td>`0`</td></tr>
/// <tr><td>`progress_callback`</td><td>`Progress_callback`</td>
///     <td>called with the stage name and the fraction done; returning
///         `false` cancels the computation (`Operation_cancelled`)</td>
///     <td>none</td></tr>
/// </table>
///
/// The CGAL parameters read by SpectralSeg's functions are
/// `vertex_point_map`, `vertex_index_map` and `face_index_map` (see
/// `extract_mesh_geometry()`).
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
/// `<SpectralSeg/Rendering/Color_map.h>`, `<SpectralSeg/Rendering/Image.h>`,
/// `<SpectralSeg/Rendering/Software_rasterizer.h>`,
/// `<SpectralSeg/Rendering/write_png.h>`.

/// \defgroup PkgSpectralSegRayCasting Ray casting (in development)
/// \ingroup PkgSpectralSegRef
/// \brief Backends that cast rays against a mesh, for the metrics that look
/// at the volume enclosed by the surface.
///
/// Work in progress: see the Roadmap section of the user manual.

/// \defgroup PkgSpectralSegVSI VSI metric (in development)
/// \ingroup PkgSpectralSegRef
/// \brief The stages of the volumetric shape image metric.
///
/// Work in progress: see the Roadmap section of the user manual.

/// \brief Everything in SpectralSeg: the dual graph, metrics, distances, and
/// (in sub-namespaces) metric policies, file input/output and rendering.
namespace SpectralSeg {

/// \ingroup PkgSpectralSegMetrics
/// \brief Metric policies: models of `DualEdgeWeight`, and weight helpers.
namespace Metrics {}

/// \ingroup PkgSpectralSegIO
/// \brief Reading mesh files with repairs, writing per-face values.
namespace IO {}

/// \ingroup PkgSpectralSegRendering
/// \brief Colour maps, images, a software rasteriser and PNG output.
namespace Rendering {}

} // namespace SpectralSeg
