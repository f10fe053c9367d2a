// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_mesh_file.h
/// \brief Reading OFF, OBJ, PLY and STL files into a checked, repaired triangle mesh.
#ifndef SPECTRALSEG_IO_READ_MESH_FILE_H
#define SPECTRALSEG_IO_READ_MESH_FILE_H

#include <SpectralSeg/IO/Mesh_file_report.h>
#include <SpectralSeg/IO/internal/read_polygon_soup.h>
#include <SpectralSeg/IO/internal/triangulate_polygon.h>
#include <SpectralSeg/IO/triangle_soup_to_mesh.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/execution_from.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <string>

namespace SpectralSeg {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

// `read_mesh_file()` on bytes already read (`format`: "off", "obj", "ply"
// or "stl"), its sorts on `threads` threads: what the fuzz targets call.
template <typename Point>
Mesh_file_report read_mesh_bytes(const File_bytes& file, const std::string& format, CGAL::Surface_mesh<Point>& mesh,
                                 unsigned threads = 1)
{
  mesh.clear();
  Polygon_soup soup = read_polygon_soup(file, format);
  Mesh_file_report report =
    polygon_soup_to_mesh(soup, "'" + file.path + "'", mesh, &triangulate_polygon<Point>, threads);
  report.path = file.path;
  return report;
}

#if SPECTRALSEG_DEFAULT_INSTANCES
SPECTRALSEG_INSTANTIATE Mesh_file_report read_mesh_bytes<CGAL::Epick::Point_3>(const File_bytes&, const std::string&,
                                                                             CGAL::Surface_mesh<CGAL::Epick::Point_3>&,
                                                                             unsigned);
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegIO
/// \brief Reads a mesh file (OFF, OBJ, PLY or STL, ASCII or binary, by
/// extension, in any letter case), checks it and repairs what can be repaired without
/// changing the shape, into a `CGAL::Surface_mesh`.
///
/// Repairs, each counted in the report with a warning:
/// - vertices with exactly the same coordinates are merged (STL files and
///   unwelded exports store each triangle's corners separately);
/// - vertices that no kept face uses are left out of the mesh;
/// - faces with more than three vertices are triangulated (minimum-area
///   triangulation of the polygon);
/// - faces with fewer than three distinct vertices are dropped;
/// - duplicate faces (the same vertex set) are dropped, keeping the first;
/// - non-manifold edges and vertices are split (CGAL's
///   `orient_polygon_soup()`), so faces across a non-manifold edge are not
///   adjacent;
/// - faces are oriented consistently, and, when the whole mesh is closed,
///   each component outward (an open mesh keeps the orientation the
///   consistent-orientation pass gives it; concavity depends on it).
///
/// Refused, with the line (or byte, or element) at fault: anything the
/// format does not allow (a malformed number, a fractional, negative or
/// overflowing index, an index past the vertices, an unknown statement or
/// property type), counts in the header that the file's size cannot hold
/// (checked before anything is allocated), data after the last announced
/// element, a non-finite coordinate (`Invalid_input`), faces of more than
/// `max_face_vertices` vertices, and a file in which the repeats of other
/// faces outnumber the distinct faces (`Invalid_input`). Legal content that
/// carries no face is skipped: OBJ texture coordinates, normals, groups,
/// materials, `l` and `p` elements (counted in `ignored_elements`); PLY
/// elements and properties other than the vertex coordinates and face
/// lists, whatever their types. The whole file is read into memory first;
/// a path that is not a regular file (a directory, a device such as
/// `/dev/zero`, a FIFO) is refused before it is opened.
///
/// The mesh stores its vertices and faces along Hilbert curves through
/// their positions and centroids (CGAL's `hilbert_sort()`, ties broken by
/// coordinates), not in the file's order: faces that are neighbours on the
/// surface are neighbours in memory, so a file listing its faces in any
/// order is processed as fast, and into the same mesh, as a well-ordered one.
/// Reading takes \f$O(n \log n)\f$ time for \f$n\f$ faces, whatever the
/// vertex degrees (a fan of a million triangles around one vertex reads in
/// about 2 s).
///
/// Degenerate (zero-area) faces are kept and reported: the library handles
/// them (see `Mesh_geometry`). Open meshes and several connected components
/// are valid input.
///
/// `Mesh_file_report::face_of_input_face` maps each face of the file to the
/// mesh face that carries its values, so that per-face outputs can be
/// written in the file's face order with `write_face_values()`.
///
/// \tparam Point a CGAL point type
/// \tparam NamedParameters a sequence of named parameters
/// \param path the file
/// \param mesh receives the mesh (cleared first)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads of the sorts (welding, repeated faces, the Hilbert order); 0 means all hardware threads. The mesh does not depend on it}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Io_error if the file is missing, empty, of an unknown format or
///         malformed (the message names the line, byte or element)
/// \throws Invalid_input if it holds a non-finite coordinate, no usable face
///         or mostly repeated faces
template <typename Point, typename NamedParameters = parameters::Default_named_parameters>
Mesh_file_report read_mesh_file(const std::string& path, CGAL::Surface_mesh<Point>& mesh,
                                const NamedParameters& np = parameters::default_values())
{
  mesh.clear();
  const std::string format = internal::mesh_file_format(path);
  return internal::read_mesh_bytes(internal::read_file_bytes(path), format, mesh,
                                   SpectralSeg::internal::execution_from(np).threads());
}

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_READ_MESH_FILE_H
