// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// k-way segmentation: known parts found, exact and Nyström agree, Gamma,
// determinism across thread counts, bad k.
#include "test_meshes.h"

#include <SpectralSeg/Embedding/nystrom_spectral_embedding.h>
#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/Kernels/Any_kernel.h>
#include <SpectralSeg/Kernels/Gaussian_kernel.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Refinement/graph_cut_boost_backends.h>
#include <SpectralSeg/evaluation.h>
#include <SpectralSeg/k_way_segmentation.h>
#include <SpectralSeg/segment_hybrid.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
using namespace SpectralSeg;

struct Star
{
  test_meshes::Soup soup = test_meshes::star(2);
  Mesh mesh = test_meshes::to_mesh<Mesh>(soup);
  Dual_graph graph = make_dual_graph(mesh);
  std::vector<double> weights = Metrics::Part_aware_weight<>()(graph);
  Weighted_dual_graph weighted{graph, weights};
};

const Star& star()
{
  static const Star s;
  return s;
}

K_way_options with_method(Embedding::Method m)
{
  K_way_options o;
  o.embedding.method = m;
  return o;
}
} // namespace

TEST_CASE("k-way finds the body and the four limbs of a star", "[k_way]")
{
  const Star& s = star();
  REQUIRE(s.soup.face_part.size() == s.graph.number_of_faces());
  for(Embedding::Method m : {Embedding::Method::exact, Embedding::Method::nystrom})
  {
    INFO("method " << int(m));
    const K_way_result r = segment_k_way(s.weighted, 5, with_method(m));
    CHECK(r.number_of_segments == 5);
    CHECK(r.embedding.exact == (m == Embedding::Method::exact));
    // the default tries two over-segmentations and keeps one
    CHECK((r.extra_clusters == K_way_options().extra_clusters ||
           r.extra_clusters == K_way_options().alternative_extra_clusters.at(0)));
    CHECK(r.clusters.centroids.rows() == Eigen::Index(5 + r.extra_clusters));
    CHECK(Evaluation::rand_index_error(r.labels, s.soup.face_part) < 0.05);
    // the thesis's method: K-means with exactly k clusters, no merging
    K_way_options thesis = K_way_options::thesis();
    thesis.embedding.method = m;
    const K_way_result t = segment_k_way(s.weighted, 5, thesis);
    CHECK(t.number_of_segments == 5);
    CHECK(t.clusters.centroids.rows() == 5);
    CHECK(Evaluation::rand_index_error(t.labels, s.soup.face_part) < 0.05);
  }
}

TEST_CASE("automatic k-way finds the five parts of the star by itself", "[k_way][automatic]")
{
  const Star& s = star();
  const K_way_result r = segment_k_way_automatic(s.weighted);
  // the five parts, give or take a sliver: on this sharp-edged shape a
  // 31-face piece of the body whose boundary runs partly along the concave
  // junction of a limb keeps a mean concave angle above the limit
  CHECK(r.number_of_segments >= 5);
  CHECK(r.number_of_segments <= 6);
  CHECK(Evaluation::rand_index_error(r.labels, s.soup.face_part) < 0.05);
  // a huge merge limit merges down to the minimum of 2 segments
  K_way_automatic_options merge_all;
  merge_all.min_boundary_contrast = 1e6;
  const K_way_result two = segment_k_way_automatic(s.weighted, merge_all);
  CHECK(two.number_of_segments == 2);
  // its hierarchy, cut at 3 parts instead of where the rule stops
  CHECK(r.hierarchy.number_of_parts() >= 5);
  CHECK(r.hierarchy.roots.size() == 1);
  K_way_automatic_options three;
  three.parts = 3;
  const K_way_result c = segment_k_way_automatic(s.weighted, three);
  CHECK(c.number_of_segments == 3);
  CHECK(Evaluation::rand_index_error(c.labels, r.hierarchy.labels_with_parts(3)) < 0.02);
  K_way_automatic_options one;
  one.max_k = 1;
  CHECK_THROWS_AS(segment_k_way_automatic(s.weighted, one), Invalid_input);
}

TEST_CASE("segments merge across their weakest boundary first", "[k_way][merge]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(6));
  const Dual_graph g = make_dual_graph(m);
  REQUIRE(g.number_of_faces() == 12);
  // three segments of four faces along the strip (faces are in strip order)
  std::vector<int> thirds(12);
  for(std::size_t f = 0; f < 12; ++f)
    thirds[f] = int(f / 4);
  // the 0|1 boundary is strong, the 1|2 one weak
  std::vector<double> w(g.number_of_edges(), 0.5);
  for(std::size_t d = 0; d < w.size(); ++d)
  {
    const auto& e = g.edge(Dual_graph::size_type(d));
    const int a = thirds[e.face[0]], b = thirds[e.face[1]];
    if(std::min(a, b) == 0 && std::max(a, b) == 1)
      w[d] = 1.;
    if(std::min(a, b) == 1 && std::max(a, b) == 2)
      w[d] = 0.1;
  }
  std::vector<int> labels = thirds;
  CHECK(Refinement::merge_weakest_boundaries(g, w, labels, 2) == 2);
  CHECK(labels[0] == 0);
  CHECK(labels[4] == 1);
  CHECK(labels[11] == 1);
  CHECK(labels[3] != labels[4]);
  // the limit keeps boundaries at least that strong
  labels = thirds;
  CHECK(Refinement::merge_weakest_boundaries(g, w, labels, 1, 0.5) == 2);
  labels = thirds;
  CHECK(Refinement::merge_weakest_boundaries(g, w, labels, 1) == 1);
  labels = thirds;
  CHECK(Refinement::merge_weakest_boundaries(g, w, labels, 5) == 3);
  CHECK(labels == thirds);
  CHECK_THROWS_AS(Refinement::merge_weakest_boundaries(g, std::vector<double>(2, 0.), labels, 2), Invalid_input);
  // a segment under the area limit goes first, whatever its boundary: the
  // last face alone (1/12 of the area) behind the strongest boundary
  std::vector<int> flap = thirds;
  flap[11] = 3;
  std::vector<double> wf = w;
  for(std::size_t d = 0; d < wf.size(); ++d)
  {
    const auto& e = g.edge(Dual_graph::size_type(d));
    if(std::max(e.face[0], e.face[1]) == 11)
      wf[d] = 5.;
  }
  labels = flap;
  CHECK(Refinement::merge_weakest_boundaries(g, wf, labels, 3) == 3);
  CHECK(labels[11] != labels[10]); // without the limit, 1|2 is weaker
  labels = flap;
  CHECK(Refinement::merge_weakest_boundaries(g, wf, labels, 3, std::numeric_limits<double>::infinity(), 0.1) == 3);
  CHECK(labels[11] == labels[10]);
  CHECK(labels[7] != labels[8]);

  // the area factor: of two boundaries about as strong, the one around the
  // smaller part goes first. Segments of 6, 4 and 2 faces; the 6|4 boundary
  // is a little weaker than the 4|2 one.
  std::vector<int> sizes(12);
  for(std::size_t f = 0; f < 12; ++f)
    sizes[f] = f < 6 ? 0 : f < 10 ? 1 : 2;
  std::vector<double> ws(g.number_of_edges(), 1.);
  for(std::size_t d = 0; d < ws.size(); ++d)
  {
    const auto& e = g.edge(Dual_graph::size_type(d));
    const int a = sizes[e.face[0]], b = sizes[e.face[1]];
    if(a != b)
      ws[d] = std::min(a, b) == 0 ? 0.5 : 0.55;
  }
  labels = sizes;
  CHECK(Refinement::merge_weakest_boundaries(g, ws, labels, 2) == 2);
  CHECK(labels[0] == labels[6]); // the strength alone: 6|4 goes
  CHECK(labels[6] != labels[10]);
  labels = sizes;
  // 0.5 (4/12)^0.5 = 0.29 against 0.55 (2/12)^0.5 = 0.22: 4|2 goes
  CHECK(Refinement::merge_weakest_boundaries(g, ws, labels, 2, std::numeric_limits<double>::infinity(), 0., 0.5) == 2);
  CHECK(labels[0] != labels[6]);
  CHECK(labels[6] == labels[10]);
  labels = sizes;
  // the limit applies to the strength before the factor: both boundaries stay
  CHECK(Refinement::merge_weakest_boundaries(g, ws, labels, 2, 0.45, 0., 0.5) == 3);
  CHECK_THROWS_AS(Refinement::merge_weakest_boundaries(g, ws, labels, 2, 1., 0., -0.1), Invalid_input);
  CHECK_THROWS_AS(
    Refinement::merge_weakest_boundaries(g, ws, labels, 2, 1., 0., std::numeric_limits<double>::quiet_NaN()),
    Invalid_input);

  // the embedding-separation factor: segments 1 and 2 overlap in a 1-D
  // embedding, 0 lies far from both. By strength alone 0|1 (0.5) goes
  // before 1|2 (0.55); with the factor 1|2 is nearly free.
  Eigen::MatrixXd x(12, 1);
  for(Eigen::Index f = 0; f < 12; ++f)
    x(f, 0) = thirds[std::size_t(f)] == 0 ? 0.1 * double(f) : 10. + 0.1 * double(f % 4) + 0.05 * (thirds[std::size_t(f)] - 1);
  std::vector<double> wt(g.number_of_edges(), 1.);
  for(std::size_t d = 0; d < wt.size(); ++d)
  {
    const auto& e = g.edge(Dual_graph::size_type(d));
    const int a = thirds[e.face[0]], b = thirds[e.face[1]];
    if(a != b)
      wt[d] = std::min(a, b) == 0 ? 0.5 : 0.55;
  }
  const double none = std::numeric_limits<double>::infinity();
  labels = thirds;
  CHECK(Refinement::merge_weakest_boundaries(g, wt, labels, 2) == 2);
  CHECK(labels[0] == labels[4]);
  CHECK(labels[4] != labels[8]);
  Refinement::Embedding_separation sep;
  sep.coordinates = &x;
  labels = thirds;
  CHECK(Refinement::merge_weakest_boundaries(g, wt, labels, 2, none, 0., 0., sep) == 2);
  CHECK(labels[0] != labels[4]);
  CHECK(labels[4] == labels[8]);
  // a zero exponent, or a scale below the pair's separation, is no factor
  sep.exponent = 0.;
  labels = thirds;
  CHECK(Refinement::merge_weakest_boundaries(g, wt, labels, 2, none, 0., 0., sep) == 2);
  CHECK(labels[0] == labels[4]);
  sep.exponent = 1.;
  sep.scale = 1e-6;
  labels = thirds;
  CHECK(Refinement::merge_weakest_boundaries(g, wt, labels, 2, none, 0., 0., sep) == 2);
  CHECK(labels[0] == labels[4]);
  // the limit applies to the strength before the factor
  sep.scale = 2.;
  labels = thirds;
  CHECK(Refinement::merge_weakest_boundaries(g, wt, labels, 2, 0.52, 0., 0., sep) == 2);
  CHECK(labels[0] == labels[4]);
  CHECK(labels[4] != labels[8]);
  // bad arguments
  Eigen::MatrixXd short_x(11, 1);
  short_x.setZero();
  Refinement::Embedding_separation bad;
  bad.coordinates = &short_x;
  CHECK_THROWS_AS(Refinement::merge_weakest_boundaries(g, wt, labels, 2, none, 0., 0., bad), Invalid_input);
  bad.coordinates = &x;
  bad.scale = 0.;
  CHECK_THROWS_AS(Refinement::merge_weakest_boundaries(g, wt, labels, 2, none, 0., 0., bad), Invalid_input);
  bad.scale = 2.;
  bad.exponent = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(Refinement::merge_weakest_boundaries(g, wt, labels, 2, none, 0., 0., bad), Invalid_input);

  // a triangle soup: every face its own component, so every face its own
  // segment; nothing can merge, and the bookkeeping stays sparse (a dense
  // segment-by-segment table would need 2 x 20,000^2 doubles here)
  test_meshes::Soup soup;
  for(std::size_t t = 0; t < 20000; ++t)
  {
    const double x = double(t % 200) * 2., y = double(t / 200) * 2.;
    soup.points.push_back({x, y, 0.});
    soup.points.push_back({x + 1., y, 0.});
    soup.points.push_back({x, y + 1., 0.});
    soup.faces.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  // (kept apart: the default dual graph would join these nearby faces)
  const Dual_graph scattered =
    make_dual_graph(test_meshes::to_mesh<Mesh>(soup), parameters::connect_touching_parts(false));
  REQUIRE(scattered.number_of_components() == 20000);
  std::vector<int> one(20000, 0);
  CHECK(Refinement::make_segments_connected(scattered, one) == 20000);
  CHECK(Refinement::merge_weakest_boundaries(scattered, std::vector<double>(), one, 2, 1., 0.5) == 20000);

  // concave folds are strong boundaries, convex ones are not
  const Dual_graph valley = make_dual_graph(test_meshes::to_mesh<Mesh>(test_meshes::fold(0.5, true)));
  const Dual_graph ridge = make_dual_graph(test_meshes::to_mesh<Mesh>(test_meshes::fold(0.5, false)));
  const std::vector<double> wv = Refinement::concave_angle_weights(valley), wr = Refinement::concave_angle_weights(ridge);
  REQUIRE(wv.size() == 1);
  REQUIRE(wr.size() == 1);
  CHECK(wv[0] == Approx(0.5));
  CHECK(wr[0] == 0.);
}

TEST_CASE("exact and Nyström embeddings give the same segmentation", "[k_way][nystrom]")
{
  const Star& s = star();
  const K_way_result exact = segment_k_way(s.weighted, 5, with_method(Embedding::Method::exact));
  const K_way_result nystrom = segment_k_way(s.weighted, 5, with_method(Embedding::Method::nystrom));
  CHECK(Evaluation::rand_index_error(exact.labels, nystrom.labels) < 0.03);
  // the Gaussian kernel finds the parts too (chosen at run time, as the tool does)
  const K_way_result gaussian =
    segment_k_way(s.weighted, 5, with_method(Embedding::Method::nystrom).with_kernel(Kernels::Any_kernel(Kernels::Gaussian_kernel())));
  CHECK(Evaluation::rand_index_error(gaussian.labels, s.soup.face_part) < 0.05);
}

TEST_CASE("Any_kernel gives the affinities of the kernel it holds", "[k_way][kernel]")
{
  const Star& s = star();
  const std::vector<Dual_graph::size_type> samples{0, 7, 19};
  const Kernels::Any_kernel any{Kernels::Gaussian_kernel()};
  CHECK(any.name() == "gaussian");
  CHECK(any.width(2.5) == Kernels::Gaussian_kernel().width(2.5));
  CHECK(Kernels::Any_kernel(Kernels::Exponential_kernel()).width(2.5) == Kernels::Exponential_kernel().width(2.5));
  Embedding::internal::Row_matrix held = s.weighted.distance_rows(samples);
  Embedding::internal::Row_matrix wrapped = held;
  Embedding::internal::distances_to_affinities(held, Kernels::Gaussian_kernel(), Execution());
  Embedding::internal::distances_to_affinities(wrapped, any, Execution());
  CHECK(wrapped == held); // bit for bit
  CHECK(held.minCoeff() < 0.5); // not all 1: the comparison has something to compare
}

TEST_CASE("Gamma ranks a farthest-point sample set above a clustered one", "[nystrom][gamma]")
{
  const Star& s = star();
  const std::size_t l = 6;
  const auto spread = Sampling::farthest_point_samples(s.weighted, l).faces;
  // a clustered set: face 0 and its nearest faces
  const std::vector<double> d0 = s.weighted.distances(0);
  std::vector<Dual_graph::size_type> order(d0.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return d0[a] < d0[b]; });
  const std::vector<Dual_graph::size_type> clustered(order.begin(), order.begin() + l);
  auto gamma = [&](const std::vector<Dual_graph::size_type>& samples) {
    Embedding::internal::Row_matrix w = s.weighted.distance_rows(samples);
    Embedding::internal::distances_to_affinities(w, Kernels::Exponential_kernel(), Execution());
    return Embedding::nystrom_gamma(w, samples);
  };
  const double g_spread = gamma(spread), g_clustered = gamma(clustered);
  CHECK(g_spread < g_clustered);
  CHECK(g_spread >= 0.);
  // Gamma-sampling does at least as well as farthest-point sampling here
  Embedding::Embedding_options o;
  o.method = Embedding::Method::nystrom;
  o.sampling = Embedding::Sampling_method::gamma;
  o.samples = l;
  o.gamma_candidates = 30;
  const Embedding::Spectral_embedding e = Embedding::nystrom_spectral_embedding(s.weighted, 5, Kernels::Exponential_kernel(), o);
  CHECK(e.samples.size() == l);
  CHECK(e.gamma < g_clustered);
  // the embedding's Gamma, computed along the projection, is nystrom_gamma()
  // of its samples
  CHECK(e.gamma == Approx(gamma(e.samples)).epsilon(1e-9).margin(1e-9));
  Embedding::Embedding_options fp;
  fp.method = Embedding::Method::nystrom;
  const Embedding::Spectral_embedding f =
    Embedding::nystrom_spectral_embedding(s.weighted, 5, Kernels::Exponential_kernel(), fp);
  CHECK(f.gamma == Approx(gamma(f.samples)).epsilon(1e-9).margin(1e-9));
}

TEST_CASE("k-way labels do not depend on the number of threads", "[k_way][threads]")
{
  const Star& s = star();
  for(Embedding::Method m : {Embedding::Method::exact, Embedding::Method::nystrom})
  {
    const K_way_result r1 = segment_k_way(s.weighted, 5, with_method(m), Execution(1));
    const K_way_result r2 = segment_k_way(s.weighted, 5, with_method(m), Execution(2));
    const K_way_result r3 = segment_k_way(s.weighted, 5, with_method(m), Execution(3));
    CHECK(r1.labels == r2.labels);
    CHECK(r1.labels == r3.labels);
  }
}

TEST_CASE("k-way without the embedding's coordinates in the result: the same labels", "[k_way][memory]")
{
  const Star& s = star();
  for(Embedding::Method m : {Embedding::Method::exact, Embedding::Method::nystrom})
  {
    INFO("method " << int(m));
    K_way_options light = with_method(m);
    light.keep_embedding_coordinates = false;
    for(unsigned threads : {1u, 2u})
    {
      // several candidates: each one's coordinates go before its moves
      const K_way_result full = segment_k_way(s.weighted, 5, with_method(m), Execution(threads));
      const K_way_result r = segment_k_way(s.weighted, 5, light, Execution(threads));
      CHECK(r.labels == full.labels);
      CHECK(r.normalized_cut == full.normalized_cut);
      CHECK(r.extra_clusters == full.extra_clusters);
      CHECK(r.embedding.samples == full.embedding.samples);
      CHECK(r.hierarchy.nodes.size() == full.hierarchy.nodes.size());
      CHECK(full.embedding.coordinates.rows() == Eigen::Index(s.graph.number_of_faces()));
      CHECK(r.embedding.coordinates.size() == 0);
    }
    // one over-segmentation, and the automatic rule cut at a number of parts
    // (its hierarchy's cut reads the coordinates)
    K_way_options one = with_method(m);
    one.alternative_extra_clusters.clear();
    one.contrast_merge_clusters = 0;
    K_way_options one_light = one;
    one_light.keep_embedding_coordinates = false;
    CHECK(segment_k_way(s.weighted, 5, one_light).labels == segment_k_way(s.weighted, 5, one).labels);
    for(std::size_t parts : {0, 3})
    {
      K_way_automatic_options a;
      a.k_way = with_method(m);
      a.parts = parts;
      K_way_automatic_options b = a;
      b.k_way.keep_embedding_coordinates = false;
      const K_way_result ra = segment_k_way_automatic(s.weighted, a), rb = segment_k_way_automatic(s.weighted, b);
      CHECK(rb.labels == ra.labels);
      CHECK(rb.embedding.coordinates.size() == 0);
    }
  }
}

TEST_CASE("k-way entry point on a mesh; every segment is connected; bad k", "[k_way][api]")
{
  Star s;
  auto seg = s.mesh.add_property_map<Mesh::Face_index, std::size_t>("f:seg", 0).first;
  const std::size_t count = k_way_segmentation(s.mesh, 5, seg, parameters::number_of_threads(2).boundary_enhancement(true));
  CHECK(count == 5);
  std::vector<int> labels;
  for(auto f : s.mesh.faces())
    labels.push_back(int(get(seg, f)));
  CHECK(Evaluation::rand_index_error(labels, s.soup.face_part) < 0.05);
  // connected: each label's faces form one region of the dual graph
  std::vector<int> copy = labels;
  CHECK(Refinement::make_segments_connected(s.graph, copy) == 5);

  CHECK(k_way_segmentation(s.mesh, 5, seg,
                           parameters::number_of_nystrom_samples(8)
                             .embedding_method(Embedding::Method::nystrom)
                             .random_seed(3)) == 5);
  CHECK(k_way_segmentation(s.mesh, 1, seg) == 1);
  CHECK_THROWS_AS(k_way_segmentation(s.mesh, 0, seg), Invalid_input);
  CHECK_THROWS_WITH(k_way_segmentation(s.mesh, num_faces(s.mesh) + 1, seg), Catch::Contains("k must be"));

  const Embedding::Spectral_embedding e = spectral_embedding(s.mesh, 4, parameters::embedding_method(Embedding::Method::exact));
  CHECK(e.coordinates.rows() == Eigen::Index(num_faces(s.mesh)));
  CHECK(e.coordinates.cols() == 4);
  CHECK(e.eigenvalues(0) >= e.eigenvalues(3));
}

TEST_CASE("islands are merged into the neighbour with the longest shared boundary", "[k_way][connected]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(6));
  const Dual_graph g = make_dual_graph(m);
  // 12 faces in a row of triangles: label 0 everywhere but an island of 1 inside, and 1 at the end
  std::vector<int> labels(12, 0);
  labels[5] = 1;
  labels[10] = labels[11] = 1;
  CHECK(Refinement::make_segments_connected(g, labels) == 2);
  CHECK(labels[5] == 0);
  CHECK(labels[11] == 1);
}

namespace {
// make_segments_connected() by its definition: every region found again
// (depth-first floods from each region's smallest face, areas summed in the
// flood's order) before each merge of the smallest island.
std::size_t connected_by_definition(const Dual_graph& g, std::vector<int>& labels)
{
  const std::size_t n = g.number_of_faces();
  int fresh = *std::max_element(labels.begin(), labels.end()) + 1;
  for(;;)
  {
    std::vector<int> region(n, -1);
    std::vector<std::vector<Dual_graph::size_type>> faces; // in flood order
    std::vector<double> area;
    for(std::size_t s = 0; s < n; ++s)
    {
      if(region[s] >= 0)
        continue;
      const int r = int(faces.size());
      faces.emplace_back();
      area.push_back(0.);
      std::vector<Dual_graph::size_type> stack{Dual_graph::size_type(s)};
      region[s] = r;
      while(!stack.empty())
      {
        const Dual_graph::size_type f = stack.back();
        stack.pop_back();
        area[std::size_t(r)] += g.geometry().areas[f];
        faces[std::size_t(r)].push_back(f);
        g.for_each_neighbour(f, [&](Dual_graph::size_type h, Dual_graph::size_type) {
          if(region[h] < 0 && labels[h] == labels[f])
          {
            region[h] = r;
            stack.push_back(h);
          }
        });
      }
    }
    std::map<int, int> main_region; // the largest, the first on ties
    for(std::size_t r = 0; r < faces.size(); ++r)
    {
      const int l = labels[faces[r].front()];
      if(!main_region.count(l) || area[r] > area[std::size_t(main_region[l])])
        main_region[l] = int(r);
    }
    std::vector<int> islands;
    for(std::size_t r = 0; r < faces.size(); ++r)
      if(main_region[labels[faces[r].front()]] != int(r))
        islands.push_back(int(r));
    std::sort(islands.begin(), islands.end(), [&](int a, int b) {
      return std::make_pair(area[std::size_t(a)], a) < std::make_pair(area[std::size_t(b)], b);
    });
    bool merged = false;
    for(const int isl : islands)
    {
      std::map<int, double> boundary;
      for(const auto f : faces[std::size_t(isl)])
        g.for_each_neighbour(f, [&](Dual_graph::size_type h, Dual_graph::size_type e) {
          if(region[h] != isl)
            boundary[labels[h]] += g.edge(e).length;
        });
      // the longest shared boundary (the smallest label on ties), or none
      const auto longest = std::max_element(boundary.begin(), boundary.end(),
                                            [](const auto& a, const auto& b) { return a.second < b.second; });
      const int target = longest == boundary.end() ? fresh : longest->first;
      for(const auto f : faces[std::size_t(isl)])
        labels[f] = target;
      if(target == fresh)
      {
        ++fresh;
        continue;
      }
      merged = true;
      break;
    }
    if(!merged)
      break;
  }
  std::map<int, int> renumber;
  for(int& l : labels)
    l = renumber.try_emplace(l, int(renumber.size())).first->second;
  return renumber.size();
}
} // namespace

TEST_CASE("connected segments: the answer of finding every region again after each merge", "[k_way][connected]")
{
  // a box of equal right triangles (areas tie everywhere) and an unwelded
  // copy (six components, isolated islands), labels from a few seeds plus
  // scattered islands, some of them of labels found nowhere else
  const test_meshes::Soup soup = test_meshes::box(1., 1., 1., 8);
  for(const bool weld : {true, false})
  {
    const Dual_graph g =
      make_dual_graph(test_meshes::to_mesh<Mesh>(weld ? test_meshes::welded(soup) : soup), parameters::connect_touching_parts(false));
    const std::size_t n = g.number_of_faces();
    std::mt19937 random(5);
    for(int trial = 0; trial < 12; ++trial)
    {
      const int k = 2 + trial % 5;
      std::vector<int> labels(n);
      for(std::size_t f = 0; f < n; ++f)
        labels[f] = int((f * std::size_t(k)) / n);
      const std::size_t islands = std::size_t(trial) * n / 24;
      for(std::size_t i = 0; i < islands; ++i)
      {
        const std::size_t f = random() % n;
        const int l = int(random() % std::uint32_t(k + 2)) * (trial % 3 == 2 ? -1000003 : 1);
        labels[f] = l;
        if(random() % 2)
          g.for_each_neighbour(Dual_graph::size_type(f), [&](Dual_graph::size_type h, Dual_graph::size_type) { labels[h] = l; });
      }
      std::vector<int> expected = labels;
      const std::size_t count = connected_by_definition(g, expected);
      CHECK(Refinement::make_segments_connected(g, labels) == count);
      CHECK(labels == expected);
    }
  }
}

TEST_CASE("kmeans separates two blobs from max-min seeds", "[kmeans]")
{
  Eigen::MatrixXd points(6, 2);
  points << 0., 0., 0.2, 0., 0., 0.2, 10., 10., 10.2, 10., 10., 10.2;
  const Clustering::Kmeans_result r = Clustering::kmeans(points, 2);
  REQUIRE(r.labels.size() == 6);
  CHECK(r.converged);
  CHECK(r.labels[0] == r.labels[1]);
  CHECK(r.labels[0] == r.labels[2]);
  CHECK(r.labels[3] == r.labels[4]);
  CHECK(r.labels[3] == r.labels[5]);
  CHECK(r.labels[0] != r.labels[3]);
  const Eigen::Index far = r.labels[3];
  CHECK(r.centroids(far, 0) == Approx(10.2 / 3. + 20. / 3.));
  CHECK(r.centroids(far, 1) == Approx(10.2 / 3. + 20. / 3.));
  // given seeds are used as they are: the clusters keep the seeds' order
  const Clustering::Kmeans_result s = Clustering::kmeans(points, 2, {4, 0});
  CHECK(s.labels[4] == 0);
  CHECK(s.labels[0] == 1);
  CHECK_THROWS_AS(Clustering::kmeans(points, 7), Invalid_input);
}

TEST_CASE("graph_cut_boundaries moves labels to the nearest proxy along a strip", "[graphcut]")
{
  const Mesh mesh = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(20));
  const Dual_graph graph = make_dual_graph(mesh);
  const std::size_t n = graph.number_of_faces();
  Eigen::MatrixXd embedding(static_cast<Eigen::Index>(n), 1);
  for(std::size_t f = 0; f < n; ++f)
    embedding(static_cast<Eigen::Index>(f), 0) = graph.geometry().centroids[f].x();
  Eigen::MatrixXd proxies(2, 1);
  proxies << 0., 20.;
  // start from the nearest proxy, with the faces near both ends given the
  // wrong label: the data term must bring them back
  std::vector<int> labels(n);
  for(std::size_t f = 0; f < n; ++f)
  {
    const double x = embedding(static_cast<Eigen::Index>(f), 0);
    labels[f] = (x < 3. || x > 17.) == (x < 10.) ? 1 : 0;
  }
  const std::vector<int> start = labels;
  Refinement::graph_cut_boundaries(graph, embedding, proxies, labels);
  for(auto backend : {Refinement::Graph_cut_backend::boost_compressed_sparse_row,
                      Refinement::Graph_cut_backend::boost_adjacency_list})
  {
    std::vector<int> other = start;
    Refinement::Graph_cut_options o;
    o.backend = backend;
    Refinement::graph_cut_boundaries(graph, embedding, proxies, other, o);
    int wrong = 0;
    for(std::size_t f = 0; f < n; ++f)
    {
      const double x = embedding(static_cast<Eigen::Index>(f), 0);
      wrong += (x < 8. && other[f] != 0) || (x > 12. && other[f] != 1) ? 1 : 0;
    }
    INFO("backend " << int(backend));
    CHECK(wrong == 0);
    CHECK(other == labels); // one minimum, whatever the max-flow code
  }
  for(std::size_t f = 0; f < n; ++f)
  {
    const double x = embedding(static_cast<Eigen::Index>(f), 0);
    if(x < 8.)
      CHECK(labels[f] == 0);
    if(x > 12.)
      CHECK(labels[f] == 1);
  }
  // leaving the decided faces out of the max-flow problems changes nothing
  {
    std::vector<int> all = start;
    Refinement::Graph_cut_options o;
    o.fix_decided_faces = false;
    Refinement::graph_cut_boundaries(graph, embedding, proxies, all, o);
    CHECK(all == labels);
  }
  std::vector<int> bad(n - 1, 0);
  CHECK_THROWS_AS(Refinement::graph_cut_boundaries(graph, embedding, proxies, bad), Invalid_input);
  std::vector<int> out_of_range(n, 2);
  CHECK_THROWS_AS(Refinement::graph_cut_boundaries(graph, embedding, proxies, out_of_range), Invalid_input);
  // the banded cut too, before its band reads arrays by label
  const Refinement::Graph_cut_options banded = Refinement::Graph_cut_options::banded();
  std::vector<int> negative = start;
  negative[n / 2] = -1;
  CHECK_THROWS_AS(Refinement::graph_cut_boundaries(graph, embedding, proxies, negative, banded), Invalid_input);
  CHECK_THROWS_AS(Refinement::graph_cut_boundaries(graph, embedding, proxies, out_of_range, banded), Invalid_input);
}

TEST_CASE("graph_cut_boundaries: the decided faces left out, the same labels on a real mesh", "[graphcut]")
{
  const Star& s = star();
  const K_way_result r = segment_k_way(s.weighted, 4);
  Eigen::MatrixXd proxies = r.clusters.centroids;
  std::vector<int> start = r.clusters.labels;
  std::vector<int> fast = start, full = start;
  Refinement::graph_cut_boundaries(s.weighted.graph(), r.embedding.coordinates, proxies, fast);
  Refinement::Graph_cut_options o;
  o.fix_decided_faces = false;
  Refinement::graph_cut_boundaries(s.weighted.graph(), r.embedding.coordinates, proxies, full, o);
  CHECK(fast == full);
}

TEST_CASE("hybrid segmentation finds the star's parts, deterministically, and checks its options", "[k_way][hybrid]")
{
  const Star& s = star();
  const K_way_result r = segment_hybrid(s.weighted);
  INFO("segments " << r.number_of_segments);
  CHECK(r.number_of_segments >= 2);
  CHECK(r.number_of_segments <= Hybrid_options().clusters);
  CHECK(Evaluation::rand_index_error(r.labels, s.soup.face_part) < 0.1);
  const K_way_result r1 = segment_hybrid(s.weighted, Hybrid_options(), Execution(1));
  const K_way_result r4 = segment_hybrid(s.weighted, Hybrid_options(), Execution(4));
  CHECK(r1.labels == r4.labels);
  // an unreachable limit merges down to min_segments
  Hybrid_options all;
  all.min_boundary_contrast = 1e6;
  all.min_segments = 1;
  CHECK(segment_hybrid(s.weighted, all).number_of_segments == 1);
  Hybrid_options bad;
  bad.clusters = 1;
  CHECK_THROWS_AS(segment_hybrid(s.weighted, bad), Invalid_input);
  bad = Hybrid_options();
  bad.min_segments = 0;
  CHECK_THROWS_AS(segment_hybrid(s.weighted, bad), Invalid_input);
  for(double c : {0., -1., std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
  {
    bad = Hybrid_options();
    bad.min_boundary_contrast = c;
    CHECK_THROWS_AS(segment_hybrid(s.weighted, bad), Invalid_input);
  }
  for(double c : {-1., std::numeric_limits<double>::quiet_NaN()})
  {
    bad = Hybrid_options();
    bad.k_way.merge_separation_scale = c;
    CHECK_THROWS_AS(segment_hybrid(s.weighted, bad), Invalid_input);
  }
  Hybrid_options off;
  off.k_way.merge_separation_scale = 0.;
  CHECK(segment_hybrid(s.weighted, off).number_of_segments >= 2);
  // the merge hierarchy: from the clusters down to the one root; the
  // answer is its first cuts, and any number of parts comes from it
  const Part_hierarchy& h = r1.hierarchy;
  REQUIRE(h.roots.size() == 1);
  CHECK(h.nodes[h.roots[0]].faces.size() == s.graph.number_of_faces());
  CHECK(h.number_of_parts() == r1.number_of_segments);
  CHECK(h.number_of_leaves() > h.number_of_parts());
  CHECK(Evaluation::rand_index_error(h.labels(), r1.labels) < 0.02); // before and after the graph cut
  for(std::size_t parts : {std::size_t(1), std::size_t(3), r1.number_of_segments + 2})
  {
    Hybrid_options cut;
    cut.parts = parts;
    const K_way_result c = segment_hybrid(s.weighted, cut, Execution(1));
    INFO("parts " << parts);
    CHECK(c.number_of_segments == parts);
    CHECK(Evaluation::rand_index_error(c.labels, h.labels_with_parts(parts)) < 0.02);
    CHECK(c.hierarchy.labels() == h.labels()); // the hierarchy is the same
  }
}

TEST_CASE("most typical over-segmentation: the medoid of the merges, coarser clusterings, the option", "[hybrid][medoid]")
{
  // the area-weighted Rand distance: 0 for the same partition under other
  // labels, 1/2 between one segment and two halves of equal area
  const std::vector<double> area{1., 1., 1., 1.};
  const std::vector<int> halves{0, 0, 1, 1}, renamed{1, 1, 0, 0}, whole{0, 0, 0, 0}, other{0, 1, 0, 1};
  CHECK(internal::rand_distance(halves, 2, renamed, 2, area) == Approx(0.));
  CHECK(internal::rand_distance(halves, 2, whole, 1, area) == Approx(0.5));
  CHECK(internal::rand_distance(halves, 2, other, 2, area) == Approx(0.5));
  // weighted by area: the halves by area of {3, 1 | ...}
  CHECK(internal::rand_distance({0, 1, 1, 1}, 2, whole, 1, {3., 1., 1., 1.}) == Approx(1. - (9. + 9.) / 36.));
  // two answers agree, the odd one out is not the medoid, whatever its place
  CHECK(internal::medoid_labelling({other, halves, renamed}, {2, 2, 2}, area) == 1);
  CHECK(internal::medoid_labelling({halves, other, renamed}, {2, 2, 2}, area) == 0);
  // only the eligible may be kept (all vote): the odd one when it is alone,
  // else the eligible of least summed distance
  CHECK(internal::medoid_labelling({other, halves, renamed}, {2, 2, 2}, area, {1, 0, 0}) == 0);
  CHECK(internal::medoid_labelling({other, halves, renamed}, {2, 2, 2}, area, {1, 0, 1}) == 2);
  // the pairs on two threads: the same choices
  CHECK(internal::medoid_labelling({other, halves, renamed}, {2, 2, 2}, area, {}, 2) == 1);
  CHECK(internal::medoid_labelling({halves, other, renamed, whole}, {2, 2, 2, 1}, area, {}, 2) ==
        internal::medoid_labelling({halves, other, renamed, whole}, {2, 2, 2, 1}, area));
  CHECK(internal::medoid_labelling({other, halves, renamed}, {2, 2, 2}, area, {1, 0, 1}, 2) == 2);
  // coarser clusterings: K-means on four blobs from four clusters joined to
  // 2 by Ward's rule joins the blobs that are near each other
  Eigen::MatrixXd points(8, 1);
  points << 0., 0.1, 1., 1.1, 10., 10.1, 11., 11.1;
  const std::vector<int> four{0, 0, 1, 1, 2, 2, 3, 3};
  const std::vector<Clustering::Kmeans_result> coarse =
    internal::coarser_clusterings(points, four, 4, {3, 2}, 100, 0, Execution(1));
  REQUIRE(coarse.size() == 2);
  CHECK(coarse[0].centroids.rows() == 3);
  const std::vector<int>& two = coarse[1].labels;
  CHECK(two[0] == two[3]);
  CHECK(two[4] == two[7]);
  CHECK(two[0] != two[4]);
  // the option: one over-segmentation is the merge as before; five give an
  // answer of the star with its parts, the same on any number of threads
  const Star& s = star();
  Hybrid_options single;
  single.over_segmentations = 1;
  const K_way_result one = segment_hybrid(s.weighted, single, Execution(1));
  Hybrid_options five;
  five.over_segmentations = 5;
  const K_way_result r1 = segment_hybrid(s.weighted, five, Execution(1));
  const K_way_result r4 = segment_hybrid(s.weighted, five, Execution(4));
  CHECK(r1.labels == r4.labels);
  INFO("segments " << one.number_of_segments << " and " << r1.number_of_segments);
  CHECK(Evaluation::rand_index_error(r1.labels, s.soup.face_part) < 0.1);
  CHECK(r1.hierarchy.number_of_parts() == r1.number_of_segments);
  Hybrid_options none;
  none.over_segmentations = 0;
  CHECK_THROWS_AS(segment_hybrid(s.weighted, none), Invalid_input);
}

TEST_CASE("contrast merge: the embedding separation orders the merges, the limit stays on the contrast", "[hybrid][merge]")
{
  // a strip of 12 unit squares (24 faces) folded into valleys at x = 4
  // (0.5 rad) and x = 8 (0.55 rad): three segments of 8 faces
  test_meshes::Soup soup = test_meshes::square_strip(12);
  const double t1 = std::tan(0.5), t2 = std::tan(1.05);
  for(auto& p : soup.points)
    p[2] = p[0] <= 4. ? 0. : p[0] <= 8. ? t1 * (p[0] - 4.) : t1 * 4. + t2 * (p[0] - 8.);
  const Dual_graph g = make_dual_graph(test_meshes::to_mesh<Mesh>(soup));
  REQUIRE(g.number_of_faces() == 24);
  std::vector<int> thirds(24);
  for(std::size_t f = 0; f < 24; ++f)
    thirds[f] = int(f / 8);
  const std::vector<double> w(g.number_of_edges(), 1.);
  // by contrast alone 0|1 (the weaker fold) goes first
  std::vector<int> labels = thirds;
  CHECK(internal::merge_by_contrast(g, w, labels, 2, 1e6, 0.) == 2);
  CHECK(labels[0] == labels[8]);
  CHECK(labels[8] != labels[16]);
  // segments 1 and 2 overlap in a 1-D embedding, 0 lies far from both: 1|2 goes first
  Eigen::MatrixXd x(24, 1);
  for(Eigen::Index f = 0; f < 24; ++f)
    x(f, 0) = thirds[std::size_t(f)] == 0 ? 0.1 * double(f) : 10. + 0.1 * double(f % 8);
  Refinement::Embedding_separation sep;
  sep.coordinates = &x;
  labels = thirds;
  CHECK(internal::merge_by_contrast(g, w, labels, 2, 1e6, 0., sep) == 2);
  CHECK(labels[0] != labels[8]);
  CHECK(labels[8] == labels[16]);
  // a limit between the two folds' contrasts (their angles over the mesh's
  // mean concave angle, L / 1.05 with L the dual edges' total length, times
  // a metric contrast of 1): only the weaker fold may go, whatever the
  // factor says of the stronger one
  double total = 0.;
  for(std::size_t d = 0; d < g.number_of_edges(); ++d)
    total += g.edge(Dual_graph::size_type(d)).length;
  labels = thirds;
  CHECK(internal::merge_by_contrast(g, w, labels, 1, std::sqrt(0.525 * total / 1.05), 0., sep) == 2);
  CHECK(labels[0] == labels[8]);
  CHECK(labels[8] != labels[16]);
  // segments 1 and 2 sixteen times as thick as segment 0 (one face of
  // unknown thickness): the weaker fold 0|1 now bounds a part, its order
  // is 16^(1/2) = 4 and its contrast 16^(1/4) = 2 times higher, 1|2 goes
  // first, and with the limit between the folds nothing is merged; unknown
  // thickness everywhere changes nothing
  std::vector<double> thickness(24);
  for(std::size_t f = 0; f < 24; ++f)
    thickness[f] = thirds[f] == 0 ? 1. : 16.;
  thickness[20] = std::numeric_limits<double>::quiet_NaN();
  labels = thirds;
  CHECK(internal::merge_by_contrast(g, w, labels, 2, 1e6, 0., Refinement::Embedding_separation(), 0., nullptr, 0,
                                    nullptr, 0., &thickness) == 2);
  CHECK(labels[0] != labels[8]);
  CHECK(labels[8] == labels[16]);
  labels = thirds;
  CHECK(internal::merge_by_contrast(g, w, labels, 1, std::sqrt(0.525 * total / 1.05), 0.,
                                    Refinement::Embedding_separation(), 0., nullptr, 0, nullptr, 0., &thickness) == 3);
  const std::vector<double> unknown(24, std::numeric_limits<double>::quiet_NaN());
  labels = thirds;
  CHECK(internal::merge_by_contrast(g, w, labels, 2, 1e6, 0., Refinement::Embedding_separation(), 0., nullptr, 0,
                                    nullptr, 0., &unknown) == 2);
  CHECK(labels[0] == labels[8]);
  CHECK(labels[8] != labels[16]);
  // the history goes on past the limit, in the same order, to one segment,
  // and its hierarchy gives back the answer and every other count
  labels = thirds;
  Refinement::internal::Merge_history history;
  CHECK(internal::merge_by_contrast(g, w, labels, 1, std::sqrt(0.525 * total / 1.05), 0., sep, 0., &history) == 2);
  CHECK(labels[0] == labels[8]);
  CHECK(labels[8] != labels[16]);
  REQUIRE(history.steps.size() == 2);
  CHECK(history.answer == 1);
  CHECK(history.labels == thirds);
  CHECK(history.steps[0].strength < std::sqrt(0.525 * total / 1.05));
  CHECK(history.steps[1].strength >= std::sqrt(0.525 * total / 1.05));
  const Part_hierarchy h = internal::hierarchy_from_merges(history.labels, g.geometry().areas, history.steps, history.answer);
  CHECK(h.roots == std::vector<std::size_t>{0});
  CHECK(h.number_of_leaves() == 3);
  CHECK(h.number_of_cuts() == 2);
  CHECK(h.chosen_cuts == 1);
  CHECK(h.number_of_parts() == 2);
  CHECK(h.labels() == labels);
  CHECK(h.labels_with_parts(3) == thirds);
  CHECK(h.labels_with_parts(1) == std::vector<int>(24, 0));
  CHECK(h.labels_at_depth(1) == labels);
  for(std::size_t i = 0; i < h.nodes.size(); ++i)
  {
    const Part_node& n = h.nodes[i];
    INFO("node " << i);
    if(n.parent != Part_node::none)
    {
      CHECK(n.parent < i); // parents before children, roots first
      CHECK(n.depth == h.nodes[n.parent].depth + 1);
    }
    if(!n.is_leaf())
    {
      std::vector<std::uint32_t> both;
      std::merge(h.nodes[n.children[0]].faces.begin(), h.nodes[n.children[0]].faces.end(),
                 h.nodes[n.children[1]].faces.begin(), h.nodes[n.children[1]].faces.end(), std::back_inserter(both));
      CHECK(both == n.faces);
      CHECK(n.area == Approx(h.nodes[n.children[0]].area + h.nodes[n.children[1]].area));
    }
  }
  CHECK(h.nodes[0].boundary_strength == history.steps[1].strength); // the last merge is the first cut
  CHECK(h.nodes[0].cut_order == 0);
}

TEST_CASE("merge: flat seams go first, the one between the largest segments first", "[merge]")
{
  // a flat strip of 12 triangles in three segments of 2, 5 and 5 faces:
  // every dual edge is flat, so both seams are flat
  const Dual_graph g = make_dual_graph(test_meshes::to_mesh<Mesh>(test_meshes::square_strip(6)));
  REQUIRE(g.number_of_faces() == 12);
  std::vector<int> parts(12);
  for(std::size_t f = 0; f < 12; ++f)
    parts[f] = f < 2 ? 0 : f < 7 ? 1 : 2;
  // a cost that takes the seam around the smaller segment first
  const auto smaller_first = [](const Refinement::internal::Segment_boundary&, double smaller, double, double, double) {
    return Refinement::internal::Merge_cost{smaller, smaller};
  };
  const double half_degree = 0.5 * 3.14159265358979323846 / 180.;
  std::vector<int> labels = parts;
  CHECK(Refinement::internal::merge_cheapest_boundaries(g, {}, labels, 2, 0., std::numeric_limits<double>::infinity(),
                                                        smaller_first) == 2);
  CHECK(labels[0] == labels[2]); // by the cost: the 2-face segment joins its neighbour
  CHECK(labels[6] != labels[7]);
  labels = parts;
  CHECK(Refinement::internal::merge_cheapest_boundaries(g, {}, labels, 2, 0., std::numeric_limits<double>::infinity(),
                                                        smaller_first, nullptr, nullptr, nullptr, half_degree) == 2);
  CHECK(labels[0] != labels[2]); // flat seams: the two large segments join
  CHECK(labels[6] == labels[7]);
  // even past a limit that stops every other merge
  labels = parts;
  CHECK(Refinement::internal::merge_cheapest_boundaries(g, {}, labels, 1, 0., 0., smaller_first, nullptr, nullptr,
                                                        nullptr, half_degree) == 1);
  // a fold along the 1|2 seam (concave angles given): only 0|1 is flat now
  std::vector<double> folded(g.number_of_edges(), 0.);
  for(std::size_t d = 0; d < folded.size(); ++d)
  {
    const auto& e = g.edge(Dual_graph::size_type(d));
    if(parts[e.face[0]] + parts[e.face[1]] == 3)
      folded[d] = 0.1;
  }
  labels = parts;
  CHECK(Refinement::internal::merge_cheapest_boundaries(
          g, {}, labels, 2, 0., std::numeric_limits<double>::infinity(),
          [](const Refinement::internal::Segment_boundary&, double smaller, double, double, double) {
            return Refinement::internal::Merge_cost{1. - smaller, 1. - smaller}; // the largest pair first
          },
          nullptr, nullptr, &folded, half_degree) == 2);
  CHECK(labels[0] == labels[2]); // the flat 0|1 seam before the folded one, whatever the cost
  CHECK(labels[6] != labels[7]);
  // the option is checked
  K_way_options o;
  o.flat_seam_angle = -1.;
  CHECK_THROWS_AS(segment_k_way(star().weighted, 5, o), Invalid_input);
  o.flat_seam_angle = 180.;
  CHECK_THROWS_AS(segment_k_way(star().weighted, 5, o), Invalid_input);
  o.flat_seam_angle = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(segment_k_way(star().weighted, 5, o), Invalid_input);
  Hybrid_options h;
  h.k_way.flat_seam_angle = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(segment_hybrid(star().weighted, h), Invalid_input);
}

TEST_CASE("merge: the boundary of each pair with the other segments", "[merge]")
{
  // thirds of a strip of unit squares: boundaries 0|1 and 1|2 of length 1.
  // Before any merge, 0 and 1 together meet 2 along 1, and so do 1 and 2;
  // once two are merged the last pair meets nothing else
  const Dual_graph g = make_dual_graph(test_meshes::to_mesh<Mesh>(test_meshes::square_strip(12)));
  std::vector<int> labels(24);
  for(std::size_t f = 0; f < 24; ++f)
    labels[f] = int(f / 8);
  std::vector<double> seen; // per pass, per pair: the first pass sees 0|1 and 1|2, the second 01|2
  Refinement::internal::merge_cheapest_boundaries(
    g, {}, labels, 1, 0., std::numeric_limits<double>::infinity(),
    [&](const Refinement::internal::Segment_boundary& b, double, double, double outer, double) {
      CHECK(b.length == Approx(1.));
      seen.push_back(outer);
      return Refinement::internal::Merge_cost{double(seen.size()), 0.};
    });
  REQUIRE(seen.size() == 3);
  CHECK(seen[0] == Approx(1.));
  CHECK(seen[1] == Approx(1.));
  CHECK(seen[2] == Approx(0.).margin(1e-12));
}

TEST_CASE("contrast merge: the neck ratio keeps the compact part and merges the long one, at any scale",
          "[hybrid][merge]")
{
  // a strip of 12 unit squares folded into valleys at x = 2 (0.55 rad) and
  // x = 8 (0.5 rad): segments of 4, 12 and 8 faces (areas 2, 6 and 4),
  // every boundary of length 1. By contrast alone the weaker fold, 1|2,
  // goes first; with the neck factor its larger neck ratio (sqrt(4) against
  // sqrt(2)) outweighs the angle and 0|1 goes first.
  for(double scale : {1., 10.})
  {
    test_meshes::Soup soup = test_meshes::square_strip(12);
    const double t1 = std::tan(0.55), t2 = std::tan(1.05);
    for(auto& p : soup.points)
    {
      p[2] = p[0] <= 2. ? 0. : p[0] <= 8. ? t1 * (p[0] - 2.) : t1 * 6. + t2 * (p[0] - 8.);
      for(double& c : p)
        c *= scale;
    }
    const Dual_graph g = make_dual_graph(test_meshes::to_mesh<Mesh>(soup));
    REQUIRE(g.number_of_faces() == 24);
    std::vector<int> parts(24);
    for(std::size_t f = 0; f < 24; ++f)
      parts[f] = f < 4 ? 0 : f < 16 ? 1 : 2;
    const std::vector<double> w(g.number_of_edges(), 1.);
    INFO("scale " << scale);
    std::vector<int> labels = parts;
    CHECK(internal::merge_by_contrast(g, w, labels, 2, 1e6, 0.) == 2);
    CHECK(labels[0] != labels[4]);
    CHECK(labels[4] == labels[16]);
    labels = parts;
    CHECK(internal::merge_by_contrast(g, w, labels, 2, 1e6, 0., Refinement::Embedding_separation(), 0.4) == 2);
    CHECK(labels[0] == labels[4]);
    CHECK(labels[4] != labels[16]);
  }
  Hybrid_options bad;
  for(double c : {-1., std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
  {
    bad.neck_scale = c;
    CHECK_THROWS_AS(segment_hybrid(star().weighted, bad), Invalid_input);
  }
}

TEST_CASE("concave angles at a reference resolution: a finer copy of the star keeps its limbs' contrast",
          "[hybrid][merge]")
{
  // the concave contrast of the limbs' creases (their mean concave angle
  // over the mesh's, by edge length) on the star and on the same surface
  // with 16 times the faces
  const auto contrast = [](const Dual_graph& g, const std::vector<double>& w, const std::vector<int>& part) {
    double all = 0., length = 0., along = 0., along_length = 0.;
    for(std::size_t d = 0; d < w.size(); ++d)
    {
      const Dual_graph::Edge& e = g.edge(Dual_graph::size_type(d));
      all += e.length * w[d];
      length += e.length;
      if(part[e.face[0]] != part[e.face[1]])
      {
        along += e.length * w[d];
        along_length += e.length;
      }
    }
    return (along / along_length) / (all / length);
  };
  const test_meshes::Soup coarse_soup = test_meshes::star(1), fine_soup = test_meshes::star(4);
  const Dual_graph coarse = make_dual_graph(test_meshes::to_mesh<Mesh>(coarse_soup));
  const Dual_graph fine = make_dual_graph(test_meshes::to_mesh<Mesh>(fine_soup));
  REQUIRE(fine.number_of_faces() == 16 * coarse.number_of_faces());
  const std::size_t reference = coarse.number_of_faces();
  // up to the reference, the mesh's own angles, exactly
  CHECK(Refinement::concave_angle_weights(coarse, reference) == Refinement::concave_angle_weights(coarse));
  CHECK(Refinement::concave_angle_weights(fine, 0) == Refinement::concave_angle_weights(fine));
  const double at_coarse = contrast(coarse, Refinement::concave_angle_weights(coarse), coarse_soup.face_part);
  // at its own resolution the sharp creases' contrast grows with the faces
  const double own = contrast(fine, Refinement::concave_angle_weights(fine), fine_soup.face_part);
  CHECK(own > 3. * at_coarse);
  // at the reference resolution it stays about the coarse mesh's
  const double at_reference =
    contrast(fine, Refinement::concave_angle_weights(fine, reference), fine_soup.face_part);
  INFO("coarse " << at_coarse << " fine " << own << " fine at the reference " << at_reference);
  CHECK(at_reference > 0.5 * at_coarse);
  CHECK(at_reference < 1.25 * at_coarse);
}

TEST_CASE("contrast merge: the clusters are split along closed concave creases first", "[hybrid][creases]")
{
  // two K-means clusters cannot hold the star's five parts; split along the
  // creases that close around each limb, they become five regions, and the
  // limbs' creased boundaries are too strong to merge
  const Star& s = star();
  Hybrid_options two;
  two.clusters = 2;
  const K_way_result split = segment_hybrid(s.weighted, two, Execution(1));
  INFO("segments " << split.number_of_segments);
  CHECK(split.number_of_segments == 5);
  CHECK(Evaluation::rand_index_error(split.labels, s.soup.face_part) < 0.02);
  // without the split, at most the two clusters
  two.k_way.crease_angle = 0.;
  CHECK(segment_hybrid(s.weighted, two, Execution(1)).number_of_segments <= 2);
  two.k_way.crease_angle = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(segment_hybrid(s.weighted, two), Invalid_input);
}

TEST_CASE("crease regions: closed loops of concave creases bound the star's limbs", "[k_way][creases]")
{
  const Star& s = star();
  std::vector<int> region;
  // the limbs meet the body at right angles all around: five regions, the parts
  CHECK(Refinement::crease_regions(s.graph, 30., region) == 5);
  REQUIRE(region.size() == s.soup.face_part.size());
  CHECK(Evaluation::rand_index_error(region, s.soup.face_part) == 0.);
  // creases below the angle, or the split turned off: one region
  CHECK(Refinement::crease_regions(s.graph, 100., region) == 1);
  CHECK(Refinement::crease_regions(s.graph, 0., region) == 1);
  CHECK(std::set<int>(region.begin(), region.end()) == std::set<int>{0});
  CHECK_THROWS_AS(Refinement::crease_regions(s.graph, std::numeric_limits<double>::quiet_NaN(), region), Invalid_input);
  // a convex fold never separates, a concave one does
  const Dual_graph valley = make_dual_graph(test_meshes::to_mesh<Mesh>(test_meshes::fold(1., true)));
  const Dual_graph ridge = make_dual_graph(test_meshes::to_mesh<Mesh>(test_meshes::fold(1., false)));
  CHECK(Refinement::crease_regions(valley, 30., region) == 2);
  CHECK(Refinement::crease_regions(ridge, 30., region) == 1);

  // one label split along the regions: a label per region
  Refinement::crease_regions(s.graph, 30., region);
  std::vector<int> labels(region.size(), 7);
  CHECK(Refinement::split_along_regions(region, labels) == 5);
  CHECK(labels == region);
  std::vector<int> short_labels(region.size() - 1, 0);
  CHECK_THROWS_AS(Refinement::split_along_regions(region, short_labels), Invalid_input);
}

TEST_CASE("sharp crease share: 1 on a box, 0 on a smooth sphere", "[merge]")
{
  const Dual_graph box = make_dual_graph(test_meshes::to_mesh<Mesh>(test_meshes::welded(test_meshes::box(1., 2., 3., 3))));
  CHECK(Refinement::sharp_crease_share(box) == Approx(1.));
  // the box's edges are right angles: not sharp from 100 degrees, not folded from 120
  CHECK(Refinement::sharp_crease_share(box, 30., 100.) == 0.);
  CHECK(Refinement::sharp_crease_share(box, 120., 150.) == 0.);
  const Dual_graph ball = make_dual_graph(test_meshes::to_mesh<Mesh>(test_meshes::sphere(1., 24, 48)));
  CHECK(Refinement::sharp_crease_share(ball) == 0.);
  // a coarse ball folds its edges by 15 to 45 degrees: folded, none sharp
  const Dual_graph coarse = make_dual_graph(test_meshes::to_mesh<Mesh>(test_meshes::sphere(1., 5, 8)));
  CHECK(Refinement::sharp_crease_share(coarse, 30., 60.) == 0.);
  CHECK(Refinement::sharp_crease_share(coarse, 30., 35.) > 0.);
  CHECK_THROWS_AS(Refinement::sharp_crease_share(box, 60., 30.), Invalid_input);
  CHECK_THROWS_AS(Refinement::sharp_crease_share(box, std::numeric_limits<double>::quiet_NaN(), 60.), Invalid_input);
  // the k-way option's exponent: full on blunt meshes, none on sharp ones
  CHECK(SpectralSeg::internal::separation_exponent(0.) == 1.);
  CHECK(SpectralSeg::internal::separation_exponent(0.3) == Approx(1.));
  CHECK(SpectralSeg::internal::separation_exponent(0.45) == Approx(0.5));
  CHECK(SpectralSeg::internal::separation_exponent(0.9) == 0.);
  // segment_k_way() with and without the factor: k segments either way; a
  // negative or NaN scale is refused
  const Star& s = star();
  K_way_options o;
  o.merge_separation_scale = 0.;
  CHECK(segment_k_way(s.weighted, 5, o).number_of_segments == 5);
  o.merge_separation_scale = 2.;
  CHECK(segment_k_way(s.weighted, 5, o).number_of_segments == 5);
  o.merge_separation_scale = -1.;
  CHECK_THROWS_AS(segment_k_way(s.weighted, 5, o), Invalid_input);
  o.merge_separation_scale = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(segment_k_way(s.weighted, 5, o), Invalid_input);
}

TEST_CASE("banded graph cut: faces far from the boundaries keep their label, no segment vanishes", "[graphcut]")
{
  const Star& s = star();
  const K_way_result r = segment_k_way(s.weighted, 5, K_way_options::thesis());
  const std::vector<int>& start = r.clusters.labels;
  const std::vector<char> band = Refinement::internal::boundary_band(s.graph, start, 0.4);
  std::size_t inside = 0, outside = 0;
  for(char b : band)
    (b ? inside : outside) += 1;
  CHECK(inside > 0);
  CHECK(outside > 0);
  // a smoothness term that would otherwise swallow whole segments
  Refinement::Graph_cut_options o = Refinement::Graph_cut_options::banded();
  o.smoothness = 1e6;
  std::vector<int> labels = start;
  Refinement::graph_cut_boundaries(s.graph, r.embedding.coordinates, r.clusters.centroids, labels, o);
  for(std::size_t f = 0; f < labels.size(); ++f)
    if(!band[f])
      CHECK(labels[f] == start[f]);
  CHECK(std::set<int>(labels.begin(), labels.end()) == std::set<int>(start.begin(), start.end()));
  o.band_width = -1.;
  CHECK_THROWS_AS(Refinement::graph_cut_boundaries(s.graph, r.embedding.coordinates, r.clusters.centroids, labels, o),
                  Invalid_input);
}

TEST_CASE("alpha expansion: no expansion move improves its result, out-of-reach labels are never taken", "[graphcut]")
{
  // a 12 x 12 grid with 4 labels, pseudo-random data terms and weights, and
  // a quarter of the (vertex, label) pairs out of reach (infinite cost)
  Refinement::internal::Potts_problem p;
  const std::size_t side = 12;
  p.labels = 4;
  std::uint32_t state = 12345u;
  const auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  std::vector<std::size_t> l(side * side);
  std::size_t out_of_reach = 0;
  for(std::size_t v = 0; v < side * side; ++v)
  {
    l[v] = v % p.labels;
    std::vector<double> costs(p.labels);
    for(std::size_t c = 0; c < p.labels; ++c)
    {
      costs[c] = c != l[v] && next() < 0.25 ? std::numeric_limits<double>::infinity() : 3. * next();
      out_of_reach += std::isinf(costs[c]) ? 1 : 0;
    }
    p.add_vertex(costs);
    for(std::size_t c = 0; c < p.labels; ++c)
      CHECK(p.cost_of(v, c) == costs[c]); // the finite terms stored, the others out of reach
  }
  REQUIRE(p.vertices == side * side);
  CHECK(p.cost.size() == side * side * p.labels - out_of_reach);
  CHECK(out_of_reach > 0);
  for(std::size_t i = 0; i < side; ++i)
    for(std::size_t j = 0; j < side; ++j)
    {
      if(i + 1 < side)
      {
        p.edges.emplace_back(i * side + j, (i + 1) * side + j);
        p.weights.push_back(next());
      }
      if(j + 1 < side)
      {
        p.edges.emplace_back(i * side + j, i * side + j + 1);
        p.weights.push_back(next());
      }
    }
  const double before = p.energy(l);
  const std::vector<std::size_t> start = l;
  std::vector<std::size_t> l2 = l;
#ifdef SPECTRALSEG_USE_MAXFLOW
  std::vector<std::size_t> l3 = l, l4 = l;
#endif
  const double after = Refinement::internal::alpha_expansion<CGAL::Alpha_expansion_boost_compressed_sparse_row_impl>(p, l);
  CHECK(after < before);
  // two threads: the same moves, bit for bit
  CHECK(Refinement::internal::alpha_expansion<CGAL::Alpha_expansion_boost_compressed_sparse_row_impl>(p, l2, 2) == after);
  CHECK(l2 == l);
  CHECK(after == Approx(p.energy(l)).epsilon(1e-12));
  // one sweep (Graph_cut_options::sweeps = 1): each label's move once, in
  // order, on one thread or two alike; here more sweeps still lower the
  // energy, and a second one continues from the first
  std::vector<std::size_t> once = start, once2 = start, by_hand = start;
  const double one_sweep =
    Refinement::internal::alpha_expansion<CGAL::Alpha_expansion_boost_compressed_sparse_row_impl>(p, once, 1, 1);
  CHECK(Refinement::internal::alpha_expansion<CGAL::Alpha_expansion_boost_compressed_sparse_row_impl>(p, once2, 2, 1) ==
        one_sweep);
  CHECK(once2 == once);
  CHECK(one_sweep < before);
  CHECK(one_sweep > after + 1e-9);
  {
    const Refinement::internal::Potts_adjacency adjacency(p);
    std::vector<std::size_t> candidate(p.vertices, std::size_t(-1));
    std::unique_ptr<CGAL::Alpha_expansion_boost_compressed_sparse_row_impl> flow;
    double energy = before;
    for(std::size_t alpha = 0; alpha < p.labels; ++alpha)
    {
      double delta = 0.;
      const std::vector<std::size_t> taken =
        Refinement::internal::best_expansion(p, adjacency, by_hand, alpha, candidate, delta, flow);
      if(!taken.empty() && delta < -1e-12 * std::abs(energy))
      {
        energy += delta;
        for(std::size_t v : taken)
          by_hand[v] = alpha;
      }
    }
    CHECK(by_hand == once);
  }
#ifdef SPECTRALSEG_USE_MAXFLOW
  // MaxFlow (one max-flow object serving every move of a thread): the same
  // moves as Boost's max flow
  CHECK(Refinement::internal::alpha_expansion<Refinement::internal::Maxflow_impl>(p, l3) == Approx(after).epsilon(1e-12));
  CHECK(l3 == l);
  CHECK(Refinement::internal::alpha_expansion<Refinement::internal::Maxflow_impl>(p, l4, 2) == Approx(after).epsilon(1e-12));
  CHECK(l4 == l);
#endif
  for(std::size_t v = 0; v < p.vertices; ++v)
    CHECK(std::isfinite(p.cost_of(v, l[v])));
  // a local minimum: no label's expansion lowers the energy any more
  const Refinement::internal::Potts_adjacency adjacency(p);
  std::vector<std::size_t> candidate(p.vertices, std::size_t(-1));
  std::unique_ptr<CGAL::Alpha_expansion_boost_compressed_sparse_row_impl> flow;
  for(std::size_t alpha = 0; alpha < p.labels; ++alpha)
  {
    double delta = 0.;
    Refinement::internal::best_expansion(p, adjacency, l, alpha, candidate, delta, flow);
    INFO("alpha " << alpha);
    CHECK(delta >= -1e-9);
  }
#ifdef SPECTRALSEG_USE_MAXFLOW
  // and from the start, move after move with one MaxFlow object: the
  // answers of a fresh object each time
  std::unique_ptr<Refinement::internal::Maxflow_impl> reused;
  std::size_t moved = 0;
  for(std::size_t alpha = 0; alpha < p.labels; ++alpha)
  {
    double delta = 0., fresh_delta = 0.;
    std::unique_ptr<Refinement::internal::Maxflow_impl> fresh;
    const std::vector<std::size_t> taken =
      Refinement::internal::best_expansion(p, adjacency, start, alpha, candidate, delta, reused);
    INFO("alpha " << alpha);
    CHECK(taken == Refinement::internal::best_expansion(p, adjacency, start, alpha, candidate, fresh_delta, fresh));
    CHECK(delta == fresh_delta);
    moved += taken.size();
  }
  CHECK(moved > 0);
#endif
}

TEST_CASE("alpha expansion on several threads: the moves of one thread, bit for bit", "[graphcut][threads]")
{
  // a 48 x 6 grid in 8 stripes of 6 columns, one label each; a vertex may
  // take the label of the stripe beside it within 2 columns of their
  // boundary: the moves of distant stripes read disjoint vertices, those of
  // neighbours do not
  Refinement::internal::Potts_problem p;
  const std::size_t columns = 48, rows = 6, width = 6;
  p.labels = columns / width;
  std::uint32_t state = 777u;
  const auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  std::vector<std::size_t> start(columns * rows);
  for(std::size_t i = 0; i < columns; ++i)
    for(std::size_t j = 0; j < rows; ++j)
    {
      const std::size_t own = i / width, v = i * rows + j;
      std::vector<double> costs(p.labels, std::numeric_limits<double>::infinity());
      costs[own] = 2. * next();
      if(own > 0 && i % width < 2)
        costs[own - 1] = 2. * next();
      if(own + 1 < p.labels && i % width >= width - 2)
        costs[own + 1] = 2. * next();
      start[v] = own;
      p.add_vertex(costs);
    }
  for(std::size_t i = 0; i < columns; ++i)
    for(std::size_t j = 0; j < rows; ++j)
    {
      if(i + 1 < columns)
      {
        p.edges.emplace_back(i * rows + j, (i + 1) * rows + j);
        p.weights.push_back(0.3 * next());
      }
      if(j + 1 < rows)
      {
        p.edges.emplace_back(i * rows + j, i * rows + j + 1);
        p.weights.push_back(0.3 * next());
      }
    }
  std::vector<std::size_t> one = start;
  const double energy = Refinement::internal::alpha_expansion<CGAL::Alpha_expansion_boost_compressed_sparse_row_impl>(p, one);
  CHECK(energy < p.energy(start));
  CHECK(one != start);
  for(const unsigned threads : {2u, 3u, 8u})
  {
    std::vector<std::size_t> l = start;
    INFO(threads << " threads");
    CHECK(Refinement::internal::alpha_expansion<CGAL::Alpha_expansion_boost_compressed_sparse_row_impl>(p, l, threads) ==
          energy);
    CHECK(l == one);
  }
}

TEST_CASE("banded graph cut: a face only takes the label of a segment whose boundary is within reach", "[graphcut]")
{
  const Star& s = star();
  const K_way_result r = segment_k_way(s.weighted, 5, K_way_options::thesis());
  const std::vector<int>& start = r.clusters.labels;
  const Refinement::Graph_cut_options o = Refinement::Graph_cut_options::banded();
  const std::vector<char> band = Refinement::internal::boundary_band(s.graph, start, o.band_width);
  const Refinement::internal::Band_labels reach =
    Refinement::internal::band_labels(s.graph, start, band, o.band_width);
  REQUIRE(reach.offset.size() == start.size() + 1);
  std::size_t with_reach = 0;
  for(std::size_t f = 0; f < start.size(); ++f)
  {
    if(!band[f])
      CHECK(reach.offset[f] == reach.offset[f + 1]);
    for(std::size_t i = reach.offset[f]; i < reach.offset[f + 1]; ++i)
      CHECK(reach.reachable[i] != start[f]);
    with_reach += reach.offset[f + 1] > reach.offset[f] ? 1 : 0;
  }
  CHECK(with_reach > 0);
  for(std::size_t f = 0; f < start.size(); ++f) // each face's labels ascending
    for(std::size_t i = reach.offset[f] + 1; i < reach.offset[f + 1]; ++i)
      CHECK(reach.reachable[i - 1] < reach.reachable[i]);
  // the segments' tasks on several threads: the same band and labels
  for(const unsigned threads : {2u, 3u})
  {
    INFO(threads << " threads");
    CHECK(Refinement::internal::boundary_band(s.graph, start, o.band_width, threads) == band);
    const Refinement::internal::Band_labels other =
      Refinement::internal::band_labels(s.graph, start, band, o.band_width, threads);
    CHECK(other.offset == reach.offset);
    CHECK(other.reachable == reach.reachable);
  }
  std::vector<int> labels = start;
  Refinement::graph_cut_boundaries(s.graph, r.embedding.coordinates, r.clusters.centroids, labels, o);
  std::size_t changed = 0;
  for(std::size_t f = 0; f < labels.size(); ++f)
  {
    if(labels[f] == start[f])
      continue;
    ++changed;
    CHECK(std::find(reach.reachable.begin() + std::ptrdiff_t(reach.offset[f]),
                    reach.reachable.begin() + std::ptrdiff_t(reach.offset[f + 1]),
                    labels[f]) != reach.reachable.begin() + std::ptrdiff_t(reach.offset[f + 1]));
  }
  INFO("changed " << changed);
}

TEST_CASE("kmeans skips points by bounds and still gives Lloyd's labels", "[kmeans]")
{
  // 3,000 points in 5 dimensions around 12 centres, pseudo-random
  const std::size_t n = 3000, dims = 5, k = 12;
  std::uint32_t state = 777u;
  const auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  Eigen::MatrixXd points(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(dims));
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < dims; ++j)
      points(Eigen::Index(i), Eigen::Index(j)) = double((i % 7) * (j + 1) % 5) + 1.5 * next();
  std::vector<std::size_t> seeds;
  for(std::size_t c = 0; c < k; ++c)
    seeds.push_back(c * 97);
  const Clustering::Kmeans_result fast = Clustering::kmeans(points, k, seeds, 300, Execution(2));
  // Lloyd's algorithm, every distance every round
  Eigen::MatrixXd centroids(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(dims));
  for(std::size_t c = 0; c < k; ++c)
    centroids.row(Eigen::Index(c)) = points.row(Eigen::Index(seeds[c]));
  std::vector<int> labels(n, -1);
  std::size_t rounds = 0;
  for(; rounds < 300; ++rounds)
  {
    bool changed = false;
    for(std::size_t i = 0; i < n; ++i)
    {
      int best = 0;
      double best_d = std::numeric_limits<double>::infinity();
      for(std::size_t c = 0; c < k; ++c)
      {
        double d = 0.;
        for(std::size_t j = 0; j < dims; ++j)
        {
          const double t = points(Eigen::Index(i), Eigen::Index(j)) - centroids(Eigen::Index(c), Eigen::Index(j));
          d += t * t;
        }
        if(d < best_d)
        {
          best_d = d;
          best = int(c);
        }
      }
      changed = changed || labels[i] != best;
      labels[i] = best;
    }
    if(!changed)
      break;
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(Eigen::Index(k), Eigen::Index(dims));
    std::vector<double> count(k, 0.);
    for(std::size_t i = 0; i < n; ++i)
    {
      sum.row(labels[i]) += points.row(Eigen::Index(i));
      count[std::size_t(labels[i])] += 1.;
    }
    for(std::size_t c = 0; c < k; ++c)
      if(count[c] > 0.)
        centroids.row(Eigen::Index(c)) = sum.row(Eigen::Index(c)) / count[c];
  }
  CHECK(rounds > 2);
  CHECK(fast.iterations == rounds);
  CHECK(fast.labels == labels);
  CHECK(fast.converged);
  CHECK(Clustering::kmeans(points, k, seeds, 300, Execution(1)).labels == fast.labels);

  // with a sample limit: first every 6th point, then all from there; the
  // answer is a fixed point of Lloyd's rounds on all the points
  const Clustering::Kmeans_result sampled = Clustering::kmeans(points, k, seeds, 300, Execution(2), 500);
  CHECK(sampled.converged);
  CHECK(Clustering::kmeans(points, k, seeds, 300, Execution(1), 500).labels == sampled.labels);
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(Eigen::Index(k), Eigen::Index(dims));
  std::vector<double> count(k, 0.);
  for(std::size_t i = 0; i < n; ++i)
  {
    sum.row(sampled.labels[i]) += points.row(Eigen::Index(i));
    count[std::size_t(sampled.labels[i])] += 1.;
  }
  std::size_t elsewhere = 0; // points not nearest their own centroid
  for(std::size_t i = 0; i < n; ++i)
  {
    Eigen::Index nearest = 0;
    (sampled.centroids.rowwise() - points.row(Eigen::Index(i))).rowwise().squaredNorm().minCoeff(&nearest);
    elsewhere += nearest != sampled.labels[i];
  }
  CHECK(elsewhere == 0);
  // one round on all the points after the subsample's: the same start as
  // `sampled`, stopped after one round on every point
  const Clustering::Kmeans_result once = Clustering::kmeans(points, k, seeds, 300, Execution(2), 500, 1);
  CHECK(once.iterations == 1);
  CHECK_FALSE(once.converged);
  CHECK(once.labels.size() == n);
  {
    // the centroids moved once, to the means of the points assigned to them
    Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(Eigen::Index(k), Eigen::Index(dims));
    std::vector<double> members(k, 0.);
    for(std::size_t i = 0; i < n; ++i)
    {
      mean.row(once.labels[i]) += points.row(Eigen::Index(i));
      members[std::size_t(once.labels[i])] += 1.;
    }
    for(std::size_t c = 0; c < k; ++c)
      if(members[c] > 0.)
        CHECK((mean.row(Eigen::Index(c)) / members[c] - once.centroids.row(Eigen::Index(c))).norm() < 1e-9);
  }
  CHECK(Clustering::kmeans(points, k, seeds, 300, Execution(1), 500, 1).labels == once.labels);
  CHECK(Clustering::kmeans(points, k, seeds, 300, Execution(2), 500, 300).labels == sampled.labels);
  // without a sample limit, full_rounds does not apply
  CHECK(Clustering::kmeans(points, k, seeds, 300, Execution(2), 0, 1).labels == fast.labels);
  // more centroids than the distance loop's block (64): the same rule
  std::vector<std::size_t> many;
  for(std::size_t c = 0; c < 70; ++c)
    many.push_back(c * 41);
  const Clustering::Kmeans_result wide = Clustering::kmeans(points, many.size(), many, 300, Execution(2));
  CHECK(wide.converged);
  CHECK(Clustering::kmeans(points, many.size(), many, 300, Execution(1)).labels == wide.labels);
  std::size_t wide_elsewhere = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    Eigen::Index nearest = 0;
    (wide.centroids.rowwise() - points.row(Eigen::Index(i))).rowwise().squaredNorm().minCoeff(&nearest);
    wide_elsewhere += nearest != wide.labels[i];
  }
  CHECK(wide_elsewhere == 0);
  for(std::size_t c = 0; c < k; ++c)
    if(count[c] > 0.)
      CHECK((sampled.centroids.row(Eigen::Index(c)) - sum.row(Eigen::Index(c)) / count[c]).norm() < 1e-9);
}

TEST_CASE("concave normalized cut: boundaries along concave creases cost less", "[k_way][choice]")
{
  const Star& s = star();
  const std::size_t n = s.graph.number_of_faces();
  // the five parts meet along concave creases; five segments by face index do not
  std::vector<int> striped(n);
  for(std::size_t f = 0; f < n; ++f)
    striped[f] = int(f % 5);
  const double parts = Refinement::concave_normalized_cut(s.graph, s.soup.face_part, 0.1);
  const double stripes = Refinement::concave_normalized_cut(s.graph, striped, 0.1);
  CHECK(parts > 0.);
  CHECK(parts < 0.1 * stripes);
  // the labels' values do not matter, one segment has no cut
  std::vector<int> shifted = s.soup.face_part;
  for(int& l : shifted)
    l = 100 - 3 * l;
  CHECK(Refinement::concave_normalized_cut(s.graph, shifted, 0.1) == parts);
  // labels outside [0, faces) (a map instead of a table): the same value, bit for bit
  std::vector<int> negative = s.soup.face_part, large = s.soup.face_part;
  for(int& l : negative)
    l = -1 - l;
  for(int& l : large)
    l += int(n);
  CHECK(Refinement::concave_normalized_cut(s.graph, negative, 0.1) == parts);
  CHECK(Refinement::concave_normalized_cut(s.graph, large, 0.1) == parts);
  CHECK(Refinement::concave_normalized_cut(s.graph, std::vector<int>(n, 4), 0.1) == 0.);
  // a larger scale makes the creases count for less
  CHECK(Refinement::concave_normalized_cut(s.graph, s.soup.face_part, 1.) > parts);
  CHECK_THROWS_AS(Refinement::concave_normalized_cut(s.graph, std::vector<int>(n - 1, 0), 0.1), Invalid_input);
  CHECK_THROWS_AS(Refinement::concave_normalized_cut(s.graph, striped, 0.), Invalid_input);
  CHECK_THROWS_AS(Refinement::concave_normalized_cut(s.graph, striped, std::numeric_limits<double>::quiet_NaN()),
                  Invalid_input);
}

TEST_CASE("k-way with alternative extra clusters keeps the result with the lower concave normalized cut",
          "[k_way][choice]")
{
  const Star& s = star();
  CHECK(K_way_options().alternative_extra_clusters == std::vector<std::size_t>{8});
  CHECK(K_way_options::thesis().alternative_extra_clusters.empty());
  for(Embedding::Method m : {Embedding::Method::exact, Embedding::Method::nystrom})
  for(std::size_t k : {3, 5})
  {
    INFO("k " << k << ", method " << int(m));
    // with Nyström the candidates share the samples of the largest: the
    // same labels as separate runs, since farthest-point samples are nested
    K_way_options few = with_method(m), many = with_method(m), both = with_method(m);
    few.extra_clusters = 0;
    few.alternative_extra_clusters.clear();
    few.contrast_merge_clusters = 0;
    many.extra_clusters = 6;
    many.alternative_extra_clusters.clear();
    many.contrast_merge_clusters = 0;
    both.extra_clusters = 0;
    both.alternative_extra_clusters = {6, 0, 6}; // repeats are tried once
    both.contrast_merge_clusters = 0;
    both.min_candidate_clusters = 0; // k + 0 clusters tried too
    const K_way_result a = segment_k_way(s.weighted, k, few), b = segment_k_way(s.weighted, k, many);
    const K_way_result c = segment_k_way(s.weighted, k, both);
    CHECK(a.extra_clusters == 0);
    CHECK(b.extra_clusters == 6);
    CHECK(a.normalized_cut == 0.); // one segmentation: no choice made
    const double na = Refinement::concave_normalized_cut(s.graph, a.labels, both.cut_angle_scale);
    const double nb = Refinement::concave_normalized_cut(s.graph, b.labels, both.cut_angle_scale);
    const K_way_result& lower = nb < na ? b : a; // ties to the first tried
    CHECK(c.labels == lower.labels);
    CHECK(c.extra_clusters == lower.extra_clusters);
    CHECK(c.normalized_cut == Approx(std::min(na, nb)));
    CHECK(c.number_of_segments == k);
    CHECK(c.clusters.centroids.rows() == Eigen::Index(k + c.extra_clusters));
    CHECK(c.embedding.samples == lower.embedding.samples);
    // every candidate reported in the order tried, the kept one flagged,
    // each with its own cuts and, when asked, its own labels
    CHECK(a.candidates.empty());
    REQUIRE(c.candidates.size() == 2);
    CHECK(c.candidates[0].extra_clusters == 0);
    CHECK(c.candidates[1].extra_clusters == 6);
    CHECK(c.candidates[0].normalized_cut == Approx(na));
    CHECK(c.candidates[1].normalized_cut == Approx(nb));
    CHECK(c.candidates[nb < na ? 1 : 0].kept);
    CHECK_FALSE(c.candidates[nb < na ? 0 : 1].kept);
    for(const K_way_candidate& candidate : c.candidates)
    {
      CHECK_FALSE(candidate.contrast_merge);
      CHECK(candidate.normalized_cut_before_graph_cut > 0.);
      CHECK(candidate.number_of_segments == k);
      CHECK(candidate.labels.empty());
    }
    K_way_options keep = both;
    keep.keep_candidate_labels = true;
    const K_way_result kept = segment_k_way(s.weighted, k, keep);
    REQUIRE(kept.candidates.size() == 2);
    CHECK(kept.labels == c.labels);
    CHECK(kept.candidates[0].labels == a.labels);
    CHECK(kept.candidates[1].labels == b.labels);
    // the candidates run side by side on several threads, one after the
    // other on one: the same result
    const K_way_result one = segment_k_way(s.weighted, k, both, Execution(1));
    const K_way_result three = segment_k_way(s.weighted, k, both, Execution(3));
    CHECK(one.labels == c.labels);
    CHECK(three.labels == c.labels);
    // cancelled while the candidates run: the exception, no hang or crash
    std::size_t calls = 0;
    const Execution cancel(2, [&calls](const std::string& stage, double) {
      return !(stage == "graph cut" && ++calls > 1);
    });
    if(both.boundary_enhancement)
      CHECK_THROWS_AS(segment_k_way(s.weighted, k, both, cancel), Operation_cancelled);
    // every stage timed once, the candidates' times summed
    std::set<std::string> stages;
    for(const auto& t : c.timings)
      CHECK(stages.insert(t.first).second);
    CHECK(stages.count("choice") == 1);
  }
}

TEST_CASE("k-way leaves out the candidates of too few clusters while others are tried", "[k_way][choice]")
{
  const Star& s = star();
  CHECK(K_way_options().min_candidate_clusters == 6);
  const auto alone = [&](std::size_t k, std::size_t extra) {
    K_way_options o;
    o.extra_clusters = extra;
    o.alternative_extra_clusters.clear();
    o.contrast_merge_clusters = 0;
    return segment_k_way(s.weighted, k, o);
  };
  K_way_options o;
  o.contrast_merge_clusters = 0; // extra clusters 2 and 8
  for(std::size_t k : {2, 3})
  {
    INFO("k " << k);
    // k + 2 clusters are fewer than 6: only k + 8 is tried
    const K_way_result r = segment_k_way(s.weighted, k, o), eight = alone(k, 8);
    CHECK(r.extra_clusters == 8);
    CHECK(r.labels == eight.labels);
    // with the filter off, the choice between both
    K_way_options all = o;
    all.min_candidate_clusters = 0;
    const K_way_result both = segment_k_way(s.weighted, k, all), two = alone(k, 2);
    const double n2 = Refinement::concave_normalized_cut(s.graph, two.labels, o.cut_angle_scale);
    const double n8 = Refinement::concave_normalized_cut(s.graph, eight.labels, o.cut_angle_scale);
    CHECK(both.labels == (n8 < n2 ? eight.labels : two.labels));
    CHECK(r.normalized_cut == Approx(n8)); // reported as after a choice
    CHECK(eight.normalized_cut == 0.);     // none asked for
  }
  // from k = 4 on, k + 2 clusters are enough: both candidates are tried
  K_way_options all = o;
  all.min_candidate_clusters = 0;
  const K_way_result four = segment_k_way(s.weighted, 4, o);
  CHECK(four.labels == segment_k_way(s.weighted, 4, all).labels);
  CHECK(four.normalized_cut > 0.);
  // every candidate too small: the one of the most clusters stays, with the
  // contrast merge still tried beside it
  K_way_options tiny;
  tiny.extra_clusters = 0;
  tiny.alternative_extra_clusters = {1};
  tiny.min_candidate_clusters = 100;
  tiny.contrast_merge_clusters = 0;
  const K_way_result one = segment_k_way(s.weighted, 3, tiny);
  CHECK(one.extra_clusters == 1);
  CHECK(one.labels == alone(3, 1).labels);
  tiny.contrast_merge_clusters = 20;
  K_way_options kept = tiny;
  kept.alternative_extra_clusters.clear();
  kept.extra_clusters = 1;
  kept.min_candidate_clusters = 0;
  CHECK(segment_k_way(s.weighted, 3, tiny).labels == segment_k_way(s.weighted, 3, kept).labels);
}

TEST_CASE("k-way tries the contrast merge cut at k and keeps it when its concave normalized cut is lower",
          "[k_way][choice]")
{
  CHECK(K_way_options().contrast_merge_clusters == 20);
  CHECK(K_way_options::thesis().contrast_merge_clusters == 0);
  bool kept_contrast = false, kept_concave = false;
  const auto check = [&](const Dual_graph& graph, const Weighted_dual_graph& weighted, std::size_t k,
                         std::size_t clusters, Embedding::Method m, bool threads) {
    INFO("k " << k << ", method " << int(m) << ", contrast-merge clusters " << clusters << ", "
              << graph.number_of_faces() << " faces");
    K_way_options alone = with_method(m), with = with_method(m);
    alone.alternative_extra_clusters.clear();
    alone.contrast_merge_clusters = 0;
    with.alternative_extra_clusters.clear();
    with.contrast_merge_clusters = clusters;
    const K_way_result a = segment_k_way(weighted, k, alone), c = segment_k_way(weighted, k, with);
    // the candidate is the contrast merge of segment_hybrid() with that
    // many clusters (at least k), of one over-segmentation, its hierarchy
    // cut at k parts
    Hybrid_options h;
    h.k_way = with_method(m);
    h.clusters = std::max(clusters, k);
    h.over_segmentations = 1;
    h.parts = k;
    const K_way_result d = segment_hybrid(weighted, h);
    const double na = Refinement::concave_normalized_cut(graph, a.labels, with.cut_angle_scale);
    const double nd = Refinement::concave_normalized_cut(graph, d.labels, with.cut_angle_scale);
    const bool contrast = nd < na; // ties to the first tried
    CHECK(c.labels == (contrast ? d.labels : a.labels));
    CHECK(c.contrast_merge == contrast);
    CHECK(c.extra_clusters == (contrast ? std::max(clusters, k) - k : a.extra_clusters));
    CHECK(c.normalized_cut == Approx(std::min(na, nd)));
    CHECK(c.number_of_segments == k);
    REQUIRE(c.candidates.size() == 2); // alone's over-segmentation, then the contrast merge
    CHECK_FALSE(c.candidates.front().contrast_merge);
    CHECK(c.candidates.back().contrast_merge);
    CHECK(c.candidates.back().kept == contrast);
    CHECK(c.candidates.back().normalized_cut == Approx(nd));
    if(contrast)
      CHECK(c.hierarchy.nodes.size() == d.hierarchy.nodes.size());
    (contrast ? kept_contrast : kept_concave) = true;
    // side by side on several threads or one after the other: the same
    if(threads)
    {
      CHECK(segment_k_way(weighted, k, with, Execution(1)).labels == c.labels);
      CHECK(segment_k_way(weighted, k, with, Execution(3)).labels == c.labels);
    }
  };
  const Star& s = star();
  for(Embedding::Method m : {Embedding::Method::exact, Embedding::Method::nystrom})
    for(std::size_t k : {2, 5})
      check(s.graph, s.weighted, k, 8, m, true);
  // the elephant's trunk and legs meet the body along short loops
  Mesh elephant;
  IO::read_mesh_file(SPECTRALSEG_SOURCE_DIR "/data/elephant.off", elephant);
  const Dual_graph graph = make_dual_graph(elephant);
  const std::vector<double> weights = Metrics::Part_aware_weight<>()(graph);
  const Weighted_dual_graph weighted(graph, weights);
  check(graph, weighted, 3, 20, Embedding::Method::nystrom, false);
  // both kinds of candidate won somewhere, so the comparisons are not vacuous
  CHECK(kept_contrast);
  CHECK(kept_concave);
}
