// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Cut_state.h
/// \brief Where the salient-cut search stands: what salience terms are asked
/// to score.
#ifndef SPECTRALSEG_SALIENCE_CUT_STATE_H
#define SPECTRALSEG_SALIENCE_CUT_STATE_H

#include <SpectralSeg/Mesh_piece.h>

#include <algorithm>
#include <cstddef>

namespace SpectralSeg {
namespace Salience {

/// \ingroup PkgSpectralSegSalience
/// \brief Which segmentability test let a piece be cut; the salience weights
/// depend on it (thesis 6.4.2).
enum class Projection
{
  structure, ///< the test passed on the contour of the Laplacian (L) projection, or its MDS version
  geometry   ///< the test passed on the contour of the curvature-weighted (M) projection, or its MDS version
};

/// \ingroup PkgSpectralSegSalience
/// \brief The state of the salient-cut search at one position of the face
/// sequence: the faces before the position (the *prefix*) form one side of
/// the cut, the other faces the other side.
///
/// Salience is measured on the smaller side (by area), as in the thesis;
/// a term that tracks prefix quantities gets those of the other side as the
/// piece's total minus the prefix's.
struct Cut_state
{
  /// the piece being cut
  const Mesh_piece* piece = nullptr;
  /// number of faces in the prefix
  std::size_t prefix_faces = 0;
  /// area of the prefix
  double prefix_area = 0.;
  /// number of dual edges between the two sides
  std::size_t boundary_edges = 0;

  /// area of the whole piece
  double piece_area() const { return piece->area(); }
  /// whether the prefix is the smaller side (ties: yes)
  bool prefix_is_smaller() const { return prefix_area <= piece->area() - prefix_area; }
  /// area of the smaller side
  double smaller_area() const { return std::max(0., std::min(prefix_area, piece->area() - prefix_area)); }
};

/// \ingroup PkgSpectralSegSalience
/// \brief A convenience base for models of `SalienceTerm`: every event is
/// ignored. Derive from it and override (hide) the events a term needs.
struct Term_base
{
  /// a new piece is about to be searched
  void start(const Mesh_piece&) {}
  /// local face `f` joined the prefix
  void add_face(Mesh_piece::size_type) {}
  /// local edge `e` now separates the two sides
  void add_boundary_edge(Mesh_piece::size_type) {}
  /// local edge `e` no longer separates the two sides
  void remove_boundary_edge(Mesh_piece::size_type) {}
  /// local vertex `v` now lies on the boundary between the sides
  void add_boundary_vertex(Mesh_piece::size_type) {}
  /// local vertex `v` no longer lies on the boundary
  void remove_boundary_vertex(Mesh_piece::size_type) {}
};

} // namespace Salience
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENCE_CUT_STATE_H
