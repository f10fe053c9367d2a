// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file AABB_ray_caster.h
/// \brief Ray casting against a mesh with a CGAL AABB tree (the default backend).
#ifndef SPECTRALSEG_RAY_CASTING_AABB_RAY_CASTER_H
#define SPECTRALSEG_RAY_CASTING_AABB_RAY_CASTER_H

#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/Ray_casting/internal/near_distance.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <CGAL/version.h>
#include <CGAL/AABB_tree.h>
#if CGAL_VERSION_NR >= 1060000000 // CGAL 6 renamed them (the old names are deprecated)
#include <CGAL/AABB_traits_3.h>
#include <CGAL/AABB_triangle_primitive_3.h>
#else
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#endif
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
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
#if CGAL_VERSION_NR >= 1060000000
  typedef CGAL::AABB_triangle_primitive_3<K, Iterator> Primitive;
  typedef CGAL::AABB_traits_3<K, Primitive> Base_traits;
#else
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_traits<K, Primitive> Base_traits;
#endif

  /// \cond SKIP_IN_MANUAL
  // CGAL's traits, but a node's triangles are split at the median of their
  // centroids along the longest axis of its box, instead of the median of
  // their first vertices (CGAL's reference point): the children's boxes
  // overlap less, and a ray tests fewer boxes and triangles.
  struct Traits : Base_traits
  {
    struct Split_primitives
    {
      template <typename PrimitiveIterator>
      void operator()(PrimitiveIterator first, PrimitiveIterator beyond, const CGAL::Bbox_3& box) const
      {
        const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(), dz = box.zmax() - box.zmin();
        const int axis = dx >= dy ? (dx >= dz ? 0 : 2) : (dy >= dz ? 1 : 2); // CGAL's longest axis
        // three times the centroid's coordinate (the order is the same)
        const auto key = [axis](const Primitive& p) {
          const K::Triangle_3& t = p.datum();
          return t[0][axis] + t[1][axis] + t[2][axis];
        };
        std::nth_element(first, first + (beyond - first) / 2, beyond,
                         [&key](const Primitive& a, const Primitive& b) { return key(a) < key(b); });
      }
    };
    Split_primitives split_primitives_object() const { return Split_primitives(); }
  };
  /// \endcond
  typedef CGAL::AABB_tree<Traits> Tree;

public:
  /// face index type
  typedef std::uint32_t size_type;
  /// "no face": pass as `skip` to skip nothing; returned as hit face when nothing is hit
  static constexpr size_type no_face = static_cast<size_type>(-1);

  /// builds the tree over the faces of `geometry` (which need not outlive this object);
  /// degenerate faces are left out
  explicit AABB_ray_caster(const Mesh_geometry& geometry);

  AABB_ray_caster(const AABB_ray_caster&) = delete;
  AABB_ray_caster& operator=(const AABB_ray_caster&) = delete;

  /// the backend's name
  static std::string name() { return "aabb"; }

  /// Distance from `origin` along the unit vector `direction` to the first
  /// face hit, ignoring face `skip`; `+infinity` if the ray hits nothing.
  /// If `hit_face` is not null it receives the face hit (or `no_face`).
  /// With a finite `max_distance`, only hits at most that far count (the
  /// search skips the boxes beyond it). Hits closer than \f$10^{-7}\f$
  /// times the bounding-box diagonal of the mesh do not count: a ray
  /// leaving a face does not meet the faces at its origin by rounding, and
  /// a ray leaving a flat region does not enter every box that touches its
  /// origin (a fan of a million triangles around one vertex).
  double first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, size_type skip = no_face,
                   size_type* hit_face = nullptr,
                   double max_distance = std::numeric_limits<double>::infinity()) const
  {
    if(hit_face)
      *hit_face = no_face;
    if(triangles_.empty())
      return std::numeric_limits<double>::infinity();
    // One traversal of the tree for the nearest hit within max_distance,
    // nearer boxes first: a node is entered only when the ray's stretch up
    // to the nearest hit so far crosses its box (slab test), and each
    // triangle is intersected with Moller-Trumbore.
    Nearest_hit query(origin, direction, near_, max_distance,
                      skip == no_face ? triangles_.cend() : triangle_of_face(skip));
    tree_.traversal_with_priority(query, query);
    if(!query.found)
      return std::numeric_limits<double>::infinity();
    if(hit_face)
      *hit_face = face_of_triangle_[static_cast<std::size_t>(query.hit - triangles_.cbegin())];
    return query.t;
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

  // The query and the traversal traits of CGAL's AABB_tree::traversal() at
  // once: the nearest triangle hit by a ray, within a distance.
  struct Nearest_hit
  {
    double o[3], d[3], inv[3];
    int lower[3]; // per axis, the Bbox_3 coordinate (min: 0, max: 3) the ray enters the slab by
    double near;  // hits closer than this do not count
    double t;     // the nearest hit so far, or the bound
    bool found = false;
    Iterator hit, skip;

    Nearest_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double near_distance,
                double max_distance, Iterator skipped)
      : near(near_distance), t(max_distance), skip(skipped)
    {
      for(int i = 0; i < 3; ++i)
      {
        o[i] = origin[i];
        d[i] = direction[i];
        inv[i] = 1. / direction[i];
        lower[i] = inv[i] < 0. ? 3 : 0;
      }
    }

    bool go_further() const { return true; }

    typedef double Priority;

    // where the ray's stretch [near, t] enters the box, or -1 if it misses it
    double entry(const CGAL::Bbox_3& b) const
    {
      // The slab's near and far planes chosen by the sign of the direction,
      // so that no swap is needed: the same values as ordering the two. A
      // zero component gives an infinite inverse, and 0 * inf = NaN where
      // the origin lies on the slab's plane; std::max and std::min return
      // their first argument when the second is NaN, so such a slab bounds
      // nothing, as the origin is inside it.
      const double box[6] = {b.xmin(), b.ymin(), b.zmin(), b.xmax(), b.ymax(), b.zmax()};
      double lo = near, hi = t;
      for(int i = 0; i < 3; ++i)
      {
        const double a = (box[lower[i] + i] - o[i]) * inv[i];
        const double c = (box[3 - lower[i] + i] - o[i]) * inv[i];
        lo = (std::max)(lo, a);
        hi = (std::min)(hi, c);
      }
      return lo <= hi ? lo : -1.;
    }
    template <typename Node>
    bool do_intersect(const Nearest_hit&, const Node& node) const
    {
      return entry(node.bbox()) >= 0.;
    }

    // nearer boxes first
    template <typename Node>
    std::pair<bool, Priority> do_intersect_with_priority(const Nearest_hit&, const Node& node) const
    {
      const double e = entry(node.bbox());
      return std::make_pair(e >= 0., -e);
    }

    void intersection(const Nearest_hit&, const Primitive& primitive)
    {
      const Iterator it = primitive.id();
      if(it == skip)
        return;
      const K::Triangle_3& tri = *it;
      const K::Point_3 &p0 = tri[0], &p1 = tri[1], &p2 = tri[2];
      const double e1[3] = {p1.x() - p0.x(), p1.y() - p0.y(), p1.z() - p0.z()};
      const double e2[3] = {p2.x() - p0.x(), p2.y() - p0.y(), p2.z() - p0.z()};
      const double pv[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
      const double det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
      if(det == 0.)
        return; // parallel to the triangle's plane
      const double f = 1. / det;
      const double s[3] = {o[0] - p0.x(), o[1] - p0.y(), o[2] - p0.z()};
      const double u = f * (s[0] * pv[0] + s[1] * pv[1] + s[2] * pv[2]);
      if(u < 0. || u > 1.)
        return;
      const double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
      const double v = f * (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]);
      if(v < 0. || u + v > 1.)
        return;
      const double h = f * (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]);
      if(h >= near && h <= t && (!found || h < t || it < hit))
      {
        t = h;
        hit = it;
        found = true;
      }
    }
  };

  Iterator triangle_of_face(size_type f) const
  {
    // a table, not a search: it is asked once per ray
    if(f >= triangle_of_face_.size() || triangle_of_face_[f] == no_face)
      return triangles_.cend();
    return triangles_.cbegin() + static_cast<std::ptrdiff_t>(triangle_of_face_[f]);
  }

  std::vector<K::Triangle_3> triangles_;
  std::vector<size_type> face_of_triangle_;
  std::vector<size_type> triangle_of_face_; // no_face for a degenerate face
  Tree tree_;
  double near_ = 0.; // hits closer than this do not count
};

#if SPECTRALSEG_DEFINE_FUNCTIONS
SPECTRALSEG_INLINE AABB_ray_caster::AABB_ray_caster(const Mesh_geometry& geometry)
{
  triangles_.reserve(geometry.number_of_faces());
  face_of_triangle_.reserve(geometry.number_of_faces());
  triangle_of_face_.assign(geometry.number_of_faces(), no_face);
  for(std::size_t f = 0; f < geometry.number_of_faces(); ++f)
  {
    if(geometry.degenerate[f])
      continue;
    triangle_of_face_[f] = static_cast<size_type>(triangles_.size());
    const auto& t = geometry.triangles[f];
    triangles_.emplace_back(point(geometry.points[t[0]]), point(geometry.points[t[1]]),
                            point(geometry.points[t[2]]));
    face_of_triangle_.push_back(static_cast<size_type>(f));
  }
  tree_.insert(triangles_.cbegin(), triangles_.cend());
  tree_.build();
  near_ = internal::near_distance_fraction * geometry.bbox_diagonal;
}
#endif

} // namespace Ray_casting
} // namespace SpectralSeg

#endif // SPECTRALSEG_RAY_CASTING_AABB_RAY_CASTER_H
