// Copyright (c) SpectralSeg contributors.
//
// Colour maps turning per-face scalar fields and per-face integer labels into
// RGB colours for the software renderer.

#ifndef SPECTRALSEG_RENDERING_COLOR_MAP_H
#define SPECTRALSEG_RENDERING_COLOR_MAP_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace SpectralSeg {
namespace Rendering {

/// \brief An 8-bit-per-channel RGB colour.
struct Rgb
{
  unsigned char r; ///< red channel
  unsigned char g; ///< green channel
  unsigned char b; ///< blue channel
};

/// \brief Component-wise equality of two colours.
inline bool operator==(const Rgb& a, const Rgb& b)
{
  return a.r == b.r && a.g == b.g && a.b == b.b;
}

/// \brief Component-wise inequality of two colours.
inline bool operator!=(const Rgb& a, const Rgb& b) { return !(a == b); }

namespace internal {

/// \brief Converts a channel value in [0,1] to an 8-bit channel, clamping.
inline unsigned char to_channel(double v)
{
  const double c = std::min(1.0, std::max(0.0, v));
  return static_cast<unsigned char>(std::lround(c * 255.0));
}

/// \brief Converts an HSL colour to RGB.
/// \param hue_degrees hue in degrees, any real value (taken modulo 360)
/// \param saturation saturation in [0,1]
/// \param lightness lightness in [0,1]
inline Rgb hsl_to_rgb(double hue_degrees, double saturation, double lightness)
{
  double h = std::fmod(hue_degrees, 360.0);
  if(h < 0.0)
    h += 360.0;
  const double c = (1.0 - std::fabs(2.0 * lightness - 1.0)) * saturation;
  const double hp = h / 60.0;
  const double x = c * (1.0 - std::fabs(std::fmod(hp, 2.0) - 1.0));
  double r = 0.0, g = 0.0, b = 0.0;
  if(hp < 1.0)      { r = c; g = x; }
  else if(hp < 2.0) { r = x; g = c; }
  else if(hp < 3.0) { g = c; b = x; }
  else if(hp < 4.0) { g = x; b = c; }
  else if(hp < 5.0) { r = x; b = c; }
  else              { r = c; b = x; }
  const double m = lightness - 0.5 * c;
  return Rgb{to_channel(r + m), to_channel(g + m), to_channel(b + m)};
}

/// \brief Builds a colour from a 0xRRGGBB literal.
constexpr Rgb hex_color(unsigned int rgb)
{
  return Rgb{static_cast<unsigned char>((rgb >> 16) & 0xFFu),
             static_cast<unsigned char>((rgb >> 8) & 0xFFu),
             static_cast<unsigned char>(rgb & 0xFFu)};
}

/// \brief The categorical palette used by `label_color()`: the Tableau 10
/// colours (without its grey) followed by ten further hues chosen to stay
/// apart in CIELAB from the others and from the missing-value grey.
constexpr std::array<Rgb, 20> label_palette{{
  hex_color(0x4E79A7), hex_color(0xF28E2B), hex_color(0xE15759), hex_color(0x76B7B2),
  hex_color(0x59A14F), hex_color(0xEDC948), hex_color(0xB07AA1), hex_color(0xFF9DA7),
  hex_color(0x9C755F), hex_color(0x0BB4E0), hex_color(0x9EA7F5), hex_color(0x8DB600),
  hex_color(0x7A1FA2), hex_color(0x882D17), hex_color(0xD9C8A0), hex_color(0xD6338A),
  hex_color(0x00695C), hex_color(0x6B6B1F), hex_color(0x1A2A6C), hex_color(0xC9F07A)
}};

} // namespace internal

/// \brief Maps a normalised scalar to a colour, blue for small and red for
/// large values.
///
/// The hue is interpolated in HSL from 240 degrees (blue) at `t = 0` down to
/// 0 degrees (red) at `t = 1`, passing through cyan, green and yellow, with
/// full saturation and lightness 0.5.
/// \param t the normalised value; clamped to [0,1], NaN maps to 0
inline Rgb field_color(double t)
{
  if(!(t >= 0.0))
    t = 0.0;
  if(t > 1.0)
    t = 1.0;
  return internal::hsl_to_rgb(240.0 * (1.0 - t), 1.0, 0.5);
}

/// \brief Returns the colour of a segment label from a fixed palette of 20
/// well-separated colours, cycling for larger labels.
/// \param label the non-negative label
inline Rgb label_color(std::size_t label)
{
  return internal::label_palette[label % internal::label_palette.size()];
}

/// \brief Returns the mid grey used for missing data: non-finite field values
/// and negative labels.
inline Rgb missing_color() { return Rgb{128, 128, 128}; }

/// \brief Colours a scalar field, normalising its finite values linearly from
/// their minimum to their maximum onto [0,1] before applying `field_color()`.
///
/// A constant field maps entirely to `field_color(0)`; non-finite values
/// (NaN, infinities) map to `missing_color()`.
/// \param field one value per element
inline std::vector<Rgb> field_colors(const std::vector<double>& field)
{
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  for(double v : field)
  {
    if(std::isfinite(v))
    {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  const double range = hi - lo;
  std::vector<Rgb> colors;
  colors.reserve(field.size());
  for(double v : field)
  {
    if(!std::isfinite(v))
      colors.push_back(missing_color());
    else if(range > 0.0 && std::isfinite(range))
      colors.push_back(field_color((v - lo) / range));
    else if(range > 0.0) // range overflows a double: scale before subtracting
      colors.push_back(field_color((v * 0.5 - lo * 0.5) / (hi * 0.5 - lo * 0.5)));
    else
      colors.push_back(field_color(0.0));
  }
  return colors;
}

/// \brief Colours integer labels with `label_color()`; negative labels map to
/// `missing_color()`.
/// \param labels one label per element
inline std::vector<Rgb> label_colors(const std::vector<int>& labels)
{
  std::vector<Rgb> colors;
  colors.reserve(labels.size());
  for(int l : labels)
    colors.push_back(l < 0 ? missing_color() : label_color(static_cast<std::size_t>(l)));
  return colors;
}

} // namespace Rendering
} // namespace SpectralSeg

#endif // SPECTRALSEG_RENDERING_COLOR_MAP_H
