// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_segmented_obj.h
/// \brief The OBJ and MTL writers of `write_segmented_mesh()`.
#ifndef SPECTRALSEG_IO_INTERNAL_WRITE_SEGMENTED_OBJ_H
#define SPECTRALSEG_IO_INTERNAL_WRITE_SEGMENTED_OBJ_H

#include <SpectralSeg/IO/internal/write_segmented_ply.h>
#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/version.h>

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace IO {
namespace internal {

// `segment_N`, or `no_segment` for faces without one
inline std::string material_name(int segment)
{
  return segment < 0 ? std::string("no_segment") : "segment_" + std::to_string(segment);
}

// One material per label present in `labels`, coloured as in the pictures.
inline void write_segment_materials(std::ostream& out, const std::vector<int>& labels)
{
  std::vector<int> present(labels);
  std::sort(present.begin(), present.end());
  present.erase(std::unique(present.begin(), present.end()), present.end());
  out << "# written by SpectralSeg " SPECTRALSEG_VERSION_STRING ": one material per segment\n"
      << std::fixed << std::setprecision(4);
  for(int s : present)
  {
    const Rendering::Rgb c = segment_color(s);
    out << "\nnewmtl " << material_name(s) << "\nKa 0 0 0\nKd " << c.r / 255. << ' ' << c.g / 255. << ' '
        << c.b / 255. << "\nKs 0 0 0\nd 1\nillum 1\n";
  }
}

// The mesh, its faces in order, with `usemtl segment_N` (and a group of the
// same name) wherever the segment changes; `mtl_name` is the material
// library's file name, relative to the OBJ file.
inline void write_segmented_obj(std::ostream& out, const std::string& mtl_name, const Mesh_geometry& geometry,
                                const std::vector<int>& labels, int precision)
{
  out << "# written by SpectralSeg " SPECTRALSEG_VERSION_STRING ": one material per segment\nmtllib " << mtl_name
      << '\n'
      << std::setprecision(precision);
  for(const Eigen::Vector3d& p : geometry.points)
    out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for(std::size_t f = 0; f < geometry.number_of_faces(); ++f)
  {
    if(f == 0 || labels[f] != labels[f - 1])
      out << "g " << material_name(labels[f]) << "\nusemtl " << material_name(labels[f]) << '\n';
    const auto& t = geometry.triangles[f];
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
}

} // namespace internal
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_WRITE_SEGMENTED_OBJ_H
