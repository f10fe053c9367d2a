// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// The ray-casting backends (models of RayCaster): known answers on a cube
// and a sphere, and agreement of the Embree backend with the AABB one.
#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/Ray_casting/AABB_ray_caster.h>
#include <SpectralSeg/Ray_casting/Embree_ray_caster.h>

#include <catch2/catch.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using SpectralSeg::Mesh_geometry;
using SpectralSeg::Ray_casting::AABB_ray_caster;
#ifdef SPECTRALSEG_HAS_EMBREE
using SpectralSeg::Ray_casting::Embree_ray_caster;
#define SPECTRALSEG_TEST_RAY_CASTERS AABB_ray_caster, Embree_ray_caster
#else
#define SPECTRALSEG_TEST_RAY_CASTERS AABB_ray_caster
#endif

const double infinity = std::numeric_limits<double>::infinity();

// Orients every face of a convex mesh around the origin outwards.
void orient_outwards(Mesh_geometry& g)
{
  for(auto& t : g.triangles)
  {
    const Eigen::Vector3d& a = g.points[t[0]];
    const Eigen::Vector3d& b = g.points[t[1]];
    const Eigen::Vector3d& c = g.points[t[2]];
    if((b - a).cross(c - a).dot(a + b + c) < 0)
      std::swap(t[1], t[2]);
  }
}

// The cube [-0.5, 0.5]^3 (12 triangles, outward normals), translated by `shift`.
Mesh_geometry unit_cube(const Eigen::Vector3d& shift = Eigen::Vector3d::Zero())
{
  Mesh_geometry g;
  for(int i = 0; i < 8; ++i) // vertex i: bit 0 -> x, bit 1 -> y, bit 2 -> z
    g.points.emplace_back((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5);
  const int quads[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  for(const auto& q : quads) // +x, -x, +y, -y, +z, -z: faces 2k and 2k+1
  {
    g.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2])});
    g.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
  }
  orient_outwards(g);
  for(auto& p : g.points)
    p += shift;
  g.compute_face_attributes();
  return g;
}

// An icosphere of radius 1 (20 * 4^subdivisions faces), centred at `centre`.
Mesh_geometry icosphere(int subdivisions, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero())
{
  Mesh_geometry g;
  const double t = (1. + std::sqrt(5.)) / 2.;
  const double base[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for(const auto& p : base)
    g.points.push_back(Eigen::Vector3d(p[0], p[1], p[2]).normalized());
  g.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for(int s = 0; s < subdivisions; ++s)
  {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = middle.find(key);
      if(it != middle.end())
        return it->second;
      g.points.push_back((g.points[a] + g.points[b]).normalized());
      const std::uint32_t m = static_cast<std::uint32_t>(g.points.size() - 1);
      middle.emplace(key, m);
      return m;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    for(const auto& tr : g.triangles)
    {
      const std::uint32_t a = mid(tr[0], tr[1]), b = mid(tr[1], tr[2]), c = mid(tr[2], tr[0]);
      finer.push_back({tr[0], a, c});
      finer.push_back({tr[1], b, a});
      finer.push_back({tr[2], c, b});
      finer.push_back({a, b, c});
    }
    g.triangles.swap(finer);
  }
  orient_outwards(g);
  for(auto& p : g.points)
    p += centre;
  g.compute_face_attributes();
  return g;
}

// A tiny OFF reader (polygons are fanned into triangles); false if the file
// cannot be read.
[[maybe_unused]] bool read_off(const std::string& path, Mesh_geometry& g)
{
  std::ifstream in(path);
  if(!in)
    return false;
  std::vector<std::string> lines;
  for(std::string line; std::getline(in, line);)
  {
    line = line.substr(0, line.find('#'));
    if(line.find_first_not_of(" \t\r") != std::string::npos)
      lines.push_back(line);
  }
  if(lines.empty() || lines[0].find("OFF") == std::string::npos)
    return false;
  std::size_t l = 1, nv = 0, nf = 0;
  {
    std::istringstream header(lines[0].substr(lines[0].find("OFF") + 3));
    if(!(header >> nv >> nf))
    {
      if(l >= lines.size())
        return false;
      std::istringstream counts(lines[l++]);
      if(!(counts >> nv >> nf))
        return false;
    }
  }
  if(lines.size() < l + nv + nf)
    return false;
  g = Mesh_geometry();
  for(std::size_t v = 0; v < nv; ++v)
  {
    std::istringstream s(lines[l++]);
    double x, y, z;
    if(!(s >> x >> y >> z))
      return false;
    g.points.emplace_back(x, y, z);
  }
  for(std::size_t f = 0; f < nf; ++f)
  {
    std::istringstream s(lines[l++]);
    std::size_t n;
    std::vector<std::uint32_t> poly;
    if(!(s >> n))
      return false;
    for(std::size_t i = 0; i < n; ++i)
    {
      std::uint32_t v;
      if(!(s >> v))
        return false;
      poly.push_back(v);
    }
    for(std::size_t i = 1; i + 1 < poly.size(); ++i)
      g.triangles.push_back({poly[0], poly[i], poly[i + 1]});
  }
  g.compute_face_attributes();
  return true;
}

[[maybe_unused]] std::string shared_mesh(const std::string& name)
{
#ifdef SPECTRALSEG_SHARED_DATA
  return std::string(SPECTRALSEG_SHARED_DATA) + "/meshes/" + name;
#else
  return "/work/shared/data/meshes/" + name;
#endif
}

// Reads a mesh of ../shared/data/meshes into `g`; false, with a warning
// that the test is skipped, if it is not there.
[[maybe_unused]] bool read_shared_mesh(const std::string& name, Mesh_geometry& g)
{
  const std::string path = shared_mesh(name);
  if(std::filesystem::exists(path) && read_off(path, g))
    return true;
  WARN("skipped: " << path << " not found");
  return false;
}

Eigen::Vector3d random_unit(std::mt19937& rng)
{
  std::normal_distribution<double> normal;
  Eigen::Vector3d d;
  do
    d = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
  while(d.norm() < 1e-6);
  return d.normalized();
}

// A random unit direction at most `half_angle` from the unit vector `axis`
// (uniform in solid angle).
[[maybe_unused]] Eigen::Vector3d random_in_cone(const Eigen::Vector3d& axis, double half_angle, std::mt19937& rng)
{
  std::uniform_real_distribution<double> uniform(0., 1.);
  const double z = 1. - uniform(rng) * (1. - std::cos(half_angle));
  const double r = std::sqrt(std::max(0., 1. - z * z));
  const double phi = 2. * 3.14159265358979323846 * uniform(rng);
  const Eigen::Vector3d helper = std::abs(axis.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = axis.cross(helper).normalized();
  const Eigen::Vector3d v = axis.cross(u);
  return (r * std::cos(phi) * u + r * std::sin(phi) * v + z * axis).normalized();
}

// The AABB backend's answers on the cube, and those every backend shares.
template <typename Caster>
void check_cube(const Caster& caster, const Mesh_geometry& cube)
{
  typedef typename Caster::size_type size_type;
  const Eigen::Vector3d c = 0.5 * (cube.points[0] + cube.points[7]); // cube centre

  // From the centre along +x: the +x side (faces 0 and 1) at 0.5. The ray
  // passes through the diagonal shared by faces 0 and 1.
  size_type face = Caster::no_face;
  CHECK(caster.first_hit(c, Eigen::Vector3d::UnitX(), Caster::no_face, &face) == Approx(0.5).margin(1e-6));
  CHECK((face == 0 || face == 1));

  // Off the diagonal, along each axis: exactly one face.
  for(int axis = 0; axis < 3; ++axis)
    for(int sign = -1; sign <= 1; sign += 2)
    {
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      d[axis] = sign;
      Eigen::Vector3d o = c;
      o[(axis + 1) % 3] += 0.2;
      o[(axis + 2) % 3] -= 0.1;
      face = Caster::no_face;
      const double t = caster.first_hit(o, d, Caster::no_face, &face);
      CHECK(t == Approx(0.5).margin(1e-6));
      REQUIRE(face != Caster::no_face);
      CHECK(cube.normals[face].dot(d) == Approx(1.));
      // the hit point lies in the face's triangle: (o + t d) is closer to
      // its centroid than to the other triangle of the side
      const size_type other = face ^ 1u;
      const Eigen::Vector3d p = o + t * d;
      CHECK((p - cube.centroids[face]).norm() < (p - cube.centroids[other]).norm());
    }

  // From outside, pointing away: nothing.
  face = 7;
  CHECK(caster.first_hit(c + Eigen::Vector3d(2, 0, 0), Eigen::Vector3d::UnitX(), Caster::no_face, &face) == infinity);
  CHECK(face == Caster::no_face);
  CHECK(caster.first_hit(c + Eigen::Vector3d(0, -3, 0), -Eigen::Vector3d::UnitY()) == infinity);
  // From outside, pointing at the cube: the near side.
  CHECK(caster.first_hit(c + Eigen::Vector3d(0.1, 0.2, 3), -Eigen::Vector3d::UnitZ(), Caster::no_face, &face) ==
        Approx(2.5).margin(1e-6));
  CHECK(cube.normals[face].z() == Approx(1.));

  // From each face centroid along its inward normal, skipping it: the opposite side at 1.
  for(size_type f = 0; f < cube.number_of_faces(); ++f)
  {
    face = Caster::no_face;
    CHECK(caster.first_hit(cube.centroids[f], -cube.normals[f], f, &face) == Approx(1.).margin(1e-6));
    REQUIRE(face != Caster::no_face);
    CHECK(cube.normals[face].dot(cube.normals[f]) == Approx(-1.));
  }
}

} // namespace

TEST_CASE("Ray casting: AABB backend on a cube", "[ray_casting]")
{
  const Mesh_geometry cube = unit_cube();
  const AABB_ray_caster caster(cube);
  CHECK(AABB_ray_caster::name() == "aabb");
  check_cube(caster, cube);

  // Without skipping, a ray from a face centroid does not meet that face
  // (a hit at distance 0, under 1e-7 of the diagonal): it crosses the cube.
  for(AABB_ray_caster::size_type f = 0; f < cube.number_of_faces(); ++f)
  {
    AABB_ray_caster::size_type face = AABB_ray_caster::no_face;
    CHECK(caster.first_hit(cube.centroids[f], -cube.normals[f], AABB_ray_caster::no_face, &face) ==
          Approx(1.).margin(1e-12));
    CHECK(face != f);
    CHECK(face != AABB_ray_caster::no_face);
  }

  // Rays along -z whose origin lies on the planes x = 0.5 or y = -0.5 that
  // bound the boxes of the tree, with a zero direction component across
  // them (0 * inf = NaN in the slab test): the top face's edge is hit at
  // 1.5. A slab test that took the NaN for a miss would find nothing.
  for(const Eigen::Vector3d& o : {Eigen::Vector3d(0.5, 0.1, 2.), Eigen::Vector3d(0.2, -0.5, 2.),
                                  Eigen::Vector3d(-0.5, 0.3, 2.)})
  {
    AABB_ray_caster::size_type face = AABB_ray_caster::no_face;
    CHECK(caster.first_hit(o, -Eigen::Vector3d::UnitZ(), AABB_ray_caster::no_face, &face) == Approx(1.5));
    REQUIRE(face != AABB_ray_caster::no_face);
    CHECK(cube.normals[face].z() == Approx(1.));
  }
  // ... and one beside those planes, outside every box: nothing.
  CHECK(caster.first_hit(Eigen::Vector3d(0.5 + 1e-3, 0.1, 2.), -Eigen::Vector3d::UnitZ()) ==
        std::numeric_limits<double>::infinity());
}

#ifdef SPECTRALSEG_HAS_EMBREE
TEST_CASE("Ray casting: Embree backend on a cube", "[ray_casting][embree]")
{
  CHECK(Embree_ray_caster::name() == "embree");
  // centred at the origin, and far from it (the backend recentres the mesh)
  for(const Eigen::Vector3d& shift : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1e5, -2e5, 3e5)})
  {
    const Mesh_geometry cube = unit_cube(shift);
    const Embree_ray_caster caster(cube);
    check_cube(caster, cube);

    // As with AABB: without skipping, a ray from a face centroid does not
    // meet that face (under 1e-7 of the diagonal) and crosses the cube.
    for(Embree_ray_caster::size_type f = 0; f < cube.number_of_faces(); ++f)
    {
      Embree_ray_caster::size_type face = Embree_ray_caster::no_face;
      const double t = caster.first_hit(cube.centroids[f], -cube.normals[f], Embree_ray_caster::no_face, &face);
      CHECK(t == Approx(1.).margin(1e-5));
      CHECK(face != f);
      CHECK(face != Embree_ray_caster::no_face);
    }
  }
}
#endif

TEMPLATE_TEST_CASE("Ray casting: rays from the centre of a sphere", "[ray_casting]", SPECTRALSEG_TEST_RAY_CASTERS)
{
  const Mesh_geometry sphere = icosphere(4); // 5120 faces
  REQUIRE(sphere.number_of_faces() == 5120);
  const TestType caster(sphere);
  std::mt19937 rng(12345);
  std::vector<Eigen::Vector3d> directions;
  for(int i = 0; i < 200; ++i)
    directions.push_back(random_unit(rng));
  std::vector<double> batch(directions.size());
  caster.first_hits(Eigen::Vector3d::Zero(), directions.data(), directions.size(), TestType::no_face, batch.data());
  for(std::size_t i = 0; i < directions.size(); ++i)
  {
    typename TestType::size_type face = TestType::no_face;
    const double t = caster.first_hit(Eigen::Vector3d::Zero(), directions[i], TestType::no_face, &face);
    CHECK(t == Approx(1.).margin(1e-2));
    CHECK(batch[i] == Approx(t).epsilon(1e-12));
    REQUIRE(face != TestType::no_face);
    // the face hit is the one the direction points at
    CHECK(sphere.normals[face].dot(directions[i]) > 0.99);
  }
}

TEMPLATE_TEST_CASE("Ray casting: degenerate faces, empty meshes, odd batches", "[ray_casting]",
                   SPECTRALSEG_TEST_RAY_CASTERS)
{
  typedef typename TestType::size_type size_type;
  // The cube plus a zero-area face across its middle: it is never hit.
  Mesh_geometry cube = unit_cube();
  cube.points.emplace_back(0., -0.5, -0.5);
  cube.points.emplace_back(0., 0.5, 0.5);
  cube.triangles.push_back({8, 9, 8});
  cube.compute_face_attributes();
  REQUIRE(cube.degenerate[12] == 1);
  {
    const TestType caster(cube);
    size_type face = TestType::no_face;
    CHECK(caster.first_hit(Eigen::Vector3d(-0.2, 0., 0.), Eigen::Vector3d::UnitX(), 12, &face) ==
          Approx(0.7).margin(1e-6));
    CHECK(face <= 1);
    CHECK(caster.first_hit(Eigen::Vector3d(-0.2, 0.01, 0.02), Eigen::Vector3d::UnitX()) == Approx(0.7).margin(1e-6));

    // Batches of any size, including empty ones and sizes that are not a
    // multiple of a packet width.
    std::mt19937 rng(7);
    for(std::size_t count : {0, 1, 3, 8, 9, 17, 33})
    {
      std::vector<Eigen::Vector3d> dirs;
      for(std::size_t i = 0; i < count; ++i)
        dirs.push_back(random_unit(rng));
      std::vector<double> batch(count + 1, -1.);
      caster.first_hits(Eigen::Vector3d(0.1, 0.05, -0.2), dirs.data(), count, TestType::no_face, batch.data());
      for(std::size_t i = 0; i < count; ++i)
        CHECK(batch[i] == Approx(caster.first_hit(Eigen::Vector3d(0.1, 0.05, -0.2), dirs[i])).epsilon(1e-12));
      CHECK(batch[count] == -1.); // nothing written past the end
    }
  }
  // Degenerate faces before and between the real ones, so that the casters'
  // own numbering of the triangles differs from the faces': a ray from the
  // centre towards each face's centroid hits that face, and skipping it, the
  // ray meets no face there (the other half of the square side lies beside).
  {
    const Mesh_geometry base = unit_cube();
    Mesh_geometry g;
    g.points = base.points;
    g.points.emplace_back(0., -0.5, -0.5);
    g.points.emplace_back(0., 0.5, 0.5);
    g.triangles.push_back({8, 9, 8});
    g.triangles.push_back({9, 9, 9});
    for(std::size_t f = 0; f < base.triangles.size(); ++f)
    {
      g.triangles.push_back(base.triangles[f]);
      if(f == 5)
        g.triangles.push_back({8, 8, 9});
    }
    g.compute_face_attributes();
    const TestType caster(g);
    std::size_t real = 0;
    for(std::size_t f = 0; f < g.triangles.size(); ++f)
    {
      if(g.degenerate[f])
        continue;
      ++real;
      const Eigen::Vector3d to = g.centroids[f].normalized();
      size_type face = TestType::no_face;
      CHECK(caster.first_hit(Eigen::Vector3d::Zero(), to, TestType::no_face, &face) == Approx(g.centroids[f].norm()));
      CHECK(face == size_type(f));
      face = TestType::no_face;
      caster.first_hit(Eigen::Vector3d::Zero(), to, size_type(f), &face);
      CHECK(face != size_type(f));
    }
    CHECK(real == 12);
  }
  // A mesh without faces hits nothing.
  {
    Mesh_geometry empty;
    empty.compute_face_attributes();
    const TestType caster(empty);
    size_type face = 3;
    CHECK(caster.first_hit(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), TestType::no_face, &face) == infinity);
    CHECK(face == TestType::no_face);
    const Eigen::Vector3d d = Eigen::Vector3d::UnitX();
    double t = 0.;
    caster.first_hits(Eigen::Vector3d::Zero(), &d, 1, TestType::no_face, &t);
    CHECK(t == infinity);
  }
}

#ifdef SPECTRALSEG_HAS_EMBREE
namespace {

struct Ray
{
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;
  std::uint32_t skip;
};

// Casts `rays` with both backends and checks that they agree: distances
// within `relative` (plus a tiny absolute slack for near-zero distances),
// the same face except in near ties, and first_hits() == first_hit().
void compare_backends(const Mesh_geometry& g, const std::vector<Ray>& rays, double relative,
                      double max_face_mismatch_fraction)
{
  const AABB_ray_caster aabb(g);
  const Embree_ray_caster embree(g);
  const double slack = 1e-6 * g.bbox_diagonal;
  std::size_t hits = 0, face_mismatches = 0, distance_mismatches = 0;
  for(const Ray& r : rays)
  {
    std::uint32_t fa = AABB_ray_caster::no_face, fe = Embree_ray_caster::no_face;
    const double ta = aabb.first_hit(r.origin, r.direction, r.skip, &fa);
    const double te = embree.first_hit(r.origin, r.direction, r.skip, &fe);
    const bool agree = (std::isinf(ta) && std::isinf(te)) || std::abs(ta - te) <= relative * ta + slack;
    if(!agree && ++distance_mismatches <= 10)
    {
      UNSCOPED_INFO("ray from (" << r.origin.transpose() << ") along (" << r.direction.transpose() << ") skip "
                                 << r.skip << ": aabb " << ta << " (face " << fa << "), embree " << te
                                 << " (face " << fe << ")");
    }
    if(std::isfinite(ta))
    {
      ++hits;
      if(fa != fe)
        ++face_mismatches;
    }
  }
  INFO(rays.size() << " rays, " << hits << " hits, " << face_mismatches << " different faces, "
                   << distance_mismatches << " different distances");
  CHECK(distance_mismatches == 0);
  CHECK(double(face_mismatches) <= max_face_mismatch_fraction * double(hits));
  CHECK(hits > rays.size() / 2);

  // first_hits() gives first_hit(), ray by ray (batches of 13 rays from one origin).
  std::size_t batch_mismatches = 0;
  for(std::size_t start = 0; start < rays.size(); start += 13)
  {
    std::vector<Eigen::Vector3d> dirs;
    for(std::size_t i = start; i < std::min(rays.size(), start + 13); ++i)
      dirs.push_back(rays[i].direction);
    std::vector<double> batch(dirs.size());
    embree.first_hits(rays[start].origin, dirs.data(), dirs.size(), rays[start].skip, batch.data());
    for(std::size_t i = 0; i < dirs.size(); ++i)
    {
      const double single = embree.first_hit(rays[start].origin, dirs[i], rays[start].skip);
      if(!(batch[i] == single || std::abs(batch[i] - single) <= 1e-6 * single))
        ++batch_mismatches;
    }
  }
  CHECK(batch_mismatches == 0);
}

} // namespace

TEST_CASE("Ray casting: Embree agrees with AABB on a sphere", "[ray_casting][embree]")
{
  // centred at the origin, and far from it
  for(const Eigen::Vector3d& centre : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(-3e4, 1e4, 2e4)})
  {
    const Mesh_geometry sphere = icosphere(4, centre);
    std::mt19937 rng(2026);
    std::uniform_real_distribution<double> uniform(0., 1.);
    std::uniform_int_distribution<std::uint32_t> any_face(0, std::uint32_t(sphere.number_of_faces() - 1));
    std::vector<Ray> rays;
    // rays from random interior points (uniform in the ball of radius 0.95)
    while(rays.size() < 1000)
    {
      const Eigen::Vector3d p(2 * uniform(rng) - 1, 2 * uniform(rng) - 1, 2 * uniform(rng) - 1);
      if(p.norm() < 0.95)
        rays.push_back({centre + p, random_unit(rng), AABB_ray_caster::no_face});
    }
    // rays from face centroids into the sphere (at most ~84 degrees from the
    // inward normal), skipping the face; groups of 4 rays per face
    while(rays.size() < 2000)
    {
      const std::uint32_t f = any_face(rng);
      for(int k = 0; k < 4; ++k)
        rays.push_back({sphere.centroids[f], random_in_cone(-sphere.normals[f], 1.47, rng), f});
    }
    compare_backends(sphere, rays, 1e-4, 0.005);
  }
}

#endif

TEMPLATE_TEST_CASE("Ray casting: hits closer than 1e-7 of the diagonal do not count; a flat fan", "[ray_casting]",
                   SPECTRALSEG_TEST_RAY_CASTERS)
{
  const Mesh_geometry cube = unit_cube(); // diagonal sqrt(3)
  const TestType caster(cube);
  const double near = 1e-7 * std::sqrt(3.);
  // towards the face x = 0.5 from just inside it: too close, then far enough
  CHECK(caster.first_hit(Eigen::Vector3d(0.5 - 0.1 * near, 0.1, 0.2), Eigen::Vector3d::UnitX()) == infinity);
  CHECK(caster.first_hit(Eigen::Vector3d(0.5 - 10. * near, 0.1, 0.2), Eigen::Vector3d::UnitX()) ==
        Approx(10. * near).margin(near));

  // A flat disc of 20,000 triangles around one vertex: every bounding box
  // touches the centre's region, and the rays leaving the plane from the
  // faces' centroids meet nothing (each would enter a fifth of the boxes
  // at distance 0 if hits at 0 counted).
  const std::size_t n = 20000;
  Mesh_geometry fan;
  fan.points.emplace_back(0., 0., 0.);
  for(std::size_t i = 0; i < n; ++i)
  {
    const double a = 2. * CGAL_PI * double(i) / double(n);
    fan.points.emplace_back(std::cos(a), std::sin(a), 0.);
    fan.triangles.push_back({0, std::uint32_t(1 + i), std::uint32_t(1 + (i + 1) % n)});
  }
  fan.compute_face_attributes();
  const TestType flat(fan);
  std::size_t hits = 0;
  for(std::size_t f = 0; f < n; f += 7)
    for(const Eigen::Vector3d& d : {Eigen::Vector3d(0.3, 0.2, 1.).normalized(), Eigen::Vector3d(-0.1, 0.4, -1.).normalized()})
      hits += std::isfinite(flat.first_hit(fan.centroids[f], d, typename TestType::size_type(f))) ? 1 : 0;
  CHECK(hits == 0);
}

TEMPLATE_TEST_CASE("Ray casting: concurrent queries", "[ray_casting]", SPECTRALSEG_TEST_RAY_CASTERS)
{
  // Queries are const and thread-safe: four threads casting the same rays
  // get the serial results.
  const Mesh_geometry sphere = icosphere(3);
  const TestType caster(sphere);
  std::mt19937 rng(99);
  std::vector<Eigen::Vector3d> directions;
  for(int i = 0; i < 400; ++i)
    directions.push_back(random_unit(rng));
  const Eigen::Vector3d origin(0.2, -0.1, 0.3);
  std::vector<double> serial(directions.size());
  for(std::size_t i = 0; i < directions.size(); ++i)
    serial[i] = caster.first_hit(origin, directions[i]);
  std::vector<std::vector<double>> results(4, std::vector<double>(directions.size()));
  std::vector<std::thread> threads;
  for(std::size_t t = 0; t < results.size(); ++t)
    threads.emplace_back([&, t] {
      for(int repeat = 0; repeat < 5; ++repeat)
        for(std::size_t i = 0; i < directions.size(); i += 10)
          caster.first_hits(origin, directions.data() + i, 10, TestType::no_face, results[t].data() + i);
    });
  for(std::thread& t : threads)
    t.join();
  for(const std::vector<double>& r : results)
    CHECK(r == serial);
}

#ifdef SPECTRALSEG_HAS_EMBREE
TEST_CASE("Ray casting: Embree agrees with AABB on armadillo.off", "[ray_casting][embree]")
{
  Mesh_geometry g;
  if(!read_shared_mesh("armadillo.off", g))
    return;
  REQUIRE(g.number_of_faces() > 1000);
  std::mt19937 rng(42);
  std::uniform_int_distribution<std::uint32_t> any_face(0, std::uint32_t(g.number_of_faces() - 1));
  std::vector<Ray> rays;
  // as the VSI metric casts them: from face centroids, in a cone of 80
  // degrees around the inward normal, skipping the face
  while(rays.size() < 2000)
  {
    const std::uint32_t f = any_face(rng);
    if(g.degenerate[f])
      continue;
    for(int k = 0; k < 8; ++k)
      rays.push_back({g.centroids[f], random_in_cone(-g.normals[f], 40. * 3.14159265358979323846 / 180., rng), f});
  }
  compare_backends(g, rays, 1e-4, 0.005);
}
#endif

// The nearest hit of a ray among all the faces of `g` but `skip`, within
// [near, max_distance], by a scan of every triangle (Moller-Trumbore);
// ties go to the smallest face index. {distance, face}, or {inf, no_face}.
std::pair<double, AABB_ray_caster::size_type> scan_every_face(const Mesh_geometry& g, const Eigen::Vector3d& o,
                                                             const Eigen::Vector3d& d, AABB_ray_caster::size_type skip,
                                                             double near, double max_distance)
{
  std::pair<double, AABB_ray_caster::size_type> best(infinity, AABB_ray_caster::no_face);
  for(std::size_t f = 0; f < g.number_of_faces(); ++f)
  {
    if(f == skip || g.degenerate[f])
      continue;
    const Eigen::Vector3d& p0 = g.points[g.triangles[f][0]];
    const Eigen::Vector3d e1 = g.points[g.triangles[f][1]] - p0, e2 = g.points[g.triangles[f][2]] - p0;
    const Eigen::Vector3d pv = d.cross(e2);
    const double det = e1.dot(pv);
    if(det == 0.)
      continue;
    const Eigen::Vector3d s = o - p0;
    const double u = s.dot(pv) / det;
    const Eigen::Vector3d q = s.cross(e1);
    const double v = d.dot(q) / det;
    const double t = e2.dot(q) / det;
    if(u < 0. || u > 1. || v < 0. || u + v > 1. || t < near || t > max_distance)
      continue;
    if(t < best.first)
      best = {t, static_cast<AABB_ray_caster::size_type>(f)};
  }
  return best;
}

TEST_CASE("Ray casting: the AABB backend finds the hit a scan of every face finds", "[ray_casting]")
{
  Mesh_geometry g;
  if(!read_shared_mesh("armadillo.off", g))
    return;
  REQUIRE(g.number_of_faces() > 1000);
  const AABB_ray_caster caster(g);
  const double near = 1e-7 * g.bbox_diagonal;
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> any_face(0, std::uint32_t(g.number_of_faces() - 1));
  std::size_t hits = 0, rays = 0;
  while(rays < 300)
  {
    const std::uint32_t f = any_face(rng);
    if(g.degenerate[f])
      continue;
    ++rays;
    // into the shape as the metric casts them, and anywhere from a point off the surface
    const bool inward = rays % 2 == 0;
    const Eigen::Vector3d o =
      inward ? g.centroids[f] : Eigen::Vector3d(g.centroids[f] + 0.01 * g.bbox_diagonal * random_unit(rng));
    const Eigen::Vector3d d = inward ? random_in_cone(-g.normals[f], 1.4, rng) : random_unit(rng);
    const AABB_ray_caster::size_type skip = inward ? f : AABB_ray_caster::no_face;
    const auto expected = scan_every_face(g, o, d, skip, near, infinity);
    AABB_ray_caster::size_type face = AABB_ray_caster::no_face;
    const double t = caster.first_hit(o, d, skip, &face);
    CHECK(face == expected.second);
    if(expected.second == AABB_ray_caster::no_face)
    {
      CHECK(t == infinity);
      continue;
    }
    ++hits;
    CHECK(t == Approx(expected.first).epsilon(1e-12));
    // a bound short of the hit leaves nothing; a bound beyond it the same hit
    CHECK(caster.first_hit(o, d, skip, nullptr, 0.5 * expected.first) == infinity);
    CHECK(caster.first_hit(o, d, skip, nullptr, 2. * expected.first) == Approx(expected.first).epsilon(1e-12));
    // skipping the face hit finds what the scan finds without it
    if(!inward)
    {
      const auto behind = scan_every_face(g, o, d, expected.second, near, infinity);
      AABB_ray_caster::size_type next = AABB_ray_caster::no_face;
      caster.first_hit(o, d, expected.second, &next);
      CHECK(next == behind.second);
      CHECK(next != expected.second);
    }
  }
  CHECK(hits > 150);
}
