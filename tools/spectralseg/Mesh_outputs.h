// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// --mesh, --binary and --parts-dir of `segment` and `render`: the segmented
// mesh (IO::write_segmented_mesh()) and one file per segment
// (IO::write_segment_parts()).
#ifndef SPECTRALSEG_TOOLS_MESH_OUTPUTS_H
#define SPECTRALSEG_TOOLS_MESH_OUTPUTS_H

#include "Argument_checks.h"
#include "Loaded_mesh.h"

#include <SpectralSeg/IO/Mesh_output_format.h>
#include <SpectralSeg/IO/write_segment_parts.h>
#include <SpectralSeg/IO/write_segmented_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace spectralseg_cli {

inline void add_mesh_output_options(CLI::App& cmd, std::string& mesh, bool& binary, std::string& parts_dir)
{
  cmd.add_option("--mesh", mesh,
                 "output: the mesh in the colours of the segments, by extension: .ply (vertices copied per segment "
                 "and coloured, face colours, the label as face property 'segment'), .obj (one material per "
                 "segment, in a .mtl file beside it) or .off (face colours)");
  cmd.add_flag("--binary", binary, "write the PLY outputs (--mesh .ply, --parts-dir) in binary (little endian)");
  cmd.add_option("--parts-dir", parts_dir,
                 "output: one PLY file per segment in this directory (created if needed): part_000.ply, "
                 "part_001.ply, ...");
}

// The directory without trailing slashes ("/" stays "/").
inline std::string without_trailing_slash(std::string dir)
{
  while(dir.size() > 1 && dir.back() == '/')
    dir.pop_back();
  return dir;
}

// Before any work: the mesh format (a usage error, exit code 2), then the
// files named by --mesh (and its .mtl) together with the command's other
// outputs (check_outputs()), then the parts directory: an existing one must
// take a new file, a missing one must be creatable (exit code 1).
inline void check_mesh_outputs(const std::string& mesh, const std::string& parts_dir,
                               std::vector<Output_file> other_outputs)
{
  if(!mesh.empty() && SpectralSeg::IO::mesh_output_format(mesh) == SpectralSeg::IO::Mesh_output_format::unsupported)
    throw Usage_error("--mesh '" + mesh +
                      "': unsupported format; use .ply (coloured vertices and the labels), .obj (one material "
                      "per segment, with a .mtl file beside it) or .off (face colours)");
  other_outputs.push_back({"--mesh", mesh});
  if(SpectralSeg::IO::mesh_output_format(mesh) == SpectralSeg::IO::Mesh_output_format::obj)
    other_outputs.push_back({"--mesh (its material library)", SpectralSeg::IO::material_library_path(mesh)});
  check_outputs(other_outputs);
  if(parts_dir.empty())
    return;
  if(parts_dir == "-")
    throw Usage_error("--parts-dir '-': give a directory");
  const std::string dir = without_trailing_slash(parts_dir);
  struct stat st;
  if(::stat(dir.c_str(), &st) != 0)
    SpectralSeg::IO::check_writable(dir); // can a file (the directory) be made beside it?
  else if(!S_ISDIR(st.st_mode))
    throw SpectralSeg::Io_error("cannot write parts into '" + parts_dir + "': it is not a directory");
  else
    SpectralSeg::IO::check_writable(SpectralSeg::IO::segment_part_path(dir, 0));
}

// The mesh output options given that no output uses.
inline std::vector<std::string> inapplicable_mesh_output_options(const CLI::App* cmd, const std::string& mesh,
                                                     const std::string& parts_dir)
{
  std::vector<std::string> w;
  if(given(cmd, "--binary") && parts_dir.empty() &&
     SpectralSeg::IO::mesh_output_format(mesh) != SpectralSeg::IO::Mesh_output_format::ply)
    w.push_back("--binary cannot be used here: it applies to PLY outputs (--mesh .ply, --parts-dir) and there is none");
  return w;
}

// Writes the mesh outputs asked for; `say` gets the lines that name the
// files written.
inline void write_mesh_outputs(const std::string& mesh, bool binary, const std::string& parts_dir,
                               const Loaded_mesh& m, const std::vector<int>& labels,
                               const std::function<void(const std::string&)>& say)
{
  if(mesh.empty() && parts_dir.empty())
    return;
  // labels are in the order of the mesh's face indices
  const auto segment_of = [&labels](Mesh::Face_index f) -> int { return labels[std::size_t(f)]; };
  const auto segments = boost::make_function_property_map<Mesh::Face_index, int>(segment_of);
  // faces and vertices in the file's order (the mesh stores them along a
  // Hilbert curve): each face's position in the file's face order, each
  // vertex's in the order those faces first use the vertices
  const std::vector<std::size_t> face_ranks = m.report.input_rank_of_faces();
  std::vector<Mesh::Face_index> in_file_order(face_ranks.size());
  for(Mesh::Face_index f : m.mesh.faces())
    in_file_order[face_ranks[std::size_t(f)]] = f;
  std::vector<std::size_t> vertex_ranks(m.mesh.number_of_vertices(), std::size_t(-1));
  std::size_t next = 0;
  for(Mesh::Face_index f : in_file_order)
    for(Mesh::Vertex_index v : vertices_around_face(m.mesh.halfedge(f), m.mesh))
      if(vertex_ranks[std::size_t(v)] == std::size_t(-1))
        vertex_ranks[std::size_t(v)] = next++;
  const auto face_rank = boost::make_function_property_map<Mesh::Face_index, std::size_t>(
    [&face_ranks](Mesh::Face_index f) { return face_ranks[std::size_t(f)]; });
  const auto vertex_rank = boost::make_function_property_map<Mesh::Vertex_index, std::size_t>(
    [&vertex_ranks](Mesh::Vertex_index v) { return vertex_ranks[std::size_t(v)]; });
  const auto np =
    SpectralSeg::parameters::use_binary_mode(binary).face_index_map(face_rank).vertex_index_map(vertex_rank);
  if(!mesh.empty())
  {
    SpectralSeg::IO::write_segmented_mesh(mesh, m.mesh, segments, np);
    say("mesh: " + mesh);
    if(SpectralSeg::IO::mesh_output_format(mesh) == SpectralSeg::IO::Mesh_output_format::obj)
      say("materials: " + SpectralSeg::IO::material_library_path(mesh));
  }
  if(!parts_dir.empty())
  {
    const std::vector<std::string> files =
      SpectralSeg::IO::write_segment_parts(without_trailing_slash(parts_dir), m.mesh, segments, np);
    say("parts: " + parts_dir + " (" + std::to_string(files.size()) + " files)");
  }
}

} // namespace spectralseg_cli

#endif
