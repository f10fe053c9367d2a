// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file render_mesh_geometry.h
/// \brief The PNG renderers of `render_png.h` for a `Mesh_geometry` (for
/// example `Dual_graph::geometry()`), whose faces are the rows of per-face
/// values.
#ifndef SPECTRALSEG_RENDERING_RENDER_MESH_GEOMETRY_H
#define SPECTRALSEG_RENDERING_RENDER_MESH_GEOMETRY_H

#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/Rendering/render_png.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Rendering {

/// \ingroup PkgSpectralSegRendering
/// \brief The vertex positions of `geometry`, in the form the renderers take.
inline std::vector<std::array<double, 3>> rendering_points(const Mesh_geometry& geometry)
{
  std::vector<std::array<double, 3>> points;
  points.reserve(geometry.points.size());
  for(const auto& p : geometry.points)
    points.push_back({p.x(), p.y(), p.z()});
  return points;
}

/// \ingroup PkgSpectralSegRendering
/// \brief The triangles of `geometry`, in the form the renderers take.
inline std::vector<std::array<std::size_t, 3>> rendering_triangles(const Mesh_geometry& geometry)
{
  std::vector<std::array<std::size_t, 3>> triangles;
  triangles.reserve(geometry.triangles.size());
  for(const auto& t : geometry.triangles)
    triangles.push_back({t[0], t[1], t[2]});
  return triangles;
}

/// \ingroup PkgSpectralSegRendering
/// \brief `render_face_labels_png()` for the faces of `geometry`.
inline void render_face_labels_png(const std::string& path, const Mesh_geometry& geometry,
                                   const std::vector<int>& labels, const Render_options& options = {})
{
  render_face_labels_png(path, rendering_points(geometry), rendering_triangles(geometry), labels, options);
}

/// \ingroup PkgSpectralSegRendering
/// \brief `render_face_field_png()` for the faces of `geometry`.
inline void render_face_field_png(const std::string& path, const Mesh_geometry& geometry,
                                  const std::vector<double>& field, const Render_options& options = {})
{
  render_face_field_png(path, rendering_points(geometry), rendering_triangles(geometry), field, options);
}

} // namespace Rendering
} // namespace SpectralSeg

#endif
