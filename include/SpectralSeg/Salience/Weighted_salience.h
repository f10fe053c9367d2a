// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Weighted_salience.h
/// \brief Part salience as a weighted sum of salience terms (thesis eq. 6.9).
#ifndef SPECTRALSEG_SALIENCE_WEIGHTED_SALIENCE_H
#define SPECTRALSEG_SALIENCE_WEIGHTED_SALIENCE_H

#include <SpectralSeg/Salience/Boundary_strength_term.h>
#include <SpectralSeg/Salience/Cut_state.h>
#include <SpectralSeg/Salience/Protrusion_term.h>
#include <SpectralSeg/Salience/Size_term.h>
#include <SpectralSeg/exceptions.h>

#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

namespace SpectralSeg {
namespace Salience {

/// \ingroup PkgSpectralSegSalience
/// \brief The salience of a cut: \f$\sum_i w_i \Upsilon_i\f$ over a list of
/// salience terms, with one set of weights for pieces that passed a
/// structure (L) test and one for pieces that passed a geometry (M) test.
///
/// Every search event is forwarded to every term, so the sum costs what its
/// terms cost per position. Add, drop or reweight terms by instantiating it
/// with other terms and weights; `thesis_salience()` is the thesis's.
///
/// \tparam Terms models of `SalienceTerm`
///
/// \cgalModels `Salience`
template <typename... Terms>
class Weighted_salience
{
public:
  /// number of terms
  static constexpr std::size_t size = sizeof...(Terms);
  /// one weight per term
  typedef std::array<double, size> Weights;

  /// \param after_structure the weights used on pieces that passed an L test
  /// \param after_geometry the weights used on pieces that passed an M test
  /// \param terms the terms
  /// \throws Invalid_input if a weight is negative or not finite
  Weighted_salience(const Weights& after_structure, const Weights& after_geometry, Terms... terms)
    : structure_(after_structure), geometry_(after_geometry), terms_(std::move(terms)...)
  {
    for(const Weights* w : {&structure_, &geometry_})
      for(double x : *w)
        if(!(x >= 0.) || !std::isfinite(x))
          throw Invalid_input("Weighted_salience: weights must be finite and non-negative");
  }

  /// the weights used after the test on `p` passed
  const Weights& weights(Projection p) const { return p == Projection::structure ? structure_ : geometry_; }
  /// sets the weights used after the test on `p` passed
  void set_weights(Projection p, const Weights& w) { (p == Projection::structure ? structure_ : geometry_) = w; }
  /// the terms
  const std::tuple<Terms...>& terms() const { return terms_; }
  /// the terms
  std::tuple<Terms...>& terms() { return terms_; }

  /// \cond SKIP_IN_MANUAL
  void start(const Mesh_piece& piece)
  {
    std::apply([&](auto&... t) { (t.start(piece), ...); }, terms_);
  }
  void add_face(Mesh_piece::size_type f)
  {
    std::apply([&](auto&... t) { (t.add_face(f), ...); }, terms_);
  }
  void add_boundary_edge(Mesh_piece::size_type e)
  {
    std::apply([&](auto&... t) { (t.add_boundary_edge(e), ...); }, terms_);
  }
  void remove_boundary_edge(Mesh_piece::size_type e)
  {
    std::apply([&](auto&... t) { (t.remove_boundary_edge(e), ...); }, terms_);
  }
  void add_boundary_vertex(Mesh_piece::size_type v)
  {
    std::apply([&](auto&... t) { (t.add_boundary_vertex(v), ...); }, terms_);
  }
  void remove_boundary_vertex(Mesh_piece::size_type v)
  {
    std::apply([&](auto&... t) { (t.remove_boundary_vertex(v), ...); }, terms_);
  }
  /// \endcond

  /// the value of each term at the current position
  Weights term_values(const Cut_state& s) const
  {
    Weights v{};
    std::size_t i = 0;
    std::apply([&](const auto&... t) { ((v[i++] = t.value(s)), ...); }, terms_);
    return v;
  }

  /// the salience at the current position, with the weights for `p`
  double value(const Cut_state& s, Projection p) const
  {
    const Weights v = term_values(s);
    const Weights& w = weights(p);
    double sum = 0.;
    for(std::size_t i = 0; i < size; ++i)
      sum += w[i] * v[i];
    return sum;
  }

  /// the names of the terms, `"size+boundary+protrusion"`
  std::string name() const
  {
    std::string s;
    std::apply([&](const auto&... t) { ((s += (s.empty() ? "" : "+") + t.name()), ...); }, terms_);
    return s;
  }

private:
  Weights structure_, geometry_;
  std::tuple<Terms...> terms_;
};

/// \ingroup PkgSpectralSegSalience
/// \brief The thesis's salience: size, boundary strength and protrusion.
typedef Weighted_salience<Size_term, Boundary_strength_term, Protrusion_term> Thesis_salience;

/// \ingroup PkgSpectralSegSalience
/// \brief The thesis's salience with its weights: \f$(w_s, w_b, w_p) =
/// (0.1, 0.3, 0.6)\f$ after an L test, \f$(0.1, 0.6, 0.3)\f$ after an M
/// test (thesis 6.5).
inline Thesis_salience thesis_salience(
  Boundary_strength_term boundary = Boundary_strength_term())
{
  return Thesis_salience({0.1, 0.3, 0.6}, {0.1, 0.6, 0.3}, Size_term(), std::move(boundary), Protrusion_term());
}

/// \ingroup PkgSpectralSegSalience
/// \brief Our salience, the default of `Automatic_segmentation_options`:
/// the thesis's terms and weights, with the size factor saturating at 10%
/// of the piece (`Size_term(0.1)`), so that a half of a symmetric body no
/// longer outscores its limbs, and the protrusion's base estimated from the
/// boundary as a curve (`Protrusion_term::Base::curve_covariance`), which
/// does not depend on how the mesh spaces its vertices along the cut
/// (doc/benchmarks.md, \ref ss_quality_salient).
inline Thesis_salience improved_salience(Boundary_strength_term boundary = Boundary_strength_term())
{
  return Thesis_salience({0.1, 0.3, 0.6}, {0.1, 0.6, 0.3}, Size_term(0.1), std::move(boundary),
                         Protrusion_term(Protrusion_term::Base::curve_covariance));
}

} // namespace Salience
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENCE_WEIGHTED_SALIENCE_H
