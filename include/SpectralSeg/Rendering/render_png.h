// Copyright (c) SpectralSeg contributors.
//
// Convenience entry points: render a mesh with per-face colours, a per-face
// scalar field or per-face labels from several views side by side, and write
// the picture to a PNG file (link with -lpng).

#ifndef SPECTRALSEG_RENDERING_RENDER_PNG_H
#define SPECTRALSEG_RENDERING_RENDER_PNG_H

#include <SpectralSeg/Rendering/Color_map.h>
#include <SpectralSeg/Rendering/Image.h>
#include <SpectralSeg/Rendering/Software_rasterizer.h>
#include <SpectralSeg/Rendering/write_png.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Rendering {

/// \brief An orthographic view of the mesh.
struct View
{
  std::string name;                ///< label of the view, e.g. "front"
  std::array<double, 3> direction; ///< viewing direction, from the camera into the scene
  std::array<double, 3> up;        ///< world direction shown upwards
};

/// \brief Returns the three default views: front (camera on +Z looking
/// towards -Z), side (camera on +X looking towards -X) and back (camera on
/// -Z looking towards +Z), all with +Y up.
inline std::vector<View> default_views()
{
  return {View{"front", {0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}},
          View{"side", {-1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}},
          View{"back", {0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}}};
}

/// \brief Returns three views chosen from the shape of the mesh: along its
/// thinnest principal axis from either side ("front" and "back", where the
/// mesh shows its largest outline) and from above at an angle between them
/// ("oblique").
///
/// The principal axes are those of the surface (its exact second moments),
/// so they do not depend on the tessellation. An upright body, thin from front
/// to back, is seen as by `default_views()`; a table or a hand lying flat is
/// seen from above and below instead of edge-on. The up vector is the world
/// direction +Y (else +Z, then +X) most perpendicular to the viewing
/// direction, projected onto the picture; axis signs follow the world axes,
/// so the views are deterministic. A mesh without area gets
/// `default_views()`.
/// \param points the vertex positions
/// \param triangles the faces, as indices into `points`
inline std::vector<View> shape_views(const std::vector<std::array<double, 3>>& points,
                                     const std::vector<std::array<std::size_t, 3>>& triangles)
{
  typedef Eigen::Vector3d V;
  double area = 0.;
  V mean = V::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for(const auto& t : triangles)
  {
    if(t[0] >= points.size() || t[1] >= points.size() || t[2] >= points.size())
      continue; // reported by the renderer
    const V a(points[t[0]].data()), b(points[t[1]].data()), c(points[t[2]].data());
    const double w = 0.5 * (b - a).cross(c - a).norm();
    if(!std::isfinite(w) || !(w > 0.))
      continue;
    // the exact first and second moments of the triangle's surface
    const V sum = a + b + c;
    area += w;
    mean += w / 3. * sum;
    second += w / 12. * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  if(!(area > 0.))
    return default_views();
  mean /= area;
  const Eigen::Matrix3d covariance = second / area - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if(solver.info() != Eigen::Success)
    return default_views();
  // ascending eigenvalues: column 0 is the thinnest axis
  V thin = solver.eigenvectors().col(0).normalized();
  // the sign: towards the world's +Z (the camera side of default_views()'s
  // front), else +X, else +Y
  for(int axis : {2, 0, 1})
    if(std::abs(thin[axis]) > 1e-3)
    {
      if(thin[axis] < 0.)
        thin = -thin;
      break;
    }
  // up: the first of the world axes +Y, +Z, +X not within 30 degrees of
  // the viewing direction, made perpendicular to it (at most one axis is
  // that close to a unit vector, so one of the first two always serves)
  V up = V::UnitY() - thin.y() * thin;
  if(up.norm() <= 0.5)
    up = V::UnitZ() - thin.z() * thin;
  up.normalize();
  const V right = (-thin).cross(up); // the picture's right in the front view
  const V oblique = (-thin - up - right).normalized(); // from above, in front, on the right
  const V oblique_up = (up - up.dot(oblique) * oblique).normalized();
  const auto a = [](const V& v) { return std::array<double, 3>{{v.x(), v.y(), v.z()}}; };
  return {View{"front", a(-thin), a(up)}, View{"oblique", a(oblique), a(oblique_up)},
          View{"back", a(thin), a(up)}};
}

/// \brief Options of the convenience renderers.
struct Render_options
{
  int view_width = 480;    ///< width of each view in pixels
  int view_height = 480;   ///< height of each view in pixels
  bool supersample = true; ///< 2x2 supersampling anti-aliasing
  /// views, composed left to right; empty (the default): `shape_views()`
  /// of the mesh drawn, `default_views()` for the world axes
  std::vector<View> views;
};

/// \brief Renders a mesh with one colour per face from every view of
/// `options`, placing the views side by side from left to right.
/// \param points the vertex positions
/// \param triangles the faces, as indices into `points`
/// \param colors one colour per face
/// \param options image size, anti-aliasing and views
/// \return an image of `views.size() * view_width` x `view_height` pixels
///         (3 views when `views` is empty)
/// \throws SpectralSeg::Invalid_input if `colors` does not have one entry per
///         face, an index is out of range, a view direction is zero, or the
///         view size is out of range (see `Software_rasterizer`)
inline Image render_face_colors(const std::vector<std::array<double, 3>>& points,
                                const std::vector<std::array<std::size_t, 3>>& triangles,
                                const std::vector<Rgb>& colors,
                                const Render_options& options = {})
{
  internal::check_mesh(points.size(), triangles, colors.size(), "face colours");
  const std::vector<View> views = options.views.empty() ? shape_views(points, triangles) : options.views;
  const Software_rasterizer rasterizer(options.view_width, options.view_height,
                                       options.supersample);
  const int max_views = std::numeric_limits<int>::max() / options.view_width;
  if(views.size() > static_cast<std::size_t>(max_views))
    throw Invalid_input("render_face_colors: too many views for one image");
  Image picture(static_cast<int>(views.size()) * options.view_width,
                options.view_height);
  for(std::size_t i = 0; i < views.size(); ++i)
  {
    const View& v = views[i];
    picture.paste(rasterizer.render(points, triangles, colors, v.direction, v.up),
                  static_cast<int>(i) * options.view_width, 0);
  }
  return picture;
}

/// \brief Renders a per-face scalar field, coloured with `field_colors()`
/// (blue for the minimum, red for the maximum, grey for non-finite values),
/// and writes it as a PNG file.
/// \param path the output file
/// \param points the vertex positions
/// \param triangles the faces, as indices into `points`
/// \param field one value per face
/// \param options image size, anti-aliasing and views
/// \throws SpectralSeg::Invalid_input as `render_face_colors()`, naming the field
/// \throws SpectralSeg::Io_error if the file cannot be written
inline void render_face_field_png(const std::string& path,
                                  const std::vector<std::array<double, 3>>& points,
                                  const std::vector<std::array<std::size_t, 3>>& triangles,
                                  const std::vector<double>& field,
                                  const Render_options& options = {})
{
  internal::check_mesh(points.size(), triangles, field.size(), "field values");
  write_png(path, render_face_colors(points, triangles, field_colors(field), options));
}

/// \brief Renders per-face integer labels, coloured with `label_colors()`
/// (grey for negative labels), and writes them as a PNG file.
/// \param path the output file
/// \param points the vertex positions
/// \param triangles the faces, as indices into `points`
/// \param labels one label per face
/// \param options image size, anti-aliasing and views
/// \throws SpectralSeg::Invalid_input as `render_face_colors()`, naming the labels
/// \throws SpectralSeg::Io_error if the file cannot be written
inline void render_face_labels_png(const std::string& path,
                                   const std::vector<std::array<double, 3>>& points,
                                   const std::vector<std::array<std::size_t, 3>>& triangles,
                                   const std::vector<int>& labels,
                                   const Render_options& options = {})
{
  internal::check_mesh(points.size(), triangles, labels.size(), "labels");
  write_png(path, render_face_colors(points, triangles, label_colors(labels), options));
}

} // namespace Rendering
} // namespace SpectralSeg

#endif // SPECTRALSEG_RENDERING_RENDER_PNG_H
