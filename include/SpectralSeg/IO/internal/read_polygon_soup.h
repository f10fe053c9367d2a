// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_polygon_soup.h
/// \brief The points and polygons of an OFF, OBJ, PLY or STL file, as the
/// file gives them (no CGAL: the readers of `read_mesh_file()`).
#ifndef SPECTRALSEG_IO_INTERNAL_READ_POLYGON_SOUP_H
#define SPECTRALSEG_IO_INTERNAL_READ_POLYGON_SOUP_H

#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/read_obj.h>
#include <SpectralSeg/IO/internal/read_off.h>
#include <SpectralSeg/IO/internal/read_ply.h>
#include <SpectralSeg/IO/internal/read_stl.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace SpectralSeg {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

inline std::string lowercase_extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// The points and faces of a file, as the file gives them, by format.
inline Polygon_soup read_polygon_soup(const std::string& path)
{
  const std::string ext = lowercase_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
  {
    const File_bytes probe = read_file_bytes(path); // a missing file says so first
    throw Io_error("'" + path + "': unknown mesh format '" + ext + "' (use .off, .obj, .ply or .stl)");
  }
  const File_bytes file = read_file_bytes(path);
  Polygon_soup soup;
  if(ext == "off")
    read_off(file, soup);
  else if(ext == "obj")
    read_obj(file, soup);
  else if(ext == "ply")
    read_ply(file, soup);
  else
    read_stl(file, soup);
  return soup;
}

} // namespace internal
/// \endcond

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_READ_POLYGON_SOUP_H
