// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The same computation on CGAL::Surface_mesh, CGAL::Polyhedron_3 and an
// OpenMesh TriMesh gives the same distances.
#include "test_meshes.h"

#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Blend.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/face_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <map>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef OpenMesh::TriMesh_ArrayKernelT</* default traits */> Open_mesh;

test_meshes::Soup load_soup()
{
  const std::filesystem::path p = std::filesystem::path(SPECTRALSEG_SHARED_DATA) / "meshes" / "elephant.off";
  if(!std::filesystem::exists(p))
    return test_meshes::welded(test_meshes::box(3., 1., 1., 6));
  std::vector<K::Point_3> points;
  test_meshes::Soup s;
  CGAL::IO::read_polygon_soup(p.string(), points, s.faces);
  for(const auto& q : points)
    s.points.push_back({q.x(), q.y(), q.z()});
  return s;
}

// Distances from face `source` (in soup order) to every face, in soup order.
template <typename Mesh>
std::vector<double> distances_in_soup_order(const Mesh& mesh, std::size_t source)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  std::vector<face_descriptor> fs(faces(mesh).begin(), faces(mesh).end());
  std::map<face_descriptor, double> d;
  const auto metric = SpectralSeg::Metrics::make_blend(SpectralSeg::Metrics::Geodesic_weight(), 0.01,
                                                       SpectralSeg::Metrics::Angular_weight(), 0.99);
  SpectralSeg::face_distances(mesh, fs.at(source), boost::make_assoc_property_map(d),
                              SpectralSeg::parameters::metric(metric));
  std::vector<double> out;
  for(face_descriptor f : fs) // all three types iterate faces in insertion order
    out.push_back(d.at(f));
  return out;
}
} // namespace

TEST_CASE("Surface_mesh, Polyhedron_3 and OpenMesh give the same distances", "[mesh_types]")
{
  const test_meshes::Soup soup = load_soup();
  const Surface_mesh sm = test_meshes::to_mesh<Surface_mesh>(soup);
  const Polyhedron poly = test_meshes::to_mesh<Polyhedron>(soup);
  Open_mesh om;
  {
    std::vector<Open_mesh::VertexHandle> vh;
    for(const auto& p : soup.points)
      vh.push_back(om.add_vertex(Open_mesh::Point(float(p[0]), float(p[1]), float(p[2]))));
    for(const auto& f : soup.faces)
      om.add_face(vh[f[0]], vh[f[1]], vh[f[2]]);
  }
  REQUIRE(num_faces(sm) == soup.faces.size());
  REQUIRE(num_faces(poly) == soup.faces.size());
  REQUIRE(num_faces(om) == soup.faces.size());

  for(std::size_t source : {std::size_t(0), soup.faces.size() / 2})
  {
    const std::vector<double> a = distances_in_soup_order(sm, source);
    const std::vector<double> b = distances_in_soup_order(poly, source);
    const std::vector<double> c = distances_in_soup_order(om, source);
    double largest = 0;
    for(std::size_t f = 0; f < a.size(); ++f)
    {
      CHECK(a[f] == b[f]); // same double input: identical results
      // OpenMesh's default points are floats: equal to float precision
      CHECK(c[f] == Approx(a[f]).epsilon(1e-4).margin(1e-4));
      largest = std::max(largest, a[f]);
    }
    CHECK(largest > 0);
  }
}
