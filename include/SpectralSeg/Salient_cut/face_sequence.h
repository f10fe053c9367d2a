// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file face_sequence.h
/// \brief The faces of a piece in one sequence, from one sample face to
/// another (thesis 6.3).
#ifndef SPECTRALSEG_SALIENT_CUT_FACE_SEQUENCE_H
#define SPECTRALSEG_SALIENT_CUT_FACE_SEQUENCE_H

#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Mesh_piece.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/Fill_reducing_order.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/dijkstra_shortest_paths_no_color_map.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Salient_cut {

/// \ingroup PkgSpectralSegSalientCut
/// \brief A linear order of a piece's faces.
struct Face_sequence
{
  /// local faces in order, from `source` to `target`
  std::vector<Mesh_piece::size_type> order;
  /// \f$d(f, s) - d(f, t)\f$ of each local face (indexed by local face)
  std::vector<double> key;
  /// the first sample face (local)
  Mesh_piece::size_type source = 0;
  /// the second sample face (local)
  Mesh_piece::size_type target = 0;
};

/// \ingroup PkgSpectralSegSalientCut
/// \brief Shortest-path distances inside a piece from one of its faces.
///
/// The graph is the piece's dual graph with the weight `weights[e]` on the
/// mesh's dual edge `e`; edges leaving the piece are not used. Faces the
/// source cannot reach get `+infinity`.
/// \pre `weights` has one finite, non-negative value per dual edge of the mesh
SPECTRALSEG_INLINE std::vector<double> piece_distances(const Mesh_piece& piece, const std::vector<double>& weights,
                                                       Mesh_piece::size_type source)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  typedef boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, boost::no_property,
                                             boost::no_property, Mesh_piece::size_type, Mesh_piece::size_type>
    Graph;
  const std::size_t n = piece.number_of_faces();
  if(source >= n)
    throw Invalid_input("piece_distances: source face out of range");
  std::vector<std::pair<Mesh_piece::size_type, Mesh_piece::size_type>> arcs;
  std::vector<double> arc_weight;
  arcs.reserve(2 * piece.edges().size());
  arc_weight.reserve(2 * piece.edges().size());
  for(Mesh_piece::size_type f = 0; f < n; ++f) // sorted by source face: CSR needs no sort
  {
    const auto range = piece.neighbours(f);
    for(const Mesh_piece::Neighbour* nb = range.first; nb != range.second; ++nb)
    {
      arcs.emplace_back(f, nb->face);
      arc_weight.push_back(weights[piece.edges()[nb->edge].dual_edge]);
    }
  }
  const Graph g(boost::edges_are_sorted, arcs.begin(), arcs.end(), static_cast<Mesh_piece::size_type>(n));
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> d(n, inf);
  const auto index = get(boost::vertex_index, g);
  boost::dijkstra_shortest_paths_no_color_map(
    g, source, boost::dummy_property_map(), boost::make_iterator_property_map(d.begin(), index),
    boost::make_iterator_property_map(arc_weight.begin(), get(boost::edge_index, g)), index, std::less<double>(),
    boost::closed_plus<double>(inf), inf, 0., boost::default_dijkstra_visitor());
  return d;
}
#else
;
#endif

/// \ingroup PkgSpectralSegSalientCut
/// \brief Sorts the faces of a piece by \f$d(f, s) - d(f, t)\f$ (thesis eq.
/// 6.3): the sequence starts at `source`, ends at `target`, and a cut that
/// separates the part around `source` from the part around `target` is one
/// of its prefixes when the samples lie on two different parts.
///
/// Ties are broken by local face index, so the order is deterministic; the
/// two Dijkstra runs go in parallel when `exec` allows two threads.
///
/// \param piece the piece
/// \param weights one weight per dual edge of the mesh (geodesic and angular
///        blend by default in the automatic segmentation)
/// \param source the first sample face (local)
/// \param target the second sample face (local)
/// \param exec threads
/// \pre the piece is connected, so every face has finite distances
/// \throws Invalid_input if a sample is out of range
SPECTRALSEG_INLINE Face_sequence face_sequence(const Mesh_piece& piece, const std::vector<double>& weights,
                                               Mesh_piece::size_type source, Mesh_piece::size_type target,
                                               const Execution& exec = Execution())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = piece.number_of_faces();
  if(source >= n || target >= n)
    throw Invalid_input("face_sequence: sample face out of range");
  std::vector<double> ds, dt;
  internal::parallel_range(0, 2, std::min(exec.threads(), 2u), [&](std::size_t i) {
    (i == 0 ? ds : dt) = piece_distances(piece, weights, i == 0 ? source : target);
  });
  Face_sequence s;
  s.source = source;
  s.target = target;
  s.key.resize(n);
  for(std::size_t f = 0; f < n; ++f)
  {
    const double k = ds[f] - dt[f];
    s.key[f] = std::isfinite(k) ? k : 0.; // unreachable faces (a disconnected piece) sit in the middle
  }
  s.order.resize(n);
  std::iota(s.order.begin(), s.order.end(), Mesh_piece::size_type(0));
  std::sort(s.order.begin(), s.order.end(), [&](Mesh_piece::size_type a, Mesh_piece::size_type b) {
    return s.key[a] < s.key[b] || (s.key[a] == s.key[b] && a < b);
  });
  return s;
}
#else
;
#endif

/// \cond SKIP_IN_MANUAL
namespace internal {

// The system of harmonic_face_sequence() for one piece, factorised once for
// every pair of samples: the weighted Laplacian of its dual graph, one face
// of each conducting component grounded (its row and column those of the
// identity; explicit zeros keep the pattern). The field from s (0) to t (1)
// is the potential of a unit current sent from t to s, normalised:
// u = (phi - phi_s) / (phi_t - phi_s), harmonic at every other face, so
// each pair costs one solve. Everything here may run on a second thread
// while the piece is tested.
class Harmonic_system
{
public:
  // face_order: the elimination order of the piece's faces (empty: their
  // approximate minimum degree order)
  Harmonic_system(const Mesh_piece& piece, double angle_scale,
                  SpectralSeg::internal::Elimination_permutation face_order = SpectralSeg::internal::Elimination_permutation())
    : piece_(&piece)
  {
    solver_.set_permutation(std::move(face_order));
    const std::size_t n = piece.number_of_faces();
    if(!(angle_scale > 0.) || !std::isfinite(angle_scale))
      throw Invalid_input("harmonic_face_sequence: the angle scale must be a positive number");
    std::vector<double> diagonal(n, 0.);
    std::vector<double> weight(piece.edges().size(), 0.);
    // the conducting components (union-find; the smallest face is the root)
    component_.resize(n);
    std::iota(component_.begin(), component_.end(), Mesh_piece::size_type(0));
    const auto find = [&](Mesh_piece::size_type f) {
      while(component_[f] != f)
        f = component_[f] = component_[component_[f]];
      return f;
    };
    for(std::size_t k = 0; k < piece.edges().size(); ++k)
    {
      const Mesh_piece::Edge& pe = piece.edges()[k];
      const Dual_graph::Edge& e = piece.graph().edge(pe.dual_edge);
      double w = e.geodesic_length > 0. ? e.length / e.geodesic_length : 0.;
      if(e.concave)
        w *= std::exp(-e.normal_angle / angle_scale);
      if(!(w > 0.) || !std::isfinite(w))
        continue; // kept as an explicit zero: the pattern stays the graph's
      weight[k] = w;
      diagonal[pe.face[0]] += w;
      diagonal[pe.face[1]] += w;
      const Mesh_piece::size_type a = find(pe.face[0]), b = find(pe.face[1]);
      if(a != b)
        component_[std::max(a, b)] = std::min(a, b);
    }
    for(Mesh_piece::size_type f = 0; f < n; ++f)
      component_[f] = find(f);
    const auto grounded = [&](Mesh_piece::size_type f) { return component_[f] == f; };
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(2 * piece.edges().size() + n);
    for(std::size_t k = 0; k < piece.edges().size(); ++k)
    {
      const Mesh_piece::Edge& pe = piece.edges()[k];
      const double w = grounded(pe.face[0]) || grounded(pe.face[1]) ? 0. : weight[k];
      entries.emplace_back(Eigen::Index(pe.face[0]), Eigen::Index(pe.face[1]), -w);
      entries.emplace_back(Eigen::Index(pe.face[1]), Eigen::Index(pe.face[0]), -w);
    }
    for(Mesh_piece::size_type f = 0; f < n; ++f)
      entries.emplace_back(Eigen::Index(f), Eigen::Index(f), grounded(f) ? 1. : diagonal[f]);
    Eigen::SparseMatrix<double> matrix(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    matrix.setFromTriplets(entries.begin(), entries.end());
    matrix.makeCompressed();
    solver_.compute(matrix);
    if(solver_.info() != Eigen::Success)
      throw Error("harmonic_face_sequence: the field's system could not be factorised");
  }

  Face_sequence sequence(Mesh_piece::size_type source, Mesh_piece::size_type target) const
  {
    const Mesh_piece& piece = *piece_;
    const std::size_t n = piece.number_of_faces();
    if(source >= n || target >= n || source == target)
      throw Invalid_input("harmonic_face_sequence: the samples must be two different faces of the piece");
    Face_sequence s;
    s.source = source;
    s.target = target;
    s.key.assign(n, 0.);
    if(component_[source] == component_[target])
    {
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(n));
      rhs(Eigen::Index(target)) += 1.;
      rhs(Eigen::Index(source)) -= 1.;
      rhs(Eigen::Index(component_[source])) = 0.; // the ground
      Eigen::VectorXd phi;
      solver_.solve(rhs, phi);
      const double low = phi(Eigen::Index(source)), span = phi(Eigen::Index(target)) - low;
      for(Mesh_piece::size_type f = 0; f < n; ++f)
        if(component_[f] == component_[source])
          s.key[f] = span > 0. ? std::min(1., std::max(0., (phi(Eigen::Index(f)) - low) / span)) : 0.;
    }
    else // no current flows between them: each sample's part takes its value
      for(Mesh_piece::size_type f = 0; f < n; ++f)
        if(component_[f] == component_[target])
          s.key[f] = 1.;
    s.key[source] = 0.;
    s.key[target] = 1.;
    s.order.resize(n);
    std::iota(s.order.begin(), s.order.end(), Mesh_piece::size_type(0));
    // the samples first and last whatever the rounding
    const auto rank = [&](Mesh_piece::size_type f) { return f == source ? 0 : f == target ? 2 : 1; };
    std::sort(s.order.begin(), s.order.end(), [&](Mesh_piece::size_type x, Mesh_piece::size_type y) {
      if(rank(x) != rank(y))
        return rank(x) < rank(y);
      return s.key[x] < s.key[y] || (s.key[x] == s.key[y] && x < y);
    });
    return s;
  }

private:
  const Mesh_piece* piece_;
  std::vector<Mesh_piece::size_type> component_; // the grounded face of each face's conducting component
  SpectralSeg::internal::Permuted_ldlt solver_;
};

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegSalientCut
/// \brief Sorts the faces of a piece by a concavity-aware harmonic field
/// from `source` (0) to `target` (1) (our variant of thesis 6.3, after Au
/// et al., "Mesh segmentation with concavity-aware fields", 2012).
///
/// The field \f$u\f$ solves \f$\sum_g w_{fg}(u_f - u_g) = 0\f$ at every
/// face but the two samples, over the piece's dual edges, with
/// \f$w_{fg} = \frac{l_e}{d_e} \exp(-\theta_e / s)\f$ across a concave
/// edge and \f$\frac{l_e}{d_e}\f$ across any other: \f$l_e\f$ the shared
/// edge's length, \f$d_e\f$ the distance between the two face centres
/// through its midpoint, \f$\theta_e\f$ the angle between the two normals
/// and \f$s\f$ `angle_scale`. The field changes fastest where the
/// conductance is low, across concave creases, so its level sets gather
/// there: each prefix of the sequence is a cut that follows the creases
/// between the samples, where the distance difference of `face_sequence()`
/// gives bisectors that cross them (a thigh cut through the pelvis, a leg
/// cut at the knee). The weights are ratios and angles: the order does not
/// depend on the mesh's scale.
///
/// One sparse Cholesky factorisation (Eigen's `SimplicialLDLT`); ties are
/// broken by local face index, so the order is deterministic. Faces of a
/// part of the piece that neither sample reaches get 0.
///
/// \param piece the piece
/// \param source the first sample face (local), key 0
/// \param target the second sample face (local), key 1
/// \param angle_scale \f$s\f$, in radians (positive)
/// \throws Invalid_input if a sample is out of range, the two samples are
///         the same face or `angle_scale` is not a positive number
/// \throws Error if the factorisation fails
SPECTRALSEG_INLINE Face_sequence harmonic_face_sequence(const Mesh_piece& piece, Mesh_piece::size_type source,
                                                        Mesh_piece::size_type target, double angle_scale)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = piece.number_of_faces();
  if(source >= n || target >= n || source == target)
    throw Invalid_input("harmonic_face_sequence: the samples must be two different faces of the piece");
  internal::Harmonic_system system(piece, angle_scale);
  return system.sequence(source, target);
}
#else
;
#endif

} // namespace Salient_cut
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENT_CUT_FACE_SEQUENCE_H
