// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a mesh file for the command-line tool, with its report printed.
#ifndef SPECTRALSEG_TOOLS_LOADED_MESH_H
#define SPECTRALSEG_TOOLS_LOADED_MESH_H

#include "Progress_printer.h"
#include "heap_tuning.h"

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/evaluation.h>
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/named_parameters.h>

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

  // Without `keep_mesh` the halfedge mesh is released once the dual graph
  // is built (the graph holds all the geometry the methods and the picture
  // use; only the mesh outputs need the mesh): on a large mesh it is a
  // twentieth of the peak memory of a segmentation. The reading and the dual graph run
  // on `threads` threads (0: all); the heap memory the file will need gets
  // its page size chosen and, with more than one thread, is faulted in on
  // two threads first (prepare_heap()).
  Loaded_mesh(const std::string& path, const Progress_printer& out, bool keep_mesh = true, unsigned threads = 0)
  {
    prepare_heap_for_mesh_file(path, threads);
    report = SpectralSeg::IO::read_mesh_file(path, mesh, SpectralSeg::parameters::number_of_threads(threads));
    for(const std::string& w : report.warnings)
      out.message("warning: " + w);
    graph = SpectralSeg::make_dual_graph(mesh, SpectralSeg::parameters::number_of_threads(threads));
    if(!keep_mesh)
      mesh = Mesh();
    const std::size_t degenerate = graph.geometry().number_of_degenerate_faces();
    if(degenerate > 0)
      out.message("warning: " + std::to_string(degenerate) +
                  " degenerate (zero-area) faces kept; they take their neighbours' normal");
  }

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
inline std::vector<int> labels_in_mesh_order(const Loaded_mesh& m, const std::string& path)
{
  const std::vector<int> file_labels = SpectralSeg::Evaluation::read_labels(path);
  const std::size_t file_faces = m.report.face_of_input_face.size();
  if(file_labels.size() != file_faces)
    throw SpectralSeg::Invalid_input("'" + path + "' has " + std::to_string(file_labels.size()) + " labels but '" +
                                     m.report.path + "' has " + std::to_string(file_faces) +
                                     " faces: a label file needs exactly one label per face of the mesh file, "
                                     "in the file's face order");
  const std::vector<std::size_t>& source = m.report.input_face_of_face;
  std::vector<int> labels(source.size());
  for(std::size_t f = 0; f < source.size(); ++f)
    labels[f] = file_labels[source[f]];
  return labels;
}

} // namespace spectralseg_cli

#endif
