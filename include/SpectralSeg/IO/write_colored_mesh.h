// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_colored_mesh.h
/// \brief Writing a mesh with one colour per face (PLY or OFF).
#ifndef SPECTRALSEG_IO_WRITE_COLORED_MESH_H
#define SPECTRALSEG_IO_WRITE_COLORED_MESH_H

#include <SpectralSeg/IO/Atomic_output_file.h>
#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/Rendering/Color_map.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace IO {

/// \ingroup PkgSpectralSegIO
/// \brief Writes the triangles of `geometry` with one RGB colour per face,
/// as ASCII PLY (`.ply`: face properties `red green blue`) or OFF (`.off`:
/// colour components after each face's vertex indices), chosen by extension.
/// The file is written all or nothing (`Atomic_output_file`).
/// \throws Io_error if the file cannot be written (an existing file is then
/// left unchanged) or the extension is neither
/// \throws Invalid_input if there is not one colour per face
inline void write_colored_mesh(const std::string& path, const Mesh_geometry& geometry,
                               const std::vector<Rendering::Rgb>& colors)
{
  if(colors.size() != geometry.number_of_faces())
    throw Invalid_input("write_colored_mesh: " + std::to_string(colors.size()) + " colours for " +
                        std::to_string(geometry.number_of_faces()) + " faces");
  std::string ext = path.substr(path.find_last_of('.') == std::string::npos ? path.size() : path.find_last_of('.') + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(ext != "ply" && ext != "off")
    throw Io_error("'" + path + "': coloured meshes are written as .ply or .off");
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  if(ext == "ply")
    out << "ply\nformat ascii 1.0\ncomment written by SpectralSeg\nelement vertex " << geometry.number_of_vertices()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << geometry.number_of_faces()
        << "\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
           "end_header\n";
  else
    out << "OFF\n" << geometry.number_of_vertices() << ' ' << geometry.number_of_faces() << " 0\n";
  for(const auto& p : geometry.points)
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for(std::size_t f = 0; f < geometry.number_of_faces(); ++f)
  {
    const auto& t = geometry.triangles[f];
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << int(colors[f].r) << ' ' << int(colors[f].g) << ' '
        << int(colors[f].b) << '\n';
  }
  file.commit();
}

} // namespace IO
} // namespace SpectralSeg

#endif
