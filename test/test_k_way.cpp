// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// k-way segmentation: known parts found, exact and Nyström agree, Gamma,
// determinism across thread counts, bad k.
#include "test_meshes.h"

#include <SpectralSeg/Embedding/nystrom_spectral_embedding.h>
#include <SpectralSeg/Kernels/Gaussian_kernel.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/evaluation.h>
#include <SpectralSeg/k_way_segmentation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <catch2/catch.hpp>

#include <set>

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
    const K_way_result r = segment_k_way(s.weighted, 5, Kernels::Exponential_kernel(), with_method(m));
    CHECK(r.number_of_segments == 5);
    CHECK(r.embedding.exact == (m == Embedding::Method::exact));
    CHECK(Evaluation::rand_index_error(r.labels, s.soup.face_part) < 0.05);
  }
}

TEST_CASE("exact and Nyström embeddings give the same segmentation", "[k_way][nystrom]")
{
  const Star& s = star();
  const K_way_result exact = segment_k_way(s.weighted, 5, Kernels::Exponential_kernel(), with_method(Embedding::Method::exact));
  const K_way_result nystrom = segment_k_way(s.weighted, 5, Kernels::Exponential_kernel(), with_method(Embedding::Method::nystrom));
  CHECK(Evaluation::rand_index_error(exact.labels, nystrom.labels) < 0.03);
  // the Gaussian kernel finds the parts too
  const K_way_result gaussian = segment_k_way(s.weighted, 5, Kernels::Gaussian_kernel(), with_method(Embedding::Method::nystrom));
  CHECK(Evaluation::rand_index_error(gaussian.labels, s.soup.face_part) < 0.05);
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
}

TEST_CASE("k-way labels do not depend on the number of threads", "[k_way][threads]")
{
  const Star& s = star();
  for(Embedding::Method m : {Embedding::Method::exact, Embedding::Method::nystrom})
  {
    const K_way_result r1 = segment_k_way(s.weighted, 5, Kernels::Exponential_kernel(), with_method(m), Execution(1));
    const K_way_result r2 = segment_k_way(s.weighted, 5, Kernels::Exponential_kernel(), with_method(m), Execution(2));
    const K_way_result r3 = segment_k_way(s.weighted, 5, Kernels::Exponential_kernel(), with_method(m), Execution(3));
    CHECK(r1.labels == r2.labels);
    CHECK(r1.labels == r3.labels);
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
