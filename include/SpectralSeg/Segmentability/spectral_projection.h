// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file spectral_projection.h
/// \brief The planar projections of a piece by the Laplacian (structure) and
/// the curvature-weighted Laplacian (geometry) (thesis 6.2.1 and 6.2.2).
#ifndef SPECTRALSEG_SEGMENTABILITY_SPECTRAL_PROJECTION_H
#define SPECTRALSEG_SEGMENTABILITY_SPECTRAL_PROJECTION_H

#include <SpectralSeg/Mesh_piece.h>
#include <SpectralSeg/Salience/Cut_state.h>
#include <SpectralSeg/Segmentability/principal_curvatures.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/Fill_reducing_order.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

using Salience::Projection;

/// \ingroup PkgSpectralSegSegmentability
/// \brief Parameters of the projections.
struct Projection_options
{
  /// \f$\epsilon\f$: weight of an edge whose two vertices are both convex
  /// in the geometry operator M
  double convex_weight = 0.1;
  /// pieces with at most this many vertices are solved with a dense
  /// eigensolver, larger ones with Spectra's shift-invert Lanczos
  std::size_t dense_limit = 400;
  /// Lanczos subspace size (at least 4)
  std::size_t lanczos_vectors = 20;
  /// relative tolerance of the eigenvalues
  double tolerance = 1e-8;
  /// the weight of a concave edge of M is at least \f$\epsilon\f$ (our
  /// addition; `false`, the thesis: it may fall far below, on faces that are
  /// flat but for noise, where \f$\kappa\f$ is a tiny negative number)
  bool concave_floor = false;
  /// which projections are whitened: their two principal axes scaled to the
  /// same spread before the contour is drawn (our addition; none, the
  /// thesis: one scale on both axes, so an M projection that the concave
  /// weights squeeze into a needle a few pixels thick loses its concavities)
  enum class Whitening
  {
    none,     ///< the thesis
    geometry, ///< the M projection only (an elongated L projection is a limb without branches)
    both      ///< L and M
  };
  /// which projections are whitened
  Whitening whiten = Whitening::none;
};

/// \ingroup PkgSpectralSegSegmentability
/// \brief A piece flattened to the plane.
struct Planar_projection
{
  /// the 2D position of each local vertex of the piece
  std::vector<Eigen::Vector2d> points;
  /// the 2nd and 3rd smallest eigenvalues of the operator
  Eigen::Vector2d eigenvalues = Eigen::Vector2d::Zero();
};

/// \ingroup PkgSpectralSegSegmentability
/// \brief The operator \f$D - T\f$ on the vertices of a piece, as a sparse
/// symmetric matrix.
///
/// - `Projection::structure`: the graph Laplacian L, \f$T_{ij} = 1\f$ on
///   every mesh edge of the piece (thesis 6.2.1);
/// - `Projection::geometry`: M, \f$T_{ij} = (|\kappa_i| + |\kappa_j|)\,
///   |\langle e, z\rangle|\, l\f$ when \f$\kappa_i < 0\f$ or
///   \f$\kappa_j < 0\f$, else \f$\epsilon\f$ (thesis 6.2.2), with
///   \f$\kappa\f$ the minimal principal curvatures, \f$z\f$ the normalised
///   mean of the two minimal-curvature directions (made to agree in sign),
///   \f$e\f$ the unit edge direction and \f$l\f$ the edge length over the
///   piece's mean edge length. Curvatures are made dimensionless by the
///   mesh's bounding-box diagonal (our choice: the thesis does not say, and
///   \f$\epsilon\f$ is only meaningful against a scale-free weight).
///
/// \pre for `Projection::geometry`, `curvatures` holds the mesh's curvatures
SPECTRALSEG_INLINE Eigen::SparseMatrix<double> projection_operator(
    const Mesh_piece& piece, Projection which, const Principal_curvatures* curvatures,
    const Projection_options& options = Projection_options())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = piece.number_of_vertices();
  const auto edges = piece.vertex_edges();
  std::vector<double> w(edges.size(), 1.);
  if(which == Projection::geometry)
  {
    if(!curvatures || curvatures->minimum.size() != piece.geometry().number_of_vertices())
      throw Invalid_input("projection_operator: the geometry operator needs the mesh's principal curvatures");
    double mean_length = 0.;
    for(const auto& e : edges)
      mean_length += (piece.point(e.second) - piece.point(e.first)).norm();
    mean_length = edges.empty() ? 1. : mean_length / double(edges.size());
    const double scale = piece.geometry().bbox_diagonal > 0. ? piece.geometry().bbox_diagonal : 1.;
    for(std::size_t k = 0; k < edges.size(); ++k)
    {
      const auto gi = piece.vertices()[edges[k].first], gj = piece.vertices()[edges[k].second];
      const double ki = curvatures->minimum[gi] * scale, kj = curvatures->minimum[gj] * scale;
      if(!(ki < 0. || kj < 0.))
      {
        w[k] = options.convex_weight;
        continue;
      }
      const Eigen::Vector3d& di = curvatures->minimum_direction[gi];
      const Eigen::Vector3d& dj = curvatures->minimum_direction[gj];
      Eigen::Vector3d z = di + (di.dot(dj) < 0. ? -dj : dj);
      const Eigen::Vector3d d = piece.point(edges[k].second) - piece.point(edges[k].first);
      const double len = d.norm();
      const double zn = z.norm();
      const double align = (zn > 0. && len > 0.) ? std::abs(d.dot(z)) / (len * zn) : 0.;
      w[k] = (std::abs(ki) + std::abs(kj)) * align * (len / mean_length);
      if(options.concave_floor && !(w[k] >= options.convex_weight))
        w[k] = options.convex_weight;
      if(!std::isfinite(w[k]) || w[k] < options.convex_weight * 1e-3)
        w[k] = std::isfinite(w[k]) ? std::max(w[k], options.convex_weight * 1e-3) : options.convex_weight;
    }
  }
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(4 * edges.size() + n);
  std::vector<double> degree(n, 0.);
  for(std::size_t k = 0; k < edges.size(); ++k)
  {
    const int i = static_cast<int>(edges[k].first), j = static_cast<int>(edges[k].second);
    t.emplace_back(i, j, -w[k]);
    t.emplace_back(j, i, -w[k]);
    degree[std::size_t(i)] += w[k];
    degree[std::size_t(j)] += w[k];
  }
  for(std::size_t i = 0; i < n; ++i)
    t.emplace_back(int(i), int(i), degree[i]);
  Eigen::SparseMatrix<double> m(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  m.setFromTriplets(t.begin(), t.end());
  return m;
}
#else
;
#endif

/// \cond SKIP_IN_MANUAL
namespace internal {

// (A - sigma I)^{-1} for Spectra, by a sparse Cholesky factorisation in a
// given elimination order (empty: the approximate minimum degree of A's)
class Cholesky_shift_solve
{
public:
  typedef double Scalar;
  Cholesky_shift_solve(const Eigen::SparseMatrix<double>& a, SpectralSeg::internal::Elimination_permutation order) : a_(a)
  {
    solver_.set_permutation(std::move(order));
  }
  Eigen::Index rows() const { return a_.rows(); }
  Eigen::Index cols() const { return a_.cols(); }
  void set_shift(double sigma)
  {
    Eigen::SparseMatrix<double> id(a_.rows(), a_.cols());
    id.setIdentity();
    solver_.compute(a_ - sigma * id);
    if(solver_.info() != Eigen::Success)
      throw Error("spectral projection: the shifted operator could not be factorised");
  }
  void perform_op(const double* x, double* y) const
  {
    Eigen::Map<const Eigen::VectorXd> in(x, a_.rows());
    Eigen::Map<Eigen::VectorXd> out(y, a_.rows());
    solver_.solve(in, out);
  }

private:
  const Eigen::SparseMatrix<double>& a_;
  SpectralSeg::internal::Permuted_ldlt solver_;
};


// spectral_projection() with the sparse factorisations in the elimination
// order `vertex_order` of the piece's vertices (empty: their approximate
// minimum degree order)
SPECTRALSEG_INLINE Planar_projection spectral_projection(
    const Mesh_piece& piece, Projection which, const Principal_curvatures* curvatures,
    const Projection_options& options, const SpectralSeg::internal::Elimination_permutation& vertex_order)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = piece.number_of_vertices();
  Planar_projection p;
  p.points.assign(n, Eigen::Vector2d::Zero());
  if(n < 3)
    return p;
  const Eigen::SparseMatrix<double> op = projection_operator(piece, which, curvatures, options);
  Eigen::MatrixXd vectors; // n x 3, ascending eigenvalues
  Eigen::VectorXd values;
  if(n <= options.dense_limit)
  {
    const Eigen::MatrixXd dense(op);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense);
    if(solver.info() != Eigen::Success)
      throw Error("spectral projection: the dense eigensolver failed");
    vectors = solver.eigenvectors().leftCols(3);
    values = solver.eigenvalues().head(3);
  }
  else
  {
    const double mean_diagonal = op.diagonal().sum() / double(n);
    const double sigma = -1e-6 * (mean_diagonal > 0. ? mean_diagonal : 1.);
    Cholesky_shift_solve shift(op, vertex_order);
    const Eigen::Index ncv = static_cast<Eigen::Index>(std::min<std::size_t>(n, std::max<std::size_t>(options.lanczos_vectors, 7)));
    Spectra::SymEigsShiftSolver<internal::Cholesky_shift_solve> eigs(shift, 3, ncv, sigma);
    eigs.init();
    eigs.compute(Spectra::SortRule::LargestMagn, 1000, options.tolerance);
    if(eigs.info() != Spectra::CompInfo::Successful)
      throw Error("spectral projection: the Lanczos iteration did not converge");
    const Eigen::VectorXd v = eigs.eigenvalues();
    const Eigen::MatrixXd u = eigs.eigenvectors();
    std::vector<Eigen::Index> idx(3);
    std::iota(idx.begin(), idx.end(), Eigen::Index(0));
    std::sort(idx.begin(), idx.end(), [&](Eigen::Index a, Eigen::Index b) { return v(a) < v(b); });
    vectors.resize(static_cast<Eigen::Index>(n), 3);
    values.resize(3);
    for(int c = 0; c < 3; ++c)
    {
      vectors.col(c) = u.col(idx[std::size_t(c)]);
      values(c) = v(idx[std::size_t(c)]);
    }
  }
  p.eigenvalues = values.tail(2);
  // the projected coordinates: x_i = c + xi2(i) a2 + xi3(i) a3, with a_k = xi_k^T X
  Eigen::MatrixXd x(static_cast<Eigen::Index>(n), 3);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for(std::size_t v = 0; v < n; ++v)
    centre += piece.point(static_cast<Mesh_piece::size_type>(v));
  centre /= double(n);
  for(std::size_t v = 0; v < n; ++v)
    x.row(static_cast<Eigen::Index>(v)) = (piece.point(static_cast<Mesh_piece::size_type>(v)) - centre).transpose();
  Eigen::Matrix<double, 3, 2> a;
  a.col(0) = x.transpose() * vectors.col(1);
  a.col(1) = x.transpose() * vectors.col(2);
  Eigen::HouseholderQR<Eigen::Matrix<double, 3, 2>> qr(a);
  const Eigen::Matrix2d r = qr.matrixQR().topLeftCorner<2, 2>().triangularView<Eigen::Upper>();
  for(std::size_t v = 0; v < n; ++v)
    p.points[v] = r * Eigen::Vector2d(vectors(static_cast<Eigen::Index>(v), 1), vectors(static_cast<Eigen::Index>(v), 2));
  if(options.whiten == Projection_options::Whitening::both ||
     (options.whiten == Projection_options::Whitening::geometry && which == Projection::geometry))
  {
    // principal axes of the projected points, each scaled to unit spread
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for(const Eigen::Vector2d& q : p.points)
      mean += q;
    mean /= double(n);
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for(const Eigen::Vector2d& q : p.points)
      cov += (q - mean) * (q - mean).transpose();
    cov /= double(n);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> pca(cov);
    const Eigen::Vector2d l = pca.eigenvalues();
    if(l(0) > 1e-12 * l(1) && l(1) > 0.)
    {
      const Eigen::Matrix2d w = Eigen::Vector2d(1. / std::sqrt(l(0)), 1. / std::sqrt(l(1))).asDiagonal() *
                                pca.eigenvectors().transpose();
      for(Eigen::Vector2d& q : p.points)
        q = w * (q - mean);
    }
  }
  return p;
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegSegmentability
/// \brief Projects a piece to the plane: the vertex coordinates filtered to
/// the three smallest eigenvectors of `projection_operator()`
/// (\f$\tilde X = \Xi_{[1..3]}\Xi_{[1..3]}^T X\f$); the first eigenvector
/// is constant, so the projected points lie in a plane, returned in an
/// orthonormal basis of it.
///
/// The eigenvectors come from a dense solver for small pieces and from
/// Spectra's shift-invert Lanczos method (`SymEigsShiftSolver`, shift just
/// below 0, sparse Cholesky factorisation) for large ones; both are
/// deterministic.
///
/// \param piece the piece (connected, at least 3 vertices)
/// \param which L or M
/// \param curvatures the mesh's principal curvatures (for M)
/// \param options solver parameters
/// \throws Error if the eigensolver does not converge
SPECTRALSEG_INLINE Planar_projection spectral_projection(const Mesh_piece& piece, Projection which,
                                                         const Principal_curvatures* curvatures,
                                                         const Projection_options& options = Projection_options())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  return internal::spectral_projection(piece, which, curvatures, options, SpectralSeg::internal::Elimination_permutation());
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_SPECTRAL_PROJECTION_H
