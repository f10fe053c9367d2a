// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file salient_cut_search.h
/// \brief The most salient cut along a face sequence (thesis 6.4.2).
#ifndef SPECTRALSEG_SALIENT_CUT_SALIENT_CUT_SEARCH_H
#define SPECTRALSEG_SALIENT_CUT_SALIENT_CUT_SEARCH_H

#include <SpectralSeg/Mesh_piece.h>
#include <SpectralSeg/Salience/Cut_state.h>
#include <SpectralSeg/exceptions.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace SpectralSeg {
namespace Salient_cut {

/// \ingroup PkgSpectralSegSalientCut
/// \brief The best cut found along a face sequence.
struct Salient_cut
{
  /// number of faces of the sequence before the cut (in `[1, n - 1]`)
  std::size_t position = 0;
  /// salience of the cut
  double salience = -std::numeric_limits<double>::infinity();
  /// 1 for the local faces before the cut, 0 for the others
  std::vector<std::uint8_t> side;
  /// the salience at every position `1 .. n-1` (index `i` holds position
  /// `i + 1`), when asked for
  std::vector<double> curve;
};

/// \ingroup PkgSpectralSegSalientCut
/// \brief Walks the face sequence, scores the cut at every position with
/// `salience`, and returns the position of the highest score (the first one
/// on ties).
///
/// At each step one face joins the prefix; the dual edges between the two
/// sides and the vertices on them are updated from that face's neighbours,
/// and the salience model hears of every change, so the whole walk costs
/// \f$O(n)\f$ events plus what the model spends per event.
///
/// \tparam SalienceModel a model of `Salience` (e.g. `Salience::Weighted_salience`)
/// \param piece the piece
/// \param order the piece's local faces, each once
/// \param salience the salience model; `start()` is called here
/// \param projection which test let the piece be cut (chooses the weights)
/// \param keep_curve whether to return the salience of every position
/// \param min_side_area positions where the smaller side's area is below
///        this are not candidates (0: every position is, as in the thesis)
/// \param concave_angles with `min_contrast`: one concavity weight per dual
///        edge of the piece's graph, e.g. `Refinement::concave_angle_weights()`
///        (`segment_automatically()` passes those angles mapped by the
///        boundary term, `Salience::Boundary_strength_term::edge_weight()`)
/// \param min_contrast positions whose boundary's mean weight (each edge
///        weighted by its length) is below this multiple of the piece's
///        mean are not candidates (0: every position is, as in the thesis)
/// \return the best cut; `position` is 0 if no position was a candidate
/// \throws Invalid_input if `order` is not a permutation of the piece's faces
///         or the piece has fewer than 2 faces
template <typename SalienceModel>
Salient_cut salient_cut_search(const Mesh_piece& piece, const std::vector<Mesh_piece::size_type>& order,
                               SalienceModel& salience, Salience::Projection projection, bool keep_curve = false,
                               double min_side_area = 0., const std::vector<double>* concave_angles = nullptr,
                               double min_contrast = 0.)
{
  const std::size_t n = piece.number_of_faces();
  if(n < 2)
    throw Invalid_input("salient_cut_search: a piece needs at least two faces to be cut");
  if(order.size() != n)
    throw Invalid_input("salient_cut_search: the sequence does not list every face of the piece");
  std::vector<std::uint8_t> in_prefix(n, 0);
  for(Mesh_piece::size_type f : order)
  {
    if(f >= n || in_prefix[f])
      throw Invalid_input("salient_cut_search: the sequence is not a permutation of the piece's faces");
    in_prefix[f] = 1;
  }
  std::fill(in_prefix.begin(), in_prefix.end(), 0);
  // the concave contrast: the boundary's length and summed angle against
  // the piece's mean angle
  const bool contrast = min_contrast > 0. && concave_angles;
  if(contrast && concave_angles->size() != piece.graph().number_of_edges())
    throw Invalid_input("salient_cut_search: expected one concave angle per dual edge");
  double mean_angle = 0., boundary_length = 0., boundary_angle = 0.;
  if(contrast)
  {
    double length = 0.;
    for(Mesh_piece::size_type e = 0; e < piece.edges().size(); ++e)
    {
      length += piece.edge_length(e);
      mean_angle += piece.edge_length(e) * (*concave_angles)[piece.edges()[e].dual_edge];
    }
    mean_angle = length > 0. ? mean_angle / length : 0.;
  }
  std::vector<std::uint32_t> vertex_edges(piece.number_of_vertices(), 0);

  salience.start(piece);
  Salience::Cut_state state;
  state.piece = &piece;
  Salient_cut best;
  if(keep_curve)
    best.curve.reserve(n - 1);
  for(std::size_t i = 0; i + 1 < n; ++i)
  {
    const Mesh_piece::size_type f = order[i];
    in_prefix[f] = 1;
    state.prefix_area += piece.face_area(f);
    ++state.prefix_faces;
    salience.add_face(f);
    const auto range = piece.neighbours(f);
    for(const Mesh_piece::Neighbour* nb = range.first; nb != range.second; ++nb)
    {
      const Mesh_piece::Edge& e = piece.edges()[nb->edge];
      if(in_prefix[nb->face])
      {
        salience.remove_boundary_edge(nb->edge);
        --state.boundary_edges;
        if(contrast)
        {
          boundary_length -= piece.edge_length(nb->edge);
          boundary_angle -= piece.edge_length(nb->edge) * (*concave_angles)[e.dual_edge];
        }
        for(Mesh_piece::size_type v : e.vertex)
          if(--vertex_edges[v] == 0)
            salience.remove_boundary_vertex(v);
      }
      else
      {
        salience.add_boundary_edge(nb->edge);
        ++state.boundary_edges;
        if(contrast)
        {
          boundary_length += piece.edge_length(nb->edge);
          boundary_angle += piece.edge_length(nb->edge) * (*concave_angles)[e.dual_edge];
        }
        for(Mesh_piece::size_type v : e.vertex)
          if(vertex_edges[v]++ == 0)
            salience.add_boundary_vertex(v);
      }
    }
    const double s = salience.value(state, projection);
    if(keep_curve)
      best.curve.push_back(s);
    if(s > best.salience && state.smaller_area() >= min_side_area &&
       (!contrast || boundary_angle >= min_contrast * mean_angle * boundary_length))
    {
      best.salience = s;
      best.position = i + 1;
    }
  }
  best.side.assign(n, 0);
  for(std::size_t i = 0; i < best.position; ++i)
    best.side[order[i]] = 1;
  return best;
}

} // namespace Salient_cut
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENT_CUT_SALIENT_CUT_SEARCH_H
