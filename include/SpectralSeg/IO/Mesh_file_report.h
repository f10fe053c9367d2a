// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Mesh_file_report.h
/// \brief What reading a mesh file found and repaired, and how its faces map to the mesh.
#ifndef SPECTRALSEG_IO_MESH_FILE_REPORT_H
#define SPECTRALSEG_IO_MESH_FILE_REPORT_H

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace IO {

/// \ingroup PkgSpectralSegIO
/// \brief The findings of `read_mesh_file()`.
struct Mesh_file_report
{
  /// marks an input face that has no mesh face (an invalid face)
  static constexpr std::size_t no_face = static_cast<std::size_t>(-1);

  std::string path;                       ///< the file read (empty for `triangle_soup_to_mesh()`)
  std::size_t input_vertices = 0;         ///< vertices in the file
  std::size_t input_faces = 0;            ///< faces (polygons) in the file
  std::size_t merged_vertices = 0;        ///< vertices merged with an identical one
  std::size_t unused_vertices = 0;        ///< vertices (after merging) that no kept face uses, left out of the mesh
  std::size_t non_triangle_faces = 0;     ///< polygons with more than three vertices, triangulated
  std::size_t triangles_from_polygons = 0;///< triangles those polygons became
  std::size_t invalid_faces = 0;          ///< faces with fewer than three distinct vertices, dropped
  std::size_t duplicate_faces = 0;        ///< faces repeating another's vertex set, dropped
  std::size_t non_manifold_edges = 0;     ///< edges shared by more than two faces in the file
  std::size_t split_vertices = 0;         ///< vertices duplicated to make the mesh manifold
  std::size_t ignored_elements = 0;       ///< elements that are not faces (OBJ `l` polylines and `p` points), ignored
  bool closed = false;                    ///< whether the resulting mesh has no border edge

  /// for each face of the file, the mesh face carrying its values (the
  /// first triangle of a triangulated polygon; the kept copy of a duplicate),
  /// or `no_face` for an invalid face
  std::vector<std::size_t> face_of_input_face;
  /// for each mesh face, the face of the file it comes from
  std::vector<std::size_t> input_face_of_face;

  /// for each mesh face, its position when the mesh faces are listed in
  /// the file's order (the faces of one triangulated polygon one after
  /// the other): the face order of outputs that follow the file, as a
  /// face index map (the mesh itself stores its faces along a Hilbert curve)
  std::vector<std::size_t> input_rank_of_faces() const
  {
    std::vector<std::size_t> faces(input_face_of_face.size());
    for(std::size_t f = 0; f < faces.size(); ++f)
      faces[f] = f;
    std::stable_sort(faces.begin(), faces.end(),
                     [this](std::size_t a, std::size_t b) { return input_face_of_face[a] < input_face_of_face[b]; });
    std::vector<std::size_t> rank(faces.size());
    for(std::size_t i = 0; i < faces.size(); ++i)
      rank[faces[i]] = i;
    return rank;
  }

  /// one sentence per repair made, for the user
  std::vector<std::string> warnings;

  /// fills `warnings` from the counts
  void finish()
  {
    auto say = [this](std::size_t n, const std::string& what) {
      if(n > 0)
        warnings.push_back(std::to_string(n) + " " + what);
    };
    say(merged_vertices, "vertices with identical coordinates merged");
    say(unused_vertices, "vertices that no face uses left out");
    say(non_triangle_faces, "non-triangle faces triangulated into " + std::to_string(triangles_from_polygons) +
                              " triangles (outputs give each such face the value of its first triangle)");
    say(invalid_faces, "faces with fewer than three distinct vertices dropped (outputs give them -1 / nan)");
    say(duplicate_faces, "duplicate faces dropped (outputs give them the value of the face they repeat)");
    say(non_manifold_edges, "non-manifold edges split: faces across them are not adjacent");
    say(split_vertices, "vertices duplicated to make the mesh manifold");
    say(ignored_elements, "line or point elements ignored (only faces are read)");
  }
};

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_MESH_FILE_REPORT_H
