// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_segmented_ply.h
/// \brief The PLY writer of `write_segmented_mesh()` and `write_segment_parts()`.
#ifndef SPECTRALSEG_IO_INTERNAL_WRITE_SEGMENTED_PLY_H
#define SPECTRALSEG_IO_INTERNAL_WRITE_SEGMENTED_PLY_H

#include <SpectralSeg/IO/internal/Segment_split_mesh.h>
#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/Rendering/Color_map.h>
#include <SpectralSeg/version.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <ostream>

namespace SpectralSeg {
namespace IO {
namespace internal {

// Writes `value` in little-endian byte order, whatever the machine's.
template <typename T>
void put_little_endian(std::ostream& out, T value)
{
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  if(first != 1) // a big-endian machine
    std::reverse(bytes, bytes + sizeof(T));
  out.write(reinterpret_cast<const char*>(bytes), sizeof(T));
}

inline Rendering::Rgb segment_color(int segment)
{
  return segment < 0 ? Rendering::missing_color() : Rendering::label_color(std::size_t(segment));
}

// PLY (ASCII, or binary little endian): every vertex copy with its
// segment's colour (`red green blue`), every face with the same colour and
// its label (`property int segment`, -1 for none).
inline void write_segmented_ply(std::ostream& out, const Mesh_geometry& geometry, const Segment_split_mesh& mesh,
                                bool binary, int precision)
{
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii")
      << " 1.0\ncomment written by SpectralSeg " SPECTRALSEG_VERSION_STRING
         "\ncomment vertices are copied once per segment of their faces: each has its segment's colour\n"
         "element vertex "
      << mesh.number_of_vertices()
      << "\nproperty double x\nproperty double y\nproperty double z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\n"
         "element face "
      << mesh.number_of_faces()
      << "\nproperty list uchar int vertex_indices\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty int segment\nend_header\n";
  if(binary)
  {
    for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
    {
      const Eigen::Vector3d& p = geometry.points[mesh.source_vertex[v]];
      const Rendering::Rgb c = segment_color(mesh.vertex_segment[v]);
      for(int i = 0; i < 3; ++i)
        put_little_endian(out, p[i]);
      put_little_endian(out, c.r);
      put_little_endian(out, c.g);
      put_little_endian(out, c.b);
    }
    for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    {
      const Rendering::Rgb c = segment_color(mesh.face_segment[f]);
      put_little_endian(out, std::uint8_t(3));
      for(std::uint32_t v : mesh.triangles[f])
        put_little_endian(out, std::int32_t(v));
      put_little_endian(out, c.r);
      put_little_endian(out, c.g);
      put_little_endian(out, c.b);
      put_little_endian(out, std::int32_t(mesh.face_segment[f]));
    }
    return;
  }
  out << std::setprecision(precision);
  for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
  {
    const Eigen::Vector3d& p = geometry.points[mesh.source_vertex[v]];
    const Rendering::Rgb c = segment_color(mesh.vertex_segment[v]);
    out << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << int(c.r) << ' ' << int(c.g) << ' ' << int(c.b) << '\n';
  }
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    const auto& t = mesh.triangles[f];
    const Rendering::Rgb c = segment_color(mesh.face_segment[f]);
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << int(c.r) << ' ' << int(c.g) << ' ' << int(c.b) << ' '
        << mesh.face_segment[f] << '\n';
  }
}

} // namespace internal
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_WRITE_SEGMENTED_PLY_H
