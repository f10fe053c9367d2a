// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Segment_split_mesh.h
/// \brief Triangles of a segmented mesh with their vertices copied once per
/// segment, so that per-vertex colours stay crisp along segment boundaries.
#ifndef SPECTRALSEG_IO_INTERNAL_SEGMENT_SPLIT_MESH_H
#define SPECTRALSEG_IO_INTERNAL_SEGMENT_SPLIT_MESH_H

#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/exceptions.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace SpectralSeg {
namespace IO {
namespace internal {

// Some faces of a mesh; a vertex touching faces of several segments is
// copied once per segment. Copies are numbered by (mesh vertex, segment):
// in the order of the mesh's vertices, a vertex's copies by segment.
struct Segment_split_mesh
{
  std::vector<std::uint32_t> source_vertex;            // the mesh vertex of each copy
  std::vector<int> vertex_segment;                     // the segment of each copy
  std::vector<std::array<std::uint32_t, 3>> triangles; // the kept faces, on the copies
  std::vector<int> face_segment;                       // the segment of each kept face

  std::size_t number_of_vertices() const { return source_vertex.size(); }
  std::size_t number_of_faces() const { return triangles.size(); }
};

// The faces `faces` of `geometry` (indices, in the order given), labelled by
// `labels` (one per face of `geometry`; -1: no segment).
inline Segment_split_mesh split_by_segment(const Mesh_geometry& geometry, const std::vector<int>& labels,
                                           const std::vector<std::size_t>& faces)
{
  // a copy is the pair (vertex, segment + 1), packed so that sorting gives the copies' order
  const auto key = [&](std::uint32_t v, int segment) {
    return (std::uint64_t(v) << 32) | std::uint64_t(std::uint32_t(segment + 1));
  };
  std::vector<std::uint64_t> copies;
  copies.reserve(3 * faces.size());
  for(std::size_t f : faces)
    for(std::uint32_t v : geometry.triangles[f])
      copies.push_back(key(v, labels[f]));
  std::sort(copies.begin(), copies.end());
  copies.erase(std::unique(copies.begin(), copies.end()), copies.end());

  Segment_split_mesh out;
  out.source_vertex.reserve(copies.size());
  out.vertex_segment.reserve(copies.size());
  for(std::uint64_t c : copies)
  {
    out.source_vertex.push_back(std::uint32_t(c >> 32));
    out.vertex_segment.push_back(int(std::uint32_t(c & 0xffffffffu)) - 1);
  }
  out.triangles.reserve(faces.size());
  out.face_segment.reserve(faces.size());
  for(std::size_t f : faces)
  {
    std::array<std::uint32_t, 3> t;
    for(int i = 0; i < 3; ++i)
      t[i] = std::uint32_t(std::lower_bound(copies.begin(), copies.end(), key(geometry.triangles[f][i], labels[f])) -
                           copies.begin());
    out.triangles.push_back(t);
    out.face_segment.push_back(labels[f]);
  }
  return out;
}

// A segment label read from a property map: a negative value means "no
// segment" (-1); a value above INT_MAX - 1 is refused.
template <typename T>
int to_segment_label(const T& value)
{
  static_assert(std::is_integral<T>::value, "segment labels must be integers");
  if constexpr(std::is_signed<T>::value)
  {
    if(value < 0)
      return -1;
  }
  if(static_cast<unsigned long long>(value) > static_cast<unsigned long long>(INT_MAX - 1))
    throw Invalid_input("segment label " + std::to_string(value) + " is too large (at most " +
                        std::to_string(INT_MAX - 1) + ")");
  return static_cast<int>(value);
}

// The geometry of `tm` and the label of each of its faces, in the order of
// the face index map of `np`.
template <typename TriangleMesh, typename FaceSegmentMap, typename NamedParameters>
void labelled_geometry(const TriangleMesh& tm, const FaceSegmentMap& segments, const NamedParameters& np,
                       Mesh_geometry& geometry, std::vector<int>& labels)
{
  geometry = extract_mesh_geometry(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  labels.assign(geometry.number_of_faces(), -1);
  for(typename boost::graph_traits<TriangleMesh>::face_descriptor f : faces(tm))
    labels[get(fim, f)] = to_segment_label(get(segments, f));
}

} // namespace internal
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_SEGMENT_SPLIT_MESH_H
