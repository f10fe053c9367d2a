// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_off.h
/// \brief Reading an ASCII OFF file into a polygon soup.
#ifndef SPECTRALSEG_IO_INTERNAL_READ_OFF_H
#define SPECTRALSEG_IO_INTERNAL_READ_OFF_H

#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/Text_cursor.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// The vertex `index` of face `face`, checked against the `vertices` of the file.
inline std::size_t checked_vertex_index(Text_cursor& in, std::size_t face, std::size_t vertices)
{
  const std::uint64_t v = in.integer(Label("a vertex index of face", face), UINT64_MAX);
  if(v >= vertices)
    in.fail("face " + std::to_string(face) + " refers to vertex " + std::to_string(v) + " but the file has " +
            std::to_string(vertices) + " vertices (numbered from 0)");
  return std::size_t(v);
}

// The vertex count of a face, checked against the limit and the bytes left.
inline std::size_t checked_face_size(Text_cursor& in, std::size_t face)
{
  const std::uint64_t n = in.integer(Label("the vertex count of face", face), UINT64_MAX);
  if(n > max_face_vertices)
    in.fail("face " + std::to_string(face) + " has " + std::to_string(n) + " vertices; faces of more than " +
            std::to_string(max_face_vertices) + " vertices are refused (split the polygon)");
  return std::size_t(n);
}

/// Reads OFF (the geomview format): an optional `[ST][C][N][4][n]OFF`
/// keyword, the vertex, face and edge counts, one vertex per line (the
/// first three numbers, or four homogeneous ones for `4OFF`; colours,
/// normals and texture coordinates after them are skipped) and one face
/// per line (a vertex count, that many 0-based indices, an optional colour).
inline void read_off(const File_bytes& file, Polygon_soup& soup)
{
  Text_cursor in(file, 0, '#');
  const Text_cursor start = in;
  const std::string_view token = in.expect("the OFF keyword or the vertex count");
  bool homogeneous = false;
  if(token.size() >= 3 && token.substr(token.size() - 3) == "OFF")
  {
    std::string_view prefix = token.substr(0, token.size() - 3);
    bool dimension_given = false;
    for(const std::string_view code : {"ST", "C", "N", "4", "n"})
      if(prefix.substr(0, code.size()) == code)
      {
        homogeneous = homogeneous || code == "4";
        dimension_given = dimension_given || code == "n";
        prefix.remove_prefix(code.size());
      }
    if(!prefix.empty())
      in.fail("unknown OFF keyword " + quoted(token));
    const Text_cursor after_keyword = in;
    std::string_view next;
    if(in.next_on_line(next) && next == "BINARY")
      in.fail("binary OFF is not supported; convert the file to ASCII OFF, PLY or STL");
    in = after_keyword;
    if(dimension_given && in.integer("the dimension of an nOFF file", 64) != 3)
      in.fail("an nOFF file of a dimension other than 3");
  }
  else
    in = start; // the keyword is optional

  const std::uint64_t bound = UINT64_MAX / 16; // no overflow below; the file's size is checked next
  const std::size_t vertices = std::size_t(in.integer("the vertex count", bound));
  const std::size_t faces = std::size_t(in.integer("the face count", bound));
  in.integer("the edge count", UINT64_MAX);
  in.skip_line();
  // each vertex takes at least "0 0 0\n", each face at least "0\n"
  const std::uint64_t least = 6 * std::uint64_t(vertices) + 2 * std::uint64_t(faces);
  if(least > in.remaining() + 1)
    in.fail("the header announces " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
            " faces, which need at least " + std::to_string(least) + " bytes, but only " +
            std::to_string(in.remaining()) + " bytes follow (truncated file or wrong counts)");

  soup.points.reserve(vertices);
  for(std::size_t v = 0; v < vertices; ++v)
  {
    std::array<double, 3> p{};
    p[0] = in.number(Label("the x coordinate of vertex", v));
    p[1] = in.number(Label("the y coordinate of vertex", v));
    p[2] = in.number(Label("the z coordinate of vertex", v));
    if(homogeneous)
    {
      const double w = in.number(Label("the w coordinate of vertex", v));
      if(w == 0.)
        throw Invalid_input(file.message(in.where(), "vertex " + std::to_string(v) + " has w = 0 (a point at infinity)"));
      for(double& c : p)
        c /= w;
    }
    soup.points.push_back(p);
    in.skip_line();
  }
  soup.face_begin.reserve(faces + 1);
  for(std::size_t f = 0; f < faces; ++f)
  {
    const std::size_t n = checked_face_size(in, f);
    if(2 * n > in.remaining() + 1)
      in.fail("face " + std::to_string(f) + " announces " + std::to_string(n) + " vertices but the file ends first");
    for(std::size_t i = 0; i < n; ++i)
      soup.corners.push_back(checked_vertex_index(in, f, vertices));
    soup.end_face();
    in.skip_line(); // an optional colour
  }
  std::string_view extra;
  if(in.next(extra))
    in.fail("unexpected " + quoted(extra) + " after the " + std::to_string(faces) +
            " faces the header announces (wrong counts in the header?)");
}

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_READ_OFF_H
