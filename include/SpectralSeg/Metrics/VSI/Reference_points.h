// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Reference_points.h
/// \brief Reference points of the faces inside the shape (thesis 3.4.2).
#ifndef SPECTRALSEG_METRICS_VSI_REFERENCE_POINTS_H
#define SPECTRALSEG_METRICS_VSI_REFERENCE_POINTS_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/Metrics/VSI/ray_directions.h>
#include <SpectralSeg/Metrics/VSI/spread_samples.h>
#include <SpectralSeg/internal/Point_neighbours.h>
#include <SpectralSeg/internal/parallel_for.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace SpectralSeg {
/// \cond SKIP_IN_MANUAL
namespace internal {

// Gives each face that is not `known` (and is `fillable`) the mean of
// `value` over its known neighbours that are `usable`, layer after layer
// over the dual graph until no face changes: `set(f, mean)` for each, after
// the whole layer is read.
template <typename T, typename Fillable, typename Usable, typename Set>
void fill_from_neighbours(const Dual_graph& graph, std::vector<std::uint8_t> known, const std::vector<T>& value,
                          const T& zero, Fillable fillable, Usable usable, Set set)
{
  bool changed = true;
  while(changed)
  {
    changed = false;
    std::vector<std::pair<std::size_t, T>> filled;
    for(std::size_t f = 0; f < known.size(); ++f)
    {
      if(known[f] || !fillable(f))
        continue;
      T sum = zero;
      int count = 0;
      graph.for_each_neighbour(static_cast<Dual_graph::size_type>(f), [&](Dual_graph::size_type g, Dual_graph::size_type) {
        if(known[g] && usable(std::size_t(g)))
        {
          sum += value[g];
          ++count;
        }
      });
      if(count > 0)
        filled.emplace_back(f, sum / count);
    }
    for(const auto& p : filled)
    {
      set(p.first, p.second);
      known[p.first] = 1;
      changed = true;
    }
  }
}

} // namespace internal
/// \endcond

namespace Metrics {
namespace VSI {

/// \ingroup PkgSpectralSegVSI
/// \brief Parameters of the reference-point construction. The defaults of
/// the ray cone are the thesis's; the smoothing ones are ours (the thesis
/// does not give them).
struct Reference_point_options
{
  /// rays cast into the shape from each face centroid (one along the inward normal)
  std::size_t rays = 16;
  /// full opening angle of the cone of rays, in degrees
  double cone_angle_degrees = 80.;
  /// fraction of the faces that cast their cone, spread over the shape
  /// (`spread_samples()` on the centroids); the others take their
  /// neighbours' mean diameter along their own normal (1: every face, the
  /// thesis's construction, up to `max_measured_faces`; doc/benchmarks.md
  /// has 0.25 measured)
  double measured_fraction = 1.;
  /// at most this many faces cast their cone (0: no limit, every face as in
  /// the thesis); on a larger mesh that many faces, spread over the shape,
  /// cast it and the others are filled in as with `measured_fraction`
  /// (whichever of the two leaves fewer faces casting applies). The
  /// inscribed sphere changes over the shape's thickness, not over its
  /// triangles, so a finer mesh adds rays but no information; the limit
  /// keeps the cost of the rays bounded (doc/benchmarks.md has it measured)
  std::size_t max_measured_faces = 100000;
  /// Laplacian smoothing iterations over the neighbourhood graph (0: none)
  std::size_t smoothing_iterations = 3;
  /// how far each iteration moves a point towards its neighbours' mean, in (0, 1]
  double smoothing_step = 0.5;
  /// Euclidean nearest neighbours of a reference point added to its face
  /// neighbours in the neighbourhood graph
  std::size_t euclidean_neighbours = 6;
};

/// \ingroup PkgSpectralSegVSI
/// \brief The reference points of all faces.
struct Reference_points
{
  /// one point per face, inside the shape
  std::vector<Eigen::Vector3d> points;
  /// estimated diameter \f$d_i\f$ of the inscribed sphere touching each face
  /// (`NaN` where no cone ray hit the surface)
  std::vector<double> diameters;
  /// 1 where the face's own rays gave its point; 0 where it was filled in
  /// from neighbours (no cone ray hit: open meshes)
  std::vector<std::uint8_t> measured;
  /// number of points that left the shape during smoothing and were moved
  /// to a neighbour's point
  std::size_t relocated = 0;
};

/// \ingroup PkgSpectralSegVSI
/// \brief Computes a reference point inside the shape for every face.
///
/// From the centroid \f$c_i\f$ of face \f$i\f$, `rays` rays are cast into a
/// cone around the inward normal \f$-n_i\f$. A ray at angle \f$\theta_j\f$
/// to the normal that travels \f$\ell_j\f$ inside the shape estimates the
/// diameter of the inscribed sphere touching \f$c_i\f$ as
/// \f$\ell_j / \cos\theta_j\f$; the smallest estimate \f$d_i\f$ gives the
/// sphere's centre \f$r_i = c_i - \tfrac12 d_i n_i\f$. The points are then
/// smoothed (Jacobi Laplacian steps) over a graph joining each face to its
/// mesh neighbours and to the faces whose points are its nearest Euclidean
/// neighbours. A point whose smoothing path crosses the surface is moved to
/// the nearest neighbouring point that did not.
///
/// With `options.measured_fraction` below 1, or more faces than
/// `options.max_measured_faces`, only that fraction or that many of the
/// faces, spread over the shape, cast their cone (a quarter of the rays at
/// 0.25); each other face takes the mean diameter of its neighbours that
/// have one, propagated over the dual graph, and its point lies at half
/// that depth along its own inward normal.
///
/// Faces none of whose rays hit anything (open meshes) take the mean of
/// their neighbours' points, propagated over the dual graph; a component
/// without any hit keeps its centroids.
///
/// \throws Invalid_input if `options.measured_fraction` is not in (0, 1]
///
/// \tparam RayCaster a model of `RayCaster`
///
/// Deterministic and independent of the number of threads.
template <typename RayCaster>
Reference_points compute_reference_points(const Dual_graph& graph, const RayCaster& caster,
                                          const Reference_point_options& options = Reference_point_options(),
                                          const Execution& exec = Execution())
{
  if(!(options.measured_fraction > 0. && options.measured_fraction <= 1.))
    throw Invalid_input("reference points: the fraction of faces that cast rays must be in (0, 1]");
  const Mesh_geometry& geo = graph.geometry();
  const std::size_t n = geo.number_of_faces();
  const double pi = CGAL_PI;
  Reference_points out;
  out.points.resize(n);
  out.diameters.assign(n, std::numeric_limits<double>::quiet_NaN());
  out.measured.assign(n, 0);

  const std::vector<Eigen::Vector3d> cone =
    cone_directions(options.rays, options.cone_angle_degrees * pi / 180.);
  std::size_t casting =
    options.measured_fraction < 1. ? std::size_t(std::ceil(options.measured_fraction * double(n))) : n;
  if(options.max_measured_faces > 0)
    casting = std::min(casting, options.max_measured_faces);
  const bool every_face = casting >= n;
  std::vector<std::uint8_t> casts(n, 1);
  if(!every_face)
  {
    casts.assign(n, 0);
    for(std::uint32_t f : spread_samples(geo.centroids, casting))
      casts[f] = 1;
  }
  internal::parallel_for(n, exec, "reference points", [&](std::size_t f) {
    const Eigen::Vector3d& normal = geo.normals[f];
    out.points[f] = geo.centroids[f];
    if(!casts[f] || normal.squaredNorm() < 0.5)
      return;
    thread_local std::vector<Eigen::Vector3d> dirs; // no allocation per face
    rotate_to(-normal, cone, dirs);
    // A ray at angle theta can only lower the estimate d if it hits closer
    // than d cos(theta): later rays are cast with that bound.
    const auto skip = static_cast<typename RayCaster::size_type>(f);
    double d = std::numeric_limits<double>::infinity();
    for(std::size_t j = 0; j < dirs.size(); ++j)
    {
      const double t = caster.first_hit(geo.centroids[f], dirs[j], skip, nullptr, d * cone[j].z());
      if(std::isfinite(t))
        d = std::min(d, t / cone[j].z()); // cone[j].z() = cos(theta_j)
    }
    if(std::isfinite(d))
    {
      out.diameters[f] = d;
      out.points[f] = geo.centroids[f] - 0.5 * d * normal;
      out.measured[f] = 1;
    }
  });

  // Faces that did not cast their cone: the mean inscribed-sphere diameter
  // of their neighbours that did (or got one), along their own normal.
  if(!every_face)
    internal::fill_from_neighbours(
      graph, casts, out.diameters, 0.,
      [&](std::size_t f) { return geo.normals[f].squaredNorm() >= 0.5; },
      [&](std::size_t g) { return std::isfinite(out.diameters[g]); },
      [&](std::size_t f, double d) {
        out.diameters[f] = d;
        out.points[f] = geo.centroids[f] - 0.5 * d * geo.normals[f];
        out.measured[f] = 1;
      });

  // Faces without a hit: the mean of their measured neighbours' points.
  internal::fill_from_neighbours(
    graph, out.measured, out.points, Eigen::Vector3d::Zero().eval(), [](std::size_t) { return true; },
    [](std::size_t) { return true; }, [&](std::size_t f, const Eigen::Vector3d& p) { out.points[f] = p; });

  if(options.smoothing_iterations == 0 || n < 2)
    return out;

  // Neighbourhood graph: mesh neighbours plus Euclidean neighbours of the
  // points, face f's ascending in nb[first[f]], ..., nb[first[f] + count[f]
  // - 1] (one array for all, room for each face's own degree plus the
  // searched neighbours: no allocation per face).
  const std::size_t searched = options.euclidean_neighbours + 1;
  std::vector<std::size_t> first(n + 1, 0);
  for(std::size_t f = 0; f < n; ++f)
    first[f + 1] = first[f] + graph.degree(static_cast<Dual_graph::size_type>(f)) + searched;
  // not zeroed: each face's list is written by the loop below before it is
  // read, on every thread, which also touches the pages first
  const std::unique_ptr<std::uint32_t[]> nb(new std::uint32_t[first[n]]);
  std::vector<std::uint32_t> count(n, 0);
  {
    const internal::Point_neighbours knn(out.points);
    internal::parallel_for(n, exec, "reference point neighbours", [&](std::size_t f) {
      thread_local std::vector<std::pair<std::size_t, double>> nearest;
      std::uint32_t* list = nb.get() + first[f];
      std::size_t size = 0;
      graph.for_each_neighbour(static_cast<Dual_graph::size_type>(f),
                               [&](Dual_graph::size_type g, Dual_graph::size_type) { list[size++] = g; });
      knn.nearest(out.points[f], searched, nearest);
      for(const auto& q : nearest)
        if(q.first != f)
          list[size++] = static_cast<std::uint32_t>(q.first);
      std::sort(list, list + size);
      count[f] = static_cast<std::uint32_t>(std::unique(list, list + size) - list);
    });
  }

  const std::vector<Eigen::Vector3d> start = out.points;
  std::vector<Eigen::Vector3d> next(n);
  for(std::size_t it = 0; it < options.smoothing_iterations; ++it)
  {
    internal::parallel_range(0, n, exec.threads(), [&](std::size_t f) {
      if(count[f] == 0)
      {
        next[f] = out.points[f];
        return;
      }
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for(std::size_t i = 0; i < count[f]; ++i)
        mean += out.points[nb[first[f] + i]];
      mean /= double(count[f]);
      next[f] = (1. - options.smoothing_step) * out.points[f] + options.smoothing_step * mean;
    });
    out.points.swap(next);
  }

  // Points whose smoothing path crosses the surface left the shape.
  std::vector<std::uint8_t> inside(n, 1);
  internal::parallel_for(n, exec, "reference point check", [&](std::size_t f) {
    if(!out.measured[f])
      return;
    const Eigen::Vector3d step = out.points[f] - start[f];
    const double len = step.norm();
    if(len > 0 && caster.first_hit(start[f], step / len) < len)
      inside[f] = 0;
  });
  // each point that left moves to its nearest neighbour still inside, or
  // back to its start; chosen among the points before any move
  std::vector<std::pair<std::size_t, Eigen::Vector3d>> moves;
  for(std::size_t f = 0; f < n; ++f)
  {
    if(inside[f])
      continue;
    ++out.relocated;
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector3d to = start[f]; // fallback: the unsmoothed point, inside by construction
    for(std::size_t i = 0; i < count[f]; ++i)
    {
      const std::uint32_t g = nb[first[f] + i];
      const double d2 = (out.points[g] - out.points[f]).squaredNorm();
      if(inside[g] && d2 < best)
      {
        best = d2;
        to = out.points[g];
      }
    }
    moves.emplace_back(f, to);
  }
  for(const auto& m : moves)
    out.points[m.first] = m.second;
  return out;
}

} // namespace VSI
} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_VSI_REFERENCE_POINTS_H
