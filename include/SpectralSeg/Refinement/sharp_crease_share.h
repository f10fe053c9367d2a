// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file sharp_crease_share.h
/// \brief How much of a mesh's folding is sharp: a measure that separates
/// CAD-like meshes (flat and cylindrical patches meeting at sharp edges) from
/// scanned or sculpted ones.
#ifndef SPECTRALSEG_REFINEMENT_SHARP_CREASE_SHARE_H
#define SPECTRALSEG_REFINEMENT_SHARP_CREASE_SHARE_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <boost/math/constants/constants.hpp>

namespace SpectralSeg {
namespace Refinement {

/// \ingroup PkgSpectralSegRefinement
/// \brief The share of the folded edge length that is folded sharply: the
/// total length of the mesh edges whose dihedral angle (the angle between the
/// two face normals, `Dual_graph::Edge::normal_angle`, concave or convex) is
/// at least `sharp_degrees`, over that of the edges folded at least
/// `fold_degrees`; 0 when no edge is folded that much.
///
/// On a mesh of flat and cylindrical patches (a machine part) nearly every
/// fold is a sharp edge between patches, and the share is near 1; on a
/// scanned or sculpted surface most folds are blunt, and it is small (its
/// values on the Princeton benchmark's models are in the benchmarks page's
/// tuning history). Contact edges (`Dual_graph::Edge::contact`) are left out.
///
/// \param graph the dual graph
/// \param fold_degrees the angle from which an edge counts as folded
/// \param sharp_degrees the angle from which a fold counts as sharp
/// \throws Invalid_input unless \f$0 \le\f$ `fold_degrees` \f$\le\f$
///         `sharp_degrees` \f$\le 180\f$
SPECTRALSEG_INLINE double sharp_crease_share(const Dual_graph& graph, double fold_degrees = 30.,
                                             double sharp_degrees = 60.)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(!(fold_degrees >= 0. && fold_degrees <= sharp_degrees && sharp_degrees <= 180.))
    throw Invalid_input("sharp_crease_share: expected 0 <= fold angle <= sharp angle <= 180 degrees");
  const double degree = boost::math::constants::pi<double>() / 180.;
  double folded = 0., sharp = 0.;
  for(const Dual_graph::Edge& e : graph.edges())
  {
    if(e.contact)
      continue;
    if(e.normal_angle >= fold_degrees * degree)
      folded += e.length;
    if(e.normal_angle >= sharp_degrees * degree)
      sharp += e.length;
  }
  return folded > 0. ? sharp / folded : 0.;
}
#else
;
#endif

} // namespace Refinement
} // namespace SpectralSeg

#endif // SPECTRALSEG_REFINEMENT_SHARP_CREASE_SHARE_H
