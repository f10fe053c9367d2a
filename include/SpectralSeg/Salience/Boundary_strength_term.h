// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Boundary_strength_term.h
/// \brief The boundary-strength factor of part salience (thesis 6.4.2).
#ifndef SPECTRALSEG_SALIENCE_BOUNDARY_STRENGTH_TERM_H
#define SPECTRALSEG_SALIENCE_BOUNDARY_STRENGTH_TERM_H

#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Salience/Cut_state.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Salience {

/// \ingroup PkgSpectralSegSalience
/// \brief How concave the cut's boundary is: the length-weighted mean of the
/// boundary edges' weights,
/// \f$\Upsilon_b = \frac{1}{l}\sum_{e \in \partial M_s} l_e \frac{w(e)}{w_{max}}\f$,
/// with \f$w(e) = \log(\nu a(e) + 1) / \log(\nu + 1)\f$ the mapped angular
/// weight of the graph cut (thesis eq. 4.20; \f$a(e)\f$ the angular weight,
/// \f$\nu = 10\f$) and \f$l\f$ the boundary's length. In \f$[0, 1]\f$.
///
/// The thesis divides by the largest weight *on the boundary*; read
/// literally, a boundary whose edges are all equally flat would then be as
/// strong as one along a crease. The default divides by the largest weight
/// in the whole piece (`Normalization::piece_maximum`), so that a boundary
/// along the piece's deepest creases scores 1 and one across flat faces
/// scores near 0; `Normalization::boundary_maximum` gives the literal form.
///
/// Each position costs \f$O(1)\f$ (\f$O(\log n)\f$ with the literal
/// normalisation, which keeps the boundary's weights in an ordered map).
///
/// \cgalModels `SalienceTerm`
class Boundary_strength_term : public Term_base
{
public:
  /// what \f$w_{max}\f$ is
  enum class Normalization
  {
    piece_maximum,   ///< the largest weight among the piece's edges (default)
    boundary_maximum ///< the largest weight on the current boundary (the thesis's formula, read literally)
  };

  /// \param normalization what \f$w_{max}\f$ is
  /// \param nu \f$\nu\f$ of the logarithmic mapping (non-negative)
  /// \param convex_weight angular weight of convex folds
  explicit Boundary_strength_term(Normalization normalization = Normalization::piece_maximum, double nu = 10.,
                                  double convex_weight = 0.001)
    : normalization_(normalization), nu_(nu), angular_(convex_weight)
  {
    if(!(nu >= 0.) || !std::isfinite(nu))
      throw Invalid_input("Boundary_strength_term: nu must be finite and non-negative");
  }

  /// `"boundary"`
  std::string name() const { return "boundary"; }

  /// the mapped angular weight \f$w(e)\f$ of a dual edge
  double edge_weight(const Dual_graph::Edge& e) const
  {
    const double norm = std::log(nu_ + 1.);
    return norm > 0. ? std::log(nu_ * angular_.weight(e) + 1.) / norm : angular_.weight(e);
  }

  /// \cond SKIP_IN_MANUAL
  void start(const Mesh_piece& piece)
  {
    piece_ = &piece;
    weights_.resize(piece.edges().size());
    max_ = 0.;
    for(std::size_t e = 0; e < weights_.size(); ++e)
    {
      weights_[e] = edge_weight(piece.graph().edge(piece.edges()[e].dual_edge));
      max_ = std::max(max_, weights_[e]);
    }
    length_ = weighted_ = 0.;
    count_ = 0;
    on_boundary_.clear();
  }
  void add_boundary_edge(Mesh_piece::size_type e)
  {
    const double l = piece_->edge_length(e);
    length_ += l;
    weighted_ += l * weights_[e];
    ++count_;
    if(normalization_ == Normalization::boundary_maximum)
      ++on_boundary_[weights_[e]];
  }
  void remove_boundary_edge(Mesh_piece::size_type e)
  {
    const double l = piece_->edge_length(e);
    length_ -= l;
    weighted_ -= l * weights_[e];
    --count_;
    if(normalization_ == Normalization::boundary_maximum)
    {
      auto it = on_boundary_.find(weights_[e]);
      if(--it->second == 0)
        on_boundary_.erase(it);
    }
  }
  /// \endcond

  /// the factor at the current position
  double value(const Cut_state&) const
  {
    if(count_ == 0 || !(length_ > 0.))
      return 0.;
    const double wmax = normalization_ == Normalization::piece_maximum
                          ? max_
                          : (on_boundary_.empty() ? 0. : on_boundary_.rbegin()->first);
    if(!(wmax > 0.))
      return 0.;
    return std::max(0., std::min(1., weighted_ / (length_ * wmax)));
  }

private:
  Normalization normalization_;
  double nu_;
  Metrics::Angular_weight angular_;
  const Mesh_piece* piece_ = nullptr;
  std::vector<double> weights_;
  double max_ = 0., length_ = 0., weighted_ = 0.;
  std::size_t count_ = 0;
  std::map<double, std::size_t> on_boundary_;
};

} // namespace Salience
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENCE_BOUNDARY_STRENGTH_TERM_H
