// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file morphological_closing.h
/// \brief Smoothing the boundary of a two-way cut by morphological closing
/// on faces (thesis 6.4.3).
#ifndef SPECTRALSEG_REFINEMENT_MORPHOLOGICAL_CLOSING_H
#define SPECTRALSEG_REFINEMENT_MORPHOLOGICAL_CLOSING_H

#include <SpectralSeg/Mesh_piece.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace SpectralSeg {
namespace Refinement {

/// \cond SKIP_IN_MANUAL
namespace internal {

// Faces around each local vertex of a piece (compressed rows).
struct Vertex_faces
{
  explicit Vertex_faces(const Mesh_piece& piece)
  {
    const std::size_t nv = piece.number_of_vertices();
    offsets.assign(nv + 1, 0);
    for(const auto& t : piece.triangles())
      for(auto v : t)
        ++offsets[v + 1];
    for(std::size_t v = 0; v < nv; ++v)
      offsets[v + 1] += offsets[v];
    faces.resize(offsets.back());
    std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for(std::uint32_t f = 0; f < piece.triangles().size(); ++f)
      for(auto v : piece.triangles()[f])
        faces[fill[v]++] = f;
  }
  // calls fn(g) for every face g sharing a vertex with f (f itself included, maybe repeatedly)
  template <typename Fn>
  void for_each_vertex_neighbour(const Mesh_piece& piece, std::uint32_t f, const Fn& fn) const
  {
    for(auto v : piece.triangles()[f])
      for(std::uint32_t i = offsets[v]; i < offsets[v + 1]; ++i)
        fn(faces[i]);
  }
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> faces;
};

// Ring distance (through shared vertices) from the seed faces, up to `rings`;
// faces farther away keep `unreached`.
SPECTRALSEG_INLINE void ring_distances(const Mesh_piece& piece, const Vertex_faces& vf,
                                       const std::vector<std::uint32_t>& seeds, std::size_t rings,
                                       std::vector<std::uint32_t>& dist, std::vector<std::uint32_t>& touched)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::uint32_t unreached = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> frontier = seeds, next;
  for(std::uint32_t s : seeds)
    if(dist[s] == unreached)
    {
      dist[s] = 0;
      touched.push_back(s);
    }
  for(std::uint32_t d = 1; d <= rings && !frontier.empty(); ++d)
  {
    next.clear();
    for(std::uint32_t f : frontier)
      vf.for_each_vertex_neighbour(piece, f, [&](std::uint32_t g) {
        if(dist[g] == unreached)
        {
          dist[g] = d;
          touched.push_back(g);
          next.push_back(g);
        }
      });
    frontier.swap(next);
  }
}
#else
;
#endif

// Closing of the faces labelled `a` by a `rings`-ring structuring element;
// returns the faces of the other label that it moves into `a` (not applied).
SPECTRALSEG_INLINE std::vector<std::uint32_t> closing_swaps(const Mesh_piece& piece, const Vertex_faces& vf,
                                                            const std::vector<std::uint8_t>& side, std::uint8_t a,
                                                            std::size_t rings)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::uint32_t n = piece.number_of_faces();
  const std::uint32_t unreached = std::numeric_limits<std::uint32_t>::max();
  // boundary faces of side a: they touch the other side through a vertex
  std::vector<std::uint32_t> boundary;
  for(std::uint32_t f = 0; f < n; ++f)
    if(side[f] == a)
    {
      bool touches = false;
      vf.for_each_vertex_neighbour(piece, f, [&](std::uint32_t g) { touches = touches || side[g] != a; });
      if(touches)
        boundary.push_back(f);
    }
  std::vector<std::uint32_t> dist(n, unreached), touched;
  // dilation: other-side faces within `rings` rings of side a
  ring_distances(piece, vf, boundary, rings, dist, touched);
  std::vector<std::uint8_t> marked(n, 0);
  std::vector<std::uint32_t> candidates;
  for(std::uint32_t f : touched)
    if(side[f] != a)
    {
      marked[f] = 1;
      candidates.push_back(f);
    }
  for(std::uint32_t f : touched)
    dist[f] = unreached;
  touched.clear();
  // erosion: a marked face goes back if an unmarked face of the other side
  // lies within `rings` rings of it
  std::vector<std::uint32_t> outside;
  for(std::uint32_t f : candidates)
    vf.for_each_vertex_neighbour(piece, f, [&](std::uint32_t g) {
      if(side[g] != a && !marked[g] && dist[g] == unreached)
      {
        dist[g] = 0;
        outside.push_back(g);
      }
    });
  for(std::uint32_t g : outside)
    dist[g] = unreached;
  ring_distances(piece, vf, outside, rings, dist, touched);
  std::vector<std::uint32_t> kept;
  for(std::uint32_t f : candidates)
    if(dist[f] == unreached)
      kept.push_back(f);
  return kept;
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegRefinement
/// \brief One closing of a two-way cut, from the side that gains more.
///
/// Faces are neighbours when they share a vertex; the structuring element is
/// the `rings`-ring of a face. The closing of a side first adds every face
/// of the other side within `rings` rings of it (dilation), then gives back
/// each added face that has a face of the other side, not added, within
/// `rings` rings (erosion): notches and thin intrusions of the other side
/// along the boundary are filled. Both sides are tried, and the closing that
/// moves more faces is applied; a closing that would empty a side is not.
///
/// \param piece the piece
/// \param side one value per local face, 0 or 1
/// \param rings radius of the structuring element (at least 1)
/// \return the number of faces that changed side
/// \throws Invalid_input if `side` does not have one entry per face
SPECTRALSEG_INLINE std::size_t close_cut_boundary(const Mesh_piece& piece, std::vector<std::uint8_t>& side,
                                                  std::size_t rings)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(side.size() != piece.number_of_faces())
    throw Invalid_input("close_cut_boundary: one side per face expected");
  if(rings == 0)
    return 0;
  const internal::Vertex_faces vf(piece);
  std::size_t count[2] = {0, 0};
  for(std::uint8_t s : side)
    ++count[s ? 1 : 0];
  std::vector<std::uint32_t> best;
  std::uint8_t best_side = 0;
  for(std::uint8_t a = 0; a < 2; ++a)
  {
    std::vector<std::uint32_t> swaps = internal::closing_swaps(piece, vf, side, a, rings);
    if(swaps.size() >= count[1 - a]) // would empty the other side
      continue;
    if(swaps.size() > best.size())
    {
      best = std::move(swaps);
      best_side = a;
    }
  }
  for(std::uint32_t f : best)
    side[f] = best_side;
  return best.size();
}
#else
;
#endif

/// \ingroup PkgSpectralSegRefinement
/// \brief Makes each side of a two-way cut one connected region (through
/// shared edges). Every connected component of a side except the largest
/// (by area) of that side joins the other side, the smallest first: each
/// round flips, in increasing area, the components that touch no component
/// flipped in the same round, until each side is one region.
/// \return the number of faces that changed side
SPECTRALSEG_INLINE std::size_t make_cut_sides_connected(const Mesh_piece& piece, std::vector<std::uint8_t>& side)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::uint32_t n = piece.number_of_faces();
  if(side.size() != n)
    throw Invalid_input("make_cut_sides_connected: one side per face expected");
  const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::size_t moved = 0;
  std::vector<std::uint32_t> comp(n), stack;
  std::vector<std::vector<std::uint32_t>> members;
  std::vector<double> area;
  for(;;)
  {
    std::fill(comp.begin(), comp.end(), none);
    members.clear();
    area.clear();
    std::vector<std::uint8_t> comp_side;
    for(std::uint32_t s = 0; s < n; ++s)
    {
      if(comp[s] != none)
        continue;
      const std::uint32_t c = static_cast<std::uint32_t>(members.size());
      members.emplace_back();
      area.push_back(0.);
      comp_side.push_back(side[s]);
      comp[s] = c;
      stack.push_back(s);
      while(!stack.empty())
      {
        const std::uint32_t f = stack.back();
        stack.pop_back();
        members[c].push_back(f);
        area[c] += piece.face_area(f);
        const auto range = piece.neighbours(f);
        for(const Mesh_piece::Neighbour* nb = range.first; nb != range.second; ++nb)
          if(side[nb->face] == side[f] && comp[nb->face] == none)
          {
            comp[nb->face] = c;
            stack.push_back(nb->face);
          }
      }
    }
    // the largest component of each side stays
    std::uint32_t keep[2] = {none, none};
    for(std::uint32_t c = 0; c < members.size(); ++c)
    {
      std::uint32_t& k = keep[comp_side[c] ? 1 : 0];
      if(k == none || area[c] > area[k])
        k = c;
    }
    std::vector<std::uint32_t> others;
    for(std::uint32_t c = 0; c < members.size(); ++c)
      if(c != keep[0] && c != keep[1])
        others.push_back(c);
    if(others.empty())
      return moved;
    std::stable_sort(others.begin(), others.end(), [&](std::uint32_t a, std::uint32_t b) { return area[a] < area[b]; });
    std::vector<std::uint8_t> flipped(members.size(), 0);
    for(std::uint32_t c : others)
    {
      bool touches = false;
      for(std::uint32_t f : members[c])
      {
        const auto range = piece.neighbours(f);
        for(const Mesh_piece::Neighbour* nb = range.first; nb != range.second; ++nb)
          touches = touches || flipped[comp[nb->face]];
      }
      if(touches)
        continue;
      flipped[c] = 1;
      for(std::uint32_t f : members[c])
        side[f] = static_cast<std::uint8_t>(1 - side[f]);
      moved += members[c].size();
    }
  }
}
#else
;
#endif

/// \ingroup PkgSpectralSegRefinement
/// \brief The thesis's boundary enhancement of a salient cut: a closing with
/// a 3-ring element, then one with a 1-ring element (`close_cut_boundary()`,
/// each from the side that gains more), then each side made connected
/// (`make_cut_sides_connected()`).
/// \param piece the piece
/// \param side one value per local face, 0 or 1
/// \param rings the radii of the successive closings
/// \return the number of faces that changed side
SPECTRALSEG_INLINE std::size_t enhance_cut_boundary(const Mesh_piece& piece, std::vector<std::uint8_t>& side,
                                                    const std::vector<std::size_t>& rings = {3, 1})
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::size_t moved = 0;
  for(std::size_t r : rings)
    moved += close_cut_boundary(piece, side, r);
  return moved + make_cut_sides_connected(piece, side);
}
#else
;
#endif

} // namespace Refinement
} // namespace SpectralSeg

#endif // SPECTRALSEG_REFINEMENT_MORPHOLOGICAL_CLOSING_H
