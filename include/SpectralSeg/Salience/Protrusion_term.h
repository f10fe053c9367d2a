// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Protrusion_term.h
/// \brief The protrusion factor of part salience (thesis 6.4.2).
#ifndef SPECTRALSEG_SALIENCE_PROTRUSION_TERM_H
#define SPECTRALSEG_SALIENCE_PROTRUSION_TERM_H

#include <SpectralSeg/Salience/Cut_state.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>

namespace SpectralSeg {
namespace Salience {

/// \ingroup PkgSpectralSegSalience
/// \brief How far the smaller side sticks out of its base:
/// \f$\Upsilon_p = 1 - \mathrm{Area}(\partial M_s) / \mathrm{Area}(M_s)\f$,
/// where the base area \f$\mathrm{Area}(\partial M_s)\f$ is estimated as
/// \f$4\sqrt{\lambda_1\lambda_2}\f$, \f$\lambda_1 \ge \lambda_2\f$ the two
/// largest eigenvalues of the covariance matrix of the boundary's vertices
/// (the area of their principal bounding box). It is 0 when the estimated
/// base exceeds the side's area (a flat side). In \f$[0, 1]\f$.
///
/// The sums of the boundary vertices' positions and of their outer products
/// are updated as vertices join and leave the boundary, so each position
/// costs \f$O(1)\f$ (one 3x3 eigenvalue problem).
///
/// `Base::perimeter` (our variant) estimates the base instead as the area
/// of a disk with the boundary's length, \f$l^2 / 4\pi\f$: a long seam
/// across a body (which the covariance box sees as a thin, small base) then
/// counts as a wide base, and a limb cut at its narrow root stays protrusive.
///
/// \cgalModels `SalienceTerm`
class Protrusion_term : public Term_base
{
public:
  /// how the base area is estimated
  enum class Base
  {
    covariance, ///< \f$4\sqrt{\lambda_1\lambda_2}\f$ of the boundary vertices (the thesis)
    perimeter   ///< \f$l^2 / 4\pi\f$, \f$l\f$ the boundary's length
  };

  /// \param base how the base area is estimated
  explicit Protrusion_term(Base base = Base::covariance) : base_(base) {}

  /// `"protrusion"`
  std::string name() const { return "protrusion"; }

  /// \cond SKIP_IN_MANUAL
  void start(const Mesh_piece& piece)
  {
    piece_ = &piece;
    // positions are taken relative to the piece's first vertex, which keeps
    // the sums small and the covariance free of cancellation
    origin_ = piece.number_of_vertices() > 0 ? piece.point(0) : Eigen::Vector3d::Zero();
    count_ = 0;
    sum_.setZero();
    outer_.setZero();
    length_ = 0.;
    edges_ = 0;
  }
  void add_boundary_edge(Mesh_piece::size_type e)
  {
    length_ += piece_->edge_length(e);
    ++edges_;
  }
  void remove_boundary_edge(Mesh_piece::size_type e)
  {
    length_ -= piece_->edge_length(e);
    --edges_;
  }
  void add_boundary_vertex(Mesh_piece::size_type v)
  {
    const Eigen::Vector3d p = piece_->point(v) - origin_;
    ++count_;
    sum_ += p;
    outer_ += p * p.transpose();
  }
  void remove_boundary_vertex(Mesh_piece::size_type v)
  {
    const Eigen::Vector3d p = piece_->point(v) - origin_;
    --count_;
    sum_ -= p;
    outer_ -= p * p.transpose();
  }
  /// \endcond

  /// the estimated base area of the current boundary
  double base_area() const
  {
    if(base_ == Base::perimeter)
      return edges_ > 0 ? std::max(0., length_) * std::max(0., length_) / (4. * CGAL_PI) : 0.;
    if(count_ < 2)
      return 0.;
    const double m = static_cast<double>(count_);
    const Eigen::Vector3d mean = sum_ / m;
    const Eigen::Matrix3d covariance = outer_ / m - mean * mean.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d l = solver.eigenvalues(); // ascending
    return 4. * std::sqrt(std::max(0., l(2)) * std::max(0., l(1)));
  }

  /// the factor at the current position
  double value(const Cut_state& s) const
  {
    const double area = s.smaller_area();
    if(!(area > 0.) || count_ < 2)
      return 0.;
    const double base = base_area();
    return base <= area ? 1. - base / area : 0.;
  }

private:
  Base base_;
  double length_ = 0.;
  std::size_t edges_ = 0;
  const Mesh_piece* piece_ = nullptr;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  std::size_t count_ = 0;
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer_ = Eigen::Matrix3d::Zero();
};

} // namespace Salience
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENCE_PROTRUSION_TERM_H
