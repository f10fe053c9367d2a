// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Segmentation scores of the Princeton Segmentation Benchmark, label files.
#include "test_meshes.h"

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/evaluation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
using namespace SpectralSeg;
namespace E = SpectralSeg::Evaluation;

// O(n^2) Rand index error straight from the definition.
double brute_force_rand_index_error(const std::vector<int>& a, const std::vector<int>& b)
{
  std::uint64_t disagree = 0, all = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    for(std::size_t j = i + 1; j < a.size(); ++j)
    {
      ++all;
      disagree += ((a[i] == a[j]) != (b[i] == b[j])) ? 1 : 0;
    }
  return double(disagree) / double(all);
}

// O(n^2) sum over faces of w_f E(S1,S2,f), region sizes in area.
std::vector<double> brute_force_face_errors(const std::vector<int>& s1, const std::vector<int>& s2,
                                            const std::vector<double>& w)
{
  std::vector<double> e(s1.size());
  for(std::size_t f = 0; f < s1.size(); ++f)
  {
    double region = 0., outside = 0.;
    for(std::size_t g = 0; g < s1.size(); ++g)
      if(s1[g] == s1[f])
      {
        region += w[g];
        if(s2[g] != s2[f])
          outside += w[g];
      }
    e[f] = outside / region;
  }
  return e;
}

// O(n * regions^2) Hamming distance D_H(S1 => S2) from the set definition.
double brute_force_directional_hamming(const std::vector<int>& s1, const std::vector<int>& s2,
                                       const std::vector<double>& w)
{
  std::vector<int> regions2(s2.begin(), s2.end()), regions1(s1.begin(), s1.end());
  std::sort(regions2.begin(), regions2.end());
  regions2.erase(std::unique(regions2.begin(), regions2.end()), regions2.end());
  std::sort(regions1.begin(), regions1.end());
  regions1.erase(std::unique(regions1.begin(), regions1.end()), regions1.end());
  double d = 0.;
  for(int r2 : regions2)
  {
    double best_overlap = -1.;
    int best = 0;
    for(int r1 : regions1)
    {
      double overlap = 0.;
      for(std::size_t f = 0; f < s1.size(); ++f)
        overlap += (s2[f] == r2 && s1[f] == r1) ? w[f] : 0.;
      if(overlap > best_overlap)
      {
        best_overlap = overlap;
        best = r1;
      }
    }
    for(std::size_t f = 0; f < s1.size(); ++f)
      d += (s2[f] == r2 && s1[f] != best) ? w[f] : 0.;
  }
  return d;
}

// Labels 0 on faces [0, cut) and 1 on [cut, n).
std::vector<int> halves(std::size_t n, std::size_t cut)
{
  std::vector<int> l(n, 1);
  for(std::size_t f = 0; f < cut; ++f)
    l[f] = 0;
  return l;
}

std::string temp_path(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("spectralseg_test_evaluation_" + name)).string();
}
} // namespace

TEST_CASE("identical labellings score zero, also with permuted labels", "[evaluation]")
{
  const std::vector<double> areas = {1., 2., 3., 4.};
  const std::vector<std::vector<int>> same = {{0, 0, 1, 1}, {5, 5, 2, 2}, {-7, -7, 100, 100}};
  for(const std::vector<int>& b : same)
  {
    const std::vector<int> a = {0, 0, 1, 1};
    CHECK(E::rand_index_error(a, b) == 0.);
    CHECK(E::global_consistency_error(a, b, areas) == 0.);
    CHECK(E::local_consistency_error(a, b, areas) == 0.);
    const E::Hamming_distance h = E::hamming(a, b, areas);
    CHECK(h.distance == 0.);
    CHECK(h.missing_rate == 0.);
    CHECK(h.false_alarm_rate == 0.);
    CHECK(E::hamming_distance(a, b, areas) == 0.);
  }
}

TEST_CASE("Rand index error: one segment against two equal halves of 4 faces", "[evaluation][rand]")
{
  // 6 pairs; the one-segment labelling puts every pair together, the halves
  // only {0,1} and {2,3}: they agree on 2 pairs, 1 - RI = 4/6
  CHECK(E::rand_index_error({0, 0, 0, 0}, {0, 0, 1, 1}) == Approx(4. / 6.));
  CHECK(E::rand_index_error({0, 0, 1, 1}, {3, 3, 3, 3}) == Approx(4. / 6.));
  // a single face has no pair
  CHECK(E::rand_index_error({1}, {2}) == 0.);
}

TEST_CASE("GCE, LCE and Hamming distance with unequal areas, by hand", "[evaluation][consistency][hamming]")
{
  // areas w = {1, 2, 3, 4}, A = 10
  // a = {0,0,1,1}: regions a0 = {0,1} (area 3), a1 = {2,3} (area 7)
  // b = {0,1,1,1}: regions b0 = {0}   (area 1), b1 = {1,2,3} (area 9)
  // E(a,b,f) = |R(a,f) \ R(b,f)| / |R(a,f)|: face 0: 2/3, face 1: 1/3, faces 2, 3: 0
  //   sum w E(a,b) = 1*2/3 + 2*1/3 = 4/3
  // E(b,a,f): face 0: 0, face 1: 7/9, faces 2, 3: 2/9
  //   sum w E(b,a) = 2*7/9 + 3*2/9 + 4*2/9 = 28/9
  // GCE = min(4/3, 28/9) / 10 = 2/15
  // LCE = (1*min(2/3,0) + 2*min(1/3,7/9) + 0 + 0) / 10 = (2/3) / 10 = 1/15
  // Rm = sum over b regions of area outside the best a region:
  //   b0: 1 - 1 = 0, b1: 9 - max(2, 7) = 2  -> Rm = 2/10
  // Rf = over a regions: a0: 3 - max(1, 2) = 1, a1: 7 - 7 = 0 -> Rf = 1/10
  // HD = (0.2 + 0.1) / 2 = 0.15
  // Rand (unweighted): pairs 01, 12, 13 disagree -> 3/6
  const std::vector<int> a = {0, 0, 1, 1}, b = {0, 1, 1, 1};
  const std::vector<double> w = {1., 2., 3., 4.};
  CHECK(E::global_consistency_error(a, b, w) == Approx(2. / 15.));
  CHECK(E::global_consistency_error(b, a, w) == Approx(2. / 15.));
  CHECK(E::local_consistency_error(a, b, w) == Approx(1. / 15.));
  CHECK(E::local_consistency_error(b, a, w) == Approx(1. / 15.));
  const E::Hamming_distance h = E::hamming(a, b, w);
  CHECK(h.missing_rate == Approx(0.2));
  CHECK(h.false_alarm_rate == Approx(0.1));
  CHECK(h.distance == Approx(0.15));
  const E::Hamming_distance r = E::hamming(b, a, w); // the roles exchange
  CHECK(r.missing_rate == Approx(0.1));
  CHECK(r.false_alarm_rate == Approx(0.2));
  CHECK(E::rand_index_error(a, b) == Approx(0.5));

  SECTION("unit areas, three labels")
  {
    // s1 = {0,0,1,1,2,2}, s2 = {0,1,3,2,2,2}; cells (0,0) (0,1) (1,3) (1,2): 1 face, (2,2): 2
    // E(s1,s2): faces 0-3: 1/2, faces 4, 5: 0 -> 2;  E(s2,s1): face 3: 2/3, faces 4, 5: 1/3 -> 4/3
    // GCE = (4/3)/6 = 2/9; LCE = min(1/2, 2/3)/6 = 1/12
    // Rm: s2 regions 0, 1, 3 fully inside one s1 region, region 2 (3 faces) 1 outside -> 1/6
    // Rf: s1 regions 0 and 1 have 1 face outside their best s2 region -> 2/6
    // Rand: 15 pairs; together in s1: 3, in s2: 3, in both: 1 -> (2 + 2)/15
    const std::vector<int> s1 = {0, 0, 1, 1, 2, 2}, s2 = {0, 1, 3, 2, 2, 2};
    const std::vector<double> unit(6, 1.);
    CHECK(E::global_consistency_error(s1, s2, unit) == Approx(2. / 9.));
    CHECK(E::local_consistency_error(s1, s2, unit) == Approx(1. / 12.));
    const E::Hamming_distance hs = E::hamming(s1, s2, unit);
    CHECK(hs.missing_rate == Approx(1. / 6.));
    CHECK(hs.false_alarm_rate == Approx(1. / 3.));
    CHECK(hs.distance == Approx(1. / 4.));
    CHECK(E::rand_index_error(s1, s2) == Approx(4. / 15.));
  }
}

TEST_CASE("contingency-table scores agree with the O(n^2) definitions on random labellings",
          "[evaluation][rand][consistency][hamming]")
{
  std::mt19937 rng(20090803);
  std::uniform_real_distribution<double> area(0.1, 5.);
  for(int trial = 0; trial < 200; ++trial)
  {
    const std::size_t n = 60;
    const int ka = 1 + trial % 9, kb = 1 + (trial / 9) % 7;
    const int offset = trial % 2 == 0 ? -3 : 1000; // labels need not be small or contiguous
    std::uniform_int_distribution<int> la(0, ka - 1), lb(0, kb - 1);
    std::vector<int> a(n), b(n);
    std::vector<double> w(n);
    for(std::size_t f = 0; f < n; ++f)
    {
      a[f] = offset + 7 * la(rng);
      b[f] = -lb(rng);
      w[f] = area(rng);
    }
    INFO("trial " << trial);
    CHECK(E::rand_index_error(a, b) == Approx(brute_force_rand_index_error(a, b)).epsilon(1e-14));

    double total = 0., e12 = 0., e21 = 0., local = 0.;
    const std::vector<double> x = brute_force_face_errors(a, b, w), y = brute_force_face_errors(b, a, w);
    for(std::size_t f = 0; f < n; ++f)
    {
      total += w[f];
      e12 += w[f] * x[f];
      e21 += w[f] * y[f];
      local += w[f] * std::min(x[f], y[f]);
    }
    CHECK(E::global_consistency_error(a, b, w) == Approx(std::min(e12, e21) / total).margin(1e-12));
    CHECK(E::local_consistency_error(a, b, w) == Approx(local / total).margin(1e-12));
    const E::Hamming_distance h = E::hamming(a, b, w);
    CHECK(h.missing_rate == Approx(brute_force_directional_hamming(a, b, w) / total).margin(1e-12));
    CHECK(h.false_alarm_rate == Approx(brute_force_directional_hamming(b, a, w) / total).margin(1e-12));
  }

  SECTION("many labels (hashed contingency table)")
  {
    const std::size_t n = 1000;
    std::uniform_int_distribution<int> l(-100000, 100000), few(0, 299);
    std::vector<int> a(n), b(n);
    for(std::size_t f = 0; f < n; ++f)
    {
      a[f] = l(rng) % 400; // ~400 labels each: 160000 label pairs > 4n
      b[f] = 1000 * few(rng);
    }
    CHECK(E::rand_index_error(a, b) == Approx(brute_force_rand_index_error(a, b)).epsilon(1e-14));
  }
}

TEST_CASE("Rand index error stays exact for a million faces", "[evaluation][rand]")
{
  // one segment against two halves of n = 10^6: together in both = 2 C(n/2, 2),
  // disagreeing pairs = C(n, 2) - 2 C(n/2, 2) = n^2 / 4
  const std::size_t n = 1000000;
  const std::vector<int> one(n, 0);
  const std::vector<int> two = halves(n, n / 2);
  const double expected = (double(n) * double(n) / 4.) / (double(n) * double(n - 1) / 2.);
  CHECK(E::rand_index_error(one, two) == Approx(expected).epsilon(1e-15));
}

TEST_CASE("cut discrepancy on a strip of equilateral triangles", "[evaluation][cut_discrepancy]")
{
  // 20 triangles of side 1 in a row: face t is adjacent to t - 1 and t + 1;
  // every dual edge has geodesic length 2 * inradius = sqrt(3)/3 (one hop)
  const std::size_t n = 20;
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::equilateral_strip(n));
  const Dual_graph g = make_dual_graph(m);
  REQUIRE(g.number_of_faces() == n);
  const double hop = std::sqrt(3.) / 3.;

  // average radius: up triangle 2i has centroid (i + 1/2, h/3), down triangle
  // 2i + 1 has (i + 1, 2h/3), h = sqrt(3)/2; all areas equal, so the centre
  // is (5.25, h/2) and each centroid is h/6 off it vertically
  const double h = std::sqrt(3.) / 2.;
  double radius = 0.;
  for(std::size_t i = 0; i < n / 2; ++i)
    radius += std::hypot(i + 0.5 - 5.25, h / 6.) + std::hypot(i + 1. - 5.25, h / 6.);
  radius /= double(n);

  SECTION("identical cuts: 0")
  {
    CHECK(E::cut_discrepancy(g, halves(n, 10), halves(n, 10)) == 0.);
    CHECK(E::cut_discrepancy(g, halves(n, 10), {5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2}) == 0.);
  }
  SECTION("cuts 3 hops apart")
  {
    // a cuts 9|10: boundary faces {9, 10}; b cuts 12|13: boundary faces {12, 13}
    // a -> b: face 9 is 3 hops from face 12, face 10 is 2 hops: mean 2.5 hops
    // b -> a: face 12 is 2 hops from 10, face 13 is 3 hops: mean 2.5 hops
    CHECK(E::cut_discrepancy(g, halves(n, 10), halves(n, 13)) == Approx(5. * hop / radius));
    CHECK(E::cut_discrepancy(g, halves(n, 13), halves(n, 10)) == Approx(5. * hop / radius));
  }
  SECTION("adjacent cuts, 1 hop apart")
  {
    // a: {9, 10}, b: {10, 11}; a -> b: (1 + 0)/2 hop, b -> a: (0 + 1)/2 hop
    CHECK(E::cut_discrepancy(g, halves(n, 10), halves(n, 11)) == Approx(hop / radius));
  }
  SECTION("two cuts against one")
  {
    // a: three segments cut 4|5 and 14|15: boundary {4, 5, 14, 15}; b cuts 9|10: {9, 10}
    // a -> b: 5, 4, 4, 5 hops: mean 4.5; b -> a: face 9 is 4 hops from 5, face 10 is 4 from 14: mean 4
    std::vector<int> a(n, 0);
    for(std::size_t f = 5; f < 15; ++f)
      a[f] = 1;
    for(std::size_t f = 15; f < n; ++f)
      a[f] = 2;
    CHECK(E::cut_discrepancy(g, a, halves(n, 10)) == Approx(8.5 * hop / radius));
  }
  SECTION("no cut on one side: NaN; on neither side: 0")
  {
    const std::vector<int> one(n, 3);
    CHECK(std::isnan(E::cut_discrepancy(g, one, halves(n, 10))));
    CHECK(std::isnan(E::cut_discrepancy(g, halves(n, 10), one)));
    CHECK(E::cut_discrepancy(g, one, std::vector<int>(n, -1)) == 0.);
  }
  SECTION("labellings of the wrong size throw")
  {
    CHECK_THROWS_AS(E::cut_discrepancy(g, halves(n - 1, 10), halves(n, 10)), Invalid_input);
    CHECK_THROWS_AS(E::cut_discrepancy(g, halves(n, 10), {}), Invalid_input);
  }
}

TEST_CASE("evaluate averages over the ground truths and skips an undefined cut discrepancy", "[evaluation]")
{
  const std::size_t n = 20;
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::equilateral_strip(n));
  const Dual_graph g = make_dual_graph(m);
  const std::vector<int> predicted = halves(n, 10);
  const std::vector<std::vector<int>> truths = {halves(n, 13), std::vector<int>(n, 0)};

  // Rand: against halves(13): together in predicted 2 C(10,2) = 90, in the
  // truth C(13,2) + C(7,2) = 99, in both C(10,2) + C(3,2) + C(7,2) = 69:
  // (21 + 30) / 190. Against one segment: (0 + 100) / 190. Mean: 151 / 380.
  const E::Scores s = E::evaluate(g, predicted, truths);
  CHECK(s.rand_index_error == Approx(151. / 380.));
  CHECK(s.cut_discrepancy == Approx(E::cut_discrepancy(g, predicted, truths[0]))); // NaN left out

  const std::vector<double>& areas = g.geometry().areas;
  const std::vector<E::Scores> each = E::evaluate_each(g, predicted, truths);
  REQUIRE(each.size() == 2);
  for(std::size_t i = 0; i < truths.size(); ++i)
  {
    CHECK(each[i].rand_index_error == Approx(E::rand_index_error(predicted, truths[i])));
    CHECK(each[i].global_consistency_error == Approx(E::global_consistency_error(predicted, truths[i], areas)));
    CHECK(each[i].local_consistency_error == Approx(E::local_consistency_error(predicted, truths[i], areas)));
    const E::Hamming_distance h = E::hamming(predicted, truths[i], areas);
    CHECK(each[i].hamming_distance == Approx(h.distance));
    CHECK(each[i].hamming_missing_rate == Approx(h.missing_rate));
    CHECK(each[i].hamming_false_alarm_rate == Approx(h.false_alarm_rate));
  }
  CHECK(std::isnan(each[1].cut_discrepancy));
  CHECK(s.global_consistency_error == Approx(0.5 * (each[0].global_consistency_error + each[1].global_consistency_error)));
  CHECK(s.hamming_missing_rate == Approx(0.5 * (each[0].hamming_missing_rate + each[1].hamming_missing_rate)));

  // one ground truth, the prediction itself: everything 0
  const E::Scores self = E::evaluate(g, predicted, {predicted});
  CHECK(self.rand_index_error == 0.);
  CHECK(self.global_consistency_error == 0.);
  CHECK(self.local_consistency_error == 0.);
  CHECK(self.hamming_distance == 0.);
  CHECK(self.cut_discrepancy == 0.);

  // only undefined cut discrepancies: NaN
  CHECK(std::isnan(E::evaluate(g, std::vector<int>(n, 1), {predicted}).cut_discrepancy));

  CHECK_THROWS_AS(E::evaluate(g, predicted, {}), Invalid_input);
  CHECK_THROWS_AS(E::evaluate(g, predicted, {halves(n + 1, 3)}), Invalid_input);
}

TEST_CASE("scores reject mismatched or empty input", "[evaluation]")
{
  const std::vector<double> w = {1., 1., 1.};
  CHECK_THROWS_AS(E::rand_index_error({0, 1, 2}, {0, 1}), Invalid_input);
  CHECK_THROWS_AS(E::rand_index_error({}, {}), Invalid_input);
  CHECK_THROWS_AS(E::global_consistency_error({0, 1, 2}, {0, 1}, w), Invalid_input);
  CHECK_THROWS_AS(E::local_consistency_error({0, 1, 2}, {0, 1, 2}, {1., 1.}), Invalid_input);
  CHECK_THROWS_AS(E::hamming({0, 1}, {0, 1, 2}, w), Invalid_input);
  CHECK_THROWS_AS(E::hamming_distance({}, {}, {}), Invalid_input);
  CHECK_THROWS_AS(E::hamming({0, 1, 2}, {0, 1, 2}, {1., -1., 1.}), Invalid_input);
  CHECK_THROWS_AS(E::global_consistency_error({0, 1, 2}, {0, 1, 2}, {0., 0., 0.}), Invalid_input);
}

TEST_CASE("label files: round trip and bad files", "[evaluation][io]")
{
  const std::string path = temp_path("labels.seg");
  const std::vector<int> labels = {0, 3, 3, -2, 2147483647, -2147483647 - 1, 7};
  E::write_labels(path, labels);
  CHECK(E::read_labels(path) == labels);

  {
    std::ofstream out(path);
    out << "1 2\r\n\t3\n\n  4  \n"; // any whitespace separates; CRLF line ends
  }
  CHECK(E::read_labels(path) == std::vector<int>{1, 2, 3, 4});

  const std::vector<std::string> bad = {"1\n2\nabc\n", "1\n2.5\n", "1\n99999999999\n", "", "  \n"};
  for(const std::string& content : bad)
  {
    {
      std::ofstream out(path);
      out << content;
    }
    INFO("content: '" << content << "'");
    CHECK_THROWS_AS(E::read_labels(path), Io_error);
    CHECK_THROWS_WITH(E::read_labels(path), Catch::Contains(path));
  }
  {
    std::ofstream out(path);
    out << "1\n2\nabc\n";
  }
  CHECK_THROWS_WITH(E::read_labels(path), Catch::Contains("line 3") && Catch::Contains("abc"));
  std::filesystem::remove(path);

  const std::string missing = temp_path("no_such_file.seg");
  CHECK_THROWS_AS(E::read_labels(missing), Io_error);
  CHECK_THROWS_WITH(E::read_labels(missing), Catch::Contains(missing));
  CHECK_THROWS_AS(E::write_labels(temp_path("no_such_dir/x.seg"), labels), Io_error);
}
