// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Documentation only: this file describes a concept. It is read by Doxygen and
// never included by code.

/// \ingroup PkgSpectralSegConcepts
/// \cgalConcept
///
/// \brief A ray-casting backend: finds where rays leave from a point and
/// first meet the triangles of a mesh.
///
/// The VSI metric (`SpectralSeg::Metrics::VSI_weight`, and through it
/// `SpectralSeg::Metrics::Part_aware_weight`) takes its backend as a template
/// parameter and builds one object per mesh; the stages of the metric
/// (`SpectralSeg::Metrics::VSI::compute_reference_points()`,
/// `SpectralSeg::Metrics::VSI::compute_shape_images()`) only ask it for
/// first hits.
///
/// Requirements on the model:
/// - *built once per mesh*: the constructor takes the mesh's
///   `SpectralSeg::Mesh_geometry` and prepares its acceleration structure;
///   the geometry need not outlive the object. Faces marked
///   `Mesh_geometry::degenerate` may be left out (both provided models do);
/// - *const and thread-safe queries*: `first_hit()` and `first_hits()` are
///   `const` and are called from several threads at once on the same object;
/// - *faces are numbered as in the geometry*: the face `f` of a hit is the
///   face `f` of the `Mesh_geometry`;
/// - the model need not be copyable (the provided ones are not).
///
/// \cgalHasModel
/// - `SpectralSeg::Ray_casting::AABB_ray_caster` (the default, CGAL AABB tree, double precision)
/// - `SpectralSeg::Ray_casting::Embree_ray_caster` (Intel Embree 3, single precision;
///   only when `SPECTRALSEG_HAS_EMBREE` is defined)
class RayCaster
{
public:
  /// An unsigned integer type for face indices.
  typedef unspecified_type size_type;

  /// The value meaning "no face": passed as `skip` to skip nothing, and
  /// stored in `*hit_face` when the ray hits nothing.
  static const size_type no_face;

  /// Builds the backend's structure over the triangles of `geometry`.
  explicit RayCaster(const SpectralSeg::Mesh_geometry& geometry);

  /// A short name of the backend, e.g. `"aabb"` or `"embree"`.
  std::string name() const;

  /// Returns the distance from `origin` along `direction` to the first
  /// triangle the ray meets, leaving out the face `skip`, or `+infinity`
  /// if the ray meets nothing.
  ///
  /// \param origin the start of the ray
  /// \param direction a unit vector
  /// \param skip a face to ignore, typically the face the origin lies on
  ///        (`no_face`: ignore nothing)
  /// \param hit_face if not null, receives the face hit, or `no_face`
  /// Hits closer to `origin` than \f$10^{-7}\f$ times the bounding-box
  /// diagonal of the mesh may be left out (both provided models leave them
  /// out, so that a ray leaving a flat region does not enter every box that
  /// touches its origin).
  ///
  /// \param max_distance the caller only needs hits closer than this: a ray
  ///        that meets nothing closer may return `+infinity` early, but a
  ///        closer hit must be returned exactly (default `+infinity`: no
  ///        bound)
  double first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, size_type skip = no_face,
                   size_type* hit_face = nullptr,
                   double max_distance = std::numeric_limits<double>::infinity()) const;

  /// `first_hit()` for `count` rays from the same `origin`, all ignoring the
  /// same face: `distances[i]` receives the distance along `directions[i]`
  /// (`+infinity` for a miss). A backend may trace the rays together
  /// (Embree uses packets of 8); the results must equal those of
  /// `first_hit()`.
  void first_hits(const Eigen::Vector3d& origin, const Eigen::Vector3d* directions, std::size_t count,
                  size_type skip, double* distances) const;
};
