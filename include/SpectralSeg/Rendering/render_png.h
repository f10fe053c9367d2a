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

#include <array>
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

/// \brief Options of the convenience renderers.
struct Render_options
{
  int view_width = 480;                      ///< width of each view in pixels
  int view_height = 480;                     ///< height of each view in pixels
  bool supersample = true;                   ///< 2x2 supersampling anti-aliasing
  std::vector<View> views = default_views(); ///< views, composed left to right
};

/// \brief Renders a mesh with one colour per face from every view of
/// `options`, placing the views side by side from left to right.
/// \param points the vertex positions
/// \param triangles the faces, as indices into `points`
/// \param colors one colour per face
/// \param options image size, anti-aliasing and views
/// \return an image of `views.size() * view_width` x `view_height` pixels
/// \throws SpectralSeg::Invalid_input if `colors` does not have one entry per
///         face, an index is out of range, `views` is empty, a view
///         direction is zero, or the view size is out of range (see
///         `Software_rasterizer`)
inline Image render_face_colors(const std::vector<std::array<double, 3>>& points,
                                const std::vector<std::array<std::size_t, 3>>& triangles,
                                const std::vector<Rgb>& colors,
                                const Render_options& options = {})
{
  internal::check_mesh(points.size(), triangles, colors.size(), "face colours");
  if(options.views.empty())
    throw Invalid_input("render_face_colors: no view requested");
  const Software_rasterizer rasterizer(options.view_width, options.view_height,
                                       options.supersample);
  const int max_views = std::numeric_limits<int>::max() / options.view_width;
  if(options.views.size() > static_cast<std::size_t>(max_views))
    throw Invalid_input("render_face_colors: too many views for one image");
  Image picture(static_cast<int>(options.views.size()) * options.view_width,
                options.view_height);
  for(std::size_t i = 0; i < options.views.size(); ++i)
  {
    const View& v = options.views[i];
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
