// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Reading files: every defect gets a clear message or a documented repair.
#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Evaluation/label_files.h>
#include <SpectralSeg/IO/Atomic_output_file.h>
#include <SpectralSeg/IO/internal/oriented_manifold_soup_to_mesh.h>
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/IO/triangle_soup_to_mesh.h>
#include <SpectralSeg/IO/write_face_values.h>
#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Weighted_dual_graph.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "../tools/spectralseg/heap_tuning.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

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

TEST_CASE("a closed mesh is oriented outward, each piece on its own", "[input]")
{
  // two unit cubes of 6 quads, the first listed outward, the second, 3 units
  // along x, inward, then both inward
  const std::vector<std::array<int, 4>> quads{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                              {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  const auto two_cubes = [&](bool first_inward, bool second_inward) {
    std::string off = "OFF\n16 12 0\n";
    for(int c = 0; c < 2; ++c)
      for(int v = 0; v < 8; ++v)
        off += std::to_string(3 * c + (v == 1 || v == 2 || v == 5 || v == 6)) + " " +
               std::to_string(int(v == 2 || v == 3 || v == 6 || v == 7)) + " " + std::to_string(int(v >= 4)) + "\n";
    for(int c = 0; c < 2; ++c)
      for(std::array<int, 4> q : quads)
      {
        if(c == 0 ? first_inward : second_inward)
          std::reverse(q.begin(), q.end());
        off += "4";
        for(int v : q)
          off += " " + std::to_string(8 * c + v);
        off += "\n";
      }
    return off;
  };
  for(const auto& inward : std::vector<std::pair<bool, bool>>{{false, false}, {false, true}, {true, true}})
  {
    INFO("first cube inward " << inward.first << ", second " << inward.second);
    Mesh m;
    const IO::Mesh_file_report r = IO::read_mesh_file(write_temp("cubes.off", two_cubes(inward.first, inward.second)), m);
    REQUIRE(r.closed);
    const Dual_graph g = make_dual_graph(m);
    REQUIRE(g.number_of_faces() == 24);
    for(std::size_t f = 0; f < 24; ++f)
    {
      const Eigen::Vector3d c = g.geometry().centroids[f];
      const Eigen::Vector3d centre(c.x() < 2 ? 0.5 : 3.5, 0.5, 0.5);
      CHECK(g.geometry().normals[f].dot(c - centre) > 0.4);
    }
  }
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

  // a quad, a face of two vertices and a triangle: as many corners as three
  // triangles, read as the polygons they are
  const std::string mixed = "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 1\n4 0 1 2 3\n2 0 1\n3 1 4 2\n";
  Mesh mm;
  const IO::Mesh_file_report mr = IO::read_mesh_file(write_temp("mixed.off", mixed), mm);
  CHECK(mr.non_triangle_faces == 1);
  CHECK(mr.triangles_from_polygons == 2);
  CHECK(mr.invalid_faces == 1);
  CHECK(num_faces(mm) == 3);
  CHECK(mr.face_of_input_face[1] == IO::Mesh_file_report::no_face);
  CHECK(mr.face_of_input_face[2] != IO::Mesh_file_report::no_face);
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

TEST_CASE("a triangle soup from arrays is repaired as a file is", "[input]")
{
  // the elephant as arrays, every triangle with its own corners (an
  // unwelded soup), then a degenerate triangle and a repeat
  Mesh from_file;
  const IO::Mesh_file_report fr = IO::read_mesh_file(SPECTRALSEG_SOURCE_DIR "/data/elephant.off", from_file);
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  for(auto f : faces(from_file))
  {
    std::array<std::size_t, 3> t;
    std::size_t i = 0;
    for(auto v : vertices_around_face(halfedge(f, from_file), from_file))
    {
      const auto& p = from_file.point(v);
      points.push_back({p.x(), p.y(), p.z()});
      t[i++] = points.size() - 1;
    }
    triangles.push_back(t);
  }
  const std::size_t n = triangles.size();
  triangles.push_back({0, 0, 1});
  triangles.push_back(triangles[5]);
  Mesh from_soup;
  const IO::Mesh_file_report sr = IO::triangle_soup_to_mesh(points, triangles, from_soup);
  CHECK(sr.path.empty());
  CHECK(sr.input_faces == n + 2);
  CHECK(sr.merged_vertices == points.size() - num_vertices(from_file));
  CHECK(sr.invalid_faces == 1);
  CHECK(sr.duplicate_faces == 1);
  CHECK(sr.closed == fr.closed);
  REQUIRE(num_faces(from_soup) == n);
  CHECK(sr.face_of_input_face[n] == IO::Mesh_file_report::no_face);
  CHECK(sr.face_of_input_face[n + 1] == sr.face_of_input_face[5]);
  // same faces, same places, same orientation
  const Dual_graph a = make_dual_graph(from_file), b = make_dual_graph(from_soup);
  REQUIRE(a.number_of_edges() == b.number_of_edges());
  for(std::size_t f = 0; f < n; ++f)
  {
    CHECK((a.geometry().centroids[f] - b.geometry().centroids[f]).norm() < 1e-12);
    CHECK((a.geometry().normals[f] - b.geometry().normals[f]).norm() < 1e-12);
  }

  Mesh m;
  std::vector<std::array<double, 3>> bad = points;
  bad[4][1] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(IO::triangle_soup_to_mesh(bad, triangles, m), Catch::Contains("vertex 4 has a non-finite"));
  std::vector<std::array<std::size_t, 3>> outside = triangles;
  outside[7][2] = points.size();
  CHECK_THROWS_WITH(IO::triangle_soup_to_mesh(points, outside, m), Catch::Contains("triangle 7 has vertex index"));
  CHECK_THROWS_WITH(IO::triangle_soup_to_mesh(points, {}, m), Catch::Contains("no face"));
  CHECK_THROWS_AS(IO::triangle_soup_to_mesh(points, {{0, 0, 1}}, m), Invalid_input);
}

TEST_CASE("the mesh is the same whatever the order of the vertices and faces", "[input]")
{
  // the elephant read from its file, then as a soup whose vertices, faces
  // and face corners are shuffled: both give the same mesh, vertex for
  // vertex and face for face, so everything after is the same too
  Mesh a;
  const IO::Mesh_file_report fr = IO::read_mesh_file(SPECTRALSEG_SOURCE_DIR "/data/elephant.off", a);
  bool reordered = false;
  for(std::size_t f = 0; f < fr.input_face_of_face.size(); ++f)
    reordered = reordered || fr.input_face_of_face[f] != f;
  CHECK(reordered); // the file is not in the mesh's order: the test means something
  std::mt19937 random(7);
  std::vector<std::size_t> vertex_of(num_vertices(a)), face_of(num_faces(a)); // shuffled -> a's
  std::iota(vertex_of.begin(), vertex_of.end(), std::size_t(0));
  std::iota(face_of.begin(), face_of.end(), std::size_t(0));
  std::shuffle(vertex_of.begin(), vertex_of.end(), random);
  std::shuffle(face_of.begin(), face_of.end(), random);
  std::vector<std::size_t> shuffled_vertex(vertex_of.size());
  std::vector<std::array<double, 3>> points(vertex_of.size());
  for(std::size_t v = 0; v < vertex_of.size(); ++v)
  {
    shuffled_vertex[vertex_of[v]] = v;
    const auto& p = a.point(Mesh::Vertex_index(Mesh::size_type(vertex_of[v])));
    points[v] = {p.x(), p.y(), p.z()};
  }
  const auto corners = [](const Mesh& m, std::size_t f) {
    std::vector<std::size_t> c;
    for(auto v : vertices_around_face(halfedge(Mesh::Face_index(Mesh::size_type(f)), m), m))
      c.push_back(std::size_t(v));
    return c;
  };
  std::vector<std::array<std::size_t, 3>> triangles(face_of.size());
  for(std::size_t t = 0; t < face_of.size(); ++t)
  {
    const std::vector<std::size_t> c = corners(a, face_of[t]);
    const std::size_t r = random() % 3; // another first corner, same orientation
    for(std::size_t i = 0; i < 3; ++i)
      triangles[t][i] = shuffled_vertex[c[(i + r) % 3]];
  }
  Mesh b;
  const IO::Mesh_file_report sr = IO::triangle_soup_to_mesh(points, triangles, b);
  REQUIRE(num_vertices(b) == num_vertices(a));
  REQUIRE(num_faces(b) == num_faces(a));
  for(auto v : vertices(a))
    REQUIRE(a.point(v) == b.point(v));
  for(std::size_t f = 0; f < num_faces(a); ++f)
    REQUIRE(corners(a, f) == corners(b, f));
  for(std::size_t t = 0; t < face_of.size(); ++t)
    REQUIRE(sr.face_of_input_face[t] == face_of[t]);

  // and whatever the number of threads of the sorts (the default uses all,
  // the elephant's 5,558 faces take the parallel Hilbert sort)
  Mesh c, d;
  IO::triangle_soup_to_mesh(points, triangles, c, parameters::number_of_threads(1));
  IO::read_mesh_file(SPECTRALSEG_SOURCE_DIR "/data/elephant.off", d, parameters::number_of_threads(1));
  for(const Mesh* m : {&c, &d})
  {
    REQUIRE(num_faces(*m) == num_faces(a));
    for(auto v : vertices(a))
      REQUIRE(a.point(v) == m->point(v));
    for(std::size_t f = 0; f < num_faces(a); ++f)
      REQUIRE(corners(a, f) == corners(*m, f));
  }
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

// ---------------------------------------------------------------------------
// Hostile files: every legal variant read, every malformed one refused with
// the place at fault, nothing allocated from a count the file cannot hold.

namespace {

std::string write_binary(const std::string& name, const std::string& bytes)
{
  const fs::path dir = fs::temp_directory_path() / "spectralseg_test_input";
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << bytes;
  return p.string();
}

// an octahedron: 6 vertices, 8 triangles, closed
const double octahedron_points[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const int octahedron_faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

std::string octahedron_off()
{
  std::string s = "OFF\n6 8 0\n";
  for(const auto& p : octahedron_points)
    s += std::to_string(int(p[0])) + " " + std::to_string(int(p[1])) + " " + std::to_string(int(p[2])) + "\n";
  for(const auto& f : octahedron_faces)
    s += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
  return s;
}

std::string octahedron_obj()
{
  std::string s = "# octahedron\nmtllib x.mtl\no oct\n";
  for(const auto& p : octahedron_points)
    s += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  s += "vt 0 0\nvn 0 0 1\ng all\nusemtl m\ns 1\n";
  for(const auto& f : octahedron_faces)
    s += "f " + std::to_string(f[0] + 1) + "/1/1 " + std::to_string(f[1] + 1) + "//1 " + std::to_string(f[2] - 6) + "\n";
  return s + "l 1 2 3\np 4\n";
}

// `offset` is added to the coordinates (1 for unsigned types: the octahedron has -1)
std::string ascii_ply(const std::string& coordinate_type, const std::string& count_type, const std::string& index_type,
                      int offset = 0)
{
  std::string s = "ply\nformat ascii 1.0\ncomment test\nelement vertex 6\nproperty " + coordinate_type +
                  " x\nproperty " + coordinate_type + " y\nproperty " + coordinate_type +
                  " z\nproperty uchar red\nelement face 8\nproperty list " + count_type + " " + index_type +
                  " vertex_indices\nproperty float quality\nelement edge 1\nproperty int vertex1\nproperty int vertex2\n"
                  "end_header\n";
  for(const auto& p : octahedron_points)
    s += std::to_string(int(p[0]) + offset) + " " + std::to_string(int(p[1]) + offset) + " " +
         std::to_string(int(p[2]) + offset) + " 255\n";
  for(const auto& f : octahedron_faces)
    s += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + " 0.5\n";
  return s + "0 1\n";
}

// a value of a PLY type in the given byte order
template <typename T>
void put(std::string& out, T value, bool big_endian)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if(big_endian)
    std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

template <typename Coordinate, typename Count, typename Index>
std::string binary_ply(const std::string& coordinate_type, const std::string& count_type, const std::string& index_type,
                       bool big_endian, std::size_t announced_vertices = 6, int offset = 0)
{
  std::string s = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\nelement vertex " + std::to_string(announced_vertices) + "\nproperty " + coordinate_type +
                  " x\nproperty " + coordinate_type + " y\nproperty " + coordinate_type + " z\nelement face 8\n" +
                  "property list " + count_type + " " + index_type + " vertex_indices\nend_header\n";
  for(const auto& p : octahedron_points)
    for(int c = 0; c < 3; ++c)
      put(s, Coordinate(p[c] + offset), big_endian);
  for(const auto& f : octahedron_faces)
  {
    put(s, Count(3), big_endian);
    for(int c = 0; c < 3; ++c)
      put(s, Index(f[c]), big_endian);
  }
  return s;
}

std::string octahedron_ascii_stl()
{
  std::string s = "solid oct\n";
  for(const auto& f : octahedron_faces)
  {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for(int c = 0; c < 3; ++c)
      s += "      vertex " + std::to_string(octahedron_points[f[c]][0]) + " " +
           std::to_string(octahedron_points[f[c]][1]) + " " + std::to_string(octahedron_points[f[c]][2]) + "\n";
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid oct\n";
}

std::string octahedron_binary_stl(std::uint32_t announced = 8)
{
  std::string s = "solid but binary";
  s.resize(80, ' ');
  put(s, announced, false);
  for(const auto& f : octahedron_faces)
  {
    for(int c = 0; c < 3; ++c)
      put(s, 0.f, false);
    for(int c = 0; c < 3; ++c)
      for(int k = 0; k < 3; ++k)
        put(s, float(octahedron_points[f[c]][k]), false);
    put(s, std::uint16_t(0), false);
  }
  return s;
}

// The octahedron in binary OFF as CGAL writes it (big-endian counts and
// floats, a colour count of 0 after each face): a normal per vertex for
// `NOFF`, `face_colours` floats per face, a count of vertices to announce.
std::string octahedron_binary_off(const std::string& keyword = "OFF", std::int32_t announced_vertices = 6,
                                  std::int32_t face_colours = 0)
{
  std::string s = keyword + " BINARY\n";
  for(const std::int32_t count : {announced_vertices, std::int32_t(8), std::int32_t(12)})
    put(s, count, true);
  for(const auto& p : octahedron_points)
  {
    for(int c = 0; c < 3; ++c)
      put(s, float(p[c]), true);
    for(int c = 0; keyword == "NOFF" && c < 3; ++c)
      put(s, float(p[c]), true);
  }
  for(const auto& f : octahedron_faces)
  {
    put(s, std::int32_t(3), true);
    for(int c = 0; c < 3; ++c)
      put(s, std::int32_t(f[c]), true);
    put(s, face_colours, true);
    for(int c = 0; c < face_colours; ++c)
      put(s, 0.5f, true);
  }
  return s + "\n";
}

// Reads `text` as a file named `name`; CHECKs that it is read as the
// octahedron (8 faces, closed).
void check_octahedron(const std::string& name, const std::string& text)
{
  INFO(name);
  Mesh m;
  IO::Mesh_file_report r;
  REQUIRE_NOTHROW(r = IO::read_mesh_file(write_binary(name, text), m));
  CHECK(num_faces(m) == 8);
  CHECK(num_vertices(m) == 6);
  CHECK(r.closed);
}

// Reading `text` throws a SpectralSeg exception whose message holds `expected`.
void check_refused(const std::string& name, const std::string& text, const std::string& expected)
{
  INFO(name << ":\n" << text.substr(0, 300));
  Mesh m;
  CHECK_THROWS_WITH(IO::read_mesh_file(write_binary(name, text), m), Catch::Contains(expected));
}

} // namespace

TEST_CASE("legal variants of each format are read", "[input][hostile]")
{
  check_octahedron("oct.off", octahedron_off());
  check_octahedron("oct_inline_counts.off", "OFF 6 8 0\n" + octahedron_off().substr(10));
  check_octahedron("oct_no_keyword.off", octahedron_off().substr(4));
  check_octahedron("oct.obj", octahedron_obj());
  for(const std::string type : {"int", "short", "int32", "char", "int8", "int16", "float", "double", "float32"})
    check_octahedron("oct_" + type + ".ply", ascii_ply(type, "uchar", "int"));
  for(const std::string type : {"uchar", "ushort", "uint", "uint8", "uint16", "uint32"})
    check_octahedron("oct_" + type + ".ply", ascii_ply(type, "uchar", "int", 1));
  check_octahedron("oct_ushort_lists.ply", ascii_ply("float", "ushort", "ushort"));
  check_octahedron("oct_uchar_lists.ply", ascii_ply("float", "uchar", "uchar"));
  for(const bool big : {false, true})
  {
    const std::string e = big ? "_be" : "_le";
    check_octahedron("oct_int" + e + ".ply", binary_ply<std::int32_t, std::uint8_t, std::int32_t>("int", "uchar", "int", big));
    check_octahedron("oct_short" + e + ".ply", binary_ply<std::int16_t, std::uint8_t, std::uint16_t>("short", "uchar", "ushort", big));
    check_octahedron("oct_uchar" + e + ".ply", binary_ply<std::uint8_t, std::uint8_t, std::uint8_t>("uchar", "uchar", "uchar", big, 6, 1));
    check_octahedron("oct_int32" + e + ".ply", binary_ply<std::int32_t, std::uint16_t, std::uint32_t>("int32", "ushort", "uint32", big));
    check_octahedron("oct_double" + e + ".ply", binary_ply<double, std::int32_t, std::int32_t>("double", "int", "int", big));
  }
  check_octahedron("oct_ascii.stl", octahedron_ascii_stl());
  check_octahedron("oct_binary.stl", octahedron_binary_stl());

  // OBJ l and p elements are counted and reported, not refused
  Mesh m;
  const IO::Mesh_file_report r = IO::read_mesh_file(write_binary("oct_lines.obj", octahedron_obj()), m);
  CHECK(r.ignored_elements == 2);
}

TEST_CASE("malformed files are refused with the place at fault", "[input][hostile]")
{
  const std::string tri = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  check_refused("wrapping.off", tri + "3 0 1 4294967296\n", "line 6: face 0 refers to vertex 4294967296");
  check_refused("huge_index.off", tri + "3 0 1 100000000000000000000\n", "out of range");
  check_refused("exponent.off", tri + "3 0 1 1e20\n", "found '1e20'");
  check_refused("letter.off", tri + "3 0 1 x\n", "found 'x'");
  check_refused("fraction.off", tri + "3 0 1 1.5\n", "found '1.5'");
  check_refused("negative.off", tri + "3 0 1 -1\n", "found '-1'");
  check_refused("missing.off", tri + "3 0 1 3\n", "refers to vertex 3 but the file has 3 vertices");
  check_refused("truncated.off", tri + "3 0 1", "line 6: face 0 announces 3 vertices but the file ends");
  check_refused("truncated_index.off", tri + "3 0 1\n\n\n", "line 9: the file ends where a vertex index of face 0");
  check_refused("extra.off", tri + "3 0 1 2\n3 0 2 1\n", "after the 1 faces");
  check_refused("word_coordinate.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "line 4");
  check_refused("overflow_coordinate.off", "OFF\n3 1 0\n0 0 0\n1 1e999 0\n0 1 0\n3 0 1 2\n", "non-finite");
  check_refused("binary.off", "OFF BINARY\n", "the file ends where the vertex count was expected");

  check_refused("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "line 4");
  check_refused("forward.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "line 4: a face refers to vertex 7");
  check_refused("relative.obj", "v 0 0 0\nv 1 0 0\nf 1 2 -3\n", "line 3");
  check_refused("fraction.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2.5\n", "'2.5'");
  check_refused("overflow.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n", "out of range");
  check_refused("short_vertex.obj", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1");
  check_refused("unknown.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nbogus 1\nf 1 2 3\n", "line 4: unknown OBJ statement 'bogus'");

  check_refused("float_indices.ply", ascii_ply("float", "uchar", "float"), "non-integer type");
  std::string big_uchar = ascii_ply("uchar", "uchar", "int", 1);
  big_uchar.replace(big_uchar.find("\n2 1 1 255"), 6, "\n256 1");
  check_refused("big_uchar.ply", big_uchar, "'256' is out of the range of its type");
  check_refused("no_xyz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n", "lacks an x, y or z");
  check_refused("bad_type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n0\n", "unknown PLY type");
  check_refused("no_end.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", "end_header");
  // a binary PLY promising more vertices than it holds: refused before reading
  check_refused("more_vertices.ply", binary_ply<float, std::uint8_t, std::int32_t>("float", "uchar", "int", false, 1000),
                "1000 'vertex' elements");
  check_refused("empty_element.ply", "ply\nformat ascii 1.0\nelement vertex 3\nelement face 1000000000000\nend_header\n", "no property");
  check_refused("truncated_binary.stl", octahedron_binary_stl(9), "announces 9 triangles");
  check_refused("no_endloop.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendfacet\n", "line 7");
  check_refused("nan.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n", "non-finite");
}

TEST_CASE("binary OFF is read as CGAL writes it, and refused when malformed", "[input][hostile]")
{
  check_octahedron("oct_binary.off", octahedron_binary_off());
  check_octahedron("oct_binary_normals.off", octahedron_binary_off("NOFF"));
  check_octahedron("oct_binary_face_colours.off", octahedron_binary_off("OFF", 6, 4));
  // written by CGAL 5.5 (Polyhedron_3, IO::BINARY mode)
  Mesh m;
  REQUIRE_NOTHROW(IO::read_mesh_file(SPECTRALSEG_SOURCE_DIR "/fuzz/corpus/fuzz_off/tetrahedron_cgal_binary.off", m));
  CHECK(num_faces(m) == 4);
  CHECK(CGAL::is_closed(m));

  check_refused("truncated_binary.off", octahedron_binary_off("OFF", 9),
                "byte 23: the header announces 9 vertices (12 bytes each) and 8 faces (at least 20 bytes each), "
                "at least 268 bytes, but only 233 bytes follow");
  check_refused("negative_binary.off", octahedron_binary_off("OFF", -1), "the vertex count is -1");
  check_refused("coloured_binary.off", octahedron_binary_off("COFF"), "binary COFF and STOFF are not supported");
  check_refused("bad_colours_binary.off", octahedron_binary_off("OFF", 6, 5), "colour component count of face 0 is 5");
  check_refused("trailing_binary.off", octahedron_binary_off() + "x", "unexpected data after the 8 faces");
  check_refused("no_data_binary.off", "OFF BINARY", "no line end after 'BINARY'");
  std::string bad_index = octahedron_binary_off();
  bad_index[11 + 12 + 6 * 12 + 4 + 3] = 6; // the first index of face 0
  check_refused("bad_index_binary.off", bad_index, "face 0 refers to vertex 6 but the file has 6 vertices");
  std::string short_face = octahedron_binary_off();
  short_face[11 + 12 + 6 * 12 + 3] = 2; // face 0 announces 2 vertices
  check_refused("short_face_binary.off", short_face, "face 0 has 2 vertices; binary faces of fewer than 3");
}

TEST_CASE("a truncated binary PLY is refused with the counts of its header", "[input][hostile]")
{
  // the hostile runs' file: 9 vertices announced, 6 held (8 faces of uchar counts); it was read as a mesh
  check_refused("truncated_9_of_6.ply", binary_ply<float, std::uint8_t, std::int32_t>("float", "uchar", "int", false, 9),
                "the header announces 9 'vertex' elements (at least 12 bytes each), 8 'face' elements (at least 13 "
                "bytes each), at least 212 bytes, but only 176 bytes of data follow it (truncated file or wrong counts)");
  check_refused("truncated_7_of_6.ply", binary_ply<float, std::uint8_t, std::int32_t>("float", "uchar", "int", true, 7),
                "7 'vertex' elements");
  // an empty face list fits the size but is refused in binary: it is how a misaligned file reads
  std::string empty_face = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  for(int v = 0; v < 3; ++v)
    for(int c = 0; c < 3; ++c)
      put(empty_face, float(v == c), false);
  put(empty_face, std::uint8_t(0), false);
  put(empty_face, std::uint8_t(6), false);
  for(const std::int32_t v : {0, 1, 2, 0, 1, 2})
    put(empty_face, v, false);
  check_refused("empty_face.ply", empty_face, "face 0 has 0 vertices: a binary face list of fewer than three is refused");
}

TEST_CASE("paths that are not regular files are refused before they are read", "[input][hostile]")
{
  const fs::path dir = fs::temp_directory_path() / "spectralseg_test_special";
  fs::remove_all(dir);
  fs::create_directories(dir / "folder.off");
  fs::create_symlink("/dev/zero", dir / "zero.off");
  REQUIRE(::mkfifo((dir / "pipe.ply").c_str(), 0600) == 0);
  Mesh m;
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH(IO::read_mesh_file((dir / "zero.off").string(), m),
                    Catch::Contains("zero.off': not a regular file (a device, FIFO or socket)"));
  CHECK_THROWS_WITH(IO::read_mesh_file("/dev/urandom", m), Catch::Contains("'/dev/urandom': not a regular file"));
  CHECK_THROWS_WITH(IO::read_mesh_file((dir / "pipe.ply").string(), m), Catch::Contains("not a regular file"));
  CHECK_THROWS_WITH(IO::read_mesh_file((dir / "folder.off").string(), m), Catch::Contains("it is a directory"));
  CHECK_THROWS_WITH(Evaluation::read_labels((dir / "zero.off").string()),
                    Catch::Contains("cannot read label file") && Catch::Contains("not a regular file"));
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 1.);
  fs::remove_all(dir);
}

TEST_CASE("vertices that no face uses are left out of the mesh", "[input]")
{
  Mesh m;
  const IO::Mesh_file_report r = IO::read_mesh_file(
    write_binary("unused.off", "OFF\n6 4 0\n5 5 5\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n7 7 7\n"
                               "3 1 3 2\n3 1 2 4\n3 2 3 4\n3 1 4 3\n"), m);
  CHECK(r.unused_vertices == 2);
  CHECK(num_vertices(m) == 4);
  CHECK(CGAL::is_valid_polygon_mesh(m));
  CHECK(m.point(*vertices(m).begin()) == K::Point_3(0, 0, 0)); // the file's order kept
  CHECK(std::find(r.warnings.begin(), r.warnings.end(), "2 vertices that no face uses left out") != r.warnings.end());
}


TEST_CASE("an oriented manifold soup is recognised, a fan around one vertex of any degree included", "[input]")
{
  typedef std::vector<std::array<std::size_t, 3>> Triangles;
  using IO::internal::is_oriented_manifold_soup;
  const Triangles tetrahedron{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  CHECK(is_oriented_manifold_soup(4, tetrahedron));
  Triangles flipped = tetrahedron;
  std::swap(flipped[3][1], flipped[3][2]);
  CHECK_FALSE(is_oriented_manifold_soup(4, flipped));
  CHECK_FALSE(is_oriented_manifold_soup(4, {{0, 1, 2}, {0, 1, 2}})); // a directed edge twice
  CHECK_FALSE(is_oriented_manifold_soup(5, {{0, 1, 2}, {0, 3, 4}})); // two fans around vertex 0
  CHECK(is_oriented_manifold_soup(5, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));

  // A disc of n triangles around its centre (a cylinder's cap made as a
  // fan): the centre's link is one path of n edges. The check is O(n log n)
  // (it was quadratic in a vertex's degree: 54 s for n = 200,000).
  const std::size_t n = 60000;
  std::vector<std::array<double, 3>> points{{0., 0., 0.}};
  Triangles fan;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double a = 2. * CGAL_PI * double(i) / double(n);
    points.push_back({std::cos(a), std::sin(a), 0.});
    if(i + 1 < n)
      fan.push_back({0, i + 1, i + 2});
  }
  CHECK(is_oriented_manifold_soup(points.size(), fan));
  fan.push_back({0, n, 1}); // closed around the centre: a cycle
  CHECK(is_oriented_manifold_soup(points.size(), fan));
  Triangles broken = fan;
  std::swap(broken[n / 2][1], broken[n / 2][2]);
  CHECK_FALSE(is_oriented_manifold_soup(points.size(), broken));
  Mesh m;
  const IO::Mesh_file_report r = IO::triangle_soup_to_mesh(points, fan, m);
  CHECK(num_faces(m) == n);
  CHECK(r.split_vertices == 0);
  CHECK(r.non_manifold_edges == 0);
  Mesh repaired;
  IO::triangle_soup_to_mesh(points, broken, repaired); // the flipped triangle is turned
  CHECK(num_faces(repaired) == n);
  CHECK(CGAL::is_valid_polygon_mesh(repaired));

  // The mesh is the one CGAL's polygon_soup_to_polygon_mesh() makes, halfedge
  // for halfedge: on the fan (a border) and on a closed mesh with a hole cut.
  Mesh elephant;
  IO::read_mesh_file(SPECTRALSEG_SOURCE_DIR "/data/elephant.off", elephant);
  std::vector<K::Point_3> elephant_points(elephant.points().begin(), elephant.points().end());
  Triangles elephant_triangles;
  for(Mesh::Face_index f : faces(elephant))
    if(f.idx() != 5 && f.idx() != num_faces(elephant) / 2) // two holes
    {
      const Mesh::Halfedge_index h = halfedge(f, elephant);
      elephant_triangles.push_back({target(h, elephant), target(next(h, elephant), elephant),
                                    target(next(next(h, elephant), elephant), elephant)});
    }
  std::vector<K::Point_3> fan_points;
  for(const auto& p : points)
    fan_points.emplace_back(p[0], p[1], p[2]);
  for(const auto& soup : {std::make_pair(&fan_points, &fan), std::make_pair(&elephant_points, &elephant_triangles)})
  {
    REQUIRE(is_oriented_manifold_soup(soup.first->size(), *soup.second));
    Mesh cgal, direct;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(*soup.first, *soup.second, cgal);
    IO::internal::oriented_manifold_soup_to_mesh(*soup.first, *soup.second, direct);
    CHECK(CGAL::is_valid_polygon_mesh(direct));
    REQUIRE(num_halfedges(direct) == num_halfedges(cgal));
    REQUIRE(num_faces(direct) == num_faces(cgal));
    std::size_t differ = 0;
    for(Mesh::Halfedge_index h : halfedges(cgal))
      differ += (target(h, cgal) != target(h, direct) || face(h, cgal) != face(h, direct) ||
                 next(h, cgal) != next(h, direct)) ? 1 : 0;
    for(Mesh::Face_index f : faces(cgal))
      differ += halfedge(f, cgal) != halfedge(f, direct) ? 1 : 0;
    for(Mesh::Vertex_index v : vertices(cgal))
      differ += halfedge(v, cgal) != halfedge(v, direct) ? 1 : 0;
    CHECK(differ == 0);
    CHECK(CGAL::is_closed(direct) == CGAL::is_closed(cgal));
  }
}
TEST_CASE("fuzz seeds are read and fuzz regressions never crash", "[input][hostile][fuzz]")
{
  // fuzz/corpus/<target>: legal files; fuzz/regressions/<target>: inputs a
  // fuzz target once failed on (doc/hardening.md), read into a valid mesh or refused
  const std::vector<std::pair<std::string, std::string>> targets = {
    {"fuzz_off", ".off"}, {"fuzz_obj", ".obj"}, {"fuzz_ply_ascii", ".ply"}, {"fuzz_ply_binary", ".ply"},
    {"fuzz_stl_ascii", ".stl"}, {"fuzz_stl_binary", ".stl"}, {"fuzz_labels", ".seg"}};
  std::size_t seeds = 0, regressions = 0;
  for(const auto& [target, ext] : targets)
    for(const std::string kind : {"corpus", "regressions"})
    {
      const fs::path dir = fs::path(SPECTRALSEG_SOURCE_DIR) / "fuzz" / kind / target;
      if(!fs::exists(dir))
        continue;
      for(const auto& entry : fs::directory_iterator(dir))
      {
        INFO(entry.path().string());
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::string path = write_binary("replay" + ext, bytes);
        (kind == std::string("corpus") ? seeds : regressions) += 1;
        try
        {
          if(ext == ".seg")
          {
            CHECK_FALSE(Evaluation::read_labels(path).empty());
            continue;
          }
          Mesh m;
          IO::read_mesh_file(path, m);
          CHECK(CGAL::is_valid_polygon_mesh(m));
          CHECK(CGAL::is_triangle_mesh(m));
        }
        catch(const Error& e)
        {
          CHECK(kind == std::string("regressions")); // every seed is a legal file
          CHECK(std::string(e.what()).find("replay") != std::string::npos);
        }
      }
    }
  CHECK(seeds >= 20);
  CHECK(regressions >= 6);
}

TEST_CASE("counts the file cannot hold are refused before allocating", "[input][hostile]")
{
  // a 40-byte OFF claiming 10^8 faces: refused at once, from the header
  const std::string text = "OFF\n3 100000000 0\n0 0 0\n1 0 0\n0 1 0\n";
  const auto start = std::chrono::steady_clock::now();
  check_refused("claims.off", text, "which need at least 200000018 bytes, but only");
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 0.5);
  check_refused("claims.ply", "ply\nformat ascii 1.0\nelement vertex 100000000\nproperty float x\nproperty float y\n"
                              "property float z\nend_header\n0 0 0\n", "100000000 'vertex' elements");
  check_refused("claims_list.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\n"
                                   "property float y\nproperty float z\nelement face 1\n"
                                   "property list uint int vertex_indices\nend_header\n\xff\xff\xff\x0f" +
                                   std::string(12, '\0'),
                "vertices; faces of more than");
  check_refused("claims_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n100000000 0 1 2\n", "faces of more than");
}

TEST_CASE("files of repeated faces and huge polygons are refused with a reason", "[input][hostile]")
{
  std::string copies = "OFF\n3 50 0\n0 0 0\n1 0 0\n0 1 0\n";
  for(int i = 0; i < 50; ++i)
    copies += i % 2 == 0 ? "3 0 1 2\n" : "3 2 1 0\n";
  check_refused("copies.off", copies, "49 of its 50 faces repeat another face");

  // a double-sided mesh (each face twice) is still repaired, not refused
  std::string twice = "OFF\n6 16 0\n" + octahedron_off().substr(10, octahedron_off().find("3 0 2 4") - 10);
  for(const auto& f : octahedron_faces)
    twice += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n3 " +
             std::to_string(f[2]) + " " + std::to_string(f[1]) + " " + std::to_string(f[0]) + "\n";
  Mesh m;
  IO::Mesh_file_report r;
  REQUIRE_NOTHROW(r = IO::read_mesh_file(write_binary("twice.off", twice), m));
  CHECK(r.duplicate_faces == 8);

  // a 6,000-gon is refused at once instead of taking a minute to triangulate
  const std::size_t n = 6000;
  std::string polygon = "OFF\n" + std::to_string(n) + " 1 0\n";
  for(std::size_t i = 0; i < n; ++i)
    polygon += std::to_string(std::cos(6.283185307179586 * double(i) / double(n))) + " " +
               std::to_string(std::sin(6.283185307179586 * double(i) / double(n))) + " 0\n";
  polygon += std::to_string(n);
  for(std::size_t i = 0; i < n; ++i)
    polygon += " " + std::to_string(i);
  const auto start = std::chrono::steady_clock::now();
  check_refused("polygon.off", polygon + "\n", "faces of more than 256 vertices are refused");
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 1.);
}

namespace {

// Mutations of a valid file. `malformed` mutations must be refused;
// the others (random bytes) only must not crash or throw anything but a
// SpectralSeg exception.
struct Fuzz_case
{
  std::string name;
  std::string bytes;
  bool malformed;
};

// replaces the `which`-th whitespace-separated token at or after `from`
std::string replace_token(const std::string& text, std::size_t from, std::size_t which, const std::string& by)
{
  std::size_t p = from;
  for(std::size_t t = 0;; ++t)
  {
    p = text.find_first_not_of(" \t\r\n", p);
    if(p == std::string::npos)
      return text;
    const std::size_t e = std::min(text.find_first_of(" \t\r\n", p), text.size());
    if(t == which)
      return text.substr(0, p) + by + text.substr(e);
    p = e;
  }
}

std::vector<Fuzz_case> fuzz_cases()
{
  struct Base
  {
    std::string name;
    std::string text;
    std::size_t data_begin;   // where the body starts (after the header)
    bool counted;             // whether the header counts the body (truncation is always malformed)
  };
  const std::string ply_a = ascii_ply("int", "uchar", "int");
  const std::string ply_b = binary_ply<std::int16_t, std::uint8_t, std::uint16_t>("short", "uchar", "ushort", false);
  const std::vector<Base> bases = {
    {"off", octahedron_off(), 10, true},
    {"obj", octahedron_obj(), 0, false},
    {"ply", ply_a, ply_a.find("end_header") + 11, true},
    {"ply", ply_b, ply_b.find("end_header") + 11, true},
    {"stl", octahedron_ascii_stl(), 0, true},
    {"stl", octahedron_binary_stl(), 84, true}};
  const std::vector<std::string> hostile_indices = {"-1", "4294967296", "1e20", "x", "1.5", "99999999999999999999", "0x1"};
  const std::vector<std::string> hostile_numbers = {"nan", "inf", "-inf", "1e999", "1,5", "--1", "0x"};
  std::vector<Fuzz_case> cases;
  std::mt19937 random(14);
  for(std::size_t b = 0; b < bases.size(); ++b)
  {
    const Base& base = bases[b];
    const std::string id = std::to_string(b) + "." + base.name;
    const bool binary = base.text.find("binary") != std::string::npos || (base.name == "stl" && base.data_begin == 84);
    // truncations: every one that cuts into the last token is malformed for counted formats
    const std::size_t last = base.text.find_last_not_of(" \r\n");
    for(std::size_t cut = 1; cut < base.text.size(); cut += 1 + base.text.size() / 40)
    {
      // ASCII STL: a cut inside the name after "endsolid" leaves a valid file
      const bool after_end = base.name == "stl" && !binary && cut >= base.text.rfind("endsolid") + 8;
      cases.push_back({"cut" + std::to_string(cut) + "_" + id, base.text.substr(0, cut),
                       base.counted && cut <= last && !after_end});
    }
    // random bytes overwritten: anything may happen but a crash
    for(int i = 0; i < 20; ++i)
    {
      std::string t = base.text;
      for(int k = 0; k < 3; ++k)
        t[random() % t.size()] = char(random() % 256);
      cases.push_back({"bytes" + std::to_string(i) + "_" + id, t, false});
    }
    if(binary)
    {
      // binary bodies: counts and lengths overwritten with large values
      for(int i = 0; i < 10; ++i)
      {
        std::string t = base.text;
        const std::size_t at = base.data_begin + random() % (t.size() - base.data_begin);
        t[at] = char(0xff);
        cases.push_back({"ff" + std::to_string(i) + "_" + id, t, false});
      }
      continue;
    }
    // hostile tokens in place of face indices and coordinates
    if(base.name == "off")
    {
      for(const std::string& h : hostile_indices)
        cases.push_back({"index_" + h + "_" + id, replace_token(base.text, base.text.find("3 0 2 4"), 2, h), true});
      for(const std::string& h : hostile_numbers)
        cases.push_back({"coord_" + h + "_" + id, replace_token(base.text, 10, 4, h), true});
      cases.push_back({"more_faces_" + id, "OFF\n6 9 0\n" + base.text.substr(10), true});
      cases.push_back({"fewer_faces_" + id, "OFF\n6 7 0\n" + base.text.substr(10), true});
      cases.push_back({"more_vertices_" + id, "OFF\n7 8 0\n" + base.text.substr(10), true});
      cases.push_back({"many_faces_" + id, "OFF\n6 800000000 0\n" + base.text.substr(10), true});
    }
    if(base.name == "obj")
      for(const std::string& h : hostile_indices)
        if(h != "-1") // -1 is a legal relative index
          cases.push_back({"index_" + h + "_" + id, replace_token(base.text, base.text.find("\nf ") + 1, 2, h), true});
    if(base.name == "ply")
    {
      for(const std::string& h : hostile_indices)
        cases.push_back({"index_" + h + "_" + id, replace_token(base.text, base.data_begin, 6 * 4 + 2, h), true});
      for(const std::string& h : hostile_numbers)
        cases.push_back({"coord_" + h + "_" + id, replace_token(base.text, base.data_begin, 1, h), true});
      for(const std::string type : {"float16", "int64", "string", "list"})
        cases.push_back({"type_" + type + "_" + id, replace_token(base.text, base.text.find("property int x"), 1, type), true});
      std::string more = base.text;
      more.replace(more.find("element face 8"), 14, "element face 9");
      cases.push_back({"more_faces_" + id, more, true});
    }
    if(base.name == "stl")
      for(const std::string& h : hostile_numbers)
        cases.push_back({"coord_" + h + "_" + id, replace_token(base.text, base.text.find("vertex "), 2, h), true});
  }
  return cases;
}

} // namespace

TEST_CASE("fuzz: malformed files of each format never crash and are never accepted", "[input][hostile][fuzz]")
{
  const std::vector<Fuzz_case> cases = fuzz_cases();
  CHECK(cases.size() >= 300);
  const auto start = std::chrono::steady_clock::now();
  std::size_t refused = 0, read = 0;
  for(const Fuzz_case& c : cases)
  {
    INFO(c.name << " (" << c.bytes.size() << " bytes):\n" << c.bytes.substr(0, 400));
    Mesh m;
    const std::string ext = c.name.substr(c.name.rfind('.'));
    bool accepted = false;
    try
    {
      IO::read_mesh_file(write_binary("fuzz" + ext, c.bytes), m);
      accepted = true;
      ++read;
    }
    catch(const Error& e)
    {
      ++refused;
      CHECK(std::string(e.what()).find("fuzz") != std::string::npos); // the message names the file
    }
    if(c.malformed)
      CHECK_FALSE(accepted);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  WARN(cases.size() << " fuzz cases: " << refused << " refused, " << read << " read, " << seconds << " s");
  CHECK(seconds < 60.);
}

TEST_CASE("outputs are written all or nothing", "[input][output]")
{
  const fs::path dir = fs::temp_directory_path() / "spectralseg_test_output";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string labels = (dir / "labels.seg").string();
  IO::write_face_values(labels, std::vector<int>{1, 2, 3});
  const std::vector<int> many(200000, 7);

  // a file-size limit of 4 KB stands for a full disk: the write fails, the old file stays
  {
    struct sigaction ignore = {}, old = {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGXFSZ, &ignore, &old);
    struct rlimit saved;
    getrlimit(RLIMIT_FSIZE, &saved);
    struct rlimit small = saved;
    small.rlim_cur = 4096;
    setrlimit(RLIMIT_FSIZE, &small);
    CHECK_THROWS_WITH(IO::write_face_values(labels, many), Catch::Contains("left unchanged"));
    CHECK_THROWS_AS(IO::write_text_file((dir / "report.json").string(), std::string(10000, 'x')), Io_error);
    setrlimit(RLIMIT_FSIZE, &saved);
    sigaction(SIGXFSZ, &old, nullptr);
  }
  std::ifstream in(labels);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text == "1\n2\n3\n");
  CHECK_FALSE(fs::exists(dir / "report.json"));
  std::size_t files = 0;
  for(const auto& entry : fs::directory_iterator(dir))
    files += entry.path().filename() == "labels.seg" ? 0 : 1;
  CHECK(files == 0); // no temporary file left behind

  // a device that is full
  if(fs::exists("/dev/full"))
    CHECK_THROWS_WITH(IO::write_face_values("/dev/full", many), Catch::Contains("No space left"));
  // unwritable places are found before any work
  CHECK_THROWS_WITH(IO::check_writable(labels + "/x.seg"), Catch::Contains("Not a directory"));
  CHECK_THROWS_WITH(IO::check_writable("/nonexistent/dir/x.seg"), Catch::Contains("cannot create a file"));
  CHECK_THROWS_WITH(IO::check_writable(dir.string()), Catch::Contains("is a directory"));
  CHECK_NOTHROW(IO::check_writable(labels));
  CHECK_NOTHROW(IO::check_writable((dir / "new.seg").string()));
  CHECK_FALSE(fs::exists(dir / "new.seg"));

  // a symbolic link is followed and kept
  fs::create_symlink(labels, dir / "link.seg");
  IO::write_face_values((dir / "link.seg").string(), std::vector<int>{4});
  CHECK(fs::is_symlink(dir / "link.seg"));
  std::ifstream again(labels);
  std::string now((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>());
  CHECK(now == "4\n");
}

// The VmFlags line of the mapping of this process that holds `address`
// (/proc/self/smaps), or "" when there is none.
static std::string mapping_flags(const void* address)
{
  std::ifstream smaps("/proc/self/smaps");
  const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  for(std::string line; std::getline(smaps, line);)
  {
    unsigned long long from = 0, to = 0;
    if(std::sscanf(line.c_str(), "%llx-%llx ", &from, &to) == 2 && line.find(':') > line.find(' '))
      inside = from <= a && a < to;
    else if(inside && line.rfind("VmFlags:", 0) == 0)
      return line;
  }
  return "";
}

TEST_CASE("the tool's heap preparation sizes, chooses the page size and leaves mapped pages at the top of the heap",
          "[input]")
{
  using namespace spectralseg_cli;
  // one thread: a page size chosen, nothing faulted in ahead
  CHECK(heap_preparation(1000, ".off", 1).page_choice_bytes == 32000);
  CHECK(heap_preparation(1000, ".off", 1).prefault_bytes == 0);
  CHECK(heap_preparation(1000, ".obj", 1).page_choice_bytes == 24000);
  CHECK(heap_preparation(1000, ".stl", 1).page_choice_bytes == 8000);
  CHECK(heap_preparation(std::uintmax_t(1) << 40, ".off", 1).page_choice_bytes == max_prefault_bytes);
  // glibc's own choice is left alone
  CHECK(heap_preparation(1000, ".off", 1, "glibc.malloc.hugetlb=0").page_choice_bytes == 0);
  CHECK(heap_preparation(1000, ".off", 1, "glibc.malloc.tcache_count=0:glibc.malloc.hugetlb=1").page_choice_bytes ==
        0);
  CHECK(heap_preparation(1000, ".off", 1, "glibc.malloc.tcache_count=0").page_choice_bytes == 32000);
  if(std::thread::hardware_concurrency() >= 2)
  {
    CHECK(heap_preparation(1000, ".off", 0).prefault_bytes == 12000);
    CHECK(heap_preparation(1000, ".ply", 2).prefault_bytes == 12000);
    CHECK(heap_preparation(1000, ".ply", 2).page_choice_bytes == 32000);
    CHECK(heap_preparation(1000, ".obj", 2).prefault_bytes == 8000);
    CHECK(heap_preparation(1000, ".stl", 2).prefault_bytes == 3000);
    CHECK(heap_preparation(std::uintmax_t(1) << 40, ".off", 2).prefault_bytes == max_prefault_bytes);
  }
  const std::size_t huge = std::size_t(2) << 20;
#if defined(__linux__)
  if(std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled"))
  {
    // 2 MB timed in 4 KB pages, 4 MB in huge pages, the rest as chosen
    void* raw = std::malloc(7 * huge);
    REQUIRE(raw != nullptr);
    char* block = static_cast<char*>(raw);
    char* first = block + (huge - reinterpret_cast<std::uintptr_t>(block) % huge) % huge;
    CHECK(mapping_flags(first).find(" hg") == std::string::npos);
    CHECK(mapping_flags(first).find(" nh") == std::string::npos);
    const Page_size size = choose_page_size(block, 7 * huge);
    REQUIRE(size != Page_size::none);
    const bool chosen = size == Page_size::huge;
    CHECK(mapping_flags(first).find(" nh") != std::string::npos);
    CHECK(mapping_flags(first + huge).find(" hg") != std::string::npos);
    CHECK(mapping_flags(first + 2 * huge).find(" hg") != std::string::npos);
    CHECK(mapping_flags(first + 3 * huge).find(chosen ? " hg" : " nh") != std::string::npos);
    CHECK(mapping_flags(first + 5 * huge).find(chosen ? " hg" : " nh") != std::string::npos);
    if(first != block)
      CHECK(mapping_flags(first - 1).find(" hg") == std::string::npos);
    // too small to time both: nothing changed
    void* small = std::malloc(4 * huge);
    REQUIRE(small != nullptr);
    CHECK(choose_page_size(static_cast<char*>(small), 4 * huge - 1) == Page_size::none);
    // as chosen, without timing
    CHECK(advise_page_size(block, 7 * huge, Page_size::small));
    CHECK(mapping_flags(first + huge).find(" nh") != std::string::npos);
    CHECK(advise_page_size(block, 7 * huge, Page_size::huge));
    CHECK(!advise_page_size(block, 7 * huge, Page_size::none));
    CHECK(mapping_flags(first).find(" hg") != std::string::npos);
    std::free(small);
    std::free(raw);
  }
#endif
#if defined(__GLIBC__)
  // as the tool runs: freed memory stays in the one heap
  keep_freed_memory_in_heap();
  const std::size_t bytes = std::size_t(32) << 20, page = 4096;
  Heap_preparation plan;
  plan.prefault_bytes = bytes;
  plan.page_choice_bytes = 2 * bytes;
  prepare_heap(plan);
  // the freed block is the free memory at the top of the heap, its page
  // size chosen
  CHECK(mallinfo2().keepcost >= 2 * bytes);
#if defined(__linux__)
  if(std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled"))
  {
    const std::string flags = mapping_flags(static_cast<char*>(sbrk(0)) - bytes);
    CHECK((flags.find(" hg") != std::string::npos || flags.find(" nh") != std::string::npos));
  }
#endif
  // an allocation carved from it touches pages already mapped
  rusage before{}, after{};
  getrusage(RUSAGE_SELF, &before);
  char* block = static_cast<char*>(std::malloc(bytes / 2));
  REQUIRE(block != nullptr);
  for(std::size_t i = 0; i < bytes / 2; i += page)
    static_cast<volatile char*>(block)[i] = 1;
  getrusage(RUSAGE_SELF, &after);
  std::free(block);
  CHECK(after.ru_minflt - before.ru_minflt < long(bytes / 2 / page / 10));
#endif
  (void)huge;
}
