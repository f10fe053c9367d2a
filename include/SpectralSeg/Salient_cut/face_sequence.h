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
#include <SpectralSeg/internal/parallel_for.h>

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
inline std::vector<double> piece_distances(const Mesh_piece& piece, const std::vector<double>& weights,
                                           Mesh_piece::size_type source)
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
inline Face_sequence face_sequence(const Mesh_piece& piece, const std::vector<double>& weights,
                                   Mesh_piece::size_type source, Mesh_piece::size_type target,
                                   const Execution& exec = Execution())
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

} // namespace Salient_cut
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENT_CUT_FACE_SEQUENCE_H
