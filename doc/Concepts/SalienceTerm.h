// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Documentation only: this file describes a concept. It is read by Doxygen and
// never included by code.

/// \ingroup PkgSpectralSegConcepts
/// \cgalConcept
///
/// \brief One factor of part salience, scored at every position of the
/// salient-cut search (thesis 6.4).
///
/// `SpectralSeg::Salient_cut::salient_cut_search()` walks a face sequence;
/// at each step one face joins the *prefix*, and the search reports every
/// change of the boundary between the prefix and the rest: dual edges that
/// start or stop separating the two sides, vertices that join or leave that
/// boundary. A term keeps whatever running sums it needs from these events
/// and returns its value for the current position in `value()`. Values are
/// expected in \f$[0, 1]\f$, larger meaning a more salient part; they are
/// measured on the smaller side (`SpectralSeg::Salience::Cut_state`), so a
/// term that sums prefix quantities gets the other side's as the piece's
/// total minus the prefix's.
///
/// Requirements on the model:
/// - every event is \f$O(1)\f$ (or cheap), so that the search stays linear;
/// - `start()` resets all state: a term is reused for every piece;
/// - the model is copyable.
///
/// Deriving from `SpectralSeg::Salience::Term_base` supplies empty events.
///
/// \cgalHasModel
/// - `SpectralSeg::Salience::Size_term`
/// - `SpectralSeg::Salience::Boundary_strength_term`
/// - `SpectralSeg::Salience::Protrusion_term`
class SalienceTerm
{
public:
  /// a new piece is about to be searched
  void start(const SpectralSeg::Mesh_piece& piece);
  /// local face `f` joined the prefix
  void add_face(SpectralSeg::Mesh_piece::size_type f);
  /// local edge `e` (index in `Mesh_piece::edges()`) now separates the sides
  void add_boundary_edge(SpectralSeg::Mesh_piece::size_type e);
  /// local edge `e` no longer separates the sides
  void remove_boundary_edge(SpectralSeg::Mesh_piece::size_type e);
  /// local vertex `v` joined the boundary
  void add_boundary_vertex(SpectralSeg::Mesh_piece::size_type v);
  /// local vertex `v` left the boundary
  void remove_boundary_vertex(SpectralSeg::Mesh_piece::size_type v);
  /// the factor at the current position
  double value(const SpectralSeg::Salience::Cut_state& state) const;
  /// a short name for reports
  std::string name() const;
};

/// \ingroup PkgSpectralSegConcepts
/// \cgalConcept
///
/// \brief The whole salience model of the salient-cut search: the events of
/// `SalienceTerm` and a value that depends on the test that let the piece be
/// cut.
///
/// \cgalHasModel
/// - `SpectralSeg::Salience::Weighted_salience` (the default:
///   `SpectralSeg::Salience::thesis_salience()`)
class Salience
{
public:
  /// as in `SalienceTerm`
  void start(const SpectralSeg::Mesh_piece& piece);
  /// as in `SalienceTerm`
  void add_face(SpectralSeg::Mesh_piece::size_type f);
  /// as in `SalienceTerm`
  void add_boundary_edge(SpectralSeg::Mesh_piece::size_type e);
  /// as in `SalienceTerm`
  void remove_boundary_edge(SpectralSeg::Mesh_piece::size_type e);
  /// as in `SalienceTerm`
  void add_boundary_vertex(SpectralSeg::Mesh_piece::size_type v);
  /// as in `SalienceTerm`
  void remove_boundary_vertex(SpectralSeg::Mesh_piece::size_type v);
  /// the salience at the current position, after a test on projection `p`
  double value(const SpectralSeg::Salience::Cut_state& state, SpectralSeg::Salience::Projection p) const;
};
