// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file AABB_ray_caster.h
/// \brief Ray casting against a mesh with a CGAL AABB tree (the default backend).
#ifndef SPECTRALSEG_RAY_CASTING_AABB_RAY_CASTER_H
#define SPECTRALSEG_RAY_CASTING_AABB_RAY_CASTER_H

#include <SpectralSeg/Mesh_geometry.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Ray_casting {

/// \ingroup PkgSpectralSegRayCasting
/// \brief Casts rays against the triangles of a `Mesh_geometry` with a CGAL
/// AABB tree (`first_intersection()`), in double precision.
///
/// Queries are const and thread-safe once the object is built.
///
/// \cgalModels `RayCaster`
class AABB_ray_caster
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_traits<K, Primitive> Traits;
  typedef CGAL::AABB_tree<Traits> Tree;

public:
  /// face index type
  typedef std::uint32_t size_type;
  /// "no face": pass as `skip` to skip nothing; returned as hit face when nothing is hit
  static constexpr size_type no_face = static_cast<size_type>(-1);

  /// builds the tree over the faces of `geometry` (which need not outlive this object);
  /// degenerate faces are left out
  explicit AABB_ray_caster(const Mesh_geometry& geometry)
  {
    triangles_.reserve(geometry.number_of_faces());
    face_of_triangle_.reserve(geometry.number_of_faces());
    for(std::size_t f = 0; f < geometry.number_of_faces(); ++f)
    {
      if(geometry.degenerate[f])
        continue;
      const auto& t = geometry.triangles[f];
      triangles_.emplace_back(point(geometry.points[t[0]]), point(geometry.points[t[1]]),
                              point(geometry.points[t[2]]));
      face_of_triangle_.push_back(static_cast<size_type>(f));
    }
    tree_.insert(triangles_.cbegin(), triangles_.cend());
    tree_.build();
    diagonal_ = geometry.bbox_diagonal;
  }

  AABB_ray_caster(const AABB_ray_caster&) = delete;
  AABB_ray_caster& operator=(const AABB_ray_caster&) = delete;

  /// the backend's name
  static std::string name() { return "aabb"; }

  /// Distance from `origin` along the unit vector `direction` to the first
  /// face hit, ignoring face `skip`; `+infinity` if the ray hits nothing.
  /// If `hit_face` is not null it receives the face hit (or `no_face`).
  /// With a finite `max_distance`, a ray that hits nothing closer than it may
  /// return `+infinity` early (a cheap segment test runs first); a hit that
  /// is closer is always returned exactly.
  double first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, size_type skip = no_face,
                   size_type* hit_face = nullptr,
                   double max_distance = std::numeric_limits<double>::infinity()) const
  {
    if(hit_face)
      *hit_face = no_face;
    if(triangles_.empty())
      return std::numeric_limits<double>::infinity();
    if(std::isfinite(max_distance))
    {
      // The segment starts a hair away from the origin so that the face the
      // origin lies on (the skipped one) does not count.
      const double offset = 1e-9 * diagonal_;
      if(max_distance <= offset)
        return std::numeric_limits<double>::infinity();
      const K::Segment_3 segment(point(origin + offset * direction), point(origin + max_distance * direction));
      if(!tree_.do_intersect(segment))
        return std::numeric_limits<double>::infinity();
    }
    const K::Point_3 o = point(origin);
    const K::Ray_3 ray(o, K::Vector_3(direction.x(), direction.y(), direction.z()));
    const Iterator skipped = skip == no_face ? triangles_.cend() : triangle_of_face(skip);
    const auto hit = tree_.first_intersection(ray, [skipped](const Iterator& it) { return it == skipped; });
    if(!hit)
      return std::numeric_limits<double>::infinity();
    double t = std::numeric_limits<double>::infinity();
    if(const K::Point_3* p = boost::get<K::Point_3>(&hit->first))
      t = std::sqrt(CGAL::squared_distance(o, *p));
    else if(const K::Segment_3* s = boost::get<K::Segment_3>(&hit->first)) // coplanar ray: nearest end
      t = std::sqrt((std::min)(CGAL::squared_distance(o, s->source()), CGAL::squared_distance(o, s->target())));
    if(hit_face)
      *hit_face = face_of_triangle_[static_cast<std::size_t>(hit->second - triangles_.cbegin())];
    return t;
  }

  /// `first_hit()` for `count` rays from the same origin, skipping the same face
  void first_hits(const Eigen::Vector3d& origin, const Eigen::Vector3d* directions, std::size_t count,
                  size_type skip, double* distances) const
  {
    for(std::size_t i = 0; i < count; ++i)
      distances[i] = first_hit(origin, directions[i], skip);
  }

private:
  static K::Point_3 point(const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); }

  Iterator triangle_of_face(size_type f) const
  {
    // face_of_triangle_ is increasing: binary search
    const auto it = std::lower_bound(face_of_triangle_.begin(), face_of_triangle_.end(), f);
    if(it == face_of_triangle_.end() || *it != f)
      return triangles_.cend();
    return triangles_.cbegin() + (it - face_of_triangle_.begin());
  }

  std::vector<K::Triangle_3> triangles_;
  std::vector<size_type> face_of_triangle_;
  Tree tree_;
  double diagonal_ = 0.;
};

} // namespace Ray_casting
} // namespace SpectralSeg

#endif // SPECTRALSEG_RAY_CASTING_AABB_RAY_CASTER_H
