// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Size_term.h
/// \brief The size factor of part salience (thesis 6.4.2).
#ifndef SPECTRALSEG_SALIENCE_SIZE_TERM_H
#define SPECTRALSEG_SALIENCE_SIZE_TERM_H

#include <SpectralSeg/Salience/Cut_state.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>

#include <string>

namespace SpectralSeg {
namespace Salience {

/// \ingroup PkgSpectralSegSalience
/// \brief Size of the smaller side relative to the piece:
/// \f$\Upsilon_s = \mathrm{Area}(M_s) / \mathrm{Area}(M_c)\f$, in \f$[0, 1/2]\f$
/// (thesis 6.4.2). Larger parts are more salient. It reads the search state
/// only, so each position costs \f$O(1)\f$.
///
/// With a `saturation` \f$\sigma < 1/2\f$ (our variant) the factor is
/// \f$\min(\mathrm{Area}(M_s) / \mathrm{Area}(M_c), \sigma) / (2\sigma)\f$:
/// it still separates slivers from parts, but every side larger than
/// \f$\sigma\f$ of the piece scores the same \f$1/2\f$, so the term no
/// longer prefers a half of a body to one of its limbs. \f$\sigma = 1/2\f$
/// (the default) is the thesis's factor.
///
/// \cgalModels `SalienceTerm`
class Size_term : public Term_base
{
public:
  /// \param saturation \f$\sigma\f$, in \f$(0, 1/2]\f$
  /// \throws Invalid_input if `saturation` is outside \f$(0, 1/2]\f$
  explicit Size_term(double saturation = 0.5) : saturation_(saturation)
  {
    if(!(saturation > 0.) || !(saturation <= 0.5))
      throw Invalid_input("Size_term: the saturation must be in (0, 1/2]");
  }
  /// `"size"`
  std::string name() const { return "size"; }
  /// \f$\sigma\f$
  double saturation() const { return saturation_; }
  /// the factor at the current position
  double value(const Cut_state& s) const
  {
    if(!(s.piece_area() > 0.))
      return 0.;
    return std::min(s.smaller_area() / s.piece_area(), saturation_) / (2. * saturation_);
  }

private:
  double saturation_;
};

} // namespace Salience
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENCE_SIZE_TERM_H
