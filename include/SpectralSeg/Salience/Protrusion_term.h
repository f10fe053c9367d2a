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
#include <utility>

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
/// `Base::cut_loop` (our variant) takes the area enclosed by the cut itself:
/// the norm of the vector area \f$\frac12\sum (a - o) \times (b - o)\f$ of
/// the boundary's edges \f$(a, b)\f$, oriented as in the faces of the
/// prefix, about the mean \f$o\f$ of the boundary's vertices. For a planar
/// loop it is the loop's exact area; a cut across a whole body (a symmetric
/// half) encloses the body's cross-section, so the half is not protrusive,
/// while the covariance box of a long, thin seam is small. Each position
/// still costs \f$O(1)\f$: the sums of \f$a \times b\f$ and of \f$b - a\f$
/// are updated as faces join the prefix.
///
/// `Base::curve_covariance` (our variant, the default of
/// `improved_salience()`) keeps the thesis's \f$4\sqrt{\lambda_1\lambda_2}\f$
/// but takes the covariance of the boundary as a curve: every point of
/// every boundary edge, each edge weighted by its length. The covariance of
/// the vertices depends on how the mesh spaces them along the cut; the
/// curve's does not. Each position still costs \f$O(1)\f$: the length,
/// first and second moments of the boundary edges are updated as edges join
/// and leave it.
///
/// \cgalModels `SalienceTerm`
class Protrusion_term : public Term_base
{
public:
  /// how the base area is estimated
  enum class Base
  {
    covariance, ///< \f$4\sqrt{\lambda_1\lambda_2}\f$ of the boundary vertices (the thesis)
    perimeter,  ///< \f$l^2 / 4\pi\f$, \f$l\f$ the boundary's length
    cut_loop,   ///< the area enclosed by the boundary (its vector area's norm)
    /// \f$4\sqrt{\lambda_1\lambda_2}\f$ of the covariance of the boundary as
    /// a curve: each boundary edge's points, weighted by its length
    curve_covariance
  };

  /// \param base how the base area is estimated
  explicit Protrusion_term(Base base = Base::covariance) : base_(base) {}

  /// how the base area is estimated
  Base base() const { return base_; }

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
    cross_.setZero();
    step_.setZero();
    curve_length_ = 0.;
    curve_sum_.setZero();
    curve_outer_.setZero();
  }
  void add_face(Mesh_piece::size_type f)
  {
    if(base_ != Base::cut_loop)
      return;
    // each edge of f towards the piece's other faces: a new boundary edge
    // oriented as in f, or an old one (oriented as in the neighbour, the
    // opposite way) leaving the boundary; both add f's orientation
    const auto& t = piece_->triangles()[f];
    const auto range = piece_->neighbours(f);
    for(const Mesh_piece::Neighbour* nb = range.first; nb != range.second; ++nb)
    {
      const Mesh_piece::Edge& e = piece_->edges()[nb->edge];
      Mesh_piece::size_type a = e.vertex[0], b = e.vertex[1];
      for(int k = 0; k < 3; ++k)
        if(t[std::size_t(k)] == b && t[std::size_t((k + 1) % 3)] == a)
          std::swap(a, b);
      const Eigen::Vector3d pa = piece_->point(a) - origin_, pb = piece_->point(b) - origin_;
      cross_ += pa.cross(pb);
      step_ += pb - pa;
    }
  }
  void add_boundary_edge(Mesh_piece::size_type e)
  {
    length_ += piece_->edge_length(e);
    ++edges_;
    if(base_ == Base::curve_covariance)
      curve_moments(e, 1.);
  }
  void remove_boundary_edge(Mesh_piece::size_type e)
  {
    length_ -= piece_->edge_length(e);
    --edges_;
    if(base_ == Base::curve_covariance)
      curve_moments(e, -1.);
  }
  void add_boundary_vertex(Mesh_piece::size_type v)
  {
    if(base_ == Base::curve_covariance) // the edges carry its moments
      return;
    const Eigen::Vector3d p = piece_->point(v) - origin_;
    ++count_;
    sum_ += p;
    outer_ += p * p.transpose();
  }
  void remove_boundary_vertex(Mesh_piece::size_type v)
  {
    if(base_ == Base::curve_covariance)
      return;
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
    if(base_ == Base::curve_covariance)
    {
      if(edges_ == 0 || !(curve_length_ > 0.))
        return 0.;
      return box_area(curve_length_, curve_sum_, curve_outer_);
    }
    if(count_ < 2)
      return 0.;
    if(base_ == Base::cut_loop)
    {
      // sum (a - o) x (b - o) = sum a x b - o x sum (b - a)
      const Eigen::Vector3d o = sum_ / static_cast<double>(count_);
      return 0.5 * (cross_ - o.cross(step_)).norm();
    }
    return box_area(static_cast<double>(count_), sum_, outer_);
  }

  /// the factor at the current position
  double value(const Cut_state& s) const
  {
    const double area = s.smaller_area();
    if(!(area > 0.) || (base_ == Base::curve_covariance ? edges_ == 0 : count_ < 2))
      return 0.;
    const double base = base_area();
    return base <= area ? 1. - base / area : 0.;
  }

private:
  // 4 sqrt(l1 l2) of the covariance of a distribution of total weight
  // `weight`, first moment `sum` and second moment `outer`
  static double box_area(double weight, const Eigen::Vector3d& sum, const Eigen::Matrix3d& outer)
  {
    const Eigen::Vector3d mean = sum / weight;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(outer / weight - mean * mean.transpose(), Eigen::EigenvaluesOnly);
    const Eigen::Vector3d l = solver.eigenvalues(); // ascending
    return 4. * std::sqrt(std::max(0., l(2)) * std::max(0., l(1)));
  }

  // the first and second moments of the boundary edge e as a segment,
  // times its length, added with `sign`
  void curve_moments(Mesh_piece::size_type e, double sign)
  {
    const Mesh_piece::Edge& edge = piece_->edges()[e];
    const Eigen::Vector3d a = piece_->point(edge.vertex[0]) - origin_, b = piece_->point(edge.vertex[1]) - origin_;
    const double l = sign * (b - a).norm();
    curve_length_ += l;
    curve_sum_ += 0.5 * l * (a + b);
    curve_outer_ += l * ((a * a.transpose() + b * b.transpose()) / 3. +
                         (a * b.transpose() + b * a.transpose()) / 6.);
  }

  Base base_;
  double curve_length_ = 0.;
  Eigen::Vector3d curve_sum_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d curve_outer_ = Eigen::Matrix3d::Zero();
  double length_ = 0.;
  std::size_t edges_ = 0;
  const Mesh_piece* piece_ = nullptr;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  std::size_t count_ = 0;
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer_ = Eigen::Matrix3d::Zero();
  Eigen::Vector3d cross_ = Eigen::Vector3d::Zero(), step_ = Eigen::Vector3d::Zero();
};

} // namespace Salience
} // namespace SpectralSeg

#endif // SPECTRALSEG_SALIENCE_PROTRUSION_TERM_H
