// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Embree_ray_caster.h
/// \brief Ray casting against a mesh with Intel Embree 3 (optional backend,
/// available when `SPECTRALSEG_HAS_EMBREE` is defined).
#ifndef SPECTRALSEG_RAY_CASTING_EMBREE_RAY_CASTER_H
#define SPECTRALSEG_RAY_CASTING_EMBREE_RAY_CASTER_H

#ifdef SPECTRALSEG_HAS_EMBREE

#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/Ray_casting/internal/near_distance.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <embree3/rtcore.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace SpectralSeg {
namespace Ray_casting {

/// \ingroup PkgSpectralSegRayCasting
/// \brief Casts rays against the triangles of a `Mesh_geometry` with Intel
/// Embree 3, in single precision.
///
/// Only available when `SPECTRALSEG_HAS_EMBREE` is defined (the CMake target
/// `SpectralSeg::SpectralSeg` defines it and links Embree when Embree 3 is
/// found).
///
/// - **Precision.** Embree works in `float`. The mesh is translated so that
///   the centre of its bounding box is at the origin before its coordinates
///   are rounded to `float`, and ray origins are translated the same way, so
///   that the precision does not depend on where the mesh lies in space.
///   Distances agree with `AABB_ray_caster`'s to within \f$10^{-4}\f$
///   relative or a few \f$10^{-6}\f$ times the bounding-box diagonal; when
///   a ray passes through a shared edge or vertex the two backends may
///   report different (adjacent) faces at the same distance.
/// - **Robustness.** The scene is built with `RTC_SCENE_FLAG_ROBUST` (a
///   watertight triangle test: a ray through a shared edge hits one of the
///   two faces, it never passes between them) and `RTC_BUILD_QUALITY_HIGH`.
/// - **Skipped face.** The face `skip` is left out exactly, by an
///   intersection filter passed through the intersect context
///   (`RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION`; the context is extended with
///   the primitive to skip and lives on the stack of each query), not by
///   moving the start of the ray.
/// - **Ray start.** As in `AABB_ray_caster`, hits closer than \f$10^{-7}\f$
///   times the bounding-box diagonal of the mesh are not counted (Embree's
///   `tnear`): a ray leaving a face does not meet the faces at its origin
///   by rounding, and a ray leaving a flat region does not enter every box
///   that touches its origin (a fan of a million triangles around one
///   vertex: minutes per hundred rays without it). Pass the face the origin
///   lies on as `skip`.
/// - Degenerate faces (`Mesh_geometry::degenerate`) are left out, as in
///   `AABB_ray_caster`.
///
/// Queries are const and thread-safe once the object is built. The object
/// owns its Embree device and scene and releases them when destroyed.
///
/// \cgalModels `RayCaster`
class Embree_ray_caster
{
public:
  /// face index type
  typedef std::uint32_t size_type;
  /// "no face": pass as `skip` to skip nothing; returned as hit face when nothing is hit
  static constexpr size_type no_face = static_cast<size_type>(-1);

  /// Builds an Embree scene over the faces of `geometry` (which need not
  /// outlive this object); degenerate faces are left out.
  ///
  /// \throws Error if Embree cannot create its device or fails to build the
  /// scene (out of memory, unsupported CPU, ...); the message gives Embree's
  /// error code and text.
  explicit Embree_ray_caster(const Mesh_geometry& geometry);

  /// not copyable: the object owns its Embree device and scene
  Embree_ray_caster(const Embree_ray_caster&) = delete;
  /// not copyable: the object owns its Embree device and scene
  Embree_ray_caster& operator=(const Embree_ray_caster&) = delete;

  /// releases the Embree scene and device
  ~Embree_ray_caster() = default;

  /// the backend's name
  static std::string name() { return "embree"; }

  /// Distance from `origin` along the unit vector `direction` to the first
  /// face hit, ignoring face `skip`; `+infinity` if the ray hits nothing
  /// (or if `origin` or `direction` is not finite, or `direction` is zero).
  /// If `hit_face` is not null it receives the face hit (or `no_face`).
  double first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, size_type skip = no_face,
                   size_type* hit_face = nullptr,
                   double max_distance = std::numeric_limits<double>::infinity()) const
  {
    if(hit_face)
      *hit_face = no_face;
    Skip_context context;
    init_context(context, skip);
    RTCRayHit rayhit;
    const Eigen::Vector3f o = (origin - centre_).cast<float>();
    const Eigen::Vector3f d = direction.cast<float>();
    if(!valid_ray(o, d))
      return std::numeric_limits<double>::infinity();
    RTCRay& ray = rayhit.ray;
    ray.org_x = o.x();
    ray.org_y = o.y();
    ray.org_z = o.z();
    ray.tnear = tnear_;
    ray.dir_x = d.x();
    ray.dir_y = d.y();
    ray.dir_z = d.z();
    ray.time = 0.f;
    ray.tfar = std::isfinite(max_distance) ? float(max_distance / double(d.norm())) * (1.f + 1e-6f)
                                           : std::numeric_limits<float>::infinity();
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_.get(), &context.base, &rayhit);
    if(rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID)
      return std::numeric_limits<double>::infinity();
    if(hit_face)
      *hit_face = face_of_primitive_[rayhit.hit.primID];
    return double(ray.tfar) * double(d.norm());
  }

  /// `first_hit()` for `count` rays from the same origin, skipping the same
  /// face: `distances[i]` is the distance along `directions[i]`. The rays
  /// are traced in packets of 8 (`rtcIntersect8`), which saves per-call
  /// overhead; the results are exactly those of `first_hit()`.
  void first_hits(const Eigen::Vector3d& origin, const Eigen::Vector3d* directions, std::size_t count,
                  size_type skip, double* distances) const
  {
    Skip_context context;
    init_context(context, skip);
    const Eigen::Vector3f o = (origin - centre_).cast<float>();
    const bool origin_ok = o.allFinite();
    RTCRayHit8 packet;
    alignas(32) int valid[8];
    float scale[8];
    for(std::size_t start = 0; start < count; start += 8)
    {
      const std::size_t n = std::min<std::size_t>(8, count - start);
      bool any = false;
      for(std::size_t i = 0; i < 8; ++i)
      {
        const Eigen::Vector3f d =
          i < n ? directions[start + i].cast<float>() : Eigen::Vector3f(0.f, 0.f, 1.f);
        valid[i] = i < n && origin_ok && valid_ray(o, d) ? -1 : 0;
        any = any || valid[i] != 0;
        scale[i] = d.norm();
        packet.ray.org_x[i] = o.x();
        packet.ray.org_y[i] = o.y();
        packet.ray.org_z[i] = o.z();
        packet.ray.tnear[i] = tnear_;
        packet.ray.dir_x[i] = d.x();
        packet.ray.dir_y[i] = d.y();
        packet.ray.dir_z[i] = d.z();
        packet.ray.time[i] = 0.f;
        packet.ray.tfar[i] = std::numeric_limits<float>::infinity();
        packet.ray.mask[i] = 0xFFFFFFFFu;
        packet.ray.id[i] = static_cast<unsigned>(i);
        packet.ray.flags[i] = 0;
        packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
      }
      if(any)
        rtcIntersect8(valid, scene_.get(), &context.base, &packet);
      for(std::size_t i = 0; i < n; ++i)
        distances[start + i] = valid[i] != 0 && packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID
                                 ? double(packet.ray.tfar[i]) * double(scale[i])
                                 : std::numeric_limits<double>::infinity();
    }
  }

private:
  // Intersect context extended with the primitive to skip. Standard layout
  // with the Embree context first, so that the filter can cast back.
  struct Skip_context
  {
    RTCIntersectContext base;
    unsigned skip_primitive;
  };
  static_assert(std::is_standard_layout<Skip_context>::value, "the filter casts the context back");

  // Context filter: rejects candidate hits on the skipped primitive.
  static void skip_filter(const RTCFilterFunctionNArguments* args)
  {
    const Skip_context* context = reinterpret_cast<const Skip_context*>(args->context);
    for(unsigned i = 0; i < args->N; ++i)
      if(args->valid[i] != 0 && RTCHitN_primID(args->hit, args->N, i) == context->skip_primitive)
        args->valid[i] = 0;
  }

  void init_context(Skip_context& context, size_type skip) const
  {
    rtcInitIntersectContext(&context.base);
    context.skip_primitive = RTC_INVALID_GEOMETRY_ID;
    if(skip == no_face)
      return;
    if(std::size_t(skip) >= primitive_of_face_.size() || primitive_of_face_[skip] == RTC_INVALID_GEOMETRY_ID)
      return; // degenerate or out of range: nothing to skip
    context.skip_primitive = primitive_of_face_[skip];
    context.base.filter = &Embree_ray_caster::skip_filter;
  }

  static bool valid_ray(const Eigen::Vector3f& o, const Eigen::Vector3f& d)
  {
    return o.allFinite() && d.allFinite() && d.squaredNorm() > 0.f;
  }

  struct Error_log
  {
    std::string message;
  };

  static void record_error(void* user, RTCError, const char* message)
  {
    Error_log* log = static_cast<Error_log*>(user);
    if(log && log->message.empty() && message)
      log->message = message;
  }

  static std::string error_text(RTCError error);

  struct Device_release
  {
    void operator()(std::remove_pointer_t<RTCDevice>* device) const { rtcReleaseDevice(device); }
  };
  struct Scene_release
  {
    void operator()(std::remove_pointer_t<RTCScene>* scene) const { rtcReleaseScene(scene); }
  };
  struct Geometry_release
  {
    void operator()(std::remove_pointer_t<RTCGeometry>* geometry) const { rtcReleaseGeometry(geometry); }
  };
  typedef std::unique_ptr<std::remove_pointer_t<RTCGeometry>, Geometry_release> Geometry_handle;

  // Declared in this order so that the scene is released before the device.
  std::unique_ptr<std::remove_pointer_t<RTCDevice>, Device_release> device_;
  std::unique_ptr<std::remove_pointer_t<RTCScene>, Scene_release> scene_;
  std::vector<size_type> face_of_primitive_; // primID -> face index
  std::vector<unsigned> primitive_of_face_;  // face index -> primID (RTC_INVALID_GEOMETRY_ID: degenerate)
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();
  float tnear_ = 0.f;
};

#if SPECTRALSEG_DEFINE_FUNCTIONS
SPECTRALSEG_INLINE Embree_ray_caster::Embree_ray_caster(const Mesh_geometry& geometry)
{
  device_.reset(rtcNewDevice(nullptr));
  if(!device_)
    throw Error("Embree_ray_caster: cannot create an Embree device (" +
                error_text(rtcGetDeviceError(nullptr)) + ")");
  // Collect Embree's error messages while building (queries report none).
  Error_log log;
  rtcSetDeviceErrorFunction(device_.get(), &Embree_ray_caster::record_error, &log);

  // The triangles kept, and the centre of their bounding box.
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * geometry.number_of_faces());
  face_of_primitive_.reserve(geometry.number_of_faces());
  primitive_of_face_.assign(geometry.number_of_faces(), RTC_INVALID_GEOMETRY_ID);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for(std::size_t f = 0; f < geometry.number_of_faces(); ++f)
  {
    if(geometry.degenerate[f])
      continue;
    for(std::uint32_t v : geometry.triangles[f])
    {
      indices.push_back(v);
      lo = lo.cwiseMin(geometry.points[v]);
      hi = hi.cwiseMax(geometry.points[v]);
    }
    primitive_of_face_[f] = static_cast<unsigned>(face_of_primitive_.size());
    face_of_primitive_.push_back(static_cast<size_type>(f));
  }
  if(!face_of_primitive_.empty())
  {
    centre_ = 0.5 * (lo + hi);
    tnear_ = float(internal::near_distance_fraction * geometry.bbox_diagonal);
  }

  scene_.reset(rtcNewScene(device_.get()));
  bool triangles_attached = face_of_primitive_.empty();
  if(scene_ && !face_of_primitive_.empty())
  {
    Geometry_handle mesh(rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE));
    if(mesh)
    {
      // Embree pads buffers it allocates itself as its vector loads need.
      float* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        mesh.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), geometry.points.size()));
      unsigned* triangles = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        mesh.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), face_of_primitive_.size()));
      if(vertices && triangles)
      {
        for(std::size_t v = 0; v < geometry.points.size(); ++v)
        {
          const Eigen::Vector3d p = geometry.points[v] - centre_;
          vertices[3 * v + 0] = static_cast<float>(p.x());
          vertices[3 * v + 1] = static_cast<float>(p.y());
          vertices[3 * v + 2] = static_cast<float>(p.z());
        }
        std::copy(indices.begin(), indices.end(), triangles);
        rtcSetGeometryBuildQuality(mesh.get(), RTC_BUILD_QUALITY_HIGH);
        rtcCommitGeometry(mesh.get());
        rtcAttachGeometry(scene_.get(), mesh.get());
        triangles_attached = true;
      }
    }
  }
  if(scene_)
  {
    rtcSetSceneFlags(scene_.get(), RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_HIGH);
    rtcCommitScene(scene_.get());
  }
  const RTCError error = rtcGetDeviceError(device_.get());
  rtcSetDeviceErrorFunction(device_.get(), nullptr, nullptr);
  if(error != RTC_ERROR_NONE || !scene_ || !triangles_attached)
    throw Error("Embree_ray_caster: Embree failed to build the scene of " +
                std::to_string(face_of_primitive_.size()) + " triangles (" +
                error_text(error == RTC_ERROR_NONE ? RTC_ERROR_UNKNOWN : error) +
                (log.message.empty() ? std::string() : ": " + log.message) + ")");
}

SPECTRALSEG_INLINE std::string Embree_ray_caster::error_text(RTCError error)
{
  switch(error)
  {
  case RTC_ERROR_NONE: return "no error";
  case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
  case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
  case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
  case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
  case RTC_ERROR_CANCELLED: return "cancelled";
  default: return "unknown error";
  }
}
#endif

} // namespace Ray_casting
} // namespace SpectralSeg

#endif // SPECTRALSEG_HAS_EMBREE

#endif // SPECTRALSEG_RAY_CASTING_EMBREE_RAY_CASTER_H
