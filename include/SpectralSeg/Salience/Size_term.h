// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Size_term.h
/// \brief The size factor of part salience (thesis 6.4.2).
#ifndef SPECTRALSEG_SALIENCE_SIZE_TERM_H
#define SPECTRALSEG_SALIENCE_SIZE_TERM_H

#include <SpectralSeg/Salience/Cut_state.h>

#include <string>

namespace SpectralSeg {
namespace Salience {

/// \ingroup PkgSpectralSegSalience
/// \brief Size of the smaller side relative to the piece:
/// \f$\Upsilon_s = \mathrm{Area}(M_s) / \mathrm{Area}(M_c)\f$, in \f$[0, 1/2]\f$.
/// Larger parts are more salient. It reads the search state only, so each
/// position costs \f$O(1)\f$.
///
/// \cgalModels `SalienceTerm`
struct Size_term : Term_base
{
  /// `"size"`
  std::string name() const { return "size"; }
  /// the factor at the current position
  double value(const Cut_state& s) const
  {
    return s.piece_area() > 0. ? s.smaller_area() / s.piece_area() : 0.;
  }
};

} // namespace Salience
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENCE_SIZE_TERM_H
