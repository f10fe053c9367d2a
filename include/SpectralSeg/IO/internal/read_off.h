// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_off.h
/// \brief Reading an OFF file (ASCII or binary) into a polygon soup.
#ifndef SPECTRALSEG_IO_INTERNAL_READ_OFF_H
#define SPECTRALSEG_IO_INTERNAL_READ_OFF_H

#include <SpectralSeg/IO/internal/Binary_cursor.h>
#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/Text_cursor.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// The vertex `index` of face `face`, checked against the `vertices` of the file.
SPECTRALSEG_INLINE std::size_t checked_vertex_index(Text_cursor& in, std::size_t face, std::size_t vertices)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::uint64_t v = in.integer(Label("a vertex index of face", face), UINT64_MAX);
  if(v >= vertices)
    in.fail("face " + std::to_string(face) + " refers to vertex " + std::to_string(v) + " but the file has " +
            std::to_string(vertices) + " vertices (numbered from 0)");
  return std::size_t(v);
}
#else
;
#endif

// The vertex count of a face, checked against the limit and the bytes left.
SPECTRALSEG_INLINE std::size_t checked_face_size(Text_cursor& in, std::size_t face)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::uint64_t n = in.integer(Label("the vertex count of face", face), UINT64_MAX);
  if(n > max_face_vertices)
    in.fail("face " + std::to_string(face) + " has " + std::to_string(n) + " vertices; faces of more than " +
            std::to_string(max_face_vertices) + " vertices are refused (split the polygon)");
  return std::size_t(n);
}
#else
;
#endif

// The keyword of an OFF file: `[ST][C][N][4][n]OFF [BINARY]`.
struct Off_keyword
{
  bool textures = false, colours = false, normals = false, homogeneous = false, dimension_given = false;
  bool binary = false;
};

// Binary OFF, as CGAL and geomview write and read it: after the keyword
// line, big-endian 32-bit integers and floats: the dimension for nOFF (3),
// the vertex, face and edge counts; per vertex x y z (and w for 4OFF) and
// for NOFF a normal of as many floats; per face a vertex count, the
// 0-based indices and a count of 0 to 4 colour components followed by as
// many floats. Binary COFF and STOFF are refused: writers disagree on how
// their vertex colours are laid out (CGAL writes three floats and reads a
// count first). Counts are checked against the file's size before
// anything is allocated, and faces of fewer than three vertices are
// refused (a truncated file or a wrong count reads as empty faces).
SPECTRALSEG_INLINE void read_binary_off(const File_bytes& file, std::size_t begin, const Off_keyword& k, Polygon_soup& soup)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Binary_cursor in(file, begin, true);
  if(k.colours || k.textures)
    in.fail("binary COFF and STOFF are not supported (vertex colours and texture coordinates); "
            "convert the file to ASCII OFF, PLY or STL");
  if(k.dimension_given && in.int32("the dimension of an nOFF file") != 3)
    in.fail("an nOFF file of a dimension other than 3");
  const std::int32_t vertices = in.int32_in("the vertex count", 0, INT32_MAX);
  const std::int32_t faces = in.int32_in("the face count", 0, INT32_MAX);
  in.int32("the edge count");
  const std::uint64_t vertex_bytes = 4 * ((k.homogeneous ? 4 : 3) * (k.normals ? 2 : 1));
  const std::uint64_t face_bytes = 4 * (1 + 3 + 1); // three indices at least, between the counts
  const std::uint64_t least = vertex_bytes * std::uint64_t(vertices) + face_bytes * std::uint64_t(faces);
  if(least > in.remaining())
    in.fail("the header announces " + std::to_string(vertices) + " vertices (" + std::to_string(vertex_bytes) +
            " bytes each) and " + std::to_string(faces) + " faces (at least " + std::to_string(face_bytes) +
            " bytes each), at least " + std::to_string(least) + " bytes, but only " +
            std::to_string(in.remaining()) + " bytes follow (truncated file or wrong counts)");
  soup.points.reserve(std::size_t(vertices));
  for(std::int32_t v = 0; v < vertices; ++v)
  {
    std::array<double, 3> p{};
    p[0] = in.float32(Label("the x coordinate of vertex", std::size_t(v)));
    p[1] = in.float32(Label("the y coordinate of vertex", std::size_t(v)));
    p[2] = in.float32(Label("the z coordinate of vertex", std::size_t(v)));
    if(k.homogeneous)
    {
      const double w = in.float32(Label("the w coordinate of vertex", std::size_t(v)));
      if(w == 0.)
        throw Invalid_input(file.message(in.where(), "vertex " + std::to_string(v) + " has w = 0 (a point at infinity)"));
      for(double& c : p)
        c /= w;
    }
    for(std::uint64_t c = 0; k.normals && c < vertex_bytes / 8; ++c)
      in.float32(Label("a normal coordinate of vertex", std::size_t(v)));
    soup.points.push_back(p);
  }
  soup.face_begin.reserve(std::size_t(faces) + 1);
  for(std::int32_t f = 0; f < faces; ++f)
  {
    const std::int32_t n = in.int32(Label("the vertex count of face", std::size_t(f)));
    if(n < 3 || n > std::int32_t(max_face_vertices))
      in.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices; binary faces of fewer than 3 "
              "(a truncated file or wrong counts) or more than " + std::to_string(max_face_vertices) +
              " vertices are refused");
    for(std::int32_t i = 0; i < n; ++i)
    {
      const std::int32_t v = in.int32(Label("a vertex index of face", std::size_t(f)));
      if(v < 0 || v >= vertices)
        in.fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " but the file has " +
                std::to_string(vertices) + " vertices (numbered from 0)");
      soup.corners.push_back(std::size_t(v));
    }
    soup.end_face();
    const std::int32_t colour = in.int32_in(Label("the colour component count of face", std::size_t(f)), 0, 4);
    for(std::int32_t c = 0; c < colour; ++c)
      in.float32(Label("a colour component of face", std::size_t(f)));
  }
  if(in.trailing_data())
    in.fail("unexpected data after the " + std::to_string(faces) +
            " faces the header announces (wrong counts in the header?)");
}
#else
;
#endif

/// Reads OFF (the geomview format), ASCII or binary (`OFF BINARY`, see
/// `read_binary_off()`): an optional `[ST][C][N][4][n]OFF`
/// keyword, the vertex, face and edge counts, one vertex per line (the
/// first three numbers, or four homogeneous ones for `4OFF`; colours,
/// normals and texture coordinates after them are skipped) and one face
/// per line (a vertex count, that many 0-based indices, an optional colour).
SPECTRALSEG_INLINE void read_off(const File_bytes& file, Polygon_soup& soup)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Text_cursor in(file, 0, '#');
  const Text_cursor start = in;
  const std::string_view token = in.expect("the OFF keyword or the vertex count");
  Off_keyword k;
  if(token.size() >= 3 && token.substr(token.size() - 3) == "OFF")
  {
    std::string_view prefix = token.substr(0, token.size() - 3);
    for(const std::string_view code : {"ST", "C", "N", "4", "n"})
      if(prefix.substr(0, code.size()) == code)
      {
        bool& flag = code == "ST" ? k.textures : code == "C" ? k.colours : code == "N" ? k.normals
                   : code == "4"  ? k.homogeneous : k.dimension_given;
        flag = true;
        prefix.remove_prefix(code.size());
      }
    if(!prefix.empty())
      in.fail("unknown OFF keyword " + quoted(token));
    const Text_cursor after_keyword = in;
    std::string_view next;
    if(in.next_on_line(next) && next == "BINARY")
    {
      const std::size_t line_end = file.data.find('\n', in.offset());
      if(line_end == std::string::npos)
        in.fail("binary OFF without its data: no line end after 'BINARY'");
      read_binary_off(file, line_end + 1, k, soup);
      return;
    }
    in = after_keyword;
    if(k.dimension_given && in.integer("the dimension of an nOFF file", 64) != 3)
      in.fail("an nOFF file of a dimension other than 3");
  }
  else
    in = start; // the keyword is optional
  const bool homogeneous = k.homogeneous;

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
#else
;
#endif

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_READ_OFF_H
