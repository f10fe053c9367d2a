// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file multidimensional_scaling.h
/// \brief Re-embedding a contour in the plane from a distance matrix, by
/// classical multidimensional scaling (thesis 6.2.4).
#ifndef SPECTRALSEG_SEGMENTABILITY_MULTIDIMENSIONAL_SCALING_H
#define SPECTRALSEG_SEGMENTABILITY_MULTIDIMENSIONAL_SCALING_H

#include <SpectralSeg/Segmentability/Contour.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>

namespace SpectralSeg {
namespace Segmentability {

/// \ingroup PkgSpectralSegSegmentability
/// \brief Places \f$n\f$ points in the plane so that their Euclidean
/// distances approximate the given ones (classical, Torgerson's
/// multidimensional scaling), and returns them as a counter-clockwise
/// contour.
///
/// The squared distances are double-centred,
/// \f$B = -\frac{1}{2} J D^{(2)} J\f$ with \f$J = I - \frac{1}{n}\mathbf{1}\mathbf{1}^T\f$,
/// and point \f$k\f$ gets the coordinates \f$(\sqrt{\lambda_1}\,v_{1k},
/// \sqrt{\lambda_2}\,v_{2k})\f$ from the two largest eigenpairs of \f$B\f$
/// (Eigen's `SelfAdjointEigenSolver`; a negative eigenvalue counts as 0).
/// When the distances are those of points in the plane, they are reproduced
/// exactly (up to rounding), the points being moved rigidly. The result is
/// centred at the origin; the sign of each axis is fixed so that the
/// coordinate of largest magnitude is positive, and if the points, taken in
/// the input's order, turn clockwise, the second axis is flipped (a mirror
/// image has the same distances), so that the contour is counter-clockwise.
///
/// With inner distances (`inner_distances()`), this straightens a bent
/// shape: the thesis's articulation-invariant contour \f$\zeta^*\f$.
///
/// \param distances a square matrix of distances; it is symmetrised
///        (\f$\frac{1}{2}(D + D^T)\f$)
/// \return one point per row of `distances`, in the same order; empty for
///         an empty matrix, the origin for a 1 x 1 matrix
/// \throws Invalid_input if the matrix is not square or has a non-finite
///         entry
SPECTRALSEG_INLINE Contour multidimensional_scaling(const Eigen::MatrixXd& distances)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(distances.rows() != distances.cols())
    throw Invalid_input("multidimensional_scaling: the distance matrix is " + std::to_string(distances.rows()) +
                        " x " + std::to_string(distances.cols()) + ", not square");
  if(!distances.allFinite())
    throw Invalid_input("multidimensional_scaling: the distance matrix has a non-finite entry");
  const Eigen::Index n = distances.rows();
  Contour points(static_cast<std::size_t>(n), Eigen::Vector2d::Zero());
  if(n < 2)
    return points;
  const Eigen::MatrixXd symmetric = 0.5 * (distances + distances.transpose());
  Eigen::MatrixXd b = symmetric.cwiseProduct(symmetric);
  const Eigen::VectorXd row_means = b.rowwise().mean();
  const double mean = row_means.mean();
  // b is symmetric, so its column means are the row means
  b = -0.5 * ((b.colwise() - row_means).rowwise() - row_means.transpose()).array() - 0.5 * mean;
  b = 0.5 * (b + b.transpose()).eval();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(b);
  if(solver.info() != Eigen::Success)
    throw Error("multidimensional_scaling: the eigen-decomposition did not converge");
  Eigen::MatrixXd coordinates(n, 2); // eigenvalues are in increasing order
  for(Eigen::Index axis = 0; axis < 2; ++axis)
  {
    const Eigen::Index k = n - 1 - axis;
    Eigen::VectorXd v = solver.eigenvectors().col(k) * std::sqrt(std::max(solver.eigenvalues()(k), 0.));
    Eigen::Index largest = 0;
    v.cwiseAbs().maxCoeff(&largest);
    if(v(largest) < 0.)
      v = -v;
    coordinates.col(axis) = v;
  }
  for(Eigen::Index k = 0; k < n; ++k)
    points[std::size_t(k)] = coordinates.row(k).transpose();
  if(signed_area(points) < 0.)
    for(Eigen::Vector2d& p : points)
      p.y() = -p.y();
  return points;
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_MULTIDIMENSIONAL_SCALING_H
