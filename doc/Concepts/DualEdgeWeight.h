// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Documentation only: this file describes a concept. It is read by Doxygen and
// never included by code.

/// \ingroup PkgSpectralSegConcepts
/// \cgalConcept
///
/// \brief A metric policy: gives every edge of a dual graph a weight, so that
/// shortest paths in the graph define a distance between faces.
///
/// The library never asks a metric for one edge at a time: a model returns
/// the weights of all dual edges in one call, which lets it precompute
/// whatever it needs (ray casts, smoothing, statistics over all edges) and
/// parallelise the work.
///
/// Requirements on the returned weights, checked by the library
/// (`SpectralSeg::Metrics::check_weights()`), which throws
/// `SpectralSeg::Invalid_input` otherwise:
/// - exactly one weight per dual edge, in the order of `graph.edges()`:
///   weight `e` belongs to `graph.edge(e)`;
/// - every weight finite and non-negative (a zero weight is allowed: it
///   makes the two faces equally distant from everything).
///
/// Requirements on the model, which the library relies on but cannot check:
/// - *deterministic*: the same graph gives the same weights, whatever the
///   number of threads in `exec`;
/// - *thread-safe*: the call operator is `const` and may be called from
///   several threads at once on different graphs;
/// - *cheap to copy*: models are passed and stored by value (in a
///   `SpectralSeg::Metrics::Blend`, in the `metric` named parameter).
///
/// A model may use `exec.threads()` threads and should report progress with
/// `exec.report()` during long computations; `exec.report()` throws
/// `SpectralSeg::Operation_cancelled` when the user cancels, and the model
/// should let that exception through.
///
/// A model may also measure the shape's thickness at each face: it then
/// has a second call operator, `operator()(graph, exec, face_thickness)`,
/// which returns the same weights and, when `face_thickness` is not null,
/// stores there one value per face (a length across the shape at the
/// face, `NaN` where unknown; the VSI metric's is
/// `SpectralSeg::Metrics::vsi_face_thickness()`) or leaves it empty. `SpectralSeg::Metrics::metric_values()` calls it when it exists;
/// the contrast merge of `SpectralSeg::segment_hybrid()` compares the
/// segments' thickness (`SpectralSeg::Weighted_dual_graph::face_thickness()`).
/// `SpectralSeg::Metrics::VSI_weight`, `SpectralSeg::Metrics::Part_aware_weight`,
/// `SpectralSeg::Metrics::Blend` and `SpectralSeg::Metrics::Any_weight` have it.
///
/// The shortest way to write a model is
/// `SpectralSeg::Metrics::make_per_edge_weight()`, which turns a function of
/// one dual edge into a policy that runs in parallel; a class with the two
/// members below is the general way (see the example
/// `examples/custom_metric.cpp`).
///
/// \cgalHasModel
/// - `SpectralSeg::Metrics::Geodesic_weight`
/// - `SpectralSeg::Metrics::Angular_weight`
/// - `SpectralSeg::Metrics::Blend`
/// - `SpectralSeg::Metrics::VSI_weight`
/// - `SpectralSeg::Metrics::Part_aware_weight` (the library's default metric)
/// - `SpectralSeg::Metrics::Per_edge_weight`
/// - `SpectralSeg::Metrics::Any_weight`
class DualEdgeWeight
{
public:
  /// The name of the metric, used in progress stages ("<name> weights") and
  /// in error messages, e.g. `"geodesic"`.
  std::string name() const;

  /// Returns one finite, non-negative weight per dual edge of `graph`, in the
  /// order of `graph.edges()`.
  ///
  /// \param graph the dual graph, with the geometry of every dual edge
  ///        (`SpectralSeg::Dual_graph::Edge`) and of every face
  ///        (`SpectralSeg::Dual_graph::geometry()`)
  /// \param exec the number of threads the metric may use and the progress
  ///        callback to report to
  std::vector<double> operator()(const SpectralSeg::Dual_graph& graph,
                                 const SpectralSeg::Execution& exec) const;
};
