// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file evaluation.h
/// \brief Scores of a segmentation against ground-truth segmentations, as the
/// Princeton Segmentation Benchmark defines them (Chen, Golovinskiy and
/// Funkhouser, "A Benchmark for 3D Mesh Segmentation", SIGGRAPH 2009). Label
/// files are read and written by `Evaluation/label_files.h`, included here.
#ifndef SPECTRALSEG_EVALUATION_H
#define SPECTRALSEG_EVALUATION_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Evaluation/label_files.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace SpectralSeg {
namespace Evaluation {

namespace internal {

// A labelling with its labels renumbered 0, 1, ..., k-1 (in order of first
// appearance), so that arbitrary integer labels can index arrays.
struct Compact_labels
{
  std::vector<std::uint32_t> index; // per face
  std::uint32_t count = 0;          // number of distinct labels
};

SPECTRALSEG_INLINE Compact_labels compact(const std::vector<int>& labels)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Compact_labels c;
  c.index.resize(labels.size());
  std::unordered_map<int, std::uint32_t> ids;
  ids.reserve(64);
  for(std::size_t f = 0; f < labels.size(); ++f)
  {
    const auto it = ids.try_emplace(labels[f], c.count);
    if(it.second)
      ++c.count;
    c.index[f] = it.first->second;
  }
  return c;
}
#else
;
#endif

// The contingency table of two labellings: one cell per pair of labels that
// share at least one face, with the number of those faces and their total
// weight. Row and column totals are sums over the cells, so that two
// identical partitions give exactly zero errors.
struct Contingency_table
{
  struct Cell
  {
    std::uint32_t row;    // label index in the first labelling
    std::uint32_t column; // label index in the second labelling
    std::uint64_t count;  // number of faces
    double weight;        // total weight of those faces (their count if unweighted)
  };
  std::vector<Cell> cells;
  std::vector<std::uint64_t> row_count, column_count;
  std::vector<double> row_weight, column_weight;
  std::uint64_t faces = 0;
  double total_weight = 0.;
};

SPECTRALSEG_INLINE void check_labellings(const std::vector<int>& a, const std::vector<int>& b, const char* what)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(a.empty() || b.empty())
    throw Invalid_input(std::string(what) + ": empty labelling");
  if(a.size() != b.size())
    throw Invalid_input(std::string(what) + ": the labellings have different sizes (" + std::to_string(a.size()) +
                        " and " + std::to_string(b.size()) + " faces)");
}
#else
;
#endif

SPECTRALSEG_INLINE void check_weights(const std::vector<double>& w, std::size_t n, const char* what)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(w.size() != n)
    throw Invalid_input(std::string(what) + ": " + std::to_string(w.size()) + " face areas given for " +
                        std::to_string(n) + " faces");
  double total = 0.;
  for(std::size_t f = 0; f < n; ++f)
  {
    if(!(w[f] >= 0.) || !std::isfinite(w[f]))
      throw Invalid_input(std::string(what) + ": the area of face " + std::to_string(f) +
                          " is negative or not finite");
    total += w[f];
  }
  if(!(total > 0.))
    throw Invalid_input(std::string(what) + ": the faces have a total area of zero");
}
#else
;
#endif

// O(n + number of cells), expected (hashing of the labels); `weights` may be
// null (unit weights).
SPECTRALSEG_INLINE Contingency_table contingency_table(const std::vector<int>& a, const std::vector<int>& b,
                                                       const std::vector<double>* weights)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = a.size();
  const Compact_labels ca = compact(a), cb = compact(b);
  Contingency_table t;
  t.faces = n;
  const std::uint64_t dense_size = std::uint64_t(ca.count) * cb.count;
  const std::uint32_t none = static_cast<std::uint32_t>(-1);
  auto add = [&](std::uint32_t& slot, std::size_t f) {
    if(slot == none)
    {
      slot = static_cast<std::uint32_t>(t.cells.size());
      t.cells.push_back({ca.index[f], cb.index[f], 0, 0.});
    }
    Contingency_table::Cell& c = t.cells[slot];
    ++c.count;
    c.weight += weights ? (*weights)[f] : 1.;
  };
  if(dense_size <= std::max<std::uint64_t>(4 * std::uint64_t(n), 1u << 16))
  {
    std::vector<std::uint32_t> slot(static_cast<std::size_t>(dense_size), none);
    for(std::size_t f = 0; f < n; ++f)
      add(slot[std::size_t(ca.index[f]) * cb.count + cb.index[f]], f);
  }
  else
  {
    std::unordered_map<std::uint64_t, std::uint32_t> slot;
    slot.reserve(std::min<std::size_t>(n, 1u << 20));
    for(std::size_t f = 0; f < n; ++f)
      add(slot.try_emplace((std::uint64_t(ca.index[f]) << 32) | cb.index[f], none).first->second, f);
  }
  t.row_count.assign(ca.count, 0);
  t.column_count.assign(cb.count, 0);
  t.row_weight.assign(ca.count, 0.);
  t.column_weight.assign(cb.count, 0.);
  for(const Contingency_table::Cell& c : t.cells)
  {
    t.row_count[c.row] += c.count;
    t.column_count[c.column] += c.count;
    t.row_weight[c.row] += c.weight;
    t.column_weight[c.column] += c.weight;
  }
  for(double w : t.row_weight)
    t.total_weight += w;
  return t;
}
#else
;
#endif

inline std::uint64_t pairs(std::uint64_t n) { return n < 2 ? 0 : (n % 2 == 0 ? (n / 2) * (n - 1) : n * ((n - 1) / 2)); }

SPECTRALSEG_INLINE double rand_index_error(const Contingency_table& t)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::uint64_t all = pairs(t.faces);
  if(all == 0)
    return 0.;
  std::uint64_t same_a = 0, same_b = 0, same_both = 0;
  for(std::uint64_t c : t.row_count)
    same_a += pairs(c);
  for(std::uint64_t c : t.column_count)
    same_b += pairs(c);
  for(const Contingency_table::Cell& c : t.cells)
    same_both += pairs(c.count);
  // pairs together in one labelling and apart in the other; no overflow as
  // same_both <= same_a, same_b <= all
  const std::uint64_t disagree = (same_a - same_both) + (same_b - same_both);
  return static_cast<double>(disagree) / static_cast<double>(all);
}
#else
;
#endif

struct Consistency_errors
{
  double global, local;
};

SPECTRALSEG_INLINE Consistency_errors consistency_errors(const Contingency_table& t)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  // A face f of cell (i, j) has E(S1,S2,f) = (r_i - w_ij) / r_i and
  // E(S2,S1,f) = (c_j - w_ij) / c_j, so each sum over faces is a sum over cells.
  double e12 = 0., e21 = 0., local = 0.;
  for(const Contingency_table::Cell& c : t.cells)
  {
    if(!(c.weight > 0.))
      continue;
    const double r = t.row_weight[c.row], k = t.column_weight[c.column];
    const double x = std::max(0., r - c.weight) / r, y = std::max(0., k - c.weight) / k;
    e12 += c.weight * x;
    e21 += c.weight * y;
    local += c.weight * std::min(x, y);
  }
  return {std::min(e12, e21) / t.total_weight, local / t.total_weight};
}
#else
;
#endif

// sum over the columns of (column weight - its largest cell): the weight of
// each region of the second labelling outside its best-matching region of
// the first, i.e. D_H(S1 => S2) of the benchmark
SPECTRALSEG_INLINE double directional_hamming(const Contingency_table& t, bool over_columns)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<double> best(over_columns ? t.column_weight.size() : t.row_weight.size(), 0.);
  for(const Contingency_table::Cell& c : t.cells)
  {
    double& b = best[over_columns ? c.column : c.row];
    b = std::max(b, c.weight);
  }
  const std::vector<double>& total = over_columns ? t.column_weight : t.row_weight;
  double d = 0.;
  for(std::size_t i = 0; i < best.size(); ++i)
    d += std::max(0., total[i] - best[i]);
  return d;
}
#else
;
#endif

SPECTRALSEG_INLINE void check_graph_labels(const Dual_graph& graph, const std::vector<int>& labels, const char* what)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(labels.empty())
    throw Invalid_input(std::string(what) + ": empty labelling");
  if(labels.size() != graph.number_of_faces())
    throw Invalid_input(std::string(what) + ": " + std::to_string(labels.size()) + " labels for a mesh of " +
                        std::to_string(graph.number_of_faces()) + " faces");
}
#else
;
#endif

// the faces with at least one neighbour of another label
SPECTRALSEG_INLINE std::vector<Dual_graph::size_type> boundary_faces(const Dual_graph& graph,
                                                                     const std::vector<int>& labels)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<Dual_graph::size_type> out;
  for(Dual_graph::size_type f = 0; f < graph.number_of_faces(); ++f)
  {
    bool boundary = false;
    graph.for_each_neighbour(f, [&](Dual_graph::size_type g, Dual_graph::size_type) {
      boundary = boundary || labels[g] != labels[f];
    });
    if(boundary)
      out.push_back(f);
  }
  return out;
}
#else
;
#endif

// area-weighted mean distance of the face centroids to the area-weighted centroid
SPECTRALSEG_INLINE double average_radius(const Mesh_geometry& geometry)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  double area = 0.;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  for(std::size_t f = 0; f < geometry.number_of_faces(); ++f)
  {
    area += geometry.areas[f];
    center += geometry.areas[f] * geometry.centroids[f];
  }
  if(!(area > 0.))
    throw Invalid_input("cut discrepancy: the mesh has a total area of zero");
  center /= area;
  double radius = 0.;
  for(std::size_t f = 0; f < geometry.number_of_faces(); ++f)
    radius += geometry.areas[f] * (geometry.centroids[f] - center).norm();
  return radius / area;
}
#else
;
#endif

SPECTRALSEG_INLINE std::vector<double> geodesic_weights(const Dual_graph& graph)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<double> w(graph.number_of_edges());
  for(Dual_graph::size_type e = 0; e < graph.number_of_edges(); ++e)
    w[e] = graph.edge(e).geodesic_length;
  return w;
}
#else
;
#endif

// The boundary faces of one labelling and the dual-graph geodesic distance
// of every face to the nearest of them (empty if there is no boundary).
struct Cut_boundary
{
  std::vector<Dual_graph::size_type> faces;
  std::vector<double> distance;
};

SPECTRALSEG_INLINE Cut_boundary cut_boundary(const Weighted_dual_graph& graph, const std::vector<int>& labels)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Cut_boundary b;
  b.faces = boundary_faces(graph.graph(), labels);
  if(!b.faces.empty())
    b.distance = graph.distances(b.faces).distance;
  return b;
}
#else
;
#endif

// mean distance from the boundary faces of `from` to the boundary of `to`;
// faces that reach no boundary face of `to` (another connected component)
// are left out; NaN if none is left
SPECTRALSEG_INLINE double mean_cut_distance(const Cut_boundary& from, const Cut_boundary& to)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  double sum = 0.;
  std::size_t n = 0;
  for(Dual_graph::size_type f : from.faces)
  {
    const double d = to.distance[f];
    if(std::isfinite(d))
    {
      sum += d;
      ++n;
    }
  }
  return n == 0 ? std::numeric_limits<double>::quiet_NaN() : sum / static_cast<double>(n);
}
#else
;
#endif

SPECTRALSEG_INLINE double cut_discrepancy(const Cut_boundary& a, const Cut_boundary& b, double radius)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(a.faces.empty() && b.faces.empty())
    return 0.;
  if(a.faces.empty() || b.faces.empty())
    return std::numeric_limits<double>::quiet_NaN();
  return (mean_cut_distance(a, b) + mean_cut_distance(b, a)) / radius;
}
#else
;
#endif

} // namespace internal

/// \ingroup PkgSpectralSegEvaluation
/// \brief The Rand index error \f$1 - RI\f$ of two labellings of the same faces.
///
/// \f$RI\f$ is the fraction of the \f$\binom{n}{2}\f$ unordered pairs of
/// faces on which the labellings agree (both put the two faces in one
/// segment, or both put them in different segments); faces are not weighted.
/// Labels are arbitrary integers, compared only for equality, so renumbering
/// the labels of either labelling does not change the score. The value is
/// computed exactly in 64-bit integers from the contingency table, in
/// \f$O(n + \text{number of label pairs})\f$ time. A single face has no pair:
/// the error is then 0.
///
/// \param a, b one label per face, in the same face order
/// \returns a value in \f$[0, 1]\f$; 0 when `a` and `b` are the same partition
/// \throws Invalid_input if a labelling is empty or the sizes differ
SPECTRALSEG_INLINE double rand_index_error(const std::vector<int>& a, const std::vector<int>& b)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_labellings(a, b, "rand_index_error");
  return internal::rand_index_error(internal::contingency_table(a, b, nullptr));
}
#else
;
#endif

/// \ingroup PkgSpectralSegEvaluation
/// \brief The global consistency error (GCE) of Martin et al., area-weighted.
///
/// For a face \f$f\f$, let \f$R(S, f)\f$ be the segment of \f$S\f$ that
/// contains it and \f$E(S_1, S_2, f) = |R(S_1, f) \setminus R(S_2, f)| /
/// |R(S_1, f)|\f$, region sizes measured in area. With \f$A\f$ the total area
/// and \f$w_f\f$ the area of \f$f\f$:
/// \f$GCE = \frac{1}{A} \min\left(\sum_f w_f E(S_1,S_2,f), \sum_f w_f E(S_2,S_1,f)\right)\f$.
/// A refinement of the other labelling scores 0. Faces of zero area count for
/// nothing. \f$O(n + \text{number of label pairs})\f$.
///
/// \param a, b one label per face, in the same face order
/// \param face_areas the area of each face (finite, non-negative, not all zero)
/// \returns a value in \f$[0, 1]\f$
/// \throws Invalid_input if a labelling is empty, the sizes differ, or the areas are invalid
SPECTRALSEG_INLINE double global_consistency_error(const std::vector<int>& a, const std::vector<int>& b,
                                                   const std::vector<double>& face_areas)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_labellings(a, b, "global_consistency_error");
  internal::check_weights(face_areas, a.size(), "global_consistency_error");
  return internal::consistency_errors(internal::contingency_table(a, b, &face_areas)).global;
}
#else
;
#endif

/// \ingroup PkgSpectralSegEvaluation
/// \brief The local consistency error (LCE) of Martin et al., area-weighted:
/// \f$LCE = \frac{1}{A} \sum_f w_f \min\left(E(S_1,S_2,f), E(S_2,S_1,f)\right)\f$,
/// with the notation of `global_consistency_error()`. Always at most the GCE.
/// \f$O(n + \text{number of label pairs})\f$.
///
/// \param a, b one label per face, in the same face order
/// \param face_areas the area of each face (finite, non-negative, not all zero)
/// \returns a value in \f$[0, 1]\f$
/// \throws Invalid_input if a labelling is empty, the sizes differ, or the areas are invalid
SPECTRALSEG_INLINE double local_consistency_error(const std::vector<int>& a, const std::vector<int>& b,
                                                  const std::vector<double>& face_areas)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_labellings(a, b, "local_consistency_error");
  internal::check_weights(face_areas, a.size(), "local_consistency_error");
  return internal::consistency_errors(internal::contingency_table(a, b, &face_areas)).local;
}
#else
;
#endif

/// \ingroup PkgSpectralSegEvaluation
/// \brief The Hamming distance of two labellings with its two directional rates.
struct Hamming_distance
{
  /// \f$(R_m + R_f) / 2\f$
  double distance;
  /// \f$R_m = D_H(S_1 \Rightarrow S_2) / A\f$: the area of each region of the
  /// reference \f$S_2\f$ outside the region of \f$S_1\f$ that overlaps it most,
  /// summed and divided by the total area (high when \f$S_1\f$ over-segments)
  double missing_rate;
  /// \f$R_f = D_H(S_2 \Rightarrow S_1) / A\f$: the same with the roles
  /// exchanged (high when \f$S_1\f$ under-segments)
  double false_alarm_rate;
};

/// \ingroup PkgSpectralSegEvaluation
/// \brief The area-weighted Hamming distance of the benchmark, with its
/// missing rate and false-alarm rate.
///
/// \f$D_H(S_1 \Rightarrow S_2) = \sum_i |R_2^i \setminus R_1^{i_t}|\f$, where
/// \f$R_1^{i_t}\f$ is the region of \f$S_1\f$ that overlaps the region
/// \f$R_2^i\f$ of \f$S_2\f$ most (ties do not change the value), sizes in area.
/// `a` plays \f$S_1\f$ (the segmentation evaluated) and `b` \f$S_2\f$ (the
/// ground truth). \f$O(n + \text{number of label pairs})\f$.
///
/// \param a the segmentation evaluated, one label per face
/// \param b the reference, one label per face in the same order
/// \param face_areas the area of each face (finite, non-negative, not all zero)
/// \throws Invalid_input if a labelling is empty, the sizes differ, or the areas are invalid
SPECTRALSEG_INLINE Hamming_distance hamming(const std::vector<int>& a, const std::vector<int>& b,
                                            const std::vector<double>& face_areas)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_labellings(a, b, "hamming");
  internal::check_weights(face_areas, a.size(), "hamming");
  const internal::Contingency_table t = internal::contingency_table(a, b, &face_areas);
  Hamming_distance h;
  h.missing_rate = internal::directional_hamming(t, true) / t.total_weight;
  h.false_alarm_rate = internal::directional_hamming(t, false) / t.total_weight;
  h.distance = 0.5 * (h.missing_rate + h.false_alarm_rate);
  return h;
}
#else
;
#endif

/// \ingroup PkgSpectralSegEvaluation
/// \brief The area-weighted Hamming distance \f$(R_m + R_f) / 2\f$; see `hamming()`.
/// It is symmetric in `a` and `b`.
/// \throws Invalid_input if a labelling is empty, the sizes differ, or the areas are invalid
SPECTRALSEG_INLINE double hamming_distance(const std::vector<int>& a, const std::vector<int>& b,
                                           const std::vector<double>& face_areas)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  return hamming(a, b, face_areas).distance;
}
#else
;
#endif

/// \ingroup PkgSpectralSegEvaluation
/// \brief The cut discrepancy of the benchmark, measured on the dual graph.
///
/// \f$CD = \left(\bar d(C_a \to C_b) + \bar d(C_b \to C_a)\right) / \bar r\f$,
/// where \f$\bar d(C_a \to C_b)\f$ is the mean distance from the cut
/// boundary of `a` to the nearest cut boundary of `b`, and \f$\bar r\f$ the
/// average radius of the mesh: the area-weighted mean distance of the face
/// centroids to the area-weighted centroid.
///
/// Approximation: the benchmark samples points on the cut edges and measures
/// surface distances. Here the cut boundary of a labelling is its set of
/// *boundary faces*, the faces with a dual-graph neighbour of another label
/// (so both sides of each cut), each face counting once; the distance of a
/// face to the other boundary is the dual-graph geodesic distance (a
/// multi-source Dijkstra over `Dual_graph::Edge::geodesic_length`, the
/// centroid - edge midpoint - centroid paths) to the nearest boundary face of
/// the other labelling. Identical cuts give 0; two parallel cuts \f$k \ge 1\f$
/// dual hops apart give about \f$k - \frac12\f$ hops in each direction,
/// since both sides of each cut are boundary faces.
///
/// Conventions: if neither labelling has a boundary (one segment each, or
/// segments that only meet across mesh borders or between components), the
/// result is 0. If exactly one has a boundary, the distance to an empty cut
/// is undefined and the result is NaN (`evaluate()` leaves NaN out of its
/// averages). Boundary faces that reach no boundary face of the other
/// labelling (in another connected component) are left out of the mean;
/// if that leaves none in a direction, the result is NaN.
///
/// \param graph the dual graph of the mesh
/// \param a, b one label per face of `graph`, in the order of its faces
/// \throws Invalid_input if a labelling is empty, does not have one label per
///         face, or the mesh has zero area
SPECTRALSEG_INLINE double cut_discrepancy(const Dual_graph& graph, const std::vector<int>& a, const std::vector<int>& b)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_graph_labels(graph, a, "cut_discrepancy");
  internal::check_graph_labels(graph, b, "cut_discrepancy");
  const double radius = internal::average_radius(graph.geometry());
  const Weighted_dual_graph weighted(graph, internal::geodesic_weights(graph));
  return internal::cut_discrepancy(internal::cut_boundary(weighted, a), internal::cut_boundary(weighted, b),
                                   radius);
}
#else
;
#endif

/// \ingroup PkgSpectralSegEvaluation
/// \brief All the scores of the benchmark for one segmentation (lower is better).
struct Scores
{
  double rand_index_error;         ///< see `rand_index_error()`
  double global_consistency_error; ///< see `global_consistency_error()`
  double local_consistency_error;  ///< see `local_consistency_error()`
  double hamming_distance;         ///< see `hamming()`
  double hamming_missing_rate;     ///< \f$R_m\f$, see `hamming()`
  double hamming_false_alarm_rate; ///< \f$R_f\f$, see `hamming()`
  double cut_discrepancy;          ///< see `cut_discrepancy()`; may be NaN
};

/// \ingroup PkgSpectralSegEvaluation
/// \brief The scores of `predicted` against each ground truth in turn, with
/// the face areas of `graph` as weights.
///
/// The Dijkstra run from the boundary of `predicted` is shared by all the
/// ground truths.
///
/// \param graph the dual graph of the mesh (areas and cut distances)
/// \param predicted one label per face of `graph`
/// \param ground_truths one or more labellings of the faces of `graph`
/// \returns one `Scores` per ground truth, in their order
/// \throws Invalid_input if there is no ground truth, a labelling does not
///         have one label per face, or the mesh has zero area
SPECTRALSEG_INLINE std::vector<Scores> evaluate_each(const Dual_graph& graph, const std::vector<int>& predicted,
                                                     const std::vector<std::vector<int>>& ground_truths)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_graph_labels(graph, predicted, "evaluate");
  if(ground_truths.empty())
    throw Invalid_input("evaluate: no ground-truth labelling given");
  for(const std::vector<int>& gt : ground_truths)
    internal::check_graph_labels(graph, gt, "evaluate");
  const std::vector<double>& areas = graph.geometry().areas;
  internal::check_weights(areas, predicted.size(), "evaluate");

  const double radius = internal::average_radius(graph.geometry());
  const Weighted_dual_graph weighted(graph, internal::geodesic_weights(graph));
  const internal::Cut_boundary predicted_cut = internal::cut_boundary(weighted, predicted);

  std::vector<Scores> out;
  out.reserve(ground_truths.size());
  for(const std::vector<int>& gt : ground_truths)
  {
    Scores s;
    const internal::Contingency_table t = internal::contingency_table(predicted, gt, &areas);
    // the Rand index counts faces, not areas: the cell counts are the same
    s.rand_index_error = internal::rand_index_error(t);
    const internal::Consistency_errors ce = internal::consistency_errors(t);
    s.global_consistency_error = ce.global;
    s.local_consistency_error = ce.local;
    s.hamming_missing_rate = internal::directional_hamming(t, true) / t.total_weight;
    s.hamming_false_alarm_rate = internal::directional_hamming(t, false) / t.total_weight;
    s.hamming_distance = 0.5 * (s.hamming_missing_rate + s.hamming_false_alarm_rate);
    s.cut_discrepancy = internal::cut_discrepancy(predicted_cut, internal::cut_boundary(weighted, gt), radius);
    out.push_back(s);
  }
  return out;
}
#else
;
#endif

/// \ingroup PkgSpectralSegEvaluation
/// \brief The mean of each score over several evaluations; NaN values are
/// left out of each mean (a mean with no value left is NaN).
/// \throws Invalid_input if `scores` is empty
SPECTRALSEG_INLINE Scores average(const std::vector<Scores>& scores)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(scores.empty())
    throw Invalid_input("average: no scores given");
  double Scores::*const fields[] = {&Scores::rand_index_error,       &Scores::global_consistency_error,
                                    &Scores::local_consistency_error, &Scores::hamming_distance,
                                    &Scores::hamming_missing_rate,    &Scores::hamming_false_alarm_rate,
                                    &Scores::cut_discrepancy};
  Scores mean;
  for(double Scores::*field : fields)
  {
    double sum = 0.;
    std::size_t n = 0;
    for(const Scores& s : scores)
      if(!std::isnan(s.*field))
      {
        sum += s.*field;
        ++n;
      }
    mean.*field = n == 0 ? std::numeric_limits<double>::quiet_NaN() : sum / static_cast<double>(n);
  }
  return mean;
}
#else
;
#endif

/// \ingroup PkgSpectralSegEvaluation
/// \brief The benchmark's score of a segmentation on one model: each score of
/// `predicted` against each ground truth, averaged over the ground truths
/// (NaN cut discrepancies left out; see `evaluate_each()` and `average()`).
///
/// The benchmark's score of a method is then the mean of these per-model
/// scores over the models.
///
/// \param graph the dual graph of the mesh (areas and cut distances)
/// \param predicted one label per face of `graph`
/// \param ground_truths one or more labellings of the faces of `graph`
/// \throws Invalid_input if there is no ground truth, a labelling does not
///         have one label per face, or the mesh has zero area
SPECTRALSEG_INLINE Scores evaluate(const Dual_graph& graph, const std::vector<int>& predicted,
                                   const std::vector<std::vector<int>>& ground_truths)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  return average(evaluate_each(graph, predicted, ground_truths));
}
#else
;
#endif

} // namespace Evaluation
} // namespace SpectralSeg

#endif // SPECTRALSEG_EVALUATION_H
