// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Binary_cursor.h
/// \brief Integers and floats of the binary mesh formats, bounds-checked.
#ifndef SPECTRALSEG_IO_INTERNAL_BINARY_CURSOR_H
#define SPECTRALSEG_IO_INTERNAL_BINARY_CURSOR_H

#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/Text_cursor.h>
#include <SpectralSeg/exceptions.h>

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// 32-bit values of a binary file in a given byte order, read from an
// offset on; every read checks that the bytes exist, and messages give the
// byte at fault.
class Binary_cursor
{
public:
  Binary_cursor(const File_bytes& file, std::size_t begin, bool big_endian)
    : file_(&file), pos_(begin), big_endian_(big_endian)
  {}

  std::size_t remaining() const { return file_->data.size() - pos_; }
  std::string where() const { return ", byte " + std::to_string(pos_); }
  [[noreturn]] void fail(const std::string& what) const { file_->fail(where(), what); }

  // the next 32-bit unsigned integer
  std::uint32_t uint32(const Label& what)
  {
    if(remaining() < 4)
      fail("the file ends where " + what.str() + " was expected (truncated file or wrong counts in the header)");
    const unsigned char* b = reinterpret_cast<const unsigned char*>(file_->data.data()) + pos_;
    pos_ += 4;
    std::uint32_t u = 0;
    for(int i = 0; i < 4; ++i)
      u |= std::uint32_t(b[big_endian_ ? 3 - i : i]) << (8 * i);
    return u;
  }
  // the next 32-bit two's-complement integer
  std::int32_t int32(const Label& what)
  {
    const std::uint32_t u = uint32(what);
    return u < 0x80000000u ? std::int32_t(u) : std::int32_t(std::int64_t(u) - (std::int64_t(1) << 32));
  }
  // the next 32-bit integer, which must be in [lo, hi]
  std::int32_t int32_in(const Label& what, std::int32_t lo, std::int32_t hi)
  {
    const std::int32_t v = int32(what);
    if(v < lo || v > hi)
      file_->fail(", byte " + std::to_string(pos_ - 4), what.str() + " is " + std::to_string(v) + ", not in [" +
                                                          std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  }
  // the next 32-bit float, which must be finite
  double float32(const Label& what)
  {
    const std::uint32_t u = uint32(what);
    float f = 0.f;
    std::memcpy(&f, &u, 4);
    if(!std::isfinite(f))
      throw Invalid_input(file_->message(", byte " + std::to_string(pos_ - 4),
                                         what.str() + " is non-finite (NaN or infinity)"));
    return double(f);
  }
  // whether a byte other than whitespace follows
  bool trailing_data() const
  {
    for(std::size_t i = pos_; i < file_->data.size(); ++i)
      if(!std::isspace(static_cast<unsigned char>(file_->data[i])))
        return true;
    return false;
  }

private:
  const File_bytes* file_;
  std::size_t pos_;
  bool big_endian_;
};

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_BINARY_CURSOR_H
