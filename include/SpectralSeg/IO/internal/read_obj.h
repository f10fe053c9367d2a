// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_obj.h
/// \brief Reading a Wavefront OBJ file into a polygon soup.
#ifndef SPECTRALSEG_IO_INTERNAL_READ_OBJ_H
#define SPECTRALSEG_IO_INTERNAL_READ_OBJ_H

#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/Text_cursor.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// OBJ statements that carry no polygon and are skipped: texture
// coordinates, normals, grouping, materials, display attributes and the
// free-form geometry statements.
SPECTRALSEG_INLINE bool is_ignored_obj_statement(std::string_view keyword)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  static const char* const ignored[] = {
    "vt", "vn", "vp", "g", "o", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "bevel", "c_interp",
    "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "cstype", "deg", "bmat", "step", "curv",
    "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con", "call", "csh"};
  return std::any_of(std::begin(ignored), std::end(ignored), [&](const char* k) { return keyword == k; });
}
#else
;
#endif

// The vertex of one `f` corner ("v", "v/vt", "v/vt/vn" or "v//vn"; 1-based,
// negative counts back from the last vertex read), 0-based. Positive
// indices may refer to vertices defined later; they are checked at the end.
SPECTRALSEG_INLINE std::size_t obj_corner(Text_cursor& in, std::string_view token, std::size_t vertices_so_far)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::string_view index = token.substr(0, token.find('/'));
  std::int64_t v = 0;
  const Parse_status s = parse_signed(index, v);
  if(s == Parse_status::malformed)
    in.fail("expected a vertex index (an integer, optionally followed by /texture/normal), found " + quoted(token));
  if(s == Parse_status::overflow || v == 0 || (v < 0 && std::uint64_t(-v) > vertices_so_far) ||
     (v > 0 && std::uint64_t(v) > (std::uint64_t(1) << 48)))
    in.fail("vertex index " + quoted(index) + " is out of range (" + std::to_string(vertices_so_far) +
            " vertices so far; OBJ indices start at 1, negative ones count back from the last vertex)");
  return v > 0 ? std::size_t(v - 1) : vertices_so_far - std::size_t(-v);
}
#else
;
#endif

/// Reads the `v` and `f` statements of an OBJ file; `l` (polyline) and `p`
/// (point) elements are counted and ignored, as are texture coordinates,
/// normals, groups, materials and free-form statements. An unknown
/// statement is refused with its line.
SPECTRALSEG_INLINE void read_obj(const File_bytes& file, Polygon_soup& soup)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Text_cursor in(file, 0, '#', true);
  std::size_t largest_index = 0, largest_index_line = 0; // forward references, checked at the end
  std::string_view keyword;
  while(in.next(keyword))
  {
    if(keyword == "v")
    {
      std::array<double, 3> p{};
      for(int c = 0; c < 3; ++c)
      {
        std::string_view token;
        if(!in.next_on_line(token))
          in.fail("a vertex with fewer than three coordinates");
        double value = 0.;
        const Parse_status s = parse_double(token, value);
        if(s == Parse_status::malformed)
          in.fail("expected the " + std::string(1, "xyz"[c]) + " coordinate of vertex " +
                  std::to_string(soup.points.size() + 1) + ", found " + quoted(token));
        if(s == Parse_status::overflow || !std::isfinite(value))
          throw Invalid_input(file.message(in.where(), "the " + std::string(1, "xyz"[c]) + " coordinate of vertex " +
                                                         std::to_string(soup.points.size() + 1) + " " + quoted(token) +
                                                         " is non-finite (NaN, infinity or out of range)"));
        p[std::size_t(c)] = value;
      }
      soup.points.push_back(p);
    }
    else if(keyword == "f" || keyword == "fo")
    {
      const std::size_t f = soup.number_of_faces();
      std::string_view token;
      std::size_t n = 0;
      while(in.next_on_line(token))
      {
        if(++n > max_face_vertices)
          in.fail("face " + std::to_string(f) + " has more than " + std::to_string(max_face_vertices) +
                  " vertices; such faces are refused (split the polygon)");
        const std::size_t v = obj_corner(in, token, soup.points.size());
        if(v >= largest_index && v >= soup.points.size())
        {
          largest_index = v;
          largest_index_line = in.line();
        }
        soup.corners.push_back(v);
      }
      soup.end_face();
    }
    else if(keyword == "l" || keyword == "p")
      ++soup.ignored_elements;
    else if(!is_ignored_obj_statement(keyword))
      in.fail("unknown OBJ statement " + quoted(keyword));
    in.skip_line();
  }
  if(largest_index_line > 0 && largest_index >= soup.points.size())
    file.fail(", line " + std::to_string(largest_index_line),
              "a face refers to vertex " + std::to_string(largest_index + 1) + " but the file has " +
                std::to_string(soup.points.size()) + " vertices");
}
#else
;
#endif

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_READ_OBJ_H
