// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Dual graph, metric policies, Dijkstra distances and named parameters;
// shape descriptors for retrieval (thesis 3.6).
#include "test_meshes.h"
#include "../benchmark/subdivide.h"

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/internal/contact_adjacencies.h>
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/IO/write_colored_mesh.h>
#include <SpectralSeg/IO/write_segment_parts.h>
#include <SpectralSeg/IO/write_segmented_mesh.h>
#include <SpectralSeg/Metrics/normalize_weights.h>
#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Any_weight.h>
#include <SpectralSeg/Metrics/Blend.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Metrics/Per_edge_weight.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/face_distances.h>
#include <SpectralSeg/Registration/align_embeddings.h>
#include <SpectralSeg/shape_retrieval.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Geometry>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
using namespace SpectralSeg;
using test_meshes::pi;
} // namespace

TEST_CASE("dual graph of a strip: nodes, edges, border, degrees", "[dual_graph]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(4));
  const Dual_graph g = make_dual_graph(m);
  CHECK(g.number_of_faces() == 8);
  CHECK(g.number_of_edges() == 7); // 4 diagonals + 3 inner verticals
  CHECK(g.number_of_border_edges() == 10);
  CHECK(g.number_of_components() == 1);
  CHECK(g.degree(0) == 2); // lower triangle: diagonal and right edge
  CHECK(g.degree(1) == 1); // upper triangle of the first square: left side is a border
  CHECK(g.degree(6) == 1);
  CHECK(g.longest_edge_length() == Approx(std::sqrt(2.)));
  for(const Dual_graph::Edge& e : g.edges())
  {
    CHECK_FALSE(e.concave);
    CHECK(e.normal_angle == Approx(0.).margin(1e-12));
  }
}

TEST_CASE("geodesic distances on a flat strip follow the exact formula", "[distances][geodesic]")
{
  SECTION("right triangles: one square further costs (sqrt(5) + sqrt(2)) / 3")
  {
    const std::size_t n = 12;
    const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(n));
    const Dual_graph g = make_dual_graph(m);
    const Weighted_dual_graph wg(g, Metrics::Geodesic_weight()(g));
    const std::vector<double> d = wg.distances(0);
    for(std::size_t k = 0; k < n; ++k)
    {
      CHECK(d[2 * k] == Approx(k * (std::sqrt(5.) + std::sqrt(2.)) / 3.).epsilon(1e-12));
      // the upper triangle of square k is entered from the left, through the lower one of square k-1
      const double upper = k == 0 ? std::sqrt(2.) / 3. : k * (std::sqrt(5.) + std::sqrt(2.)) / 3. - std::sqrt(2.) / 3.;
      CHECK(d[2 * k + 1] == Approx(upper).epsilon(1e-12));
    }
  }
  SECTION("equilateral triangles: k hops cost k / sqrt(3)")
  {
    const std::size_t n = 21;
    const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::equilateral_strip(n));
    const Dual_graph g = make_dual_graph(m);
    REQUIRE(g.number_of_faces() == n);
    const Weighted_dual_graph wg(g, Metrics::Geodesic_weight()(g));
    const std::vector<double> d = wg.distances(5);
    for(std::size_t k = 0; k < n; ++k)
      CHECK(d[k] == Approx(std::abs(double(k) - 5.) / std::sqrt(3.)).margin(1e-12));
  }
}

TEST_CASE("angular weight of concave and convex folds", "[metrics][angular]")
{
  for(double angle : {0.3, 1.0, 2.0})
  {
    const Mesh concave = test_meshes::to_mesh<Mesh>(test_meshes::fold(angle, true));
    const Mesh convex = test_meshes::to_mesh<Mesh>(test_meshes::fold(angle, false));
    const Dual_graph gc = make_dual_graph(concave);
    const Dual_graph gx = make_dual_graph(convex);
    REQUIRE(gc.number_of_edges() == 1);
    REQUIRE(gx.number_of_edges() == 1);
    CHECK(gc.edge(0).concave);
    CHECK_FALSE(gx.edge(0).concave);
    CHECK(gc.edge(0).normal_angle == Approx(angle));
    CHECK(Metrics::Angular_weight()(gc)[0] == Approx(angle / pi));
    CHECK(Metrics::Angular_weight()(gx)[0] == Approx(0.001));
    CHECK(Metrics::Angular_weight(0.25)(gx)[0] == Approx(0.25));
  }
  CHECK_THROWS_AS(Metrics::Angular_weight(-1.), Invalid_input);
}

TEST_CASE("the faces of a box meet at convex folds; a notch makes concave ones", "[metrics][angular]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::welded(test_meshes::box(2., 1., 1., 3)));
  const Dual_graph g = make_dual_graph(m);
  CHECK(g.number_of_border_edges() == 0);
  std::size_t creases = 0;
  for(const Dual_graph::Edge& e : g.edges())
  {
    CHECK_FALSE(e.concave);
    if(e.normal_angle > 1.)
    {
      ++creases;
      CHECK(e.normal_angle == Approx(pi / 2));
    }
  }
  CHECK(creases == 12 * 3);
}

TEST_CASE("blend normalises each component to [0,1] before mixing", "[metrics][blend]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::fold(1.2, true));
  const Mesh strip = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(3));
  for(const Mesh* mesh : {&m, &strip})
  {
    const Dual_graph g = make_dual_graph(*mesh);
    const std::vector<double> geo = Metrics::Geodesic_weight()(g);
    const std::vector<double> ang = Metrics::Angular_weight()(g);
    const double gmax = *std::max_element(geo.begin(), geo.end());
    const double amax = *std::max_element(ang.begin(), ang.end());
    // coefficients 1 and 3 are normalised to 0.25 and 0.75
    const auto blend = Metrics::make_blend(Metrics::Geodesic_weight(), 1., Metrics::Angular_weight(), 3.);
    CHECK(blend.coefficients()[0] == Approx(0.25));
    const std::vector<double> w = blend(g);
    for(std::size_t e = 0; e < w.size(); ++e)
    {
      CHECK(w[e] == Approx(0.25 * geo[e] / gmax + 0.75 * ang[e] / amax));
      CHECK(w[e] <= 1. + 1e-12);
    }
  }
  CHECK_THROWS_AS(Metrics::make_blend(Metrics::Geodesic_weight(), -1., Metrics::Angular_weight(), 1.), Invalid_input);
  CHECK_THROWS_AS(Metrics::make_blend(Metrics::Geodesic_weight(), 0., Metrics::Angular_weight(), 0.), Invalid_input);
}

TEST_CASE("multi-source distances give the nearest source", "[distances]")
{
  const std::size_t n = 15;
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::equilateral_strip(n));
  const Dual_graph g = make_dual_graph(m);
  const Weighted_dual_graph wg(g, Metrics::Geodesic_weight()(g));
  const Nearest_source_distances r = wg.distances(std::vector<Dual_graph::size_type>{0, 14, 4});
  for(std::size_t k = 0; k < n; ++k)
  {
    const double d0 = double(k), d1 = 14. - double(k), d2 = std::abs(double(k) - 4.);
    const double best = std::min({d0, d1, d2});
    CHECK(r.distance[k] == Approx(best / std::sqrt(3.)).margin(1e-12));
    const std::size_t expected = (d2 <= d0 && d2 <= d1) ? 2 : (d0 < d1 ? 0 : 1);
    if(d0 != d2 && d1 != d2) // ties are resolved by Dijkstra's order
      CHECK(r.nearest_source[k] == expected);
  }
  CHECK((r.nearest_source[9] == 1 || r.nearest_source[9] == 2)); // a tie: 5 hops from faces 4 and 14
  CHECK_THROWS_AS(wg.distances(std::vector<Dual_graph::size_type>{}), Invalid_input);
  CHECK_THROWS_AS(wg.distances(99), Invalid_input);
}

TEST_CASE("distance rows match single-source runs for any thread count", "[distances][threads]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::welded(test_meshes::box(3., 1., 1., 4)));
  const Dual_graph g = make_dual_graph(m);
  const Weighted_dual_graph wg(g, Metrics::make_blend(Metrics::Geodesic_weight(), 0.3, Metrics::Angular_weight(), 0.7)(g));
  const std::vector<Dual_graph::size_type> sources{0, 17, 40, 95, 3};
  const auto rows1 = wg.distance_rows(sources, Execution(1));
  const auto rows2 = wg.distance_rows(sources, Execution(2));
  const auto rows4 = wg.distance_rows(sources, Execution(4));
  CHECK(rows1 == rows2);
  CHECK(rows1 == rows4);
  for(std::size_t i = 0; i < sources.size(); ++i)
  {
    const std::vector<double> d = wg.distances(sources[i]);
    for(std::size_t f = 0; f < d.size(); ++f)
      CHECK(rows1(Eigen::Index(i), Eigen::Index(f)) == d[f]);
  }
}

TEST_CASE("distance rows with progress reports: batches that every thread shares", "[distances][threads]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::welded(test_meshes::box(3., 1., 1., 4)));
  const Dual_graph g = make_dual_graph(m);
  const Weighted_dual_graph wg(g, Metrics::Geodesic_weight()(g));
  std::vector<Dual_graph::size_type> sources;
  for(Dual_graph::size_type f = 0; f < 21; ++f)
    sources.push_back(4 * f);
  std::vector<double> reports;
  const Execution exec(2, [&reports](const std::string&, double fraction) {
    reports.push_back(fraction);
    return true;
  });
  const auto rows = wg.distance_rows(sources, exec);
  CHECK(rows == wg.distance_rows(sources, Execution(1)));
  // the start, then one report per batch of at least 4 rows per thread (a
  // batch of one row would leave the other thread idle): 21 rows, 3 batches
  REQUIRE(reports.size() == 4);
  CHECK(reports.front() == 0.);
  CHECK(reports.back() == 1.);
  CHECK(std::is_sorted(reports.begin(), reports.end()));
}

TEST_CASE("faces in another component are at infinite distance", "[distances][components]")
{
  test_meshes::Soup s = test_meshes::square_strip(2);
  test_meshes::Soup t = test_meshes::square_strip(2);
  for(auto& p : t.points)
    p[2] += 5.;
  for(auto f : t.faces)
  {
    for(auto& v : f)
      v += s.points.size();
    s.faces.push_back(f);
  }
  s.points.insert(s.points.end(), t.points.begin(), t.points.end());
  const Mesh m = test_meshes::to_mesh<Mesh>(s);
  const Dual_graph g = make_dual_graph(m);
  CHECK(g.number_of_components() == 2);
  const Weighted_dual_graph wg(g, Metrics::Geodesic_weight()(g));
  const Nearest_source_distances r = wg.distances(std::vector<Dual_graph::size_type>{0});
  for(std::size_t f = 0; f < 4; ++f)
    CHECK(std::isfinite(r.distance[f]));
  for(std::size_t f = 4; f < 8; ++f)
  {
    CHECK(std::isinf(r.distance[f]));
    CHECK(r.nearest_source[f] == Nearest_source_distances::unreachable);
  }
}

TEST_CASE("face_distances: named parameters, user metric, progress and cancellation", "[api]")
{
  Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::equilateral_strip(9));
  auto dmap = m.add_property_map<Mesh::Face_index, double>("f:d", 0.).first;
  auto nmap = m.add_property_map<Mesh::Face_index, std::size_t>("f:n", 0).first;
  std::vector<Mesh::Face_index> sources{Mesh::Face_index(0), Mesh::Face_index(8)};

  SECTION("the geodesic metric")
  {
    face_distances(m, Mesh::Face_index(0), dmap, parameters::metric(Metrics::Geodesic_weight()));
    CHECK(get(dmap, Mesh::Face_index(3)) == Approx(3. / std::sqrt(3.)));
  }
  SECTION("a user metric counts hops; the nearest-source map is filled")
  {
    const auto hops = Metrics::make_per_edge_weight([](const Dual_graph&, const Dual_graph::Edge&) { return 1.; }, "hops");
    face_distances(m, sources, dmap, parameters::metric(hops).nearest_source_map(nmap).number_of_threads(2));
    CHECK(get(dmap, Mesh::Face_index(3)) == Approx(3.));
    CHECK(get(dmap, Mesh::Face_index(6)) == Approx(2.));
    CHECK(get(nmap, Mesh::Face_index(3)) == 0);
    CHECK(get(nmap, Mesh::Face_index(6)) == 1);
  }
  SECTION("a CGAL parameter can follow a SpectralSeg one")
  {
    auto vpm = get(CGAL::vertex_point, m);
    face_distances(m, Mesh::Face_index(0), dmap,
                   parameters::metric(Metrics::Any_weight(Metrics::Geodesic_weight())).vertex_point_map(vpm));
    CHECK(get(dmap, Mesh::Face_index(2)) == Approx(2. / std::sqrt(3.)));
  }
  SECTION("progress is reported and a callback can cancel")
  {
    std::vector<std::string> stages;
    Progress_callback record = [&](const std::string& s, double) { stages.push_back(s); return true; };
    face_distances(m, Mesh::Face_index(0), dmap,
                   parameters::progress_callback(record).metric(Metrics::Geodesic_weight()));
    CHECK(std::find(stages.begin(), stages.end(), "dijkstra") != stages.end());
    Progress_callback stop = [](const std::string& s, double) { return s != "dijkstra"; };
    put(dmap, Mesh::Face_index(4), -7.);
    CHECK_THROWS_AS(face_distances(m, Mesh::Face_index(0), dmap,
                                   parameters::progress_callback(stop).metric(Metrics::Geodesic_weight())),
                    Operation_cancelled);
    CHECK(get(dmap, Mesh::Face_index(4)) == -7.); // nothing written
  }
  SECTION("invalid metric weights are rejected")
  {
    const auto bad = Metrics::make_per_edge_weight([](const Dual_graph&, const Dual_graph::Edge&) {
      return std::numeric_limits<double>::quiet_NaN(); }, "bad");
    CHECK_THROWS_AS(face_distances(m, Mesh::Face_index(0), dmap, parameters::metric(bad)), Invalid_input);
  }
}

TEST_CASE("non-triangle faces and non-finite coordinates are rejected by the library", "[api][input]")
{
  Mesh quad;
  auto a = quad.add_vertex(K::Point_3(0, 0, 0)), b = quad.add_vertex(K::Point_3(1, 0, 0)),
       c = quad.add_vertex(K::Point_3(1, 1, 0)), d = quad.add_vertex(K::Point_3(0, 1, 0));
  quad.add_face(a, b, c, d);
  CHECK_THROWS_AS(make_dual_graph(quad), Invalid_input);

  Mesh tri = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(1));
  tri.point(Mesh::Vertex_index(1)) = K::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  CHECK_THROWS_WITH(make_dual_graph(tri), Catch::Contains("non-finite"));
}

TEST_CASE("degenerate faces get their neighbours' normal and never produce NaN", "[dual_graph][degenerate]")
{
  // strip of 3 squares whose middle column is collapsed: x = 1 and x = 2 coincide
  test_meshes::Soup s = test_meshes::square_strip(3);
  s.points[4] = {1., 0., 0.};
  s.points[5] = {1., 1., 0.};
  const Mesh m = test_meshes::to_mesh<Mesh>(s);
  const Dual_graph g = make_dual_graph(m);
  CHECK(g.geometry().number_of_degenerate_faces() == 2);
  for(std::size_t f = 0; f < g.number_of_faces(); ++f)
    CHECK(g.geometry().normals[f].norm() == Approx(1.));
  const auto w = Metrics::make_blend(Metrics::Geodesic_weight(), 0.5, Metrics::Angular_weight(), 0.5)(g);
  const std::vector<double> d = Weighted_dual_graph(g, w).distances(0);
  for(double v : d)
    CHECK(std::isfinite(v));
}

#include <SpectralSeg/Sampling/farthest_point_samples.h>

TEST_CASE("farthest point sampling spreads samples along a strip", "[sampling]")
{
  const std::size_t n = 21;
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::equilateral_strip(n));
  const Dual_graph g = make_dual_graph(m);
  const Weighted_dual_graph wg(g, Metrics::Geodesic_weight()(g));
  const Sampling::Farthest_point_samples s = Sampling::farthest_point_samples(wg, 3, 7);
  REQUIRE(s.faces.size() == 3);
  // the ends of the strip first (the diameter), then its middle
  CHECK(std::min(s.faces[0], s.faces[1]) == 0);
  CHECK(std::max(s.faces[0], s.faces[1]) == n - 1);
  CHECK(s.faces[2] == n / 2);
  CHECK(s.nearest_sample[1] == (s.faces[0] == 0 ? 0u : 1u));
  CHECK(s.distance[n / 2] == 0.);
  CHECK_THROWS_AS(Sampling::farthest_point_samples(wg, n + 1), Invalid_input);
  // the kept distance rows are the samples' Dijkstra runs; the samples and
  // the nearest distances are those of the run without them
  Sampling::Farthest_point_options keep;
  keep.start = 7;
  keep.keep_distance_rows = true;
  const Sampling::Farthest_point_samples kept = Sampling::farthest_point_samples(wg, 5, keep);
  const Sampling::Farthest_point_samples plain = Sampling::farthest_point_samples(wg, 5, 7);
  CHECK(kept.faces == plain.faces);
  CHECK(kept.distance == plain.distance);
  CHECK(kept.nearest_sample == plain.nearest_sample);
  CHECK(plain.distance_rows.empty());
  REQUIRE(kept.distance_rows.size() == 5);
  for(std::size_t i = 0; i < 5; ++i)
    CHECK(kept.distance_rows[i] == wg.distances(kept.faces[i]));
  // the rows are made beside the sampling on the other threads: the same
  // on any number, every face included (its last samples at distance 0)
  const Sampling::Farthest_point_samples every = Sampling::farthest_point_samples(wg, n, 7);
  for(const unsigned threads : {1u, 2u, 4u})
  {
    INFO(threads << " threads");
    std::size_t reports = 0;
    const Sampling::Farthest_point_samples rows = Sampling::farthest_point_samples(
      wg, n, keep, Execution(threads, [&reports](const std::string&, double) { return ++reports > 0; }));
    CHECK(rows.faces == every.faces);
    CHECK(reports > 0);
    REQUIRE(rows.distance_rows.size() == n);
    for(std::size_t i = 0; i < n; ++i)
      CHECK(rows.distance_rows[i] == wg.distances(rows.faces[i]));
  }
  // asking for every face returns every face once
  const Sampling::Farthest_point_samples all = Sampling::farthest_point_samples(wg, n);
  std::vector<Dual_graph::size_type> sorted = all.faces;
  std::sort(sorted.begin(), sorted.end());
  CHECK(std::unique(sorted.begin(), sorted.end()) == sorted.end());
  CHECK(sorted.size() == n);
}

TEST_CASE("adding a source lowers the nearest-source distances as a run from all the sources would", "[sampling]")
{
  const std::size_t n = 40;
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::equilateral_strip(n));
  const Dual_graph g = make_dual_graph(m);
  std::vector<double> w = Metrics::Geodesic_weight()(g);
  for(std::size_t e = 0; e < w.size(); ++e)
    w[e] *= 1. + 0.5 * double((e * 7) % 5); // uneven, so that paths are not all alike
  const Weighted_dual_graph wg(g, w);
  const std::vector<Dual_graph::size_type> sources{3, 31, 17, 17, 0};
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> nearest(n, Nearest_source_distances::unreachable);
  for(std::size_t i = 0; i < sources.size(); ++i)
  {
    wg.add_source(sources[i], i, distance, nearest);
    const std::vector<Dual_graph::size_type> so_far(sources.begin(), sources.begin() + std::ptrdiff_t(i) + 1);
    const Nearest_source_distances all = wg.distances(so_far);
    CHECK(distance == all.distance); // bit for bit
    for(std::size_t f = 0; f < n; ++f)
    {
      INFO("face " << f << " after " << i + 1 << " sources");
      // the nearest source is one at that distance, the earliest on ties
      CHECK(wg.distances(sources[nearest[f]])[f] == distance[f]);
      for(std::size_t j = 0; j < nearest[f]; ++j)
        CHECK(wg.distances(sources[j])[f] > distance[f]);
    }
  }
  CHECK(nearest[17] == 2); // the repeated source keeps its first position
  CHECK_THROWS_AS(wg.add_source(Dual_graph::size_type(n), 0, distance, nearest), Invalid_input);
  std::vector<double> short_distance(n - 1, 0.);
  CHECK_THROWS_AS(wg.add_source(0, 0, short_distance, nearest), Invalid_input);
}

TEST_CASE("shortest paths by buckets give Dijkstra's distances bit for bit, whatever the bucket width", "[distances]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::sphere(1., 24, 48));
  const Dual_graph g = make_dual_graph(m);
  const Dual_graph::Csr& csr = g.csr();
  const std::size_t n = g.number_of_faces();
  // uneven weights, some 0 and one far above the others
  std::vector<double> arc(num_edges(csr));
  for(auto e : boost::make_iterator_range(boost::edges(csr)))
  {
    const std::size_t d = csr[e].dual_edge;
    arc[get(boost::edge_index, csr, e)] = d % 11 == 0 ? 0. : d == 5 ? 1e6 : 0.1 + 0.37 * double((d * 7919) % 97);
  }
  double mean = 0.;
  for(double w : arc)
    mean += w / double(arc.size());
  const auto arcs = [&](Dual_graph::size_type f, const auto& fn) {
    for(auto e : boost::make_iterator_range(out_edges(f, csr)))
      fn(Dual_graph::size_type(target(e, csr)), arc[get(boost::edge_index, csr, e)]);
  };
  for(const Dual_graph::size_type source : {Dual_graph::size_type(0), Dual_graph::size_type(n / 2)})
  {
    std::vector<double> dijkstra(n);
    boost::dijkstra_shortest_paths(
      csr, source,
      boost::distance_map(boost::make_iterator_property_map(dijkstra.begin(), get(boost::vertex_index, csr)))
        .weight_map(boost::make_iterator_property_map(arc.begin(), get(boost::edge_index, csr))));
    // buckets; all in one bucket; a width so small that the run goes on in a heap
    for(const double width : {mean, 1e9 * mean, 1e-9 * mean})
    {
      INFO("source " << source << ", width " << width);
      std::vector<double> d(n, std::numeric_limits<double>::infinity());
      d[source] = 0.;
      std::vector<char> lowered(n, 0);
      internal::bucket_shortest_paths<Dual_graph::size_type>(arcs, width, d, {std::make_pair(0., source)},
                                                             [&](Dual_graph::size_type f, double) {
                                                               lowered[f] = 1;
                                                               return true;
                                                             });
      CHECK(d == dijkstra);
      // every face but the source was lowered from infinity
      CHECK(std::count(lowered.begin(), lowered.end(), 1) == std::ptrdiff_t(n - 1));
      // lowering from a second source reports exactly the faces that get closer
      const Dual_graph::size_type other = Dual_graph::size_type(n - 1 - source / 3);
      std::vector<double> second(n);
      boost::dijkstra_shortest_paths(
        csr, other,
        boost::distance_map(boost::make_iterator_property_map(second.begin(), get(boost::vertex_index, csr)))
          .weight_map(boost::make_iterator_property_map(arc.begin(), get(boost::edge_index, csr))));
      const std::vector<double> before = d;
      std::fill(lowered.begin(), lowered.end(), 0);
      d[other] = 0.;
      internal::bucket_shortest_paths<Dual_graph::size_type>(arcs, width, d, {std::make_pair(0., other)},
                                                             [&](Dual_graph::size_type f, double) {
                                                               lowered[f] = 1;
                                                               return true;
                                                             });
      std::size_t closer = 0;
      for(std::size_t f = 0; f < n; ++f)
      {
        CHECK(d[f] == std::min(before[f], second[f]));
        if(f != other)
        {
          CHECK(bool(lowered[f]) == (d[f] < before[f]));
          closer += d[f] < before[f];
        }
      }
      CHECK(closer > 0);
      CHECK(closer < n - 1);
    }
  }
}

TEST_CASE("quantile normalisation divides by the quantile and clamps at 1", "[metrics][normalization]")
{
  std::vector<double> w = {0., 1., 2., 3., 100.};
  Metrics::normalize_weights(w, Metrics::Normalization::quantile(0.5)); // the median, 2
  CHECK(w == std::vector<double>({0., 0.5, 1., 1., 1.}));
  std::vector<double> m = {0., 1., 2., 3., 100.};
  Metrics::normalize_weights(m, Metrics::Normalization::maximum());
  CHECK(m[4] == 1.);
  CHECK(m[1] == Approx(0.01));
  // a zero quantile falls back to the maximum
  std::vector<double> z = {0., 0., 0., 5.};
  Metrics::normalize_weights(z, Metrics::Normalization::quantile(0.5));
  CHECK(z == std::vector<double>({0., 0., 0., 1.}));
  CHECK_THROWS_AS(Metrics::Normalization::quantile(0.), Invalid_input);
}

TEST_CASE("write_colored_mesh writes one colour per face in PLY and OFF", "[io][colored]")
{
  const Mesh mesh = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(2));
  const Mesh_geometry g = extract_mesh_geometry(mesh);
  std::vector<Rendering::Rgb> colors(g.number_of_faces(), Rendering::Rgb{10, 20, 30});
  colors[3] = Rendering::Rgb{255, 0, 7};
  const std::string dir = std::filesystem::temp_directory_path().string();
  const auto read = [](const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for(std::string l; std::getline(in, l);)
      lines.push_back(l);
    return lines;
  };
  const std::string ply = dir + "/spectralseg_colored_test.ply";
  IO::write_colored_mesh(ply, g, colors);
  const std::vector<std::string> p = read(ply);
  REQUIRE(p.size() == 13 + g.number_of_vertices() + g.number_of_faces());
  CHECK(p[0] == "ply");
  CHECK(std::find(p.begin(), p.end(), "element face 4") != p.end());
  const auto& t = g.triangles[3];
  CHECK(p.back() == "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + " 255 0 7");
  CHECK(p[p.size() - 2].substr(p[p.size() - 2].size() - 9) == " 10 20 30");
  const std::string off = dir + "/spectralseg_colored_test.OFF";
  IO::write_colored_mesh(off, g, colors);
  const std::vector<std::string> o = read(off);
  REQUIRE(o.size() == 2 + g.number_of_vertices() + g.number_of_faces());
  CHECK(o[1] == "6 4 0");
  CHECK(o.back() == p.back());
  CHECK_THROWS_AS(IO::write_colored_mesh(dir + "/spectralseg_colored_test.stl", g, colors), Io_error);
  colors.pop_back();
  CHECK_THROWS_AS(IO::write_colored_mesh(ply, g, colors), Invalid_input);
  std::filesystem::remove(ply);
  std::filesystem::remove(off);
}

TEST_CASE("make_dual_graph joins parts that touch, links specks, keeps large separate parts apart", "[dual_graph][contacts]")
{
  // three boxes: A and B touch along a face (their vertices coincide, but
  // they are separate components), a tiny C floats far away, a large D
  // floats far away
  auto shifted = [](test_meshes::Soup s, double dx, double scale) {
    for(auto& p : s.points)
    {
      for(auto& c : p)
        c *= scale;
      p[0] += dx;
    }
    return s;
  };
  test_meshes::Soup all;
  auto append = [&all](const test_meshes::Soup& s) {
    const std::size_t base = all.points.size();
    all.points.insert(all.points.end(), s.points.begin(), s.points.end());
    for(auto f : s.faces)
    {
      for(auto& v : f)
        v += base;
      all.faces.push_back(f);
    }
  };
  const test_meshes::Soup box = test_meshes::welded(test_meshes::box(1., 1., 1., 4));
  append(box);                    // A: [0,1]
  append(shifted(box, 1., 1.));   // B: [1,2], touching A at x = 1
  append(shifted(box, 4., 0.05)); // C: a speck, far away
  append(shifted(box, 8., 1.));   // D: large, far away
  const Mesh m = test_meshes::to_mesh<Mesh>(all);

  const Dual_graph thesis = make_dual_graph(m, parameters::connect_touching_parts(false));
  CHECK(thesis.number_of_components() == 4);
  for(const auto& e : thesis.edges())
    CHECK_FALSE(e.contact);

  const Dual_graph g = make_dual_graph(m);
  CHECK(g.number_of_components() == 2); // A+B+C, and D
  const std::size_t per_box = box.faces.size();
  const auto& component = g.component_of_faces();
  CHECK(component[0] == component[per_box]);     // A and B
  CHECK(component[0] == component[2 * per_box]); // the speck C joins the nearest part (B)
  CHECK(component[0] != component[3 * per_box]); // D stays apart
  std::size_t contacts = 0;
  for(const auto& e : g.edges())
    if(e.contact)
    {
      ++contacts;
      CHECK(e.length > 0.);
      CHECK(std::isfinite(e.geodesic_length));
    }
  CHECK(contacts > 1); // along the touching faces, and one for the speck
  CHECK(g.number_of_edges() == thesis.number_of_edges() + contacts);

  // no specks: C stays apart too
  CHECK(make_dual_graph(m, parameters::speck_area_fraction(0.)).number_of_components() == 3);
  CHECK_THROWS_AS(make_dual_graph(m, parameters::contact_distance(-1.)), Invalid_input);
}

TEST_CASE("many separate specks whose nearest vertices are their own are all linked", "[dual_graph][contacts]")
{
  // 150 boxes of 3 x 3 squares a side, each under 1% of the area and two
  // box widths from the next: every vertex's 12 nearest vertices are its
  // own box's, so each speck is linked through an exact search
  const test_meshes::Soup box = test_meshes::welded(test_meshes::box(1., 1., 1., 3));
  test_meshes::Soup all;
  for(int b = 0; b < 150; ++b)
  {
    const std::size_t base = all.points.size();
    for(auto p : box.points)
    {
      p[0] += 3. * (b % 6);
      p[1] += 3. * ((b / 6) % 5);
      p[2] += 3. * (b / 30);
      all.points.push_back(p);
    }
    for(auto f : box.faces)
    {
      for(auto& v : f)
        v += base;
      all.faces.push_back(f);
    }
  }
  const Mesh m = test_meshes::to_mesh<Mesh>(all);
  const Dual_graph g = make_dual_graph(m);
  CHECK(g.number_of_components() == 1);
  std::size_t contacts = 0;
  for(const auto& e : g.edges())
    contacts += e.contact ? 1 : 0;
  CHECK(contacts == 149); // one link per speck joined: a spanning tree of the boxes
  CHECK(make_dual_graph(m, parameters::speck_area_fraction(0.)).number_of_components() == 150);
}

TEST_CASE("two large fans touching at one point get the contact of their nearest faces", "[dual_graph][contacts]")
{
  // two cones of n slivers each, apices at the same point but separate
  // vertices (a split non-manifold vertex): their nearest pair of faces
  // among n x n, found through a search tree above 64 x 64 pairs
  for(const std::size_t n : {std::size_t(40), std::size_t(3000)})
  {
    Mesh_geometry geo;
    geo.points.push_back(Eigen::Vector3d::Zero());
    geo.points.push_back(Eigen::Vector3d::Zero());
    for(int side = 0; side < 2; ++side)
      for(std::size_t i = 0; i < n; ++i)
      {
        const double a = 2. * CGAL_PI * (double(i) + 0.37 * side) / double(n);
        geo.points.emplace_back(std::cos(a), std::sin(a) * (1. + 0.1 * side), side ? -1. - 0.001 * double(i % 7) : 1.);
      }
    for(std::uint32_t side = 0; side < 2; ++side)
      for(std::uint32_t i = 0; i < n; ++i)
        geo.triangles.push_back({side, std::uint32_t(2 + side * n + i), std::uint32_t(2 + side * n + (i + 1) % n)});
    geo.compute_face_attributes();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> adjacent;
    for(std::uint32_t side = 0; side < 2; ++side)
      for(std::uint32_t i = 0; i < n; ++i)
        adjacent.emplace_back(side * n + i, side * n + (i + 1) % n);
    const std::vector<SpectralSeg::internal::Contact> contacts =
      SpectralSeg::internal::contact_adjacencies(geo, adjacent, 0., 0.);
    REQUIRE(contacts.size() == 1);
    double best = std::numeric_limits<double>::infinity();
    std::pair<std::uint32_t, std::uint32_t> nearest(0, 0);
    for(std::uint32_t f = 0; f < n; ++f)
      for(std::uint32_t g = std::uint32_t(n); g < 2 * n; ++g)
      {
        const double d = (geo.centroids[f] - geo.centroids[g]).squaredNorm();
        if(d < best)
        {
          best = d;
          nearest = {f, g};
        }
      }
    CHECK(std::min(contacts[0].f0, contacts[0].f1) == nearest.first);
    CHECK(std::max(contacts[0].f0, contacts[0].f1) == nearest.second);
  }
}

TEST_CASE("write_segmented_mesh: PLY vertices copied per segment, labels, binary, OBJ materials, parts",
          "[io][segmented]")
{
  // two unit squares side by side, two triangles each; vertices 2 and 3 are
  // shared by the squares, which are segments 0 and 1
  Mesh mesh = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(2));
  auto segment = mesh.add_property_map<Mesh::Face_index, int>("f:segment", 0).first;
  for(Mesh::Face_index f : faces(mesh))
    segment[f] = f.idx() < 2 ? 0 : 1;
  const std::string dir = (std::filesystem::temp_directory_path() / "spectralseg_segmented_test").string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto read = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<std::string> lines;
    for(std::string l; std::getline(in, l);)
      lines.push_back(l);
    return lines;
  };
  const auto has = [](const std::vector<std::string>& lines, const std::string& line) {
    return std::count(lines.begin(), lines.end(), line);
  };
  const auto rgb = [](int s) {
    const Rendering::Rgb c = s < 0 ? Rendering::missing_color() : Rendering::label_color(std::size_t(s));
    return std::to_string(int(c.r)) + " " + std::to_string(int(c.g)) + " " + std::to_string(int(c.b));
  };

  CHECK(IO::mesh_output_format("a/b.PLY") == IO::Mesh_output_format::ply);
  CHECK(IO::mesh_output_format("b.obj") == IO::Mesh_output_format::obj);
  CHECK(IO::mesh_output_format("b.off") == IO::Mesh_output_format::off);
  CHECK(IO::mesh_output_format("b.xyz") == IO::Mesh_output_format::unsupported);
  CHECK(IO::mesh_output_format("a.ply/b") == IO::Mesh_output_format::unsupported);
  CHECK(IO::material_library_path("out/m.obj") == "out/m.mtl");
  CHECK(IO::segment_part_path("d", 7) == "d/part_007.ply");
  CHECK(IO::segment_part_path("d/", 1234, 4) == "d/part_1234.ply");

  // ASCII PLY: 6 vertices, the 2 shared ones copied: 8, each in its segment's colour
  const std::string ply = dir + "/m.ply";
  IO::write_segmented_mesh(ply, mesh, segment);
  const std::vector<std::string> p = read(ply);
  REQUIRE(p.size() == 18 + 8 + 4);
  CHECK(has(p, "element vertex 8") == 1);
  CHECK(has(p, "element face 4") == 1);
  CHECK(has(p, "property int segment") == 1);
  CHECK(has(p, "0 0 0 " + rgb(0)) == 1);
  CHECK(has(p, "1 0 0 " + rgb(0)) == 1); // vertex 2, shared: once per segment
  CHECK(has(p, "1 0 0 " + rgb(1)) == 1);
  CHECK(has(p, "2 1 0 " + rgb(1)) == 1);
  for(int f = 0; f < 4; ++f)
  {
    const std::string& face = p[18 + 8 + std::size_t(f)];
    const int s = f < 2 ? 0 : 1;
    CHECK(face.substr(face.size() - rgb(s).size() - 2) == rgb(s) + " " + std::to_string(s));
  }

  // binary: the same header in binary_little_endian, 8 x 27 + 4 x 20 bytes of data
  const std::string binary = dir + "/m_binary.ply";
  IO::write_segmented_mesh(binary, mesh, segment, parameters::use_binary_mode(true));
  const std::vector<std::string> b = read(binary);
  CHECK(b[1] == "format binary_little_endian 1.0");
  std::size_t header = 0;
  for(std::size_t i = 0; i < 18; ++i)
    header += b[i].size() + 1;
  CHECK(std::filesystem::file_size(binary) == header + 8 * 27 + 4 * 20);

  // OBJ: the vertices as they are, one material per run of faces of a segment
  const std::string obj = dir + "/m.obj";
  IO::write_segmented_mesh(obj, mesh, segment);
  const std::vector<std::string> o = read(obj);
  CHECK(has(o, "mtllib m.mtl") == 1);
  CHECK(std::count_if(o.begin(), o.end(), [](const std::string& l) { return l.rfind("v ", 0) == 0; }) == 6);
  CHECK(has(o, "usemtl segment_0") == 1);
  CHECK(has(o, "usemtl segment_1") == 1);
  const std::vector<std::string> mtl = read(dir + "/m.mtl");
  CHECK(has(mtl, "newmtl segment_0") == 1);
  CHECK(has(mtl, "newmtl segment_1") == 1);
  CHECK(has(mtl, "Kd 0.3059 0.4745 0.6549") == 1); // label_color(0) = #4E79A7

  // a face without segment (-1): grey, label -1, in no part
  segment[Mesh::Face_index(3)] = -1;
  IO::write_segmented_mesh(ply, mesh, segment);
  CHECK(read(ply).back().substr(read(ply).back().size() - rgb(-1).size() - 3) == rgb(-1) + " -1");
  const std::vector<std::string> parts = IO::write_segment_parts(dir + "/parts", mesh, segment);
  REQUIRE(parts == std::vector<std::string>{dir + "/parts/part_000.ply", dir + "/parts/part_001.ply"});
  const std::vector<std::string> part1 = read(parts[1]);
  CHECK(has(part1, "element vertex 3") == 1);
  CHECK(has(part1, "element face 1") == 1);

  CHECK_THROWS_AS(IO::write_segmented_mesh(dir + "/m.stl", mesh, segment), Io_error);
  CHECK_THROWS_AS(IO::write_segment_parts(ply, mesh, segment), Io_error); // a file, not a directory
  CHECK(!std::filesystem::exists(dir + "/m.stl"));
  std::filesystem::remove_all(dir);
}

namespace {
// The soup moved by x -> s R x + t, R a rotation of 37 degrees about (1, 2, 3).
test_meshes::Soup similar(const test_meshes::Soup& in, double scale)
{
  const Eigen::Matrix3d r = Eigen::AngleAxisd(37. * pi / 180., Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  test_meshes::Soup out = in;
  for(auto& p : out.points)
  {
    const Eigen::Vector3d q = scale * (r * Eigen::Vector3d(p[0], p[1], p[2])) + Eigen::Vector3d(0.3, -2., 5.);
    p = {q.x(), q.y(), q.z()};
  }
  return out;
}

Retrieval::Shape_descriptor describe(const Mesh& m, const std::string& metric, unsigned threads = 1)
{
  namespace P = SpectralSeg::parameters;
  const auto np = P::number_of_threads(threads);
  if(metric == "part-aware")
    return shape_descriptor(m, np.metric(Retrieval::retrieval_metric<Ray_casting::AABB_ray_caster>()));
  if(metric == "geodesic")
    return shape_descriptor(m, np.metric(Metrics::Geodesic_weight()));
  return shape_descriptor(m, np.metric(Retrieval::Euclidean_distance()));
}
} // namespace

TEST_CASE("shape descriptor: a distribution; chi-square is 0 on itself, symmetric, at most 1", "[retrieval]")
{
  const Mesh star = test_meshes::to_mesh<Mesh>(test_meshes::star(1));
  const Mesh t = test_meshes::to_mesh<Mesh>(test_meshes::t_shape(1));
  for(const std::string metric : {"part-aware", "geodesic", "euclidean"})
  {
    INFO(metric);
    const Retrieval::Shape_descriptor a = describe(star, metric), b = describe(t, metric);
    CHECK(a.metric == metric);
    CHECK(a.histogram.size() == 64);
    CHECK(a.mean_distance > 0.);
    double sum = 0.;
    for(double v : a.histogram)
    {
      CHECK(v >= 0.);
      sum += v;
    }
    CHECK(sum == Approx(1.).epsilon(1e-12));
    CHECK(Retrieval::chi_square_distance(a, a) == 0.);
    CHECK(Retrieval::chi_square_distance(a, b) == Retrieval::chi_square_distance(b, a));
    CHECK(Retrieval::chi_square_distance(a, b) > 0.);
    CHECK(Retrieval::chi_square_distance(a, b) <= 1.);
  }
  // geodesic: the mean distance between faces of the T is of the order of its size
  const Retrieval::Shape_descriptor g = describe(t, "geodesic");
  CHECK(g.mean_distance > 2.);
  CHECK(g.mean_distance < 12.);
  // descriptors of different metrics or bins are not comparable
  Retrieval::Shape_descriptor other = g;
  other.metric = "euclidean";
  CHECK_THROWS_AS(Retrieval::chi_square_distance(g, other), Invalid_input);
  other = g;
  other.histogram.pop_back();
  CHECK_THROWS_AS(Retrieval::chi_square_distance(g, other), Invalid_input);
  Retrieval::Descriptor_options bad;
  bad.bins = 1;
  CHECK_THROWS_AS(shape_descriptor(t, SpectralSeg::parameters::descriptor_options(bad).metric(Metrics::Geodesic_weight())),
                  Invalid_input);
}

TEST_CASE("shape descriptor: independent of scale, rotation, threads; close under 1-to-4 subdivision", "[retrieval][invariance]")
{
  // a real mesh: the voxel shapes have exact ties between distances, which
  // rounding after a rotation breaks differently (other farthest-point sources)
  Mesh m;
  IO::read_mesh_file(SPECTRALSEG_SOURCE_DIR "/data/elephant.off", m);
  test_meshes::Soup soup;
  for(auto v : m.vertices())
    soup.points.push_back({m.point(v).x(), m.point(v).y(), m.point(v).z()});
  for(auto f : m.faces())
  {
    std::vector<std::size_t> t;
    for(auto v : vertices_around_face(m.halfedge(f), m))
      t.push_back(std::size_t(v));
    soup.faces.push_back(t);
  }
  const Mesh moved = test_meshes::to_mesh<Mesh>(similar(soup, 7.3));
  const Mesh finer = spectralseg_bench::midpoint_subdivision(m);
  for(const std::string metric : {"part-aware", "geodesic", "euclidean"})
  {
    INFO(metric);
    const Retrieval::Shape_descriptor d = describe(m, metric);
    // exactly the same sums whatever the number of threads
    const Retrieval::Shape_descriptor d2 = describe(m, metric, 2);
    CHECK(d2.histogram == d.histogram);
    CHECK(d2.mean_distance == d.mean_distance);
    // scale and rotation: float rounding for the surface metrics; the
    // part-aware metric's shape images use fixed ray directions, so a
    // rotation moves some reaches (measured 0.004; doc/retrieval.md)
    const double similar_tolerance = metric == "part-aware" ? 0.02 : 1e-9;
    CHECK(Retrieval::chi_square_distance(d, describe(moved, metric)) < similar_tolerance);
    // subdivision: other faces, other sources; the part-aware metric's edge
    // weights also change with the resolution (measured 0.007, 0.0003)
    CHECK(Retrieval::chi_square_distance(d, describe(finer, metric)) < (metric == "part-aware" ? 0.03 : 0.003));
  }
}

TEST_CASE("ranking: a moved, subdivided copy of the query comes first", "[retrieval][ranking]")
{
  const test_meshes::Soup star = test_meshes::star(1);
  const std::vector<Mesh> database{test_meshes::to_mesh<Mesh>(test_meshes::t_shape(1)),
                                   test_meshes::to_mesh<Mesh>(test_meshes::welded(test_meshes::box(4., 1., 1., 4))),
                                   spectralseg_bench::midpoint_subdivision(test_meshes::to_mesh<Mesh>(similar(star, 0.2))),
                                   test_meshes::to_mesh<Mesh>(test_meshes::sphere(1., 12, 24))};
  const Mesh query = test_meshes::to_mesh<Mesh>(star);
  for(const std::string metric : {"part-aware", "geodesic", "euclidean"})
  {
    INFO(metric);
    std::vector<Retrieval::Shape_descriptor> d;
    for(const Mesh& m : database)
      d.push_back(describe(m, metric));
    const std::vector<Retrieval::Ranked_shape> r = Retrieval::rank_shapes(describe(query, metric), d);
    REQUIRE(r.size() == database.size());
    CHECK(r[0].index == 2);
    for(std::size_t i = 1; i < r.size(); ++i)
      CHECK(r[i - 1].distance <= r[i].distance);
  }
}

TEST_CASE("retrieval scores: nearest neighbour, first and second tier", "[retrieval][scores]")
{
  // classes a a b b b; distances: shape 0 finds 2 (b) then 1 (a); the b's find each other
  const std::vector<std::string> c{"a", "a", "b", "b", "b"};
  std::vector<std::vector<double>> d(5, std::vector<double>(5, 1.));
  auto set = [&](std::size_t i, std::size_t j, double v) { d[i][j] = d[j][i] = v; };
  set(0, 2, 0.1);
  set(0, 1, 0.2);
  set(2, 3, 0.1);
  set(3, 4, 0.1);
  set(2, 4, 0.1);
  set(1, 3, 0.05);
  const Retrieval::Retrieval_scores s = Retrieval::retrieval_scores(d, c);
  CHECK(s.queries == 5);
  // NN: 0 -> 2 (no), 1 -> 3 (no), 2 -> 0 (no, 0.1 ties with 3 and 4, smaller index first), 3 -> 1 (no), 4 -> 2 (yes)
  CHECK(s.nearest_neighbor == Approx(1. / 5.));
  // FT (top C-1): 0: {2} 0; 1: {3} 0; 2: {0,3} 1/2; 3: {1,2} 1/2; 4: {2,3} 1
  CHECK(s.first_tier == Approx((0. + 0. + 0.5 + 0.5 + 1.) / 5.));
  // ST (top 2(C-1)): 0: {2,1} 1; 1: {3,0} 1; 2: {0,3,4,1} 1; 3: {1,2,4,0} 1; 4: {2,3,...} 1
  CHECK(s.second_tier == Approx(1.));
  CHECK_THROWS_AS(Retrieval::retrieval_scores(d, std::vector<std::string>(4, "a")), Invalid_input);
}

TEST_CASE("align_embeddings: recovers a rotation and sign flips, with or without correspondences", "[registration]")
{
  // a scattered anisotropic cloud (no symmetry), rows shuffled, one axis
  // flipped, rotated and moved
  const Eigen::Index n = 200;
  Eigen::MatrixXd a(n, 3);
  std::uint32_t state = 12345;
  auto uniform = [&state]() {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  for(Eigen::Index i = 0; i < n; ++i)
    a.row(i) << 3. * uniform(), 2. * uniform(), uniform();
  for(const double angle : {0.1, 1.2})
  {
    INFO(angle);
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
    Eigen::MatrixXd b(n, 3), b_same_rows(n, 3);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      Eigen::Vector3d p = a.row((i * 7) % n).transpose();
      p.y() = -p.y();
      b.row(i) = (r * p + Eigen::Vector3d(0.2, -0.1, 0.4)).transpose();
    }
    for(Eigen::Index i = 0; i < n; ++i)
      b_same_rows.row((i * 7) % n) = b.row(i);
    // known pairs: exact whatever the rotation
    Registration::Alignment_options known;
    known.rows_correspond = true;
    const Registration::Embedding_alignment k = Registration::align_embeddings(b_same_rows, a, known);
    CHECK(k.rms_closest < 1e-9);
    CHECK(k.sign_flips != 0);
    CHECK((k.aligned - a).norm() < 1e-9);
    // closest points: from the right flip, a small rotation is recovered exactly
    if(angle < 0.5)
    {
      const Registration::Embedding_alignment c = Registration::align_embeddings(b, a);
      CHECK(c.rms_closest < 1e-9);
      for(Eigen::Index i = 0; i < n; ++i)
        CHECK((c.aligned.row(i) - a.row((i * 7) % n)).norm() < 1e-9);
    }
  }
  CHECK_THROWS_AS(Registration::align_embeddings(a, Eigen::MatrixXd(n, 2)), Invalid_input);
  Registration::Alignment_options known;
  known.rows_correspond = true;
  CHECK_THROWS_AS(Registration::align_embeddings(a, Eigen::MatrixXd(n - 1, 3), known), Invalid_input);
}
