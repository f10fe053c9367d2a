// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_ply.h
/// \brief Reading a PLY file (ASCII or binary, any property types) into a polygon soup.
#ifndef SPECTRALSEG_IO_INTERNAL_READ_PLY_H
#define SPECTRALSEG_IO_INTERNAL_READ_PLY_H

#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/Text_cursor.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// A PLY scalar type: its size in bytes and whether it is an integer, signed.
struct Ply_type
{
  std::size_t size = 0;
  bool integer = false;
  bool is_signed = false;
};

SPECTRALSEG_INLINE bool ply_type_of(std::string_view name, Ply_type& t)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  struct Entry { const char* name; Ply_type type; };
  static const Entry types[] = {
    {"char", {1, true, true}},    {"int8", {1, true, true}},     {"uchar", {1, true, false}},
    {"uint8", {1, true, false}},  {"short", {2, true, true}},    {"int16", {2, true, true}},
    {"ushort", {2, true, false}}, {"uint16", {2, true, false}}, {"int", {4, true, true}},
    {"int32", {4, true, true}},   {"uint", {4, true, false}},   {"uint32", {4, true, false}},
    {"float", {4, false, true}},  {"float32", {4, false, true}}, {"double", {8, false, true}},
    {"float64", {8, false, true}}};
  for(const Entry& e : types)
    if(name == e.name)
    {
      t = e.type;
      return true;
    }
  return false;
}
#else
;
#endif

struct Ply_property
{
  std::string name;
  Ply_type type;        // the item type of a list
  bool list = false;
  Ply_type count_type;  // of a list
};

struct Ply_element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
  std::size_t header_line = 0;

  // whether `p` is the list of vertex indices of the face element
  bool is_face_list(const Ply_property& p) const
  {
    return name == "face" && p.list && (p.name == "vertex_indices" || p.name == "vertex_index");
  }

  // the fewest bytes one element can take: a byte and a separator per
  // ASCII value; in binary, the scalars, the list counts and three indices
  // of a face list (shorter faces are refused in binary files: a truncated
  // file or a wrong count reads as faces of zero vertices)
  std::uint64_t least_bytes(bool ascii) const
  {
    std::uint64_t b = 0;
    for(const Ply_property& p : properties)
      b += ascii ? 2 : !p.list ? p.type.size : p.count_type.size + (is_face_list(p) ? 3 * p.type.size : 0);
    return b;
  }
};

struct Ply_header
{
  bool ascii = true;
  bool big_endian = false;
  std::vector<Ply_element> elements;
  std::size_t data_begin = 0; // offset of the first byte after end_header
  std::size_t data_line = 0;
};

SPECTRALSEG_INLINE Ply_header read_ply_header(const File_bytes& file)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::string& d = file.data;
  if(d.compare(0, 3, "ply") != 0 || (d.size() > 3 && d[3] != '\n' && d[3] != '\r'))
    file.fail("", "not a PLY file (the first line is not 'ply')");
  const std::size_t end = d.find("end_header");
  if(end == std::string::npos)
    file.fail("", "the PLY header has no 'end_header' line");
  Ply_header h;
  h.data_begin = d.find('\n', end);
  if(h.data_begin == std::string::npos)
    h.data_begin = d.size();
  else
    ++h.data_begin;
  // the header is text: read it line by line
  File_bytes header{file.path, d.substr(0, end)};
  Text_cursor in(header, 0);
  in.skip_line(); // "ply"
  bool format_seen = false;
  std::string_view keyword;
  while(in.next(keyword))
  {
    if(keyword == "comment" || keyword == "obj_info")
    {
      in.skip_line();
      continue;
    }
    std::string_view a, b, c, e;
    if(keyword == "format")
    {
      if(!in.next_on_line(a) || !in.next_on_line(b))
        in.fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if(a == "binary_little_endian" || a == "binary_big_endian")
      {
        h.ascii = false;
        h.big_endian = a == "binary_big_endian";
      }
      else if(a != "ascii")
        in.fail("unknown PLY format " + quoted(a));
      if(b != "1.0")
        in.fail("PLY version " + quoted(b) + "; only 1.0 is defined");
      format_seen = true;
    }
    else if(keyword == "element")
    {
      Ply_element el;
      el.header_line = in.line();
      if(!in.next_on_line(a))
        in.fail("an element without a name");
      el.name = std::string(a);
      const std::string what = "the count of element '" + el.name + "'";
      el.count = in.integer(what, UINT64_MAX);
      h.elements.push_back(el);
    }
    else if(keyword == "property")
    {
      if(h.elements.empty())
        in.fail("a property before any element");
      Ply_property p;
      if(!in.next_on_line(a))
        in.fail("a property without a type");
      if(a == "list")
      {
        p.list = true;
        if(!in.next_on_line(b) || !in.next_on_line(c) || !in.next_on_line(e))
          in.fail("expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
        if(!ply_type_of(b, p.count_type) || !p.count_type.integer)
          in.fail("the count type of a list must be an integer type, found " + quoted(b));
        if(!ply_type_of(c, p.type))
          in.fail("unknown PLY type " + quoted(c));
        p.name = std::string(e);
      }
      else
      {
        if(!ply_type_of(a, p.type))
          in.fail("unknown PLY type " + quoted(a));
        if(!in.next_on_line(b))
          in.fail("a property without a name");
        p.name = std::string(b);
      }
      h.elements.back().properties.push_back(p);
    }
    else
      in.fail("unknown PLY header line " + quoted(keyword));
    std::string_view extra;
    if(in.next_on_line(extra))
      in.fail("unexpected " + quoted(extra) + " at the end of a header line");
    in.skip_line();
  }
  if(!format_seen)
    file.fail("", "the PLY header has no 'format' line");
  h.data_line = in.line() + 1;
  // Counts against the size of the file, before anything is allocated.
  const std::uint64_t available = d.size() - h.data_begin;
  std::uint64_t least = 0;
  std::string counts; // "9 'vertex' (12 bytes each), 8 'face' (13 bytes each)"
  for(const Ply_element& el : h.elements)
  {
    const std::uint64_t per = el.least_bytes(h.ascii);
    if(el.count > 0 && per == 0)
      file.fail(", line " + std::to_string(el.header_line),
                "element '" + el.name + "' has no property but a count of " + std::to_string(el.count));
    if(el.count > available / std::max<std::uint64_t>(per, 1) + 1)
      file.fail(", line " + std::to_string(el.header_line),
                "the header announces " + std::to_string(el.count) + " '" + el.name + "' elements, which need at least " +
                  std::to_string(per) + " bytes each, but only " + std::to_string(available) +
                  " bytes of data follow the header (truncated file or wrong count)");
    least += el.count * per;
    if(el.count > 0)
      counts += (counts.empty() ? "" : ", ") + std::to_string(el.count) + " '" + el.name + "' elements (at least " +
                std::to_string(per) + " bytes each)";
  }
  // an ASCII file may end without a separator after its last value
  if(least > available + (h.ascii ? 1 : 0))
    file.fail("", "the header announces " + counts + ", at least " + std::to_string(least) + " bytes, but only " +
                    std::to_string(available) + " bytes of data follow it (truncated file or wrong counts)");
  return h;
}
#else
;
#endif

// Reads the values of a PLY body, ASCII or binary, one at a time.
class Ply_values
{
public:
  Ply_values(const File_bytes& file, const Ply_header& h)
    : file_(file), ascii_(h.ascii), big_endian_(h.big_endian), text_(file, h.data_begin), pos_(h.data_begin)
  {}

  // the value read next, for messages: property `property` of element `index` of `element`
  void at(const Ply_element& element, std::uint64_t index, const Ply_property& property)
  {
    element_ = &element;
    index_ = index;
    property_ = &property;
  }

  // a value of type `t` as a double
  double real(const Ply_type& t)
  {
    if(ascii_)
    {
      const std::string_view token = expect();
      if(t.integer)
        return double(ascii_integer(token, t));
      double v = 0.;
      const Parse_status s = parse_double(token, v);
      if(s == Parse_status::malformed)
        text_.fail("expected " + what() + ", found " + quoted(token));
      if(s == Parse_status::overflow || !std::isfinite(v))
        throw Invalid_input(file_.message(text_.where(), what() + " " + quoted(token) +
                                                           " is non-finite (NaN, infinity or out of range)"));
      return v;
    }
    const unsigned char* b = bytes(t.size);
    if(t.integer)
      return double(binary_integer(b, t));
    double v = 0.;
    if(t.size == 4)
    {
      float f = 0.f;
      std::memcpy(&f, ordered(b, 4).data(), 4);
      v = double(f);
    }
    else
      std::memcpy(&v, ordered(b, 8).data(), 8);
    if(!std::isfinite(v))
      throw Invalid_input(file_.message(where(), what() + " is non-finite (NaN or infinity)"));
    return v;
  }

  // a value of an integer type `t`
  std::int64_t integer(const Ply_type& t)
  {
    if(ascii_)
      return ascii_integer(expect(), t);
    return binary_integer(bytes(t.size), t);
  }

  // skips one value of type `t`
  void skip(const Ply_type& t)
  {
    if(ascii_)
      expect();
    else
      bytes(t.size);
  }

  // "property 'x' of vertex 12"
  std::string what() const
  {
    return "property '" + property_->name + "' of " + element_->name + " " + std::to_string(index_);
  }

  // at least `n` more values of `size` bytes can follow
  bool can_hold(std::uint64_t n, std::size_t size) const
  {
    const std::uint64_t left = ascii_ ? text_.remaining() + 1 : file_.data.size() - pos_;
    return n <= left / (ascii_ ? 2 : size);
  }

  // whether something other than whitespace follows
  bool trailing_data()
  {
    if(ascii_)
      return !text_.at_end();
    for(std::size_t i = pos_; i < file_.data.size(); ++i)
      if(!std::isspace(static_cast<unsigned char>(file_.data[i])))
        return true;
    return false;
  }

  std::string where() const
  {
    return ascii_ ? text_.where() : ", byte " + std::to_string(pos_);
  }
  [[noreturn]] void fail(const std::string& message) const { file_.fail(where(), message); }

private:
  std::string_view expect()
  {
    std::string_view token;
    if(!text_.next(token))
      text_.fail("the file ends where " + what() + " was expected (truncated file or wrong counts in the header)");
    return token;
  }
  std::int64_t ascii_integer(std::string_view token, const Ply_type& t)
  {
    std::int64_t v = 0;
    const Parse_status s = parse_signed(token, v);
    if(s == Parse_status::malformed)
      text_.fail("expected " + what() + " (an integer), found " + quoted(token));
    const int bits = int(8 * t.size);
    const std::int64_t lo = t.is_signed ? -(std::int64_t(1) << (bits - 1)) : 0;
    const std::int64_t hi = t.is_signed ? (std::int64_t(1) << (bits - 1)) - 1 : (std::int64_t(1) << bits) - 1;
    if(s == Parse_status::overflow || v < lo || v > hi)
      text_.fail(what() + " " + quoted(token) + " is out of the range of its type");
    return v;
  }
  std::int64_t binary_integer(const unsigned char* b, const Ply_type& t) const
  {
    const std::array<unsigned char, 8> o = ordered(b, t.size);
    std::uint64_t u = 0;
    for(std::size_t i = 0; i < t.size; ++i)
      u |= std::uint64_t(o[i]) << (8 * i); // little endian after ordering
    if(t.is_signed && t.size < 8 && (u >> (8 * t.size - 1)) != 0)
      return std::int64_t(u) - (std::int64_t(1) << (8 * t.size));
    return std::int64_t(u);
  }
  // the bytes of a value in little-endian order
  std::array<unsigned char, 8> ordered(const unsigned char* b, std::size_t size) const
  {
    std::array<unsigned char, 8> o{};
    for(std::size_t i = 0; i < size; ++i)
      o[i] = big_endian_ ? b[size - 1 - i] : b[i];
    return o;
  }
  const unsigned char* bytes(std::size_t n)
  {
    if(file_.data.size() - pos_ < n)
      fail("the file ends where " + what() + " was expected (truncated file or wrong counts in the header)");
    const unsigned char* b = reinterpret_cast<const unsigned char*>(file_.data.data()) + pos_;
    pos_ += n;
    return b;
  }

  const File_bytes& file_;
  bool ascii_;
  bool big_endian_;
  Text_cursor text_;
  std::size_t pos_;
  const Ply_element* element_ = nullptr;
  std::uint64_t index_ = 0;
  const Ply_property* property_ = nullptr;
};

/// Reads a PLY file: the `x`, `y`, `z` properties of the `vertex` element
/// (of any numeric type) and the `vertex_indices` (or `vertex_index`) list
/// of the `face` element (any integer count and index types); other
/// elements and properties are skipped.
SPECTRALSEG_INLINE void read_ply(const File_bytes& file, Polygon_soup& soup)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Ply_header h = read_ply_header(file);
  Ply_values in(file, h);
  bool vertex_seen = false;
  for(const Ply_element& el : h.elements)
  {
    const bool is_vertex = el.name == "vertex", is_face = el.name == "face";
    int coordinate[3] = {-1, -1, -1};
    int indices = -1;
    for(std::size_t i = 0; i < el.properties.size(); ++i)
    {
      const Ply_property& p = el.properties[i];
      for(int c = 0; c < 3 && is_vertex; ++c)
        if(p.name == std::string(1, "xyz"[c]) && !p.list)
          coordinate[c] = int(i);
      if(is_face && p.list && (p.name == "vertex_indices" || p.name == "vertex_index"))
      {
        if(!p.type.integer)
          file.fail(", line " + std::to_string(el.header_line), "the face list '" + p.name + "' has a non-integer type");
        indices = int(i);
      }
    }
    if(is_vertex)
    {
      vertex_seen = true;
      if(coordinate[0] < 0 || coordinate[1] < 0 || coordinate[2] < 0)
        file.fail(", line " + std::to_string(el.header_line), "the vertex element lacks an x, y or z property");
      soup.points.reserve(soup.points.size() + el.count);
    }
    if(is_face && indices < 0)
      file.fail(", line " + std::to_string(el.header_line),
                "the face element has no 'vertex_indices' (or 'vertex_index') list");
    for(std::uint64_t e = 0; e < el.count; ++e)
    {
      std::array<double, 3> point{};
      for(std::size_t i = 0; i < el.properties.size(); ++i)
      {
        const Ply_property& p = el.properties[i];
        in.at(el, e, p);
        if(!p.list)
        {
          const int c = coordinate[0] == int(i) ? 0 : coordinate[1] == int(i) ? 1 : coordinate[2] == int(i) ? 2 : -1;
          if(is_vertex && c >= 0)
            point[std::size_t(c)] = in.real(p.type);
          else
            in.skip(p.type);
          continue;
        }
        const std::int64_t n = in.integer(p.count_type);
        if(n < 0)
          in.fail("the length of " + in.what() + " is negative");
        const bool face_list = int(i) == indices;
        if(face_list && n < 3 && !h.ascii)
          in.fail("face " + std::to_string(e) + " has " + std::to_string(n) +
                  " vertices: a binary face list of fewer than three is refused (it is how a truncated file "
                  "or wrong counts in the header read)");
        if(face_list && std::uint64_t(n) > max_face_vertices)
          in.fail("face " + std::to_string(e) + " has " + std::to_string(n) + " vertices; faces of more than " +
                  std::to_string(max_face_vertices) + " vertices are refused (split the polygon)");
        if(!in.can_hold(std::uint64_t(n), p.type.size))
          in.fail("the list " + in.what() + " announces " + std::to_string(n) + " items but the file ends first");
        for(std::int64_t k = 0; k < n; ++k)
        {
          if(!face_list)
          {
            in.skip(p.type);
            continue;
          }
          const std::int64_t v = in.integer(p.type);
          if(v < 0)
            in.fail("face " + std::to_string(e) + " refers to vertex " + std::to_string(v) + " (negative)");
          soup.corners.push_back(std::size_t(v));
        }
      }
      if(is_vertex)
        soup.points.push_back(point);
      if(is_face)
        soup.end_face();
    }
  }
  if(!vertex_seen)
    file.fail("", "the PLY header has no vertex element");
  if(in.trailing_data())
    in.fail("unexpected data after the last element the header announces (wrong counts in the header?)");
  // the face element may come before the vertex element: indices are checked last
  for(std::size_t f = 0; f < soup.number_of_faces(); ++f)
    for(std::size_t i = 0; i < soup.face_size(f); ++i)
      if(soup.face(f)[i] >= soup.points.size())
        file.fail("", "face " + std::to_string(f) + " refers to vertex " + std::to_string(soup.face(f)[i]) +
                        " but the file has " + std::to_string(soup.points.size()) + " vertices (numbered from 0)");
}
#else
;
#endif

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_READ_PLY_H
