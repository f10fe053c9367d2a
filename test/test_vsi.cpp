// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The VSI metric: reference points, shape images, and the part-boundary effect.
#include "test_meshes.h"

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Metrics/Any_weight.h>
#include <SpectralSeg/Metrics/Blend.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Metrics/VSI_weight.h>
#include <SpectralSeg/Metrics/metric_values.h>
#include <SpectralSeg/Ray_casting/AABB_ray_caster.h>
#include <SpectralSeg/Weighted_dual_graph.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
using namespace SpectralSeg;

// The face facing `normal` whose centroid is nearest to `p`.
Dual_graph::size_type face_near(const Dual_graph& g, const Eigen::Vector3d& p, const Eigen::Vector3d& normal)
{
  Dual_graph::size_type best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for(Dual_graph::size_type f = 0; f < g.number_of_faces(); ++f)
  {
    const double d = (g.geometry().centroids[f] - p).norm();
    if(g.geometry().normals[f].dot(normal) > 0.9 && d < best_d)
    {
      best_d = d;
      best = f;
    }
  }
  return best;
}
} // namespace

TEST_CASE("ray directions: cone and antipodal pairs", "[vsi]")
{
  const auto cone = Metrics::VSI::cone_directions(16, 80. * 3.14159265358979323846 / 180.);
  REQUIRE(cone.size() == 16);
  CHECK(cone[0].z() == 1.);
  for(const auto& d : cone)
  {
    CHECK(d.norm() == Approx(1.));
    CHECK(d.z() >= std::cos(40. * 3.14159265358979323846 / 180.) - 1e-12);
  }
  const auto pairs = Metrics::VSI::antipodal_directions(50);
  REQUIRE(pairs.size() == 100);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for(std::size_t k = 0; k < 50; ++k)
  {
    CHECK((pairs[2 * k] + pairs[2 * k + 1]).norm() == Approx(0.).margin(1e-15));
    sum += pairs[2 * k].cwiseAbs();
  }
  // spread evenly: the mean absolute coordinate of a uniform direction is 1/2
  CHECK(sum.x() / 50. == Approx(0.5).epsilon(0.15));
  CHECK(sum.z() / 50. == Approx(0.5).epsilon(0.15));
}

TEST_CASE("the reference points of a sphere lie near its centre", "[vsi]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::sphere(2., 24, 48));
  const Dual_graph g = make_dual_graph(m);
  const Ray_casting::AABB_ray_caster caster(g.geometry());
  const Metrics::VSI::Reference_points r = Metrics::VSI::compute_reference_points(g, caster);
  double worst = 0.;
  for(std::size_t f = 0; f < g.number_of_faces(); ++f)
  {
    worst = std::max(worst, r.points[f].norm());
    CHECK(r.measured[f] == 1);
    CHECK(r.diameters[f] == Approx(4.).epsilon(0.05));
  }
  CHECK(worst < 0.1 * 2.);
  CHECK(r.relocated == 0);

  // every image of a sphere's centre reaches one diameter in every direction
  Metrics::VSI_options o;
  o.images.sample_fraction = 1.;
  const Metrics::VSI_result vsi = Metrics::compute_vsi(g, caster, o);
  CHECK(vsi.images.reaches.minCoeff() > 3.9f);
  CHECK(vsi.images.reaches.maxCoeff() < 4.05f);
}

TEST_CASE("reference points from a quarter of the faces: the others take their neighbours' depth", "[vsi]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::sphere(2., 24, 48));
  const Dual_graph g = make_dual_graph(m);
  const Ray_casting::AABB_ray_caster caster(g.geometry());
  Metrics::VSI::Reference_point_options o;
  o.measured_fraction = 0.25;
  const Metrics::VSI::Reference_points r = Metrics::VSI::compute_reference_points(g, caster, o);
  const std::vector<std::uint32_t> casting =
    Metrics::VSI::spread_samples(g.geometry().centroids, std::size_t(std::ceil(0.25 * double(g.number_of_faces()))));
  CHECK(casting.size() < g.number_of_faces() / 3);
  double worst = 0.;
  for(std::size_t f = 0; f < g.number_of_faces(); ++f)
  {
    worst = std::max(worst, r.points[f].norm());
    CHECK(r.measured[f] == 1); // every face got a depth, cast or from its neighbours
    CHECK(r.diameters[f] == Approx(4.).epsilon(0.05));
  }
  CHECK(worst < 0.1 * 2.);
  for(double bad : {0., -0.5, 1.5, std::numeric_limits<double>::quiet_NaN()})
  {
    o.measured_fraction = bad;
    CHECK_THROWS_AS(Metrics::VSI::compute_reference_points(g, caster, o), Invalid_input);
  }
}

TEST_CASE("reference points: at most max_measured_faces faces cast their cone", "[vsi]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::sphere(2., 24, 48));
  const Dual_graph g = make_dual_graph(m);
  const std::size_t n = g.number_of_faces();
  const Ray_casting::AABB_ray_caster caster(g.geometry());
  auto points = [&](double fraction, std::size_t most) {
    Metrics::VSI::Reference_point_options o;
    o.measured_fraction = fraction;
    o.max_measured_faces = most;
    return Metrics::VSI::compute_reference_points(g, caster, o).points;
  };
  const std::size_t quarter = std::size_t(std::ceil(0.25 * double(n)));
  REQUIRE(Metrics::VSI::Reference_point_options().max_measured_faces > n);
  const std::vector<Eigen::Vector3d> every = points(1., 0);
  CHECK(points(1., Metrics::VSI::Reference_point_options().max_measured_faces) == every); // the default: all of them
  CHECK(points(1., n) == every);
  const std::vector<Eigen::Vector3d> limited = points(1., quarter);
  CHECK(limited != every);
  CHECK(limited == points(0.25, 0)); // the same faces as a quarter
  CHECK(points(0.25, n) == limited); // the fewer of the two applies
  CHECK(points(0.5, quarter) == limited);
  CHECK(Metrics::VSI_options::thesis().reference.max_measured_faces == 0); // the thesis: every face
}

TEST_CASE("VSI distance jumps across the junction of a T, geodesic does not", "[vsi]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::t_shape(4));
  const Dual_graph g = make_dual_graph(m);
  REQUIRE(g.number_of_border_edges() == 0);
  const Eigen::Vector3d front(0., -1., 0.);
  // pairs of front faces one unit apart: across the junction, in the stem, in the bar
  const auto across = std::make_pair(face_near(g, {6., 0., 5.5}, front), face_near(g, {6., 0., 6.5}, front));
  const auto stem = std::make_pair(face_near(g, {6., 0., 2.5}, front), face_near(g, {6., 0., 3.5}, front));
  const auto bar = std::make_pair(face_near(g, {2., 0., 7.}, front), face_near(g, {3., 0., 7.}, front));

  const Weighted_dual_graph geodesic(g, Metrics::Geodesic_weight()(g));
  auto distance = [](const Weighted_dual_graph& w, std::pair<Dual_graph::size_type, Dual_graph::size_type> p) {
    return w.distances(p.first)[p.second];
  };
  CHECK(distance(geodesic, across) == Approx(distance(geodesic, stem)));
  CHECK(distance(geodesic, across) == Approx(distance(geodesic, bar)));

  for(double fraction : {0.01, 1.})
  {
    INFO("sample fraction " << fraction);
    Metrics::VSI_options o;
    o.images.sample_fraction = fraction;
    const Weighted_dual_graph vsi(g, Metrics::VSI_weight<>(o)(g, Execution(2)));
    const double jump = distance(vsi, across);
    CHECK(jump > 4. * distance(vsi, stem));
    CHECK(jump > 4. * distance(vsi, bar));
  }
}

TEST_CASE("VSI weights do not depend on the number of threads", "[vsi][threads]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::t_shape(2));
  const Dual_graph g = make_dual_graph(m);
  const Metrics::Part_aware_weight<> metric;
  const std::vector<double> w1 = metric(g, Execution(1));
  const std::vector<double> w2 = metric(g, Execution(2));
  const std::vector<double> w3 = metric(g, Execution(3));
  CHECK(w1 == w2);
  CHECK(w1 == w3);
}

TEST_CASE("metric_values: the faces' thickness from the metrics that measure it", "[vsi][thickness]")
{
  const Mesh m = test_meshes::to_mesh<Mesh>(test_meshes::sphere(2., 24, 48));
  const Dual_graph g = make_dual_graph(m);
  const Metrics::Part_aware_weight<> part_aware;
  const Metrics::Metric_values v = Metrics::metric_values(part_aware, g, Execution(2));
  // the same weights as the plain call, and every face of a sphere of
  // radius 2 about one diameter thick
  CHECK(v.weights == part_aware(g, Execution(2)));
  REQUIRE(v.face_thickness.size() == g.number_of_faces());
  for(double t : v.face_thickness)
    CHECK(t == Approx(4.).epsilon(0.05));
  // passed on by Any_weight, and by a Blend from its VSI component
  const Metrics::Metric_values any = Metrics::metric_values(Metrics::Any_weight(part_aware), g);
  CHECK(any.weights == v.weights);
  CHECK(any.face_thickness == v.face_thickness);
  const Metrics::Metric_values vsi = Metrics::metric_values(Metrics::VSI_weight<>(), g);
  REQUIRE(vsi.face_thickness.size() == g.number_of_faces());
  const auto blend = Metrics::make_blend(Metrics::Geodesic_weight(), 0.5, Metrics::VSI_weight<>(), 0.5);
  CHECK(Metrics::metric_values(blend, g).face_thickness == vsi.face_thickness);
  // none from a metric that casts no ray, nor from a Blend that does not
  // compute its VSI component
  CHECK(Metrics::metric_values(Metrics::Geodesic_weight(), g).face_thickness.empty());
  CHECK(Metrics::metric_values(Metrics::Any_weight(Metrics::Geodesic_weight()), g).face_thickness.empty());
  const auto no_vsi = Metrics::make_blend(Metrics::Geodesic_weight(), 1., Metrics::VSI_weight<>(), 0.);
  CHECK(Metrics::metric_values(no_vsi, g).face_thickness.empty());
  // the weighted graph keeps it, and refuses thickness that does not fit
  const Weighted_dual_graph weighted(g, v);
  CHECK(weighted.face_thickness() == v.face_thickness);
  Metrics::Metric_values bad = v;
  bad.face_thickness.pop_back();
  CHECK_THROWS_AS(Weighted_dual_graph(g, bad), Invalid_input);
  bad = v;
  bad.face_thickness[3] = -1.;
  CHECK_THROWS_AS(Weighted_dual_graph(g, bad), Invalid_input);
  bad.face_thickness[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK(Weighted_dual_graph(g, bad).face_thickness().size() == g.number_of_faces());
}

TEST_CASE("median_reaches: the median of each image's measured reaches", "[vsi][thickness]")
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Metrics::VSI::Shape_images images;
  images.reaches.resize(4, 4);
  images.reaches << 1.f, nan, 3.f, 2.f, //
    4.f, 1.f, 3.f, 2.f,                 //
    nan, 7.f, nan, nan,                 //
    nan, nan, nan, nan;
  const std::vector<double> m = Metrics::VSI::median_reaches(images, Execution(2));
  REQUIRE(m.size() == 4);
  CHECK(m[0] == 2.);
  CHECK(m[1] == 2.5);
  CHECK(m[2] == 7.);
  CHECK(std::isnan(m[3]));
}

TEST_CASE("vsi_face_thickness: the ball on a smooth surface, the chords on a rough one", "[vsi][thickness]")
{
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const std::size_t rings = 48, segments = 96;
  for(const double bump : {0., 0.03})
  {
    // a sphere of radius 2; the rough one has its vertices pushed out and
    // in, in a checkerboard, by 3% of the radius (bumps about as deep as
    // the vertices are apart)
    test_meshes::Soup s = test_meshes::sphere(2., rings, segments);
    for(std::size_t i = 1; i < rings; ++i)
      for(std::size_t j = 0; j < segments; ++j)
        for(double& c : s.points[1 + (i - 1) * segments + j])
          c *= (i + j) % 2 == 0 ? 1. + bump : 1. - bump;
    const Mesh m = test_meshes::to_mesh<Mesh>(s);
    const Dual_graph g = make_dual_graph(m);
    const Ray_casting::AABB_ray_caster caster(g.geometry());
    const Metrics::VSI_result vsi = Metrics::compute_vsi(g, caster, Metrics::VSI_options(), Execution(2));
    const std::vector<double> thickness = Metrics::vsi_face_thickness(vsi, Execution(2));
    const double ball = median(vsi.reference_points.diameters), chord = median(Metrics::VSI::median_reaches(vsi.images));
    INFO("bumps " << bump << ": median ball diameter " << ball << ", median chord " << chord);
    REQUIRE(thickness.size() == g.number_of_faces());
    if(bump == 0.)
    {
      // the ball fits the sphere, half a chord does not reach it
      CHECK(ball == Approx(4.).epsilon(0.05));
      CHECK(chord == Approx(4.).epsilon(0.05));
      CHECK(thickness == vsi.reference_points.diameters);
    }
    else
    {
      // the ball shrinks to the bumps (2% of the diameter); half the
      // median chord keeps a quarter of it
      CHECK(ball < 0.1 * 4.);
      CHECK(median(thickness) > 0.2 * 4.);
      CHECK(median(thickness) > 10. * ball);
      CHECK(median(thickness) < 4.);
    }
    // what the VSI metric reports as the faces' thickness
    CHECK(Metrics::metric_values(Metrics::VSI_weight<>(), g, Execution(2)).face_thickness == thickness);
  }
}

TEST_CASE("open meshes: rays that escape are ignored, no NaN reaches a weight", "[vsi][open]")
{
  // a box without its top: many rays leave through the opening
  test_meshes::Soup s = test_meshes::welded(test_meshes::box(2., 2., 1., 4));
  s.faces.erase(s.faces.begin() + 32, s.faces.begin() + 64); // the z = sz side
  const Mesh m = test_meshes::to_mesh<Mesh>(s);
  const Dual_graph g = make_dual_graph(m);
  REQUIRE(g.number_of_border_edges() > 0);
  const Ray_casting::AABB_ray_caster caster(g.geometry());
  Metrics::VSI_options o;
  o.images.sample_fraction = 1.;
  const Metrics::VSI_result r = Metrics::compute_vsi(g, caster, o);
  bool some_escape = false;
  for(Eigen::Index i = 0; i < r.images.reaches.size(); ++i)
    some_escape = some_escape || std::isnan(r.images.reaches.data()[i]);
  CHECK(some_escape);
  for(double w : r.weights)
  {
    CHECK(std::isfinite(w));
    CHECK(w >= 0.);
  }
  const std::vector<double> pa = Metrics::Part_aware_weight<>()(g);
  const std::vector<double> d = Weighted_dual_graph(g, pa).distances(0);
  for(double v : d)
    CHECK(std::isfinite(v));
}

TEST_CASE("image_difference: robust mean of squared reach differences", "[vsi][difference]")
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> a = {1.f, 2.f, 3.f, 4.f};
  CHECK(Metrics::VSI::image_difference(a.data(), a.data(), a.size()) == 0.);
  // equal differences: their plain mean; a pair missing in one image is ignored
  const std::vector<float> b = {2.f, 3.f, nan, 5.f};
  CHECK(Metrics::VSI::image_difference(a.data(), b.data(), a.size()) == Approx(1.));
  // one outlier (d = 100 >= mean + 2 sd) is dropped: 1, not the plain mean 10.9
  const std::vector<float> zero(10, 0.f);
  std::vector<float> one(10, 1.f);
  one[9] = 10.f;
  CHECK(Metrics::VSI::image_difference(zero.data(), one.data(), zero.size()) == Approx(1.));
  const std::vector<float> none(4, nan);
  CHECK(std::isnan(Metrics::VSI::image_difference(a.data(), none.data(), a.size())));
}

TEST_CASE("vsi_edge_weights: image differences, unmeasured edges filled from neighbours", "[vsi][weights]")
{
  const Mesh mesh = test_meshes::to_mesh<Mesh>(test_meshes::square_strip(3));
  const Dual_graph graph = make_dual_graph(mesh);
  const std::size_t n = graph.number_of_faces();
  Metrics::VSI::Shape_images images;
  images.reaches.resize(static_cast<Eigen::Index>(n), 3);
  for(std::size_t f = 0; f < n; ++f)
    images.reaches.row(static_cast<Eigen::Index>(f)).setConstant(float(f));
  images.reaches.row(2).setConstant(std::numeric_limits<float>::quiet_NaN()); // face 2: no measured ray
  std::size_t filled = 0;
  const std::vector<double> w = Metrics::vsi_edge_weights(graph, images, Execution(2), &filled);
  REQUIRE(w.size() == graph.number_of_edges());
  std::size_t touching = 0;
  for(std::size_t e = 0; e < w.size(); ++e)
  {
    const Dual_graph::Edge& edge = graph.edge(static_cast<Dual_graph::size_type>(e));
    CHECK(std::isfinite(w[e]));
    if(edge.face[0] == 2 || edge.face[1] == 2)
      ++touching;
    else
    {
      const double d = double(edge.face[0]) - double(edge.face[1]);
      CHECK(w[e] == Approx(d * d));
    }
  }
  CHECK(touching > 0);
  CHECK(filled == touching);
}
