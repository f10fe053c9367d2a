// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file principal_curvatures.h
/// \brief Principal curvatures and directions at the vertices of a mesh,
/// from the normal-cycle curvature tensor.
#ifndef SPECTRALSEG_SEGMENTABILITY_PRINCIPAL_CURVATURES_H
#define SPECTRALSEG_SEGMENTABILITY_PRINCIPAL_CURVATURES_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \ingroup PkgSpectralSegSegmentability
/// \brief Principal curvatures and directions per vertex. Curvatures are
/// signed: positive where the surface bends outward (convex), negative where
/// it bends inward (concave), for an outward-oriented mesh.
struct Principal_curvatures
{
  /// the minimal principal curvature \f$\kappa_{min}\f$ of each vertex
  std::vector<double> minimum;
  /// the maximal principal curvature \f$\kappa_{max}\f$ of each vertex
  std::vector<double> maximum;
  /// unit direction of \f$\kappa_{min}\f$ (zero where undefined); the sign
  /// of a direction is arbitrary
  std::vector<Eigen::Vector3d> minimum_direction;
  /// unit direction of \f$\kappa_{max}\f$ (zero where undefined)
  std::vector<Eigen::Vector3d> maximum_direction;
};

/// \ingroup PkgSpectralSegSegmentability
/// \brief Estimates the principal curvatures of every vertex with the
/// normal-cycle tensor of Cohen-Steiner and Morvan.
///
/// Around vertex \f$v\f$, each interior mesh edge \f$e\f$ of the faces
/// incident to \f$v\f$ adds \f$\beta(e)\, |e \cap B|\, \bar e \bar e^T\f$ to
/// a 3x3 tensor, with \f$\beta(e)\f$ the signed angle between its two face
/// normals (negative on concave folds), \f$\bar e\f$ its unit direction and
/// \f$|e \cap B|\f$ its length inside the neighbourhood \f$B\f$ (the
/// faces around \f$v\f$): the whole length for edges at \f$v\f$, half of it
/// for edges on the rim of the neighbourhood. The tensor is divided by the
/// neighbourhood's area. Its eigenvector closest to the vertex normal is
/// dropped; of the other two, the eigenvector of the larger eigenvalue is the
/// direction of *least* bending (the edges along it carry the folding
/// across it), so each eigenvalue is the curvature along the other
/// eigenvector.
///
/// Vertices with no interior edge around them get zero curvatures and
/// directions. Costs one pass over the edges and one 3x3 eigenproblem per
/// vertex.
SPECTRALSEG_INLINE Principal_curvatures principal_curvatures(const Dual_graph& graph)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Mesh_geometry& g = graph.geometry();
  const std::size_t nv = g.number_of_vertices();
  std::vector<Eigen::Matrix3d> tensor(nv, Eigen::Matrix3d::Zero());
  std::vector<double> area(nv, 0.);
  std::vector<Eigen::Vector3d> normal(nv, Eigen::Vector3d::Zero());
  for(std::size_t f = 0; f < g.number_of_faces(); ++f)
    for(auto v : g.triangles[f])
    {
      area[v] += g.areas[f];
      normal[v] += g.areas[f] * g.normals[f];
    }
  auto opposite = [&](Dual_graph::size_type f, const Dual_graph::Edge& e) {
    for(auto v : g.triangles[f])
      if(v != e.vertex[0] && v != e.vertex[1])
        return static_cast<std::size_t>(v);
    return nv;
  };
  for(const Dual_graph::Edge& e : graph.edges())
  {
    const Eigen::Vector3d d = g.points[e.vertex[1]] - g.points[e.vertex[0]];
    const double l = d.norm();
    if(!(l > 0.))
      continue;
    const Eigen::Vector3d u = d / l;
    const double beta = e.concave ? -e.normal_angle : e.normal_angle;
    const Eigen::Matrix3d t = (beta * l) * (u * u.transpose());
    tensor[e.vertex[0]] += t;
    tensor[e.vertex[1]] += t;
    for(int side = 0; side < 2; ++side)
    {
      const std::size_t o = opposite(e.face[side], e);
      if(o < nv)
        tensor[o] += 0.5 * t;
    }
  }
  Principal_curvatures c;
  c.minimum.assign(nv, 0.);
  c.maximum.assign(nv, 0.);
  c.minimum_direction.assign(nv, Eigen::Vector3d::Zero());
  c.maximum_direction.assign(nv, Eigen::Vector3d::Zero());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(!(area[v] > 0.) || tensor[v].isZero(0.))
      continue;
    solver.computeDirect(tensor[v] / area[v]);
    const Eigen::Vector3d n = normal[v].normalized();
    int drop = 0;
    double best = -1.;
    for(int i = 0; i < 3; ++i)
    {
      const double a = std::abs(solver.eigenvectors().col(i).dot(n));
      if(a > best)
      {
        best = a;
        drop = i;
      }
    }
    const int i = drop == 0 ? 1 : 0, j = drop == 2 ? 1 : 2; // the two tangent eigenpairs, i < j
    const double li = solver.eigenvalues()(i), lj = solver.eigenvalues()(j); // li <= lj
    // curvature li is along eigenvector j, curvature lj along eigenvector i
    c.minimum[v] = li;
    c.maximum[v] = lj;
    c.minimum_direction[v] = solver.eigenvectors().col(j);
    c.maximum_direction[v] = solver.eigenvectors().col(i);
  }
  return c;
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_PRINCIPAL_CURVATURES_H
