// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target of the mesh readers: the bytes of one file of the format
// SPECTRALSEG_FUZZ_FORMAT ("off", "obj", "ply" or "stl") read into the
// mesh type of the spectralseg tool, by the code `read_mesh_file()` runs
// after reading the file (doc/hardening.md). A file is either refused with
// a SpectralSeg exception naming it, or read into a valid triangle mesh
// whose report agrees with it; anything else (a crash, a sanitizer report,
// another exception, a broken invariant) is a finding.
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/exceptions.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh; // as tools/spectralseg/Loaded_mesh.h

[[noreturn]] void broken(const char* what)
{
  std::fprintf(stderr, "fuzz_mesh_reader: broken invariant: %s\n", what);
  std::abort();
}

void check_mesh(const Mesh& mesh, const SpectralSeg::IO::Mesh_file_report& report)
{
  using SpectralSeg::IO::Mesh_file_report;
  if(num_faces(mesh) == 0)
    broken("a mesh without faces was accepted");
  if(!CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh))
    broken("the mesh read is not a valid triangle mesh");
  for(const auto v : vertices(mesh))
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(mesh.point(v)[c]))
        broken("a non-finite coordinate was accepted");
  if(report.face_of_input_face.size() != report.input_faces ||
     report.input_face_of_face.size() != num_faces(mesh))
    broken("the report's face maps do not match the file and the mesh");
  for(const std::size_t f : report.face_of_input_face)
    if(f != Mesh_file_report::no_face && f >= num_faces(mesh))
      broken("an input face maps past the mesh's faces");
  for(const std::size_t f : report.input_face_of_face)
    if(f >= report.input_faces)
      broken("a mesh face maps past the file's faces");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  SpectralSeg::IO::internal::File_bytes file;
  file.path = "fuzz." SPECTRALSEG_FUZZ_FORMAT;
  file.data.assign(reinterpret_cast<const char*>(data), size);
  Mesh mesh;
  try
  {
    const SpectralSeg::IO::Mesh_file_report report =
      SpectralSeg::IO::internal::read_mesh_bytes(file, SPECTRALSEG_FUZZ_FORMAT, mesh);
    check_mesh(mesh, report);
  }
  catch(const SpectralSeg::Error& e)
  {
    if(std::string(e.what()).find(file.path) == std::string::npos)
      broken("an error message does not name the file");
  }
  return 0;
}
