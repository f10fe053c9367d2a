// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Reading files: every defect gets a clear message or a documented repair.
#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/IO/write_face_values.h>
#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Weighted_dual_graph.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
using namespace SpectralSeg;
namespace fs = std::filesystem;

std::string write_temp(const std::string& name, const std::string& text)
{
  const fs::path dir = fs::temp_directory_path() / "spectralseg_test_input";
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

// Reads, builds the dual graph and runs a part-aware distance (geodesic,
// angular and VSI) from face 0: what every command does first. Returns the report.
IO::Mesh_file_report load_and_measure(const std::string& path, Dual_graph& g)
{
  Mesh m;
  IO::Mesh_file_report r = IO::read_mesh_file(path, m);
  g = make_dual_graph(m);
  const std::vector<double> w = Metrics::Part_aware_weight<>()(g);
  const std::vector<double> d = Weighted_dual_graph(g, w).distances(0);
  for(std::size_t f = 0; f < d.size(); ++f)
  {
    INFO("face " << f);
    REQUIRE(!std::isnan(d[f]));
    REQUIRE((std::isfinite(d[f]) || g.component_of_faces()[f] != g.component_of_faces()[0]));
  }
  return r;
}
} // namespace

TEST_CASE("unreadable files give clear errors", "[input]")
{
  Mesh m;
  CHECK_THROWS_WITH(IO::read_mesh_file("/nonexistent/x.off", m), Catch::Contains("cannot open"));
  CHECK_THROWS_WITH(IO::read_mesh_file(write_temp("empty.off", ""), m), Catch::Contains("empty"));
  CHECK_THROWS_WITH(IO::read_mesh_file(write_temp("mesh.xyz", "1 2 3\n"), m), Catch::Contains("unknown mesh format"));
  CHECK_THROWS_AS(IO::read_mesh_file(write_temp("garbage.off", "OFF\n3 1 0\n0 0 0\n1 0\n"), m), Io_error);
  CHECK_THROWS_WITH(IO::read_mesh_file(write_temp("nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"), m),
                    Catch::Contains("no face"));
  CHECK_THROWS_WITH(IO::read_mesh_file(write_temp("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"), m),
                    Catch::Contains("non-finite"));
  CHECK_THROWS_WITH(IO::read_mesh_file(write_temp("inf.obj", "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n"), m),
                    Catch::Contains("non-finite"));
}

TEST_CASE("polygons are triangulated and mapped back to the file's faces", "[input]")
{
  // a cube made of 6 quads: 12 triangles, each quad's values from its first triangle
  const std::string cube = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                           "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";
  Dual_graph g;
  const IO::Mesh_file_report r = load_and_measure(write_temp("cube.off", cube), g);
  CHECK(r.non_triangle_faces == 6);
  CHECK(r.triangles_from_polygons == 12);
  CHECK(g.number_of_faces() == 12);
  CHECK(r.closed);
  REQUIRE(r.face_of_input_face.size() == 6);
  std::vector<double> per_face(12);
  for(std::size_t f = 0; f < 12; ++f)
    per_face[f] = double(r.input_face_of_face[f]);
  const std::vector<double> back = IO::values_in_input_order(r, per_face, -1.);
  for(std::size_t p = 0; p < 6; ++p)
    CHECK(back[p] == double(p));
  REQUIRE_FALSE(r.warnings.empty());
  CHECK_THAT(r.warnings.front(), Catch::Contains("triangulated"));
}

TEST_CASE("duplicate, invalid and degenerate faces are reported", "[input]")
{
  const std::string text = "OFF\n5 5 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 2 0\n"
                           "3 0 1 2\n3 2 1 0\n3 1 3 2\n3 0 0 1\n3 0 3 4\n";
  Mesh m;
  const IO::Mesh_file_report r = IO::read_mesh_file(write_temp("dups.off", text), m);
  CHECK(r.duplicate_faces == 1);
  CHECK(r.invalid_faces == 1);
  CHECK(r.face_of_input_face[1] == r.face_of_input_face[0]);
  CHECK(r.face_of_input_face[3] == IO::Mesh_file_report::no_face);
  const Dual_graph g = make_dual_graph(m);
  CHECK(g.geometry().number_of_degenerate_faces() == 1); // 0 3 4 is collinear
  const std::vector<double> values =
    IO::values_in_input_order(r, std::vector<double>(num_faces(m), 1.), std::numeric_limits<double>::quiet_NaN());
  CHECK(std::isnan(values[3]));
  CHECK(values[1] == 1.);
}

TEST_CASE("STL corners are welded", "[input]")
{
  const std::string stl = "solid t\n"
                          "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                          "facet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n"
                          "endsolid t\n";
  Dual_graph g;
  load_and_measure(write_temp("two.stl", stl), g);
  CHECK(g.number_of_faces() == 2);
  CHECK(g.number_of_edges() == 1);
}

TEST_CASE("every shared test mesh is read and measured, or rejected with a message", "[input][shared]")
{
  const fs::path dir = fs::path(SPECTRALSEG_SHARED_DATA) / "meshes";
  if(!fs::exists(dir))
  {
    WARN("skipped: " << dir << " is absent");
    return;
  }
  std::size_t count = 0;
  for(const auto& entry : fs::directory_iterator(dir))
  {
    if(entry.path().extension() != ".off")
      continue;
    ++count;
    const std::string name = entry.path().stem().string();
    INFO(name);
    Dual_graph g;
    IO::Mesh_file_report r;
    REQUIRE_NOTHROW(r = load_and_measure(entry.path().string(), g));
    CHECK(g.number_of_faces() > 0);
    if(name == "wuson_unwelded")
      CHECK(r.merged_vertices > 0);
    if(name == "truck_nonmanifold" || name == "dragon_res3_nonmanifold")
      CHECK(r.non_manifold_edges > 0);
    if(name == "dragon_res3_nonmanifold")
      CHECK(r.duplicate_faces == 1254);
    if(name == "teapot_patches")
      CHECK(g.number_of_components() > 1);
    if(name == "elephant_with_holes")
      CHECK(g.number_of_border_edges() == 1353);
    if(name == "armadillo")
    {
      CHECK(g.number_of_faces() == 52000);
      CHECK(r.closed);
      CHECK(r.warnings.empty());
    }
  }
  CHECK(count >= 20);
}
