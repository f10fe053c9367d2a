// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Contacts between the parts of a mesh that touch without sharing a mesh
// edge: vertices at the same position in different connected components
// (what splitting non-manifold edges and vertices, or an unwelded export,
// leaves behind).
#ifndef SPECTRALSEG_INTERNAL_CONTACT_ADJACENCIES_H
#define SPECTRALSEG_INTERNAL_CONTACT_ADJACENCIES_H

#include <SpectralSeg/Mesh_geometry.h>
#include <SpectralSeg/internal/Point_neighbours.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace internal {

// One contact: faces f0 and f1 touch at vertices v0 and v1 (same position).
struct Contact
{
  std::uint32_t f0, f1, v0, v1;
  double length; // nominal length: the mean edge length of the two faces
};

// For every two vertices at most `gap` apart (0: at the same position)
// whose faces lie in different connected components (under `adjacent`,
// pairs of faces sharing a mesh edge), one contact between the nearest two
// of their incident faces (centroid distance, ties by face index); one
// contact per pair of faces. Then the specks, parts with less than
// `speck_area_fraction` of the area, are linked to the nearest other part,
// smallest first, until none is left apart. Deterministic.
SPECTRALSEG_INLINE std::vector<Contact> contact_adjacencies(
    const Mesh_geometry& geo, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& adjacent, double gap,
    double speck_area_fraction)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t nf = geo.number_of_faces();
  const std::size_t nv = geo.points.size();
  std::vector<Contact> out;
  if(nf < 2)
    return out;

  // connected components of the faces
  std::vector<std::size_t> rank(nf, 0), parent(nf);
  boost::disjoint_sets<std::size_t*, std::size_t*> sets(rank.data(), parent.data());
  for(std::size_t f = 0; f < nf; ++f)
    sets.make_set(f);
  for(const auto& a : adjacent)
    sets.union_set(a.first, a.second);
  std::vector<std::size_t> component(nf);
  bool several = false;
  for(std::size_t f = 0; f < nf; ++f)
  {
    component[f] = sets.find_set(f);
    several = several || component[f] != component[0];
  }
  if(!several)
    return out;

  // faces around each vertex
  std::vector<std::size_t> first(nv + 1, 0);
  for(const auto& t : geo.triangles)
    for(std::uint32_t v : t)
      ++first[v + 1];
  for(std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<std::uint32_t> around(first[nv]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t f = 0; f < nf; ++f)
      for(std::uint32_t v : geo.triangles[f])
        around[fill[v]++] = static_cast<std::uint32_t>(f);
  }
  const auto mean_edge = [&](std::uint32_t f) {
    const auto& t = geo.triangles[f];
    return ((geo.points[t[0]] - geo.points[t[1]]).norm() + (geo.points[t[1]] - geo.points[t[2]]).norm() +
            (geo.points[t[2]] - geo.points[t[0]]).norm()) /
           3.;
  };

  // a contact between the nearest two faces of the fans of va and vb (the
  // first such pair in the order of the fans)
  const auto contact = [&](std::uint32_t va, std::uint32_t vb) {
    double best = std::numeric_limits<double>::infinity();
    Contact c{0, 0, va, vb, 0.};
    const std::size_t pairs = (first[va + 1] - first[va]) * (first[vb + 1] - first[vb]);
    if(pairs <= 4096)
      for(std::size_t x = first[va]; x < first[va + 1]; ++x)
        for(std::size_t y = first[vb]; y < first[vb + 1]; ++y)
        {
          const double d = (geo.centroids[around[x]] - geo.centroids[around[y]]).squaredNorm();
          if(d < best)
          {
            best = d;
            c.f0 = around[x];
            c.f1 = around[y];
          }
        }
    else
    {
      // two large fans (a vertex of high degree split in two): the nearest
      // face of vb's fan to each of va's from a search tree, not every pair
      std::vector<Eigen::Vector3d> fan;
      for(std::size_t y = first[vb]; y < first[vb + 1]; ++y)
        fan.push_back(geo.centroids[around[y]]);
      const Point_neighbours fan_tree(fan);
      for(std::size_t x = first[va]; x < first[va + 1]; ++x)
      {
        const std::size_t y = first[vb] + fan_tree.nearest(geo.centroids[around[x]], 1).front().first;
        const double d = (geo.centroids[around[x]] - geo.centroids[around[y]]).squaredNorm();
        if(d < best)
        {
          best = d;
          c.f0 = around[x];
          c.f1 = around[y];
        }
      }
    }
    c.length = 0.5 * (mean_edge(c.f0) + mean_edge(c.f1));
    return c;
  };

  // For each vertex with faces, the vertices of other components within
  // `gap` (at the same position when `gap` is 0): among its nearest
  // `neighbours` vertices.
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::uint32_t> vertex_of;
  for(std::size_t v = 0; v < nv; ++v)
    if(first[v + 1] > first[v])
    {
      positions.push_back(geo.points[v]);
      vertex_of.push_back(static_cast<std::uint32_t>(v));
    }
  const Point_neighbours tree(positions);
  const std::size_t neighbours = 12;
  // each vertex's nearest vertices, found once: the speck rounds below read
  // them again (one round per halving of the specks: a cloud of 200,000
  // separate triangles took 18 rounds of 600,000 searches)
  std::vector<std::size_t> near_first(positions.size() + 1, 0);
  std::vector<std::uint32_t> near_vertex;
  std::vector<double> near_distance; // squared
  near_vertex.reserve(positions.size() * neighbours);
  near_distance.reserve(positions.size() * neighbours);
  std::vector<std::pair<std::size_t, double>> nearest; // reused from vertex to vertex
  for(std::size_t i = 0; i < positions.size(); ++i)
  {
    tree.nearest(positions[i], neighbours, nearest);
    for(const auto& q : nearest)
    {
      near_vertex.push_back(static_cast<std::uint32_t>(q.first));
      near_distance.push_back(q.second);
    }
    near_first[i + 1] = near_vertex.size();
  }
  for(std::size_t i = 0; i < positions.size(); ++i)
  {
    const std::uint32_t va = vertex_of[i];
    for(std::size_t j = near_first[i]; j < near_first[i + 1]; ++j)
    {
      const std::uint32_t vb = vertex_of[near_vertex[j]];
      if(near_distance[j] > gap * gap)
        break;
      if(vb <= va || component[around[first[va]]] == component[around[first[vb]]])
        continue;
      out.push_back(contact(va, vb));
    }
  }
  // Specks (parts under `speck_area_fraction` of the total area) still apart
  // are linked to the nearest other part by a contact between their nearest
  // vertices, in rounds (Boruvka): in each round every speck finds its
  // nearest other part among its vertices' nearest neighbours, and the links
  // are added smallest speck first.
  for(const Contact& c : out)
    sets.union_set(c.f0, c.f1);
  const auto vertex_less = [](double d, std::uint32_t a, std::uint32_t b, double e, std::uint32_t c, std::uint32_t x) {
    return std::make_tuple(d, a, b) < std::make_tuple(e, c, x);
  };
  for(;;)
  {
    std::vector<double> area(nf, 0.);
    std::vector<std::size_t> root(nf);
    std::size_t parts = 0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      root[f] = sets.find_set(f);
      area[root[f]] += geo.areas[f];
      parts += root[f] == f ? 1 : 0;
    }
    double total = 0.;
    for(std::size_t f = 0; f < nf; ++f)
      total += geo.areas[f];
    std::size_t specks = 0;
    for(std::size_t f = 0; f < nf; ++f)
      specks += root[f] == f && area[f] < speck_area_fraction * total ? 1 : 0;
    if(parts < 2 || specks == 0)
      break;
    const auto part_of = [&](std::uint32_t v) { return root[around[first[v]]]; };
    struct Link { double d = std::numeric_limits<double>::infinity(); std::uint32_t a = 0, b = 0; };
    std::vector<Link> link(nf);
    for(std::size_t i = 0; i < positions.size(); ++i)
    {
      const std::size_t p = part_of(vertex_of[i]);
      for(std::size_t j = near_first[i]; j < near_first[i + 1]; ++j)
      {
        const std::pair<std::uint32_t, double> q(near_vertex[j], near_distance[j]);
        Link& l = link[p];
        if(part_of(vertex_of[q.first]) != p && vertex_less(q.second, vertex_of[i], vertex_of[q.first], l.d, l.a, l.b))
          l = Link{q.second, vertex_of[i], vertex_of[q.first]};
      }
    }
    std::vector<std::size_t> order; // the specks
    for(std::size_t f = 0; f < nf; ++f)
      if(root[f] == f && area[f] < speck_area_fraction * total)
        order.push_back(f);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return std::make_pair(area[a], a) < std::make_pair(area[b], b); });
    bool linked = false;
    for(std::size_t p : order)
    {
      const Link& l = link[p];
      if(!std::isfinite(l.d) || sets.find_set(around[first[l.a]]) == sets.find_set(around[first[l.b]]))
        continue;
      out.push_back(contact(l.a, l.b));
      sets.union_set(out.back().f0, out.back().f1);
      linked = true;
    }
    if(linked)
      continue;
    // every speck's nearest vertices are its own: each speck is linked to
    // the nearest vertex of another part, exactly, smallest speck first.
    // Its m vertices ask the search tree of all vertices for their m + 1
    // nearest (at most m of them are its own) when m * m is below the
    // number of vertices, else a tree of the other parts' vertices is built
    // for it; one round for all such specks, not one per speck (1,500
    // separate boxes: 46 s when each round linked the smallest speck only)
    const std::size_t none = std::size_t(-1);
    std::vector<std::size_t> slot(nf, none);
    for(std::size_t k = 0; k < order.size(); ++k)
      slot[order[k]] = k;
    std::vector<std::vector<std::size_t>> members(order.size());
    for(std::size_t i = 0; i < positions.size(); ++i)
    {
      const std::size_t k = slot[part_of(vertex_of[i])];
      if(k != none)
        members[k].push_back(i);
    }
    for(std::size_t k = 0; k < order.size(); ++k)
    {
      const std::size_t p = order[k];
      Link best;
      const std::size_t m = members[k].size();
      if(m * m <= positions.size())
      {
        for(const std::size_t i : members[k])
          for(const auto& q : tree.nearest(positions[i], m + 1))
            if(part_of(vertex_of[q.first]) != p &&
               vertex_less(q.second, vertex_of[i], vertex_of[q.first], best.d, best.a, best.b))
              best = Link{q.second, vertex_of[i], vertex_of[q.first]};
      }
      else
      {
        std::vector<Eigen::Vector3d> others;
        std::vector<std::uint32_t> other_vertex;
        for(std::size_t i = 0; i < positions.size(); ++i)
          if(part_of(vertex_of[i]) != p)
          {
            others.push_back(positions[i]);
            other_vertex.push_back(vertex_of[i]);
          }
        const Point_neighbours other_tree(others);
        for(const std::size_t i : members[k])
          for(const auto& q : other_tree.nearest(positions[i], 1))
            if(vertex_less(q.second, vertex_of[i], other_vertex[q.first], best.d, best.a, best.b))
              best = Link{q.second, vertex_of[i], other_vertex[q.first]};
      }
      if(!std::isfinite(best.d) || sets.find_set(around[first[best.a]]) == sets.find_set(around[first[best.b]]))
        continue;
      out.push_back(contact(best.a, best.b));
      sets.union_set(out.back().f0, out.back().f1);
    }
  }

  // one contact per pair of faces
  std::sort(out.begin(), out.end(), [](const Contact& a, const Contact& b) {
    return std::make_tuple(std::min(a.f0, a.f1), std::max(a.f0, a.f1), a.v0, a.v1) <
           std::make_tuple(std::min(b.f0, b.f1), std::max(b.f0, b.f1), b.v0, b.v1);
  });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const Contact& a, const Contact& b) {
                          return std::min(a.f0, a.f1) == std::min(b.f0, b.f1) &&
                                 std::max(a.f0, a.f1) == std::max(b.f0, b.f1);
                        }),
            out.end());
  return out;
}
#else
;
#endif

} // namespace internal
} // namespace SpectralSeg

#endif // SPECTRALSEG_INTERNAL_CONTACT_ADJACENCIES_H
