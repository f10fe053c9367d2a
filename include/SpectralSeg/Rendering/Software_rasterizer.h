// Copyright (c) SpectralSeg contributors.
//
// A headless, flat-shaded, z-buffered software rasteriser for triangle meshes
// seen through an orthographic camera.

#ifndef SPECTRALSEG_RENDERING_SOFTWARE_RASTERIZER_H
#define SPECTRALSEG_RENDERING_SOFTWARE_RASTERIZER_H

#include <SpectralSeg/Rendering/Color_map.h>
#include <SpectralSeg/Rendering/Image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Rendering {
namespace internal {

/// \brief A 3D vector.
using Vec3 = std::array<double, 3>;

/// \brief Dot product.
inline double dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// \brief Cross product.
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// \brief Difference `a - b`.
inline Vec3 minus(const Vec3& a, const Vec3& b)
{
  return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

/// \brief Linear combination `a * s + b * t`.
inline Vec3 combine(const Vec3& a, double s, const Vec3& b, double t)
{
  return Vec3{a[0] * s + b[0] * t, a[1] * s + b[1] * t, a[2] * s + b[2] * t};
}

/// \brief Returns whether all coordinates are finite.
inline bool is_finite(const Vec3& a)
{
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

/// \brief Returns `a` scaled to unit length, or the zero vector if `a` is
/// zero or not finite.
inline Vec3 normalized(const Vec3& a)
{
  const double n = std::sqrt(dot(a, a));
  if(!(n > 0.0) || !std::isfinite(n))
    return Vec3{0.0, 0.0, 0.0};
  return Vec3{a[0] / n, a[1] / n, a[2] / n};
}

/// \brief Orthonormal camera frame: `right` points to the right of the image,
/// `up` to its top, `forward` from the camera into the scene.
struct Camera_frame
{
  Vec3 right;   ///< image x axis
  Vec3 up;      ///< image y axis (upwards)
  Vec3 forward; ///< viewing direction
};

/// \brief Builds the camera frame for a viewing direction and an up vector.
///
/// If `up` is zero or parallel to `direction`, an arbitrary up vector
/// perpendicular to `direction` is used instead.
/// \param direction the viewing direction, from the camera into the scene
/// \param up the direction that should appear upwards in the image
/// \throws SpectralSeg::Invalid_input if `direction` is zero or not finite
inline Camera_frame camera_frame(const Vec3& direction, const Vec3& up)
{
  const Vec3 f = normalized(direction);
  if(dot(f, f) == 0.0)
    throw Invalid_input("Software_rasterizer: view direction must be finite and non-zero");
  Vec3 r = normalized(cross(f, normalized(up)));
  if(dot(r, r) < 0.5)
  {
    // Up vector unusable: take the world axis least aligned with the view.
    const Vec3 axis = std::fabs(f[1]) < 0.9 ? Vec3{0.0, 1.0, 0.0} : Vec3{0.0, 0.0, 1.0};
    r = normalized(cross(f, axis));
  }
  return Camera_frame{r, cross(r, f), f};
}

/// \brief A sphere enclosing the rendered vertices.
struct Bounding_sphere
{
  Vec3 center;   ///< centre of the sphere
  double radius; ///< radius, 0 for a single point
  bool empty;    ///< whether no finite vertex was found
};

/// \brief Computes a sphere enclosing the finite vertices referenced by
/// `triangles`, centred on their bounding-box centre.
/// \param points the vertex positions
/// \param triangles the faces, with indices already checked
inline Bounding_sphere bounding_sphere(const std::vector<Vec3>& points,
                                       const std::vector<std::array<std::size_t, 3>>& triangles)
{
  const double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for(const auto& t : triangles)
    for(std::size_t v : t)
      if(is_finite(points[v]))
        for(int k = 0; k < 3; ++k)
        {
          lo[k] = std::min(lo[k], points[v][k]);
          hi[k] = std::max(hi[k], points[v][k]);
        }
  if(!(lo[0] <= hi[0]))
    return Bounding_sphere{Vec3{0.0, 0.0, 0.0}, 0.0, true};
  const Vec3 c = combine(lo, 0.5, hi, 0.5);
  double r2 = 0.0;
  for(const auto& t : triangles)
    for(std::size_t v : t)
      if(is_finite(points[v]))
      {
        const Vec3 d = minus(points[v], c);
        r2 = std::max(r2, dot(d, d));
      }
  return Bounding_sphere{c, std::sqrt(r2), false};
}

/// \brief Checks that there is one colour per triangle and that every vertex
/// index is valid.
/// \param n_points the number of vertices
/// \param triangles the faces
/// \param n_colors the number of per-face values supplied
/// \param what the name of the per-face values, for the error message
/// \throws SpectralSeg::Invalid_input on mismatch or out-of-range index
inline void check_mesh(std::size_t n_points,
                       const std::vector<std::array<std::size_t, 3>>& triangles,
                       std::size_t n_colors, const char* what)
{
  if(n_colors != triangles.size())
    throw Invalid_input(std::string("SpectralSeg::Rendering: ") + std::to_string(n_colors)
                                + " " + what + " given for " + std::to_string(triangles.size())
                                + " triangles");
  for(std::size_t f = 0; f < triangles.size(); ++f)
    for(std::size_t v : triangles[f])
      if(v >= n_points)
        throw Invalid_input("SpectralSeg::Rendering: triangle " + std::to_string(f)
                                    + " references vertex " + std::to_string(v) + " but only "
                                    + std::to_string(n_points) + " vertices exist");
}

/// \brief Averages each `factor` x `factor` block of `src` into one pixel.
/// \param src the image, with dimensions multiple of `factor`
/// \param factor the block size, at least 1
inline Image box_downsample(const Image& src, int factor)
{
  Image dst(src.width / factor, src.height / factor);
  const int n = factor * factor;
  for(int y = 0; y < dst.height; ++y)
    for(int x = 0; x < dst.width; ++x)
    {
      int sum[3] = {0, 0, 0};
      for(int dy = 0; dy < factor; ++dy)
        for(int dx = 0; dx < factor; ++dx)
        {
          const Rgb c = src.pixel(x * factor + dx, y * factor + dy);
          sum[0] += c.r;
          sum[1] += c.g;
          sum[2] += c.b;
        }
      dst.set_pixel(x, y, Rgb{static_cast<unsigned char>((sum[0] + n / 2) / n),
                              static_cast<unsigned char>((sum[1] + n / 2) / n),
                              static_cast<unsigned char>((sum[2] + n / 2) / n)});
    }
  return dst;
}

/// \brief Number of fractional bits of the fixed-point screen coordinates.
constexpr int subpixel_bits = 8;

/// \brief Largest accepted image side, keeping 64-bit edge functions exact.
constexpr int max_image_side = 32768;

/// \brief Ambient term of the flat shading.
constexpr double ambient = 0.35;

/// \brief Diffuse weight of the flat shading.
constexpr double diffuse = 0.65;

/// \brief Fraction of the half viewport left free around the fitted mesh.
constexpr double fit_margin = 0.05;

} // namespace internal

/// \brief Renders triangle meshes with one colour per face into an `Image`.
///
/// The camera is orthographic; the bounding sphere of the mesh is fitted into
/// the viewport with a small margin, so every view of the same mesh uses the
/// same scale. Faces are flat shaded with `colour * (0.35 + 0.65 |n.l|)` for a
/// light placed slightly above and to the left of the camera; the absolute
/// value makes the shading two-sided, so open or inconsistently oriented
/// meshes render correctly. Hidden surfaces are removed with a z-buffer.
///
/// Rasterisation samples pixel centres with exact fixed-point edge functions
/// (8 subpixel bits) and the top-left fill rule, so faces sharing an edge
/// neither overlap nor leave gaps. Optionally each pixel is the average of a
/// 2x2 block of samples. Triangles with a non-finite vertex or a zero area are
/// skipped. The background is white.
class Software_rasterizer
{
public:
  /// \brief 3D point type of the input.
  using Point_3 = std::array<double, 3>;
  /// \brief Triangle type of the input: three indices into the points.
  using Triangle = std::array<std::size_t, 3>;

  /// \brief Creates a rasteriser producing `width` x `height` images.
  /// \param width the image width in pixels, in [1, 16384]
  /// \param height the image height in pixels, in [1, 16384]
  /// \param supersample whether to average 2x2 samples per pixel
  /// \throws SpectralSeg::Invalid_input if a size is out of range
  Software_rasterizer(int width, int height, bool supersample = true)
    : width_(width), height_(height), supersample_(supersample)
  {
    if(width < 1 || height < 1 || width > internal::max_image_side / 2
       || height > internal::max_image_side / 2)
      throw Invalid_input("Software_rasterizer: image size must be in [1, "
                                  + std::to_string(internal::max_image_side / 2) + "]");
  }

  /// \brief Returns the width of the rendered images.
  int width() const { return width_; }

  /// \brief Returns the height of the rendered images.
  int height() const { return height_; }

  /// \brief Returns whether 2x2 supersampling is enabled.
  bool supersample() const { return supersample_; }

  /// \brief Renders a mesh with per-face colours.
  /// \param points the vertex positions
  /// \param triangles the faces, as indices into `points`
  /// \param face_colors one colour per face
  /// \param view_direction the direction the camera looks along (from the
  ///        camera into the scene), e.g. `{0, 0, -1}` for a camera on +Z
  /// \param up the world direction shown upwards in the image
  /// \return the image, white where no face is visible
  /// \throws SpectralSeg::Invalid_input if `face_colors` does not have one colour
  ///         per face, an index is out of range, or `view_direction` is zero
  Image render(const std::vector<Point_3>& points,
               const std::vector<Triangle>& triangles,
               const std::vector<Rgb>& face_colors,
               const Point_3& view_direction,
               const Point_3& up) const
  {
    internal::check_mesh(points.size(), triangles, face_colors.size(), "face colours");
    const internal::Camera_frame cam = internal::camera_frame(view_direction, up);
    const int factor = supersample_ ? 2 : 1;
    Image target(width_ * factor, height_ * factor);
    const internal::Bounding_sphere sphere = internal::bounding_sphere(points, triangles);
    if(!sphere.empty)
      rasterize(points, triangles, face_colors, cam, sphere, target);
    return factor == 1 ? target : internal::box_downsample(target, factor);
  }

private:
  struct Screen_vertex
  {
    std::int64_t x, y; // fixed-point image coordinates, y downwards
    double depth;      // distance along the viewing direction
    bool valid;        // finite input position
  };

  static void rasterize(const std::vector<Point_3>& points,
                        const std::vector<Triangle>& triangles,
                        const std::vector<Rgb>& face_colors,
                        const internal::Camera_frame& cam,
                        const internal::Bounding_sphere& sphere,
                        Image& target)
  {
    using internal::dot;
    const int W = target.width, H = target.height;
    const std::int64_t one = std::int64_t(1) << internal::subpixel_bits;
    const std::int64_t half = one / 2;

    // Project every vertex once into fixed-point screen space, so that shared
    // edges are bit-identical in all incident triangles.
    const double scale = sphere.radius > 0.0
                             ? 0.5 * std::min(W, H) * (1.0 - internal::fit_margin) / sphere.radius
                             : 1.0;
    std::vector<Screen_vertex> screen(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      Screen_vertex& s = screen[i];
      s.valid = internal::is_finite(points[i]);
      if(!s.valid)
        continue;
      const internal::Vec3 d = internal::minus(points[i], sphere.center);
      const double sx = 0.5 * W + scale * dot(d, cam.right);
      const double sy = 0.5 * H - scale * dot(d, cam.up);
      s.depth = dot(d, cam.forward);
      // Unreferenced vertices may lie far outside; keep them out of overflow range.
      const double limit = 4.0 * internal::max_image_side;
      s.valid = std::fabs(sx) < limit && std::fabs(sy) < limit && std::isfinite(s.depth);
      s.x = std::llround(sx * double(one));
      s.y = std::llround(sy * double(one));
    }

    // Headlight moved slightly up and to the left of the camera.
    const internal::Vec3 towards_camera_and_up = internal::combine(cam.forward, -1.0, cam.up, 0.35);
    const internal::Vec3 light =
        internal::normalized(internal::combine(towards_camera_and_up, 1.0, cam.right, -0.3));

    std::vector<float> zbuffer(static_cast<std::size_t>(W) * static_cast<std::size_t>(H),
                               std::numeric_limits<float>::infinity());

    for(std::size_t f = 0; f < triangles.size(); ++f)
    {
      std::size_t i0 = triangles[f][0], i1 = triangles[f][1], i2 = triangles[f][2];
      if(!screen[i0].valid || !screen[i1].valid || !screen[i2].valid)
        continue;
      const internal::Vec3 n = internal::normalized(internal::cross(
          internal::minus(points[i1], points[i0]), internal::minus(points[i2], points[i0])));
      if(dot(n, n) == 0.0)
        continue; // zero area in 3D

      const double intensity = internal::ambient + internal::diffuse * std::fabs(dot(n, light));
      const Rgb base = face_colors[f];
      const Rgb shaded{internal::to_channel(base.r / 255.0 * intensity),
                       internal::to_channel(base.g / 255.0 * intensity),
                       internal::to_channel(base.b / 255.0 * intensity)};

      std::int64_t area = orient(screen[i0], screen[i1], screen[i2]);
      if(area == 0)
        continue; // seen edge-on
      if(area < 0)
      {
        std::swap(i1, i2);
        area = -area;
      }
      const Screen_vertex& a = screen[i0];
      const Screen_vertex& b = screen[i1];
      const Screen_vertex& c = screen[i2];

      // Pixels whose centre x * one + half lies in the bounding box, clipped.
      const std::int64_t min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
      const std::int64_t min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
      const int x0 = int(std::max<std::int64_t>(0, ceil_div(min_x - half, one)));
      const int x1 = int(std::min<std::int64_t>(W - 1, floor_div(max_x - half, one)));
      const int y0 = int(std::max<std::int64_t>(0, ceil_div(min_y - half, one)));
      const int y1 = int(std::min<std::int64_t>(H - 1, floor_div(max_y - half, one)));
      if(x0 > x1 || y0 > y1)
        continue;

      // Edge functions, each positive on the interior side; w_k vanishes on
      // the edge opposite vertex k.
      Edge e0(b, c, one), e1(c, a, one), e2(a, b, one);
      const std::int64_t px = std::int64_t(x0) * one + half;
      const std::int64_t py = std::int64_t(y0) * one + half;
      std::int64_t row0 = e0.at(px, py), row1 = e1.at(px, py), row2 = e2.at(px, py);
      const double inv_area = 1.0 / double(area);

      for(int y = y0; y <= y1; ++y)
      {
        std::int64_t w0 = row0, w1 = row1, w2 = row2;
        float* zrow = zbuffer.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(W);
        for(int x = x0; x <= x1; ++x)
        {
          if(((w0 + e0.bias) | (w1 + e1.bias) | (w2 + e2.bias)) >= 0)
          {
            const float z = float((double(w0) * a.depth + double(w1) * b.depth
                                   + double(w2) * c.depth) * inv_area);
            if(z < zrow[x])
            {
              zrow[x] = z;
              target.set_pixel(x, y, shaded);
            }
          }
          w0 += e0.step_x;
          w1 += e1.step_x;
          w2 += e2.step_x;
        }
        row0 += e0.step_y;
        row1 += e1.step_y;
        row2 += e2.step_y;
      }
    }
  }

  // Twice the signed area of (a, b, c); positive for clockwise order on
  // screen (y pointing down).
  static std::int64_t orient(const Screen_vertex& a, const Screen_vertex& b, const Screen_vertex& c)
  {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  }

  static std::int64_t floor_div(std::int64_t a, std::int64_t b)
  {
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
  }

  static std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }

  // Edge function of the directed edge a->b, with per-pixel increments and
  // the top-left fill rule bias: samples exactly on an edge belong to the
  // triangle only when that edge is a top or a left edge.
  struct Edge
  {
    std::int64_t ax, ay, dx, dy;
    std::int64_t step_x, step_y, bias;

    Edge(const Screen_vertex& a, const Screen_vertex& b, std::int64_t one)
      : ax(a.x), ay(a.y), dx(b.x - a.x), dy(b.y - a.y),
        step_x(-(b.y - a.y) * one), step_y((b.x - a.x) * one),
        bias((dy < 0 || (dy == 0 && dx > 0)) ? 0 : -1)
    {}

    std::int64_t at(std::int64_t px, std::int64_t py) const
    {
      return dx * (py - ay) - dy * (px - ax);
    }
  };

  int width_;
  int height_;
  bool supersample_;
};

} // namespace Rendering
} // namespace SpectralSeg

#endif // SPECTRALSEG_RENDERING_SOFTWARE_RASTERIZER_H
