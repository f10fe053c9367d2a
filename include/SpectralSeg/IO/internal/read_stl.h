// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_stl.h
/// \brief Reading an STL file (ASCII or binary) into a polygon soup.
#ifndef SPECTRALSEG_IO_INTERNAL_READ_STL_H
#define SPECTRALSEG_IO_INTERNAL_READ_STL_H

#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/Text_cursor.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// Binary STL: an 80-byte header, a little-endian 32-bit triangle count and
// 50 bytes per triangle (normal, three corners as 32-bit floats, 2 bytes).
SPECTRALSEG_INLINE std::uint64_t binary_stl_triangles(const File_bytes& file)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(file.data.size() < 84)
    return std::uint64_t(-1);
  std::uint64_t n = 0;
  for(int i = 0; i < 4; ++i)
    n |= std::uint64_t(static_cast<unsigned char>(file.data[std::size_t(80 + i)])) << (8 * i);
  return n;
}
#else
;
#endif

SPECTRALSEG_INLINE void read_binary_stl(const File_bytes& file, Polygon_soup& soup)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::uint64_t n = binary_stl_triangles(file);
  if(file.data.size() < 84)
    file.fail("", "a binary STL file of " + std::to_string(file.data.size()) + " bytes (the header alone takes 84)");
  if(84 + 50 * n != file.data.size())
    file.fail("", "the binary STL header announces " + std::to_string(n) + " triangles (" +
                    std::to_string(84 + 50 * n) + " bytes) but the file has " + std::to_string(file.data.size()) +
                    " bytes (truncated file or wrong count)");
  soup.points.reserve(3 * n);
  soup.corners.reserve(3 * n);
  soup.face_begin.reserve(n + 1);
  for(std::uint64_t t = 0; t < n; ++t)
  {
    const char* b = file.data.data() + 84 + 50 * t + 12; // after the normal
    for(int corner = 0; corner < 3; ++corner)
    {
      std::array<double, 3> p{};
      for(int c = 0; c < 3; ++c)
      {
        unsigned char le[4];
        std::memcpy(le, b + 12 * corner + 4 * c, 4);
        const std::uint32_t u = std::uint32_t(le[0]) | std::uint32_t(le[1]) << 8 | std::uint32_t(le[2]) << 16 |
                                std::uint32_t(le[3]) << 24;
        float f = 0.f;
        std::memcpy(&f, &u, 4);
        if(!std::isfinite(f))
          throw Invalid_input(file.message(", triangle " + std::to_string(t),
                                           "a corner has a non-finite coordinate (NaN or infinity)"));
        p[std::size_t(c)] = double(f);
      }
      soup.corners.push_back(soup.points.size());
      soup.points.push_back(p);
    }
    soup.end_face();
  }
}
#else
;
#endif

// ASCII STL: solid NAME, facets of "facet normal ..." "outer loop" three or
// more "vertex x y z" "endloop" "endfacet", "endsolid NAME"; several solids
// may follow each other.
SPECTRALSEG_INLINE void read_ascii_stl(const File_bytes& file, Polygon_soup& soup)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  Text_cursor in(file, 0);
  auto keyword = [&in](const char* expected) {
    const std::string_view token = in.expect(Label(expected));
    if(token != expected)
      in.fail("expected '" + std::string(expected) + "', found " + quoted(token));
  };
  std::string_view token;
  while(in.next(token))
  {
    if(token != "solid")
      in.fail("expected 'solid', found " + quoted(token));
    in.skip_line(); // the name
    for(;;)
    {
      token = in.expect(Label("'facet' or 'endsolid'"));
      if(token == "endsolid")
      {
        in.skip_line();
        break;
      }
      if(token != "facet")
        in.fail("expected 'facet' or 'endsolid', found " + quoted(token));
      in.skip_line(); // the normal, recomputed from the corners
      keyword("outer");
      keyword("loop");
      const std::size_t f = soup.number_of_faces();
      std::size_t corners = 0;
      while((token = in.expect(Label("'vertex' or 'endloop'"))) == "vertex")
      {
        if(++corners > max_face_vertices)
          in.fail("facet " + std::to_string(f) + " has more than " + std::to_string(max_face_vertices) + " vertices");
        std::array<double, 3> p{};
        p[0] = in.number(Label("the x coordinate of a corner of facet", f));
        p[1] = in.number(Label("the y coordinate of a corner of facet", f));
        p[2] = in.number(Label("the z coordinate of a corner of facet", f));
        soup.corners.push_back(soup.points.size());
        soup.points.push_back(p);
      }
      if(token != "endloop")
        in.fail("expected 'vertex' or 'endloop', found " + quoted(token));
      keyword("endfacet");
      soup.end_face();
    }
  }
}
#else
;
#endif

/// Reads an STL file. It is binary if its size is exactly that its
/// binary header announces, or if it does not start with `solid`, or if it
/// holds a NUL byte (binary files may start with `solid` too); ASCII
/// otherwise. Every triangle has its own three corners (welded later).
SPECTRALSEG_INLINE void read_stl(const File_bytes& file, Polygon_soup& soup)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const bool starts_solid = file.data.compare(0, 5, "solid") == 0;
  const std::uint64_t n = binary_stl_triangles(file);
  const bool binary_size = file.data.size() >= 84 && n < (std::uint64_t(1) << 32) && 84 + 50 * n == file.data.size();
  const bool has_nul = file.data.find('\0') != std::string::npos;
  if(binary_size || !starts_solid || has_nul)
    read_binary_stl(file, soup);
  else
    read_ascii_stl(file, soup);
}
#else
;
#endif

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_READ_STL_H
