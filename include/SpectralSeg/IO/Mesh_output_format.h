// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Mesh_output_format.h
/// \brief The file formats of the segmented-mesh writers, chosen by extension.
#ifndef SPECTRALSEG_IO_MESH_OUTPUT_FORMAT_H
#define SPECTRALSEG_IO_MESH_OUTPUT_FORMAT_H

#include <algorithm>
#include <cctype>
#include <string>

namespace SpectralSeg {
namespace IO {

/// \ingroup PkgSpectralSegIO
/// \brief The formats `write_segmented_mesh()` writes.
enum class Mesh_output_format
{
  ply,        ///< `.ply`: split vertices with colours, face colours and a face property `segment`
  obj,        ///< `.obj`: one material per segment, in a `.mtl` file beside it
  off,        ///< `.off`: one colour per face
  unsupported ///< any other extension
};

/// \ingroup PkgSpectralSegIO
/// \brief The format of `path` by its extension (`.ply`, `.obj`, `.off`, in
/// any case); `Mesh_output_format::unsupported` for any other. Lets a
/// program refuse an output path before it computes anything.
inline Mesh_output_format mesh_output_format(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return Mesh_output_format::unsupported;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(ext == "ply")
    return Mesh_output_format::ply;
  if(ext == "obj")
    return Mesh_output_format::obj;
  if(ext == "off")
    return Mesh_output_format::off;
  return Mesh_output_format::unsupported;
}

/// \ingroup PkgSpectralSegIO
/// \brief The material library that `write_segmented_mesh()` writes beside
/// an OBJ file: `path` with its extension replaced by `.mtl`
/// (`out/mesh.obj` gives `out/mesh.mtl`).
inline std::string material_library_path(const std::string& obj_path)
{
  const std::size_t slash = obj_path.find_last_of('/');
  const std::size_t dot = obj_path.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return obj_path + ".mtl";
  return obj_path.substr(0, dot) + ".mtl";
}

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_MESH_OUTPUT_FORMAT_H
