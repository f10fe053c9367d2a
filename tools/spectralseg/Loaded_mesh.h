// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a mesh file for the command-line tool, with its report printed.
#ifndef SPECTRALSEG_TOOLS_LOADED_MESH_H
#define SPECTRALSEG_TOOLS_LOADED_MESH_H

#include "Progress_printer.h"

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/IO/Mesh_file_report.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <string>
#include <vector>

namespace spectralseg_cli {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

struct Loaded_mesh
{
  Mesh mesh;
  SpectralSeg::IO::Mesh_file_report report;
  SpectralSeg::Dual_graph graph;

  // Reads a mesh file (warnings through `out`) and builds its dual graph.
  // \throws SpectralSeg::Error if the file cannot be read as a mesh
  Loaded_mesh(const std::string& path, const Progress_printer& out);

  // the mesh face carrying the values of face `input_face` of the file
  std::size_t mesh_face_of_input_face(long long input_face) const
  {
    if(input_face < 0 || static_cast<std::size_t>(input_face) >= report.face_of_input_face.size())
      throw SpectralSeg::Invalid_input("face " + std::to_string(input_face) + " does not exist: the file has " +
                                       std::to_string(report.face_of_input_face.size()) + " faces");
    const std::size_t f = report.face_of_input_face[static_cast<std::size_t>(input_face)];
    if(f == SpectralSeg::IO::Mesh_file_report::no_face)
      throw SpectralSeg::Invalid_input("face " + std::to_string(input_face) +
                                       " of the file was dropped (fewer than three distinct vertices)");
    return f;
  }
};

// Reads a label file in the face order of the mesh file and returns the
// labels in the order of the mesh faces.
std::vector<int> labels_in_mesh_order(const Loaded_mesh& m, const std::string& path);

} // namespace spectralseg_cli

#endif
