// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Polygon_soup.h
/// \brief The points and faces of a mesh file as read, before any repair,
/// and the file's bytes the format readers parse.
#ifndef SPECTRALSEG_IO_INTERNAL_POLYGON_SOUP_H
#define SPECTRALSEG_IO_INTERNAL_POLYGON_SOUP_H

#include <SpectralSeg/exceptions.h>

#include <array>
#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace SpectralSeg {
namespace IO {

/// \ingroup PkgSpectralSegIO
/// \brief Faces with more vertices than this are refused by
/// `read_mesh_file()`: the minimum-area triangulation of a polygon costs
/// up to the cube of its vertex count (6,000 vertices took 70 s).
constexpr std::size_t max_face_vertices = 256;

/// \cond SKIP_IN_MANUAL
namespace internal {

// The content of a mesh file, as the file gives it: points and polygons
// (indices into the points, in file order), stored face after face.
struct Polygon_soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::size_t> corners;           // the vertex indices of all faces, face after face
  std::vector<std::size_t> face_begin{0};     // face f is corners[face_begin[f], face_begin[f + 1])
  std::size_t ignored_elements = 0;           // elements that are not faces (OBJ lines and points)

  std::size_t number_of_faces() const { return face_begin.size() - 1; }
  std::size_t face_size(std::size_t f) const { return face_begin[f + 1] - face_begin[f]; }
  const std::size_t* face(std::size_t f) const { return corners.data() + face_begin[f]; }
  void end_face() { face_begin.push_back(corners.size()); }
};

// The bytes of a file, read whole, with its path for the messages.
struct File_bytes
{
  std::string path;
  std::string data;

  // "'path'" followed by `where` (", line 3") and ": what"
  std::string message(const std::string& where, const std::string& what) const
  {
    return "'" + path + "'" + where + ": " + what;
  }
  [[noreturn]] void fail(const std::string& where, const std::string& what) const
  {
    throw Io_error(message(where, what));
  }
};

// Reads a whole regular file; throws Io_error if it cannot be read, is
// empty or is not a regular file. A device (/dev/zero, /dev/urandom), a
// FIFO or a directory is refused before it is opened: the first two never
// end, and opening a FIFO blocks until a writer comes. `kind` names the
// file in the messages ("label file"; empty for a mesh).
inline File_bytes read_file_bytes(const std::string& path, const std::string& kind = std::string())
{
  File_bytes file;
  file.path = path;
  const std::string name = (kind.empty() ? "" : kind + " ") + "'" + path + "'";
  std::error_code status_error;
  const std::filesystem::file_status status = std::filesystem::status(path, status_error);
  if(!status_error && std::filesystem::is_directory(status))
    throw Io_error("cannot read " + name + ": it is a directory");
  if(!status_error && !std::filesystem::is_regular_file(status))
    throw Io_error("cannot read " + name + ": not a regular file (a device, FIFO or socket); "
                   "give a file, or copy the stream to a file first");
  std::FILE* in = std::fopen(path.c_str(), "rb");
  if(in == nullptr)
    throw Io_error("cannot open " + name + ": " + std::strerror(errno));
  char buffer[1 << 16];
  std::size_t got = 0;
  while((got = std::fread(buffer, 1, sizeof(buffer), in)) > 0)
    file.data.append(buffer, got);
  const bool failed = std::ferror(in) != 0;
  const int error = errno;
  std::fclose(in);
  if(failed)
    throw Io_error("cannot read " + name + ": " + std::strerror(error));
  if(file.data.empty())
    throw Io_error(name + " is empty");
  return file;
}

} // namespace internal
/// \endcond

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_POLYGON_SOUP_H
