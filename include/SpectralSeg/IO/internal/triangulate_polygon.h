// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file triangulate_polygon.h
/// \brief The triangulation of the polygons of a mesh file (CGAL's
/// minimum-area hole filling, slow to compile: only file readers need it).
#ifndef SPECTRALSEG_IO_INTERNAL_TRIANGULATE_POLYGON_H
#define SPECTRALSEG_IO_INTERNAL_TRIANGULATE_POLYGON_H

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <array>
#include <iterator>
#include <vector>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// Triangulates one polygon (given by positions) with CGAL's minimum-area
// polyline triangulation; falls back to a fan if that fails.
template <typename Point>
std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<Point>& polygon)
{
  std::vector<std::array<std::size_t, 3>> out;
  std::vector<CGAL::Triple<int, int, int>> triples;
  try
  {
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polygon, std::back_inserter(triples));
  }
  catch(const CGAL::Failure_exception&)
  {
    triples.clear();
  }
  if(triples.size() + 2 == polygon.size())
  {
    for(const auto& t : triples)
      out.push_back({std::size_t(t.first), std::size_t(t.second), std::size_t(t.third)});
    return out;
  }
  for(std::size_t i = 1; i + 1 < polygon.size(); ++i)
    out.push_back({0, i, i + 1});
  return out;
}

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_TRIANGULATE_POLYGON_H
