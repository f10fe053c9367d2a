// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a mesh file for the commands of the tool.
#include "Loaded_mesh.h"

#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/evaluation.h>

namespace spectralseg_cli {

Loaded_mesh::Loaded_mesh(const std::string& path, const Progress_printer& out)
{
  report = SpectralSeg::IO::read_mesh_file(path, mesh);
  for(const std::string& w : report.warnings)
    out.message("warning: " + w);
  graph = SpectralSeg::make_dual_graph(mesh);
  const std::size_t degenerate = graph.geometry().number_of_degenerate_faces();
  if(degenerate > 0)
    out.message("warning: " + std::to_string(degenerate) +
                " degenerate (zero-area) faces kept; they take their neighbours' normal");
}

// Reads a label file in the face order of the mesh file and returns the
// labels in the order of the mesh faces.
std::vector<int> labels_in_mesh_order(const Loaded_mesh& m, const std::string& path)
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
