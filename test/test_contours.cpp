// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The 2D contour analysis of the segmentability test (SpectralSeg/Segmentability).
#include <SpectralSeg/Segmentability/Contour.h>
#include <SpectralSeg/Segmentability/Contour_analysis.h>
#include <SpectralSeg/Segmentability/convexity.h>
#include <SpectralSeg/Segmentability/inner_distances.h>
#include <SpectralSeg/Segmentability/integrated_bending_score.h>
#include <SpectralSeg/Segmentability/multidimensional_scaling.h>
#include <SpectralSeg/Segmentability/simplify_contour.h>
#include <SpectralSeg/Segmentability/smooth_contour.h>
#include <SpectralSeg/Segmentability/trace_outer_contour.h>
#include <SpectralSeg/exceptions.h>

#include <catch2/catch.hpp>

#include "test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace {

using namespace SpectralSeg::Segmentability;
using SpectralSeg::Invalid_input;
typedef std::vector<Eigen::Vector2d> Plane_points;
typedef std::vector<std::array<std::uint32_t, 3>> Plane_triangles;
using test_meshes::pi;

struct Mesh_2
{
  Plane_points points;
  Plane_triangles triangles;
};

// The unit cells (i, j) of a grid for which `keep` is true, each split into
// two triangles, with shared vertices.
Mesh_2 grid_mesh(int nx, int ny, double cell, const std::function<bool(int, int)>& keep)
{
  Mesh_2 m;
  std::map<std::pair<int, int>, std::uint32_t> index;
  auto vertex = [&](int i, int j) {
    auto inserted = index.emplace(std::make_pair(i, j), std::uint32_t(m.points.size()));
    if(inserted.second)
      m.points.emplace_back(i * cell, j * cell);
    return inserted.first->second;
  };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
      if(keep(i, j))
      {
        const std::uint32_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      }
  return m;
}

// An annulus (or a disk when inner_radius is 0) triangulated in rings.
Mesh_2 ring_mesh(double inner_radius, double outer_radius, int rings, int sectors)
{
  Mesh_2 m;
  const bool disk = inner_radius <= 0.;
  if(disk)
    m.points.emplace_back(0., 0.);
  const int first_ring = disk ? 1 : 0;
  for(int r = first_ring; r <= rings; ++r)
    for(int s = 0; s < sectors; ++s)
    {
      const double radius = inner_radius + (outer_radius - inner_radius) * r / rings;
      const double angle = 2. * pi * s / sectors;
      m.points.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
  auto at = [&](int r, int s) {
    return std::uint32_t((disk ? 1 : 0) + (r - first_ring) * sectors + (s % sectors));
  };
  for(int s = 0; s < sectors; ++s)
  {
    if(disk)
      m.triangles.push_back({0, at(1, s), at(1, s + 1)});
    for(int r = std::max(first_ring, disk ? 1 : 0); r < rings; ++r)
    {
      m.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
  }
  return m;
}

// Each edge of `polygon` cut into pieces no longer than `step`.
Contour subdivide(const Contour& polygon, double step)
{
  Contour out;
  for(std::size_t i = 0; i < polygon.size(); ++i)
  {
    const Eigen::Vector2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const int pieces = std::max(1, int(std::ceil((b - a).norm() / step)));
    for(int k = 0; k < pieces; ++k)
      out.push_back(a + (b - a) * double(k) / pieces);
  }
  return out;
}

Contour regular_polygon(int n, double radius, double phase = 0.)
{
  Contour c;
  for(int k = 0; k < n; ++k)
    c.emplace_back(radius * std::cos(phase + 2. * pi * k / n), radius * std::sin(phase + 2. * pi * k / n));
  return c;
}

Eigen::MatrixXd euclidean_distances(const Contour& c)
{
  const Eigen::Index n = Eigen::Index(c.size());
  Eigen::MatrixXd d(n, n);
  for(Eigen::Index i = 0; i < n; ++i)
    for(Eigen::Index j = 0; j < n; ++j)
      d(i, j) = (c[std::size_t(i)] - c[std::size_t(j)]).norm();
  return d;
}

// A disk of radius 1 with a limb of width w along +x, its end at x = 1 + length.
Contour disk_with_limb(double length, double width, int arc_vertices)
{
  const double start = std::asin(width / 2.);
  Contour c;
  for(int k = 0; k <= arc_vertices; ++k)
  {
    const double a = start + (2. * pi - 2. * start) * k / arc_vertices;
    c.emplace_back(std::cos(a), std::sin(a));
  }
  c.emplace_back(std::cos(start) + length, -width / 2.);
  c.emplace_back(std::cos(start) + length, width / 2.);
  return c;
}

bool contains_point(const Contour& c, const Eigen::Vector2d& p)
{
  return std::any_of(c.begin(), c.end(), [&](const Eigen::Vector2d& q) { return (q - p).norm() < 1e-12; });
}

} // namespace

TEST_CASE("the contour of two triangles is counter-clockwise and fits their box", "[segmentability]")
{
  const Plane_points points{{0., 0.}, {2., 0.}, {2., 1.}, {0., 1.}};
  const Plane_triangles triangles{{{0, 1, 2}}, {{0, 2, 3}}};
  const Contour c = trace_outer_contour(points, triangles, 200);
  REQUIRE(c.size() > 100);
  CHECK(signed_area(c) > 0.);
  const double pixel = 2. / (200. - 5.); // the box spans the raster minus the margins
  Eigen::Vector2d lo = c.front(), hi = c.front();
  for(const Eigen::Vector2d& p : c)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  CHECK(lo.x() == Approx(0.).margin(1.5 * pixel));
  CHECK(lo.y() == Approx(0.).margin(1.5 * pixel));
  CHECK(hi.x() == Approx(2.).margin(1.5 * pixel));
  CHECK(hi.y() == Approx(1.).margin(1.5 * pixel));
  CHECK(signed_area(c) == Approx(2.).epsilon(0.03));
  // consecutive boundary pixels are neighbours, the first differs from the last
  for(std::size_t i = 0; i < c.size(); ++i)
  {
    const double step = (c[(i + 1) % c.size()] - c[i]).norm() / pixel;
    CHECK(step > 0.5);
    CHECK(step < 1.5);
  }
}

TEST_CASE("the traced contour of an annulus is its outer circle", "[segmentability]")
{
  const Mesh_2 annulus = ring_mesh(0.5, 1., 6, 96);
  const Contour c = trace_outer_contour(annulus.points, annulus.triangles);
  CHECK(signed_area(c) == Approx(pi).epsilon(0.03));
  for(const Eigen::Vector2d& p : c)
    CHECK(p.norm() > 0.97);
}

TEST_CASE("thin triangles are drawn and keep a mesh connected", "[segmentability]")
{
  // a zigzag of needles, each far thinner than a pixel, and a square at each end
  Mesh_2 m;
  const int needles = 40;
  for(int k = 0; k <= needles; ++k)
    m.points.emplace_back(double(k), (k % 2) * 3.);
  for(int k = 0; k < needles; ++k)
    m.points.emplace_back(double(k) + 1e-4, (k % 2) * 3.);
  for(int k = 0; k < needles; ++k)
    m.triangles.push_back({std::uint32_t(k), std::uint32_t(needles + 1 + k), std::uint32_t(k + 1)});
  const Contour c = trace_outer_contour(m.points, m.triangles);
  REQUIRE_FALSE(c.empty());
  double lo = c.front().x(), hi = lo;
  for(const Eigen::Vector2d& p : c)
  {
    lo = std::min(lo, p.x());
    hi = std::max(hi, p.x());
  }
  CHECK(lo < 0.5); // all needles in one region
  CHECK(hi > needles - 0.5);
  // degenerate triangles (segments) are drawn too
  const Plane_points segment{{0., 0.}, {1., 1.}};
  const Contour diagonal = trace_outer_contour(segment, {{{0, 1, 1}}}, 50);
  CHECK(diagonal.size() > 40);
}

TEST_CASE("trace_outer_contour on empty, degenerate and invalid input", "[segmentability]")
{
  CHECK(trace_outer_contour({}, {}).empty());
  CHECK(trace_outer_contour({{1., 1.}, {1., 1.}, {1., 1.}}, {{{0, 1, 2}}}).empty());
  CHECK_THROWS_AS(trace_outer_contour({{0., 0.}, {1., 0.}}, {{{0, 1, 2}}}), Invalid_input);
  CHECK_THROWS_AS(trace_outer_contour({{0., 0.}, {1., std::nan("")}, {0., 1.}}, {{{0, 1, 2}}}), Invalid_input);
  CHECK_THROWS_AS(trace_outer_contour({{0., 0.}, {1., 0.}, {0., 1.}}, {{{0, 1, 2}}}, 4), Invalid_input);
  // two separate squares: the larger one is kept
  Mesh_2 two = grid_mesh(30, 10, 1., [](int i, int) { return i < 8 || i >= 26; });
  const Contour c = trace_outer_contour(two.points, two.triangles);
  for(const Eigen::Vector2d& p : c)
    CHECK(p.x() < 9.);
}

TEST_CASE("convex shapes score below the threshold, plus and T shapes above", "[segmentability]")
{
  const Mesh_2 disk = ring_mesh(0., 1., 8, 64);
  const Mesh_2 square = grid_mesh(10, 10, 0.1, [](int, int) { return true; });
  const Mesh_2 plus = grid_mesh(30, 30, 1., [](int i, int j) { return (i >= 10 && i < 20) || (j >= 10 && j < 20); });
  const Mesh_2 tee = grid_mesh(30, 30, 1., [](int i, int j) { return j >= 22 || (i >= 12 && i < 18); });
  const Contour_analysis d = analyse_contour(disk.points, disk.triangles);
  const Contour_analysis s = analyse_contour(square.points, square.triangles);
  const Contour_analysis p = analyse_contour(plus.points, plus.triangles);
  const Contour_analysis t = analyse_contour(tee.points, tee.triangles);
  for(const Contour_analysis* a : {&d, &s, &p, &t})
  {
    CHECK(a->contour.size() == 50);
    CHECK(signed_area(a->contour) > 0.);
    CHECK(a->inner.rows() == 50);
    CHECK(a->has_normalized);
    CHECK(a->normalized.size() == 50);
  }
  CHECK(d.score < 0.03);
  CHECK(s.score < 0.03);
  CHECK(d.normalized_score < 0.05);
  CHECK(s.normalized_score < 0.05);
  CHECK(p.score > 0.2);
  CHECK(t.score > 0.15);
  CHECK(p.normalized_score > 0.1);
  CHECK(t.normalized_score > 0.1);
}

TEST_CASE("analyse_contour computes the normalised contour on demand", "[segmentability]")
{
  const Mesh_2 plus = grid_mesh(9, 9, 1., [](int i, int j) { return (i >= 3 && i < 6) || (j >= 3 && j < 6); });
  Contour_analysis a = analyse_contour(plus.points, plus.triangles, Contour_options(), false);
  CHECK_FALSE(a.has_normalized);
  CHECK(a.normalized.empty());
  CHECK(a.inner.rows() == Eigen::Index(a.contour.size()));
  add_normalized(a);
  CHECK(a.has_normalized);
  const Contour_analysis b = analyse_contour(plus.points, plus.triangles);
  CHECK(a.normalized_score == b.normalized_score); // deterministic
  CHECK(a.normalized.size() == b.normalized.size());
  // nothing to draw
  const Contour_analysis empty = analyse_contour({}, {});
  CHECK(empty.traced.empty());
  CHECK(empty.contour.empty());
  CHECK(empty.score == 0.);
  CHECK(empty.normalized_score == 0.);
  CHECK(empty.has_normalized);
  Contour_options bad;
  bad.vertices = 2;
  CHECK_THROWS_AS(analyse_contour(plus.points, plus.triangles, bad), Invalid_input);
}

TEST_CASE("Fourier smoothing meets its tolerance, tighter with a smaller one", "[segmentability]")
{
  const Mesh_2 tee = grid_mesh(30, 30, 1., [](int i, int j) { return j >= 22 || (i >= 12 && i < 18); });
  const Contour traced = trace_outer_contour(tee.points, tee.triangles);
  double diagonal = 0.;
  for(const Eigen::Vector2d& p : traced)
    for(const Eigen::Vector2d& q : traced)
      diagonal = std::max(diagonal, (p - q).norm()); // at most the box diagonal
  double previous_error = std::numeric_limits<double>::infinity();
  for(double tolerance : {0.02, 0.005, 0.001})
  {
    const Contour smooth = smooth_contour(traced, tolerance);
    REQUIRE(smooth.size() == traced.size());
    CHECK(signed_area(smooth) > 0.);
    double error = 0.;
    for(std::size_t k = 0; k < traced.size(); ++k)
      error += (smooth[k] - traced[k]).norm();
    error /= double(traced.size());
    CHECK(error < tolerance * 30. * std::sqrt(2.));
    CHECK(error > 0.); // the pixel staircase is gone
    CHECK(error <= previous_error);
    previous_error = error;
  }
  // a circle is already smooth: the first pair of frequencies rebuilds it
  const Contour circle = regular_polygon(100, 2.);
  const Contour same = smooth_contour(circle);
  for(std::size_t k = 0; k < circle.size(); ++k)
    CHECK((same[k] - circle[k]).norm() < 1e-9);
  CHECK(smooth_contour(circle, 0.).size() == 100);
  CHECK_THROWS_AS(smooth_contour(circle, -1.), Invalid_input);
}

TEST_CASE("discrete curve evolution keeps the requested number of vertices and the corners", "[segmentability]")
{
  // a rectangle with slightly wavy sides, 400 points
  Contour c = subdivide({{0., 0.}, {3., 0.}, {3., 2.}, {0., 2.}}, 0.025);
  REQUIRE(c.size() == 400);
  for(std::size_t k = 0; k < c.size(); ++k)
  {
    const bool corner = (c[k] - Eigen::Vector2d(0., 0.)).norm() < 1e-12 || (c[k] - Eigen::Vector2d(3., 0.)).norm() < 1e-12 ||
                        (c[k] - Eigen::Vector2d(3., 2.)).norm() < 1e-12 || (c[k] - Eigen::Vector2d(0., 2.)).norm() < 1e-12;
    if(!corner)
      c[k] += 0.003 * std::sin(0.7 * double(k)) * Eigen::Vector2d(1., 1.);
  }
  const Contour s = simplify_contour(c, 50);
  CHECK(s.size() == 50);
  CHECK(signed_area(s) > 0.);
  for(const Eigen::Vector2d& corner : {Eigen::Vector2d(0., 0.), Eigen::Vector2d(3., 0.), Eigen::Vector2d(3., 2.),
                                       Eigen::Vector2d(0., 2.)})
    CHECK(contains_point(s, corner));
  const Contour four = simplify_contour(c, 4);
  REQUIRE(four.size() == 4);
  CHECK(signed_area(four) == Approx(6.).epsilon(1e-9)); // exactly the corners
  // kept vertices come from c, in order
  std::size_t from = 0;
  for(const Eigen::Vector2d& p : s)
  {
    while(from < c.size() && (c[from] - p).norm() > 0.)
      ++from;
    CHECK(from < c.size());
  }
  // a clockwise input comes back counter-clockwise; short inputs are copied
  Contour clockwise(c.rbegin(), c.rend());
  CHECK(signed_area(simplify_contour(clockwise, 50)) > 0.);
  CHECK(simplify_contour(regular_polygon(5, 1.), 50).size() == 5);
  CHECK_THROWS_AS(simplify_contour(c, 2), Invalid_input);
}

TEST_CASE("convexity of convex, concave and degenerate contours", "[segmentability]")
{
  const Convexity convex = convexity(regular_polygon(12, 2.));
  CHECK(convex.area_ratio == Approx(1.).epsilon(1e-12));
  CHECK(convex.perimeter_ratio == Approx(1.).epsilon(1e-12));
  CHECK(convex.convexity == Approx(1.).epsilon(1e-12));
  CHECK(segmentability_score(regular_polygon(12, 2.)) == Approx(0.).margin(1e-12));
  // an L: three unit squares of the 2 x 2 hull square minus the corner triangle
  const Contour l{{0., 0.}, {2., 0.}, {2., 1.}, {1., 1.}, {1., 2.}, {0., 2.}};
  const Convexity lc = convexity(l);
  CHECK(lc.area_ratio == Approx(3. / 3.5));
  CHECK(lc.perimeter_ratio == Approx((6. + std::sqrt(2.)) / 8.));
  CHECK(lc.convexity == Approx(std::max(3. / 3.5, std::pow((6. + std::sqrt(2.)) / 8., 4.))));
  CHECK(convexity(l, 1.).convexity == Approx((6. + std::sqrt(2.)) / 8.));
  // a comb with thin deep slits: little area lost, much perimeter added
  Contour comb{{0., 0.}, {5., 0.}, {5., 5.}};
  for(int k = 4; k >= 1; --k)
  {
    comb.emplace_back(k + 0.01, 5.);
    comb.emplace_back(k + 0.01, 0.5);
    comb.emplace_back(k - 0.01, 0.5);
    comb.emplace_back(k - 0.01, 5.);
  }
  comb.emplace_back(0., 5.);
  const Convexity cc = convexity(comb);
  CHECK(cc.area_ratio > 0.95);
  CHECK(cc.perimeter_ratio < 0.6);
  CHECK(cc.convexity == cc.area_ratio);
  // degenerate: too few points, collinear points, repeated points
  for(const Contour& d : {Contour{}, Contour{{1., 1.}}, Contour{{0., 0.}, {1., 1.}},
                          Contour{{0., 0.}, {1., 1.}, {2., 2.}, {3., 3.}}, Contour(5, Eigen::Vector2d(1., 2.))})
  {
    CHECK(convexity(d).convexity == 1.);
    CHECK(segmentability_score(d) == 0.);
  }
  CHECK_THROWS_AS(convexity(l, 0.), Invalid_input);
}

TEST_CASE("inner distances: Euclidean in a convex polygon, around the notch of a U", "[segmentability]")
{
  const Contour convex = subdivide(regular_polygon(7, 1., 0.3), 0.2); // collinear vertices on the sides
  const Eigen::MatrixXd d = inner_distances(convex);
  CHECK((d - euclidean_distances(convex)).cwiseAbs().maxCoeff() < 1e-12);

  // a U: outer square 3 x 3, notch [1, 2] x [1, 3]; vertex 3 = (2, 3) and 6 = (1, 3) are the inner tips
  const Contour u{{0., 0.}, {3., 0.}, {3., 3.}, {2., 3.}, {2., 1.}, {1., 1.}, {1., 3.}, {0., 3.}};
  const Eigen::MatrixXd du = inner_distances(u);
  CHECK(du(3, 6) == Approx(5.));                          // down, across, up
  CHECK(du(2, 7) == Approx(1. + 2. * std::sqrt(5.)));     // outer tips, round the notch's corners
  CHECK(du(0, 2) == Approx(2. * std::sqrt(5.)));          // the diagonal crosses the notch: via (2, 1)
  CHECK(du(0, 1) == Approx(3.));
  CHECK((du - du.transpose()).cwiseAbs().maxCoeff() == 0.);
  CHECK((du - euclidean_distances(u)).minCoeff() > -1e-12);

  // the same U sampled densely: tip to tip is still about 5, far above the Euclidean 1
  const Contour dense = subdivide(u, 0.1);
  const Eigen::MatrixXd dd = inner_distances(dense);
  std::size_t a = 0, b = 0;
  for(std::size_t k = 0; k < dense.size(); ++k)
  {
    if((dense[k] - Eigen::Vector2d(2., 3.)).norm() < 1e-9)
      a = k;
    if((dense[k] - Eigen::Vector2d(1., 3.)).norm() < 1e-9)
      b = k;
  }
  CHECK(dd(Eigen::Index(a), Eigen::Index(b)) == Approx(5.));
}

TEST_CASE("inner distances stay finite on self-intersecting and degenerate contours", "[segmentability]")
{
  const Contour bow_tie{{0., 0.}, {2., 2.}, {2., 0.}, {0., 2.}};
  const Contour twisted{{0., 0.}, {4., 0.}, {4., 3.}, {1.5, 3.}, {2.5, -0.5}, {2., 3.}, {0., 3.}};
  const Contour repeated{{0., 0.}, {1., 0.}, {1., 0.}, {1., 1.}, {0., 1.}, {0., 1.}};
  const Contour collinear{{0., 0.}, {1., 0.}, {2., 0.}, {3., 0.}};
  for(const Contour& c : {bow_tie, twisted, repeated, collinear, Contour{{1., 1.}}, Contour{{0., 0.}, {1., 0.}}})
  {
    const Eigen::MatrixXd d = inner_distances(c);
    REQUIRE(d.rows() == Eigen::Index(c.size()));
    CHECK(d.allFinite());
    CHECK((d - euclidean_distances(c)).minCoeff() > -1e-12);
    CHECK((d - d.transpose()).cwiseAbs().maxCoeff() == 0.);
  }
  CHECK(inner_distances(Contour()).size() == 0);
  CHECK(inner_distances(collinear)(0, 3) == Approx(3.));
}

TEST_CASE("MDS reproduces the distances of points in the plane", "[segmentability]")
{
  // an irregular convex polygon (points on an ellipse at uneven angles), clockwise
  Contour c;
  for(int k = 0; k < 20; ++k)
  {
    const double a = -2. * pi * (k + 0.3 * std::sin(double(k))) / 20.;
    c.emplace_back(3. + 2. * std::cos(a), -1. + 0.7 * std::sin(a));
  }
  const Contour m = multidimensional_scaling(euclidean_distances(c));
  REQUIRE(m.size() == c.size());
  CHECK((euclidean_distances(m) - euclidean_distances(c)).cwiseAbs().maxCoeff() < 1e-9);
  CHECK(signed_area(m) == Approx(-signed_area(c))); // mirrored to counter-clockwise, same order
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for(const Eigen::Vector2d& p : m)
    centre += p;
  CHECK(centre.norm() < 1e-9);
  CHECK(convexity(m).convexity == Approx(1.));

  // inner distances of a U: MDS opens the U up and keeps the order
  const Contour u = subdivide({{0., 0.}, {3., 0.}, {3., 3.}, {2., 3.}, {2., 1.}, {1., 1.}, {1., 3.}, {0., 3.}}, 0.25);
  const Contour opened = multidimensional_scaling(inner_distances(u));
  CHECK(signed_area(opened) > 0.);
  CHECK(opened.size() == u.size());

  CHECK(multidimensional_scaling(Eigen::MatrixXd()).empty());
  CHECK(multidimensional_scaling(Eigen::MatrixXd::Zero(1, 1)).size() == 1);
  Eigen::MatrixXd two(2, 2);
  two << 0., 4., 4., 0.;
  const Contour pair = multidimensional_scaling(two);
  CHECK((pair[0] - pair[1]).norm() == Approx(4.));
  CHECK(multidimensional_scaling(Eigen::MatrixXd::Zero(4, 4)).size() == 4); // all points together
  CHECK_THROWS_AS(multidimensional_scaling(Eigen::MatrixXd::Zero(2, 3)), Invalid_input);
}

TEST_CASE("integrated bending scores match a numerical integration", "[segmentability]")
{
  const Contour u = subdivide({{0., 0.}, {3., 0.}, {3., 3.}, {2., 3.}, {2., 1.}, {1., 1.}, {1., 3.}, {0., 3.}}, 0.7);
  const Eigen::MatrixXd inner = inner_distances(u);
  const std::vector<double> scores = integrated_bending_scores(u, inner);
  const std::size_t n = u.size();
  REQUIRE(scores.size() == n);
  for(std::size_t p = 0; p < n; ++p)
  {
    double integral = 0.; // midpoint rule on the linearly interpolated I / E
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t j = (i + 1) % n;
      const double l = (u[j] - u[i]).norm();
      const int steps = 20000;
      for(int s = 0; s < steps; ++s)
      {
        const double t = (s + 0.5) / steps;
        const double ii = (1. - t) * inner(Eigen::Index(p), Eigen::Index(i)) + t * inner(Eigen::Index(p), Eigen::Index(j));
        const double ee = (1. - t) * (u[i] - u[p]).norm() + t * (u[j] - u[p]).norm();
        integral += l / steps * ii / ee;
      }
    }
    CHECK(scores[p] == Approx(integral).epsilon(1e-5));
    CHECK(scores[p] >= perimeter(u) * (1. - 1e-12)); // the ratio is at least 1
  }
}

TEST_CASE("bending samples: a short limb's tip, then the far side", "[segmentability]")
{
  // a unit disk with a limb of length 1 and width 0.2 along +x
  const Contour c = disk_with_limb(1., 0.2, 40);
  const Eigen::MatrixXd inner = inner_distances(c);
  const std::pair<std::size_t, std::size_t> st = bending_samples(c, inner);
  CHECK(c[st.first].x() > 1.9); // the tip of the limb
  CHECK(c[st.second].x() < -0.9); // the far side of the disk
}

TEST_CASE("bending samples: a long limb and the body are told apart", "[segmentability]")
{
  // With a limb longer than the body's radius, the body vertices next to the
  // limb have the larger score (they see the whole limb round a corner); s
  // and t still fall on different parts.
  for(double length : {2., 3.})
  {
    const Contour c = disk_with_limb(length, 0.2, 40);
    const std::pair<std::size_t, std::size_t> st = bending_samples(c, inner_distances(c));
    const double xs = c[st.first].x(), xt = c[st.second].x();
    CHECK(std::max(xs, xt) > length); // one at the limb's tip
    CHECK(std::min(xs, xt) < 1.);     // the other on the disk
  }
}

TEST_CASE("bending scores on degenerate contours", "[segmentability]")
{
  const Contour repeated{{0., 0.}, {1., 0.}, {1., 0.}, {1., 1.}, {0., 1.}, {0., 0.}};
  for(const Contour& c : {repeated, Contour{{1., 1.}}, Contour{{0., 0.}, {1., 0.}}, Contour(4, Eigen::Vector2d(1., 1.)),
                          Contour{{0., 0.}, {1., 0.}, {2., 0.}}})
  {
    const Eigen::MatrixXd inner = inner_distances(c);
    const std::vector<double> scores = integrated_bending_scores(c, inner);
    REQUIRE(scores.size() == c.size());
    for(double s : scores)
      CHECK(std::isfinite(s));
    const std::pair<std::size_t, std::size_t> st = bending_samples(c, inner);
    CHECK(st.first < c.size());
    CHECK(st.second < c.size());
  }
  CHECK(bending_samples(Contour{{1., 1.}}, Eigen::MatrixXd::Zero(1, 1)) == std::make_pair(std::size_t(0), std::size_t(0)));
  CHECK_THROWS_AS(bending_samples(Contour(), Eigen::MatrixXd()), Invalid_input);
  CHECK_THROWS_AS(integrated_bending_scores(repeated, Eigen::MatrixXd::Zero(2, 2)), Invalid_input);
}

TEST_CASE("smoothing and simplification of tiny contours", "[segmentability]")
{
  for(const Contour& c : {Contour{}, Contour{{1., 1.}}, Contour{{0., 0.}, {1., 0.}}, Contour(6, Eigen::Vector2d(2., 2.)),
                          Contour{{0., 0.}, {1., 0.}, {2., 0.}, {3., 0.}}})
  {
    const Contour s = smooth_contour(c);
    CHECK(s.size() == c.size());
    for(const Eigen::Vector2d& p : s)
      CHECK(p.allFinite());
    CHECK(simplify_contour(c, 3).size() == std::min<std::size_t>(3, c.size()));
  }
  CHECK_THROWS_AS(smooth_contour(Contour{{0., 0.}, {std::numeric_limits<double>::infinity(), 0.}, {0., 1.}}),
                  Invalid_input);
}
