// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file integrated_bending_score.h
/// \brief The integrated bending score of contour vertices and the two
/// sample vertices chosen with it (thesis 6.3.3).
#ifndef SPECTRALSEG_SEGMENTABILITY_INTEGRATED_BENDING_SCORE_H
#define SPECTRALSEG_SEGMENTABILITY_INTEGRATED_BENDING_SCORE_H

#include <SpectralSeg/Segmentability/Contour.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The mean over t in [0, 1] of (a + b t) / (c + d t), for c > 0 and
// c + d > 0: with x = d / c it is (a L(x) + b M(x)) / c, where
// L(x) = ln(1 + x) / x and M(x) = (1 - L(x)) / x, both taken from their
// Taylor series near x = 0 where the closed forms lose their digits.
SPECTRALSEG_INLINE double mean_of_ratio_of_linear(double a, double b, double c, double d)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const double x = d / c;
  double l, m;
  if(std::abs(x) < 1e-3)
  {
    l = 1. + x * (-1. / 2. + x * (1. / 3. + x * (-1. / 4. + x / 5.)));
    m = 1. / 2. + x * (-1. / 3. + x * (1. / 4. + x * (-1. / 5. + x / 6.)));
  }
  else
  {
    l = std::log1p(x) / x;
    m = (1. - l) / x;
  }
  return (a * l + b * m) / c;
}
#else
;
#endif

SPECTRALSEG_INLINE void check_inner_distances(const Contour& c, const Eigen::MatrixXd& inner, const char* function)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  check_finite(c, function);
  const Eigen::Index n = Eigen::Index(c.size());
  if(inner.rows() != n || inner.cols() != n)
    throw Invalid_input(std::string(function) + ": expected a " + std::to_string(n) + " x " + std::to_string(n) +
                        " matrix of inner distances, got " + std::to_string(inner.rows()) + " x " +
                        std::to_string(inner.cols()));
  if(!inner.allFinite())
    throw Invalid_input(std::string(function) + ": an inner distance is not finite");
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegSegmentability
/// \brief The integrated bending score (IBS) of every vertex of a contour:
/// how much, overall, the inner paths from that vertex to the rest of the
/// contour bend.
///
/// For a vertex \f$p\f$, the score is the integral along the contour of
/// \f$I_{pq} / E_{pq}\f$, the ratio of the inner distance to the Euclidean
/// distance from \f$p\f$ to the point \f$q\f$ (at least 1, large when the
/// inner path has to go round a concavity). On each edge \f$ij\f$ of
/// length \f$l\f$, \f$I\f$ and \f$E\f$ are interpolated linearly between
/// their values at \f$i\f$ and \f$j\f$, and the integral of their ratio has
/// a closed form (thesis 6.3.3), evaluated here as
/// \f$l\,(\alpha L(x) + \beta M(x)) / \gamma\f$ with
/// \f$\alpha = I_{pi}\f$, \f$\beta = I_{pj} - I_{pi}\f$,
/// \f$\gamma = E_{pi}\f$, \f$x = (E_{pj} - E_{pi}) / E_{pi}\f$,
/// \f$L(x) = \ln(1 + x) / x\f$ and \f$M(x) = (1 - L(x)) / x\f$ (series
/// near \f$x = 0\f$, which covers the case \f$E_{pi} = E_{pj}\f$).
///
/// Degenerate cases: on the two edges that end at \f$p\f$, both \f$I\f$
/// and \f$E\f$ vanish at \f$p\f$ and the interpolated ratio is the constant
/// \f$I_{pj} / E_{pj}\f$ (\f$j\f$ the other end), 1 when \f$p\f$ sees
/// \f$j\f$; an edge of zero length adds nothing; a Euclidean distance below
/// \f$10^{-12}\f$ times the perimeter (a point that coincides with \f$p\f$)
/// is raised to that value, so that a score is never infinite; a ratio
/// below 1 (a wrong inner distance) is not corrected.
///
/// \param c the contour
/// \param inner its inner distances, `inner_distances(c)`
/// \return one score per vertex of `c`, in length units of `c`; all 0 for a
///         contour of fewer than two vertices or zero perimeter
/// \throws Invalid_input if a coordinate or an inner distance is not finite
///         or `inner` is not \f$n \times n\f$
SPECTRALSEG_INLINE std::vector<double> integrated_bending_scores(const Contour& c, const Eigen::MatrixXd& inner)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  internal::check_inner_distances(c, inner, "integrated_bending_scores");
  const std::size_t n = c.size();
  std::vector<double> scores(n, 0.);
  const double length = perimeter(c);
  if(n < 2 || !(length > 0.))
    return scores;
  const double smallest = 1e-12 * length;
  for(std::size_t p = 0; p < n; ++p)
  {
    const Eigen::Index ip = Eigen::Index(p);
    double score = 0.;
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t j = (i + 1) % n;
      const double l = (c[j] - c[i]).norm();
      if(!(l > 0.))
        continue;
      const double ipi = inner(ip, Eigen::Index(i)), ipj = inner(ip, Eigen::Index(j));
      if(i == p || j == p)
      {
        // I and E both grow from 0 at p: their ratio is that at the other end
        const std::size_t other = i == p ? j : i;
        const double e = std::max((c[other] - c[p]).norm(), smallest);
        score += l * (i == p ? ipj : ipi) / e;
        continue;
      }
      const double epi = std::max((c[i] - c[p]).norm(), smallest), epj = std::max((c[j] - c[p]).norm(), smallest);
      score += l * internal::mean_of_ratio_of_linear(ipi, ipj - ipi, epi, epj - epi);
    }
    scores[p] = score;
  }
  return scores;
}
#else
;
#endif

/// \ingroup PkgSpectralSegSegmentability
/// \brief The two sample vertices of a contour, meant to lie on two
/// different parts: \f$s\f$ maximises the integrated bending score
/// (`integrated_bending_scores()`), so it tends to lie on the most isolated
/// protrusion; \f$t\f$ is the vertex with the largest inner distance from
/// \f$s\f$. Ties go to the smallest index.
///
/// \param c the contour
/// \param inner its inner distances, `inner_distances(c)`
/// \return \f$(s, t)\f$, indices into `c`; \f$(0, 0)\f$ for a single vertex
/// \throws Invalid_input if `c` is empty, or as `integrated_bending_scores()`
SPECTRALSEG_INLINE std::pair<std::size_t, std::size_t> bending_samples(const Contour& c, const Eigen::MatrixXd& inner)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(c.empty())
    throw Invalid_input("bending_samples: the contour is empty");
  const std::vector<double> scores = integrated_bending_scores(c, inner);
  const std::size_t s = std::size_t(std::max_element(scores.begin(), scores.end()) - scores.begin());
  Eigen::Index t = 0;
  inner.row(Eigen::Index(s)).maxCoeff(&t);
  return {s, std::size_t(t)};
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_INTEGRATED_BENDING_SCORE_H
