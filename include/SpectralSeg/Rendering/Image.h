// Copyright (c) SpectralSeg contributors.
//
// A minimal 8-bit RGB raster image.

#ifndef SPECTRALSEG_RENDERING_IMAGE_H
#define SPECTRALSEG_RENDERING_IMAGE_H

#include <SpectralSeg/Rendering/Color_map.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace SpectralSeg {
namespace Rendering {

/// \brief An 8-bit RGB image stored row by row from the top-left corner,
/// three bytes per pixel.
struct Image
{
  int width = 0;                  ///< number of columns
  int height = 0;                 ///< number of rows
  std::vector<unsigned char> rgb; ///< `3 * width * height` bytes, row-major

  /// \brief Creates an empty 0x0 image.
  Image() = default;

  /// \brief Creates a `w` x `h` image filled with `background`.
  /// \param w the width, non-negative
  /// \param h the height, non-negative
  /// \param background the initial colour of every pixel
  Image(int w, int h, Rgb background = Rgb{255, 255, 255})
    : width(w), height(h)
  {
    if(w < 0 || h < 0)
      throw Invalid_input("Image: negative size");
    rgb.resize(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    fill(background);
  }

  /// \brief Returns whether `(x, y)` lies inside the image.
  /// \param x the column
  /// \param y the row, 0 at the top
  bool contains(int x, int y) const
  {
    return x >= 0 && y >= 0 && x < width && y < height;
  }

  /// \brief Returns the colour of pixel `(x, y)`.
  /// \pre `contains(x, y)`
  /// \param x the column
  /// \param y the row, 0 at the top
  Rgb pixel(int x, int y) const
  {
    const std::size_t i = offset(x, y);
    return Rgb{rgb[i], rgb[i + 1], rgb[i + 2]};
  }

  /// \brief Sets the colour of pixel `(x, y)`.
  /// \pre `contains(x, y)`
  /// \param x the column
  /// \param y the row, 0 at the top
  /// \param c the new colour
  void set_pixel(int x, int y, Rgb c)
  {
    const std::size_t i = offset(x, y);
    rgb[i] = c.r;
    rgb[i + 1] = c.g;
    rgb[i + 2] = c.b;
  }

  /// \brief Sets every pixel to `c`.
  /// \param c the colour
  void fill(Rgb c)
  {
    for(std::size_t i = 0; i + 2 < rgb.size(); i += 3)
    {
      rgb[i] = c.r;
      rgb[i + 1] = c.g;
      rgb[i + 2] = c.b;
    }
  }

  /// \brief Copies `src` into this image with its top-left corner at
  /// `(x0, y0)`; the parts falling outside this image are clipped.
  /// \param src the image to copy
  /// \param x0 the destination column of the left edge of `src`
  /// \param y0 the destination row of the top edge of `src`
  void paste(const Image& src, int x0, int y0)
  {
    const int xa = std::max(0, x0), xb = std::min(width, x0 + src.width);
    const int ya = std::max(0, y0), yb = std::min(height, y0 + src.height);
    if(xa >= xb || ya >= yb)
      return;
    const std::size_t row_bytes = 3 * static_cast<std::size_t>(xb - xa);
    for(int y = ya; y < yb; ++y)
      std::copy_n(src.rgb.begin() + static_cast<std::ptrdiff_t>(src.offset(xa - x0, y - y0)),
                  row_bytes,
                  rgb.begin() + static_cast<std::ptrdiff_t>(offset(xa, y)));
  }

private:
  std::size_t offset(int x, int y) const
  {
    return 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width)
                + static_cast<std::size_t>(x));
  }
};

} // namespace Rendering
} // namespace SpectralSeg

#endif // SPECTRALSEG_RENDERING_IMAGE_H
