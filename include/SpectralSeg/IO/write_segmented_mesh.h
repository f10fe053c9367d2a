// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_segmented_mesh.h
/// \brief Writing a segmented mesh that other programs show in colour:
/// PLY with per-vertex colours and the labels, OBJ with one material per
/// segment, or OFF with face colours.
#ifndef SPECTRALSEG_IO_WRITE_SEGMENTED_MESH_H
#define SPECTRALSEG_IO_WRITE_SEGMENTED_MESH_H

#include <SpectralSeg/IO/Atomic_output_file.h>
#include <SpectralSeg/IO/Mesh_output_format.h>
#include <SpectralSeg/IO/internal/Segment_split_mesh.h>
#include <SpectralSeg/IO/internal/write_segmented_obj.h>
#include <SpectralSeg/IO/internal/write_segmented_ply.h>
#include <SpectralSeg/IO/write_colored_mesh.h>
#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/named_parameters.h>

#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

inline void write_segmented_geometry(const std::string& path, const Mesh_geometry& geometry,
                                     const std::vector<int>& labels, bool binary, int precision)
{
  switch(mesh_output_format(path))
  {
  case Mesh_output_format::ply:
  {
    std::vector<std::size_t> all(geometry.number_of_faces());
    std::iota(all.begin(), all.end(), std::size_t(0));
    const Segment_split_mesh split = split_by_segment(geometry, labels, all);
    Atomic_output_file file(path);
    write_segmented_ply(file.stream(), geometry, split, binary, precision);
    file.commit();
    return;
  }
  case Mesh_output_format::obj:
  {
    const std::string mtl = material_library_path(path);
    check_writable(path); // before the material library is replaced
    Atomic_output_file materials(mtl);
    write_segment_materials(materials.stream(), labels);
    materials.commit();
    Atomic_output_file file(path);
    write_segmented_obj(file.stream(), mtl.substr(mtl.find_last_of('/') == std::string::npos ? 0 : mtl.find_last_of('/') + 1),
                        geometry, labels, precision);
    file.commit();
    return;
  }
  case Mesh_output_format::off:
  {
    std::vector<Rendering::Rgb> colors;
    colors.reserve(labels.size());
    for(int s : labels)
      colors.push_back(segment_color(s));
    write_colored_mesh(path, geometry, colors);
    return;
  }
  default:
    throw Io_error("'" + path + "': segmented meshes are written as .ply, .obj (with a .mtl beside it) or .off");
  }
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegIO
/// \brief Writes `tm` with its segments, in a form that mesh viewers and
/// libraries (Blender, MeshLab, Open3D, trimesh) show in colour; the format
/// follows the extension of `path` (`mesh_output_format()`).
///
/// - **`.ply`**: every vertex is copied once per segment of its faces, so
///   that the per-vertex colours (`red green blue`, read by Blender, Open3D
///   and MeshLab) are crisp along the boundaries; each face also carries its
///   segment's colour and its label as `property int segment` (-1 for a
///   face without one). Faces are in the order of the face index map;
///   copies of a vertex are numbered in the order of the vertex index map,
///   then by segment. ASCII, or binary little endian with `use_binary_mode`.
/// - **`.obj`**: the vertices and faces as they are, with one material per
///   segment (`usemtl segment_N` and a group `g segment_N` wherever the
///   segment changes, `no_segment` for faces without one), the materials'
///   diffuse colours in a `.mtl` file beside it (`material_library_path()`),
///   referred to by its name (`mtllib`).
/// - **`.off`**: one colour per face, as `write_colored_mesh()`.
///
/// Colours are those of the pictures, `Rendering::label_color()` (grey,
/// `Rendering::missing_color()`, for faces without a segment). Each file is
/// written all or nothing (`Atomic_output_file`); for `.obj`, the `.mtl`
/// file is written first.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         whose faces are all triangles
/// \tparam FaceSegmentMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type
///         and an integer type as value type (for example the map filled by
///         `k_way_segmentation()`); negative values mean "no segment"
/// \tparam NamedParameters a sequence of named parameters
///
/// \param path the file to write
/// \param tm the mesh
/// \param segments the segment of each face
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{whether a `.ply` file is written in binary (little endian) rather than ASCII; OBJ and OFF are always ASCII}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{stream_precision}
///     \cgalParamDescription{the number of significant digits of the coordinates in ASCII files}
///     \cgalParamType{`int`}
///     \cgalParamDefault{17 (`std::numeric_limits<double>::%max_digits10`: coordinates are read back exactly)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
///     \cgalParamDescription{the vertex positions and the order of the vertices and faces in the file, as for `extract_mesh_geometry()`}
///     \cgalParamType{property maps as for `extract_mesh_geometry()`}
///     \cgalParamDefault{the mesh's internal maps}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Io_error if the extension is not `.ply`, `.obj` or `.off`, or a
///         file cannot be written (an existing file is then left unchanged)
/// \throws Invalid_input if a face is not a triangle, a coordinate is not
///         finite or a label is larger than `INT_MAX - 1`
template <typename TriangleMesh, typename FaceSegmentMap,
          typename NamedParameters = parameters::Default_named_parameters>
void write_segmented_mesh(const std::string& path, const TriangleMesh& tm, const FaceSegmentMap& segments,
                          const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(mesh_output_format(path) == Mesh_output_format::unsupported)
    throw Io_error("'" + path + "': segmented meshes are written as .ply, .obj (with a .mtl beside it) or .off");
  const bool binary = choose_parameter(get_parameter(np, CGAL::internal_np::use_binary_mode), false);
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision),
                                         std::numeric_limits<double>::max_digits10);
  Mesh_geometry geometry;
  std::vector<int> labels;
  internal::labelled_geometry(tm, segments, np, geometry, labels);
  internal::write_segmented_geometry(path, geometry, labels, binary, precision);
}

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_WRITE_SEGMENTED_MESH_H
