// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file trace_outer_contour.h
/// \brief The outer contour of a set of 2D triangles, traced on a raster
/// (thesis 6.2.3).
#ifndef SPECTRALSEG_SEGMENTABILITY_TRACE_OUTER_CONTOUR_H
#define SPECTRALSEG_SEGMENTABILITY_TRACE_OUTER_CONTOUR_H

#include <SpectralSeg/Segmentability/Contour.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Segmentability {

/// \cond SKIP_IN_MANUAL
namespace internal {

// A square black-and-white raster; pixel (i, j) is the unit square centred
// at (i, j), i along x, j along y (not flipped).
struct Binary_raster
{
  int size = 0;
  std::vector<unsigned char> black;

  explicit Binary_raster(int s) : size(s), black(std::size_t(s) * std::size_t(s), 0) {}
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < size && j < size; }
  unsigned char& at(int i, int j) { return black[std::size_t(j) * std::size_t(size) + std::size_t(i)]; }
  unsigned char at(int i, int j) const { return black[std::size_t(j) * std::size_t(size) + std::size_t(i)]; }
};

// Marks every pixel whose closed square meets the closed triangle abc
// (conservative rasterisation by the separating axis test: the two raster
// axes through the pixel range, the three edge normals per pixel). A
// degenerate triangle marks the pixels its segment passes through.
SPECTRALSEG_INLINE void draw_triangle_conservatively(Binary_raster& raster, const Eigen::Vector2d& a,
                                                     const Eigen::Vector2d& b, const Eigen::Vector2d& c)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Eigen::Vector2d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
  const int i0 = std::max(0, int(std::ceil(lo.x() - 0.5))), i1 = std::min(raster.size - 1, int(std::floor(hi.x() + 0.5)));
  const int j0 = std::max(0, int(std::ceil(lo.y() - 0.5))), j1 = std::min(raster.size - 1, int(std::floor(hi.y() + 0.5)));
  const Eigen::Vector2d corners[3] = {a, b, c};
  Eigen::Vector2d normal[3];
  double low[3], high[3], reach[3];
  for(int e = 0; e < 3; ++e)
  {
    const Eigen::Vector2d edge = corners[(e + 1) % 3] - corners[e];
    normal[e] = Eigen::Vector2d(-edge.y(), edge.x());
    low[e] = high[e] = normal[e].dot(corners[0]);
    for(int k = 1; k < 3; ++k)
    {
      const double d = normal[e].dot(corners[k]);
      low[e] = std::min(low[e], d);
      high[e] = std::max(high[e], d);
    }
    // half the width of a pixel along the normal, plus a little so that
    // touching counts as meeting
    reach[e] = 0.5 * (std::abs(normal[e].x()) + std::abs(normal[e].y())) * (1. + 1e-9);
  }
  for(int j = j0; j <= j1; ++j)
    for(int i = i0; i <= i1; ++i)
    {
      bool meets = true;
      for(int e = 0; e < 3 && meets; ++e)
      {
        const double centre = normal[e].x() * i + normal[e].y() * j;
        meets = centre + reach[e] >= low[e] && centre - reach[e] <= high[e];
      }
      if(meets)
        raster.at(i, j) = 1;
    }
}
#else
;
#endif

// The eight neighbours, counter-clockwise from east (y up).
SPECTRALSEG_INLINE const std::array<std::array<int, 2>, 8>& moore_offsets()
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  static const std::array<std::array<int, 2>, 8> offsets = {
      {{{1, 0}}, {{1, 1}}, {{0, 1}}, {{-1, 1}}, {{-1, 0}}, {{-1, -1}}, {{0, -1}}, {{1, -1}}}};
  return offsets;
}
#else
;
#endif

SPECTRALSEG_INLINE int moore_index(int di, int dj)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const auto& offsets = moore_offsets();
  for(int k = 0; k < 8; ++k)
    if(offsets[std::size_t(k)][0] == di && offsets[std::size_t(k)][1] == dj)
      return k;
  return -1;
}
#else
;
#endif

// Keeps only the largest 8-connected black region (ties: the one met first
// in row order). Returns its first pixel in row order (lowest row, then
// leftmost), or {-1, -1} if the raster is white.
SPECTRALSEG_INLINE std::array<int, 2> keep_largest_region(Binary_raster& raster)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const int s = raster.size;
  std::vector<int> region(raster.black.size(), -1);
  std::vector<std::size_t> sizes;
  std::vector<std::array<int, 2>> firsts, stack;
  for(int j = 0; j < s; ++j)
    for(int i = 0; i < s; ++i)
    {
      const std::size_t id = std::size_t(j) * std::size_t(s) + std::size_t(i);
      if(!raster.black[id] || region[id] >= 0)
        continue;
      const int r = int(sizes.size());
      sizes.push_back(0);
      firsts.push_back({{i, j}});
      region[id] = r;
      stack.push_back({{i, j}});
      while(!stack.empty())
      {
        const std::array<int, 2> p = stack.back();
        stack.pop_back();
        ++sizes.back();
        for(const auto& o : moore_offsets())
        {
          const int ni = p[0] + o[0], nj = p[1] + o[1];
          if(!raster.inside(ni, nj))
            continue;
          const std::size_t nid = std::size_t(nj) * std::size_t(s) + std::size_t(ni);
          if(raster.black[nid] && region[nid] < 0)
          {
            region[nid] = r;
            stack.push_back({{ni, nj}});
          }
        }
      }
    }
  if(sizes.empty())
    return {{-1, -1}};
  const int best = int(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for(std::size_t id = 0; id < region.size(); ++id)
    raster.black[id] = region[id] == best ? 1 : 0;
  return firsts[std::size_t(best)];
}
#else
;
#endif

// Moore-neighbour tracing of the outer boundary of the 8-connected region
// whose lowest-leftmost pixel is `start`. Stops when the first move is
// about to be repeated. Pixels on one-pixel-wide necks appear twice.
SPECTRALSEG_INLINE std::vector<std::array<int, 2>> moore_trace(const Binary_raster& raster, std::array<int, 2> start)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const auto& offsets = moore_offsets();
  auto black = [&](int i, int j) { return raster.inside(i, j) && raster.at(i, j) != 0; };
  std::vector<std::array<int, 2>> boundary{start};
  std::array<int, 2> current = start, first_next{{-1, -1}};
  int backtrack = 4; // west of the start pixel is white (it is the leftmost of the lowest row)
  const std::size_t limit = 4 * raster.black.size() + 8;
  for(std::size_t step = 0; step < limit; ++step)
  {
    int found = -1;
    for(int k = 1; k <= 8; ++k)
    {
      const int d = (backtrack + k) % 8;
      if(black(current[0] + offsets[std::size_t(d)][0], current[1] + offsets[std::size_t(d)][1]))
      {
        found = d;
        break;
      }
    }
    if(found < 0)
      break; // an isolated pixel
    const std::array<int, 2> next{
        {current[0] + offsets[std::size_t(found)][0], current[1] + offsets[std::size_t(found)][1]}};
    if(step > 0 && current == start && next == first_next)
    {
      boundary.pop_back(); // `start` again
      break;
    }
    if(step == 0)
      first_next = next;
    // the last white neighbour looked at, seen from the next pixel
    const int previous = (found + 7) % 8;
    const int wi = current[0] + offsets[std::size_t(previous)][0] - next[0];
    const int wj = current[1] + offsets[std::size_t(previous)][1] - next[1];
    backtrack = moore_index(wi, wj);
    current = next;
    boundary.push_back(current);
  }
  return boundary;
}
#else
;
#endif

// The holes of the black region: the white pixels that no 4-connected
// white path joins to the raster's border (the black region is
// 8-connected, so a 4-connected white path cannot cross it). Returns their
// share of the pixels inside the region's outer boundary and the length of
// their boundaries in pixels (the pixel sides between a hole and the region,
// times pi/4, the mean ratio of a curve's length to its length along the
// two axes).
SPECTRALSEG_INLINE std::pair<double, double> raster_holes(const Binary_raster& raster)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const int s = raster.size;
  std::vector<unsigned char> outside(raster.black.size(), 0);
  std::vector<std::array<int, 2>> stack;
  auto visit = [&](int i, int j) {
    if(!raster.inside(i, j) || raster.at(i, j))
      return;
    unsigned char& o = outside[std::size_t(j) * std::size_t(s) + std::size_t(i)];
    if(o)
      return;
    o = 1;
    stack.push_back({{i, j}});
  };
  for(int k = 0; k < s; ++k)
  {
    visit(k, 0);
    visit(k, s - 1);
    visit(0, k);
    visit(s - 1, k);
  }
  while(!stack.empty())
  {
    const std::array<int, 2> p = stack.back();
    stack.pop_back();
    visit(p[0] + 1, p[1]);
    visit(p[0] - 1, p[1]);
    visit(p[0], p[1] + 1);
    visit(p[0], p[1] - 1);
  }
  std::size_t black = 0, holes = 0, sides = 0;
  for(int j = 0; j < s; ++j)
    for(int i = 0; i < s; ++i)
    {
      const std::size_t id = std::size_t(j) * std::size_t(s) + std::size_t(i);
      if(raster.black[id])
        ++black;
      else if(!outside[id])
      {
        ++holes;
        // a hole pixel is never on the raster's border
        sides += std::size_t(raster.at(i + 1, j) != 0) + std::size_t(raster.at(i - 1, j) != 0) +
                 std::size_t(raster.at(i, j + 1) != 0) + std::size_t(raster.at(i, j - 1) != 0);
      }
    }
  const double pi = 3.14159265358979323846;
  return {black + holes > 0 ? double(holes) / double(black + holes) : 0., double(sides) * pi / 4.};
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegSegmentability
/// \brief Draws 2D triangles on a square raster and returns the outer
/// boundary of the largest black region, as a counter-clockwise contour in
/// the coordinates of the input.
///
/// The raster has `resolution` x `resolution` pixels and is fitted to the
/// bounding box of the vertices used by `triangles`, with the same scale on
/// both axes, the box centred and a margin of at least two white pixels on
/// every side. A triangle marks every pixel whose square it touches
/// (conservative rasterisation), so that thin and degenerate triangles are
/// drawn too and the triangles of a connected mesh give one 8-connected
/// region. Only the largest 8-connected region is kept (ties: the one with
/// the lowest, then leftmost pixel); its outer boundary is traced by Moore
/// neighbour tracing, so holes are ignored. The contour is made of the
/// centres of the boundary pixels, mapped back to the input's coordinates;
/// a pixel on a one-pixel-wide neck appears twice, and a region of a single
/// pixel gives a single point. The region is at least a pixel thicker than
/// the triangles (about one pixel all around).
///
/// \param points the 2D vertex positions
/// \param triangles vertex index triples into `points`
/// \param resolution the width and height of the raster in pixels (the
///        thesis uses 200)
/// \param holes if not null, set to the share of the pixels inside the
///        traced boundary that the triangles do not cover (the projection's
///        holes, e.g. the opening of a handle) and the length of the holes'
///        boundaries in the input's coordinates (0 and 0 when there is
///        nothing to draw)
/// \return the contour, or an empty contour when there is nothing to draw:
///         no triangle, or all the vertices used by the triangles at the
///         same point
/// \throws Invalid_input if a point is not finite, an index is out of
///         range, or `resolution` is smaller than 8
SPECTRALSEG_INLINE Contour trace_outer_contour(const std::vector<Eigen::Vector2d>& points,
                                               const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                               std::size_t resolution = 200,
                                               std::pair<double, double>* holes = nullptr)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(holes)
    *holes = {0., 0.};
  if(resolution < 8 || resolution > 100000)
    throw Invalid_input("trace_outer_contour: the resolution must be in [8, 100000], got " +
                        std::to_string(resolution));
  for(const Eigen::Vector2d& p : points)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw Invalid_input("trace_outer_contour: a point has a non-finite coordinate");
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for(const auto& t : triangles)
    for(std::uint32_t v : t)
    {
      if(v >= points.size())
        throw Invalid_input("trace_outer_contour: vertex index " + std::to_string(v) + " out of range (" +
                            std::to_string(points.size()) + " points)");
      lo = lo.cwiseMin(points[v]);
      hi = hi.cwiseMax(points[v]);
    }
  Contour contour;
  if(triangles.empty())
    return contour;
  const Eigen::Vector2d size = hi - lo;
  const double extent = size.maxCoeff();
  if(!(extent > 0.) || !std::isfinite(extent))
    return contour;

  const int pixels = int(resolution);
  const double margin = 2.;
  const double usable = double(pixels - 1) - 2. * margin; // between the first and last pixel centres
  const double scale = usable / extent;
  const Eigen::Vector2d offset = Eigen::Vector2d::Constant(margin) + 0.5 * (usable * Eigen::Vector2d::Ones() - scale * size);
  auto to_raster = [&](const Eigen::Vector2d& p) -> Eigen::Vector2d { return offset + scale * (p - lo); };

  internal::Binary_raster raster(pixels);
  for(const auto& t : triangles)
    internal::draw_triangle_conservatively(raster, to_raster(points[t[0]]), to_raster(points[t[1]]),
                                           to_raster(points[t[2]]));
  const std::array<int, 2> start = internal::keep_largest_region(raster);
  if(start[0] < 0)
    return contour;
  if(holes)
  {
    *holes = internal::raster_holes(raster);
    holes->second /= scale;
  }
  const std::vector<std::array<int, 2>> boundary = internal::moore_trace(raster, start);
  contour.reserve(boundary.size());
  for(const auto& b : boundary)
    contour.push_back(lo + (Eigen::Vector2d(double(b[0]), double(b[1])) - offset) / scale);
  internal::make_counterclockwise(contour);
  return contour;
}
#else
;
#endif

} // namespace Segmentability
} // namespace SpectralSeg

#endif // SPECTRALSEG_SEGMENTABILITY_TRACE_OUTER_CONTOUR_H
