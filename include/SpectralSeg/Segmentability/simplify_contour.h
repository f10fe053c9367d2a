// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file simplify_contour.h
/// \brief Simplifying a contour by discrete curve evolution (thesis 6.2.3).
#ifndef SPECTRALSEG_SEGMENTABILITY_SIMPLIFY_CONTOUR_H
#define SPECTRALSEG_SEGMENTABILITY_SIMPLIFY_CONTOUR_H

#include <SpectralSeg/Segmentability/Contour.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \cond SKIP_IN_MANUAL
namespace internal {

// Relevance of the vertex b between a and c in discrete curve evolution:
// turn angle times l1 l2 / (l1 + l2), lengths divided by `length_unit`.
SPECTRALSEG_INLINE double dce_relevance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                                        double length_unit)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Eigen::Vector2d u = b - a, v = c - b;
  const double l1 = u.norm() / length_unit, l2 = v.norm() / length_unit;
  if(!(l1 > 0.) || !(l2 > 0.))
    return 0.; // a repeated point carries no shape
  const double cross = u.x() * v.y() - u.y() * v.x();
  const double turn = std::atan2(std::abs(cross), u.dot(v)); // in [0, pi]
  return turn * l1 * l2 / (l1 + l2);
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegSegmentability
/// \brief Simplifies a closed contour by discrete curve evolution (Latecki
/// and Lakämper): vertices are removed one at a time, always the one that
/// contributes least to the shape, until `vertices` are left.
///
/// The contribution (relevance) of a vertex is
/// \f$K = \beta\, l_1 l_2 / (l_1 + l_2)\f$, with \f$\beta \in [0, \pi]\f$
/// the turn angle at the vertex and \f$l_1, l_2\f$ the lengths of its two
/// edges in the current polygon, divided by the perimeter of `c`. After a
/// removal only the two neighbours' relevances change. Ties go to the
/// vertex of smallest index in `c`, so the result is deterministic.
/// Vertices repeated in a row (relevance 0) go first, and the corners of a
/// polygon go last.
///
/// \param c the contour, typically from `smooth_contour()`
/// \param vertices the number of vertices to keep (the thesis uses 50)
/// \return the kept vertices of `c`, in their order in `c`, made
///         counter-clockwise if needed (then in reverse order); a copy of
///         `c` (made counter-clockwise) if it has at most `vertices` points
/// \throws Invalid_input if a coordinate is not finite or `vertices` is
///         smaller than 3
SPECTRALSEG_INLINE Contour simplify_contour(const Contour& c, std::size_t vertices = 50)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_finite(c, "simplify_contour");
  if(vertices < 3)
    throw Invalid_input("simplify_contour: at least 3 vertices must be kept, got " + std::to_string(vertices));
  const std::size_t n = c.size();
  if(n <= vertices)
  {
    Contour copy = c;
    internal::make_counterclockwise(copy);
    return copy;
  }
  double length_unit = perimeter(c);
  if(!(length_unit > 0.))
    length_unit = 1.; // all points equal: every relevance is 0

  std::vector<std::size_t> previous(n), next(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    previous[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  std::vector<double> relevance(n);
  std::set<std::pair<double, std::size_t>> queue;
  auto evaluate = [&](std::size_t i) {
    relevance[i] = internal::dce_relevance(c[previous[i]], c[i], c[next[i]], length_unit);
    queue.emplace(relevance[i], i);
  };
  for(std::size_t i = 0; i < n; ++i)
    evaluate(i);

  std::vector<bool> removed(n, false);
  for(std::size_t left = n; left > vertices; --left)
  {
    const std::size_t i = queue.begin()->second;
    queue.erase(queue.begin());
    removed[i] = true;
    const std::size_t a = previous[i], b = next[i];
    next[a] = b;
    previous[b] = a;
    queue.erase({relevance[a], a});
    queue.erase({relevance[b], b});
    evaluate(a);
    evaluate(b);
  }
  Contour simplified;
  simplified.reserve(vertices);
  for(std::size_t i = 0; i < n; ++i)
    if(!removed[i])
      simplified.push_back(c[i]);
  internal::make_counterclockwise(simplified);
  return simplified;
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_SIMPLIFY_CONTOUR_H
