// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_segment_parts.h
/// \brief Writing each segment of a mesh to its own PLY file.
#ifndef SPECTRALSEG_IO_WRITE_SEGMENT_PARTS_H
#define SPECTRALSEG_IO_WRITE_SEGMENT_PARTS_H

#include <SpectralSeg/IO/Atomic_output_file.h>
#include <SpectralSeg/IO/internal/Segment_split_mesh.h>
#include <SpectralSeg/IO/internal/write_segmented_ply.h>
#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/named_parameters.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace SpectralSeg {
namespace IO {

/// \ingroup PkgSpectralSegIO
/// \brief The path of the file of segment `segment` in `directory`, as
/// `write_segment_parts()` names it: `part_NNN.ply`, the number with
/// `digits` digits (zero-padded).
inline std::string segment_part_path(const std::string& directory, std::size_t segment, std::size_t digits = 3)
{
  std::string number = std::to_string(segment);
  if(number.size() < digits)
    number.insert(0, digits - number.size(), '0');
  return (directory.empty() || directory.back() == '/' ? directory : directory + "/") + "part_" + number + ".ply";
}

/// \ingroup PkgSpectralSegIO
/// \brief Writes each segment of `tm` into its own PLY file in `directory`:
/// `part_000.ply` for segment 0, `part_001.ply` for segment 1, and so on
/// (with more digits when there are 1000 segments or more, so that the names
/// sort in order; see `segment_part_path()`).
///
/// Each file holds the faces of one segment, in the order of the face index
/// map, and the vertices they use, in the format of the `.ply` output of
/// `write_segmented_mesh()`: per-vertex and per-face colours of the segment
/// (`Rendering::label_color()`) and the face property `segment`. Labels
/// without faces get no file, and faces with a negative label are left out.
/// `directory` is created if it does not exist (its parent must); other
/// files in it are left alone, files of the same names replaced. Each file
/// is written all or nothing (`Atomic_output_file`).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         whose faces are all triangles
/// \tparam FaceSegmentMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type
///         and an integer type as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param directory the directory of the files
/// \param tm the mesh
/// \param segments the segment of each face
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{whether the files are written in binary (little endian) rather than ASCII}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{stream_precision}
///     \cgalParamDescription{the number of significant digits of the coordinates in ASCII files}
///     \cgalParamType{`int`}
///     \cgalParamDefault{17}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
///     \cgalParamDescription{the vertex positions and the order of the vertices and faces, as for `extract_mesh_geometry()`}
///     \cgalParamType{property maps as for `extract_mesh_geometry()`}
///     \cgalParamDefault{the mesh's internal maps}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the paths of the files written, by segment
/// \throws Io_error if the directory cannot be created or a file cannot be
///         written (files written before are kept)
/// \throws Invalid_input as `write_segmented_mesh()`
template <typename TriangleMesh, typename FaceSegmentMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<std::string> write_segment_parts(const std::string& directory, const TriangleMesh& tm,
                                             const FaceSegmentMap& segments,
                                             const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const bool binary = choose_parameter(get_parameter(np, CGAL::internal_np::use_binary_mode), false);
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision),
                                         std::numeric_limits<double>::max_digits10);
  Mesh_geometry geometry;
  std::vector<int> labels;
  internal::labelled_geometry(tm, segments, np, geometry, labels);

  struct stat st;
  if(::stat(directory.c_str(), &st) != 0)
  {
    if(::mkdir(directory.c_str(), 0777) != 0)
      throw Io_error("cannot create the directory '" + directory + "': " + std::strerror(errno));
  }
  else if(!S_ISDIR(st.st_mode))
    throw Io_error("cannot write parts into '" + directory + "': it is not a directory");

  std::vector<std::vector<std::size_t>> faces_of_segment;
  for(std::size_t f = 0; f < labels.size(); ++f)
    if(labels[f] >= 0)
    {
      if(std::size_t(labels[f]) >= faces_of_segment.size())
        faces_of_segment.resize(std::size_t(labels[f]) + 1);
      faces_of_segment[std::size_t(labels[f])].push_back(f);
    }
  const std::size_t digits =
    faces_of_segment.empty() ? 3 : std::max<std::size_t>(3, std::to_string(faces_of_segment.size() - 1).size());
  std::vector<std::string> written;
  for(std::size_t s = 0; s < faces_of_segment.size(); ++s)
  {
    if(faces_of_segment[s].empty())
      continue;
    const std::string path = segment_part_path(directory, s, digits);
    const internal::Segment_split_mesh part = internal::split_by_segment(geometry, labels, faces_of_segment[s]);
    Atomic_output_file file(path);
    internal::write_segmented_ply(file.stream(), geometry, part, binary, precision);
    file.commit();
    written.push_back(path);
  }
  return written;
}

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_WRITE_SEGMENT_PARTS_H
