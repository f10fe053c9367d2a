// Copyright (c) SpectralSeg contributors.
//
// Writing an `Image` to a PNG file with libpng (link with -lpng).

#ifndef SPECTRALSEG_RENDERING_WRITE_PNG_H
#define SPECTRALSEG_RENDERING_WRITE_PNG_H

#include <SpectralSeg/IO/Atomic_output_file.h>
#include <SpectralSeg/Rendering/Image.h>
#include <SpectralSeg/exceptions.h>

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>

namespace SpectralSeg {
namespace Rendering {
namespace internal {

/// \brief Plain-old-data error state shared with the libpng callbacks; it
/// holds no object with a destructor, so `longjmp` may cross it.
struct Png_error_state
{
  char message[256];
};

extern "C" {
/// \brief libpng error callback: records the message and jumps back to the
/// `setjmp` point of `write_png_stream()`.
inline void spectralseg_png_error_callback(png_structp png, png_const_charp message)
{
  Png_error_state* state = static_cast<Png_error_state*>(png_get_error_ptr(png));
  if(state != nullptr)
  {
    std::strncpy(state->message, message != nullptr ? message : "unknown libpng error",
                 sizeof(state->message) - 1);
    state->message[sizeof(state->message) - 1] = '\0';
  }
  png_longjmp(png, 1);
}

/// \brief libpng warning callback: warnings are not fatal and are ignored.
inline void spectralseg_png_warning_callback(png_structp, png_const_charp) {}
}

/// \brief Encodes `img` as an 8-bit RGB PNG into the open stream `file`.
///
/// Only trivially destructible objects live in this frame between `setjmp`
/// and the end of encoding, so a `longjmp` out of libpng is well defined.
/// \param file an open binary stream
/// \param img the image, at least 1x1
/// \param state receives the libpng message on failure
/// \return `true` on success
inline bool write_png_stream(std::FILE* file, const Image& img, Png_error_state& state)
{
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state,
                                            spectralseg_png_error_callback,
                                            spectralseg_png_warning_callback);
  if(png == nullptr)
  {
    std::strcpy(state.message, "cannot create the libpng write structure");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if(info == nullptr)
  {
    png_destroy_write_struct(&png, nullptr);
    std::strcpy(state.message, "cannot create the libpng info structure");
    return false;
  }
  // `png` and `info` are not modified after setjmp, so they need not be volatile.
  if(setjmp(png_jmpbuf(png)))
  {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info,
               static_cast<png_uint_32>(img.width), static_cast<png_uint_32>(img.height),
               8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  const std::size_t row_bytes = 3 * static_cast<std::size_t>(img.width);
  for(int y = 0; y < img.height; ++y)
    png_write_row(png, img.rgb.data() + static_cast<std::size_t>(y) * row_bytes);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

} // namespace internal

/// \brief Writes `img` to `path` as an 8-bit RGB PNG file.
/// \param path the output file, created or overwritten
/// \param img the image; must be at least 1x1 with `3 * width * height` bytes
/// \throws SpectralSeg::Invalid_input if the image is empty or inconsistent
/// \throws SpectralSeg::Io_error if the file cannot be opened or written; the
///         message names `path`, and an existing file is left unchanged
inline void write_png(const std::string& path, const Image& img)
{
  if(img.width <= 0 || img.height <= 0)
    throw Invalid_input("write_png: cannot write an empty image to '" + path + "'");
  const std::size_t n_pixels =
      static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
  if(img.rgb.size() != 3 * n_pixels)
    throw Invalid_input("write_png: image buffer size does not match its dimensions for '"
                                + path + "'");

  IO::Atomic_output_file file(path); // all or nothing: an old picture survives a failed write
  internal::Png_error_state state{};
  if(!internal::write_png_stream(file.file(), img, state))
    throw SpectralSeg::Io_error("write_png: cannot write '" + path + "': " + state.message);
  file.commit();
}

} // namespace Rendering
} // namespace SpectralSeg

#endif // SPECTRALSEG_RENDERING_WRITE_PNG_H
