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
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace SpectralSeg {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

SPECTRALSEG_INLINE std::string lowercase_extension(const std::string& path)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}
#else
;
#endif

// The format of a mesh file by its extension ("off", "obj", "ply" or
// "stl"); throws Io_error for another extension (after checking that the
// file can be read: a missing file says so first).
SPECTRALSEG_INLINE std::string mesh_file_format(const std::string& path)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::string ext = lowercase_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
  {
    const File_bytes probe = read_file_bytes(path);
    throw Io_error("'" + path + "': unknown mesh format '" + ext + "' (use .off, .obj, .ply or .stl)");
  }
  return ext;
}
#else
;
#endif

// The points and faces of the bytes of a file of `format` (as
// `mesh_file_format()` gives it), as the file gives them.
SPECTRALSEG_INLINE Polygon_soup read_polygon_soup(const File_bytes& file, const std::string& format)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Polygon_soup soup;
  if(format == "off")
    read_off(file, soup);
  else if(format == "obj")
    read_obj(file, soup);
  else if(format == "ply")
    read_ply(file, soup);
  else if(format == "stl")
    read_stl(file, soup);
  else
    throw Io_error("'" + file.path + "': unknown mesh format '" + format + "' (use .off, .obj, .ply or .stl)");
  return soup;
}
#else
;
#endif

// The points and faces of a file, as the file gives them, by format.
SPECTRALSEG_INLINE Polygon_soup read_polygon_soup(const std::string& path)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::string format = mesh_file_format(path);
  return read_polygon_soup(read_file_bytes(path), format);
}
#else
;
#endif

} // namespace internal
/// \endcond

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_READ_POLYGON_SOUP_H
