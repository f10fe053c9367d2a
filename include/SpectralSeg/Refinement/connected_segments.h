// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file connected_segments.h
/// \brief Making every segment one connected region.
#ifndef SPECTRALSEG_REFINEMENT_CONNECTED_SEGMENTS_H
#define SPECTRALSEG_REFINEMENT_CONNECTED_SEGMENTS_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <algorithm>
#include <map>
#include <vector>

namespace SpectralSeg {
namespace Refinement {

/// \ingroup PkgSpectralSegRefinement
/// \brief Makes every segment one connected region of the dual graph and
/// numbers the segments `0 .. count-1` by their smallest face; returns `count`.
///
/// Each label's connected regions are found; the one with the largest area
/// keeps the label, and every other region (an *island*) is merged into the
/// neighbouring segment with which it shares the longest boundary, smallest
/// islands first, until no island is left. A region with no neighbour (a
/// whole connected component of the mesh) becomes a segment of its own, so
/// a mesh with several components gets at least one segment per component.
///
/// The regions are found once; after each merge only the merged region is
/// flooded again (from its smallest face, in the order a flood of the whole
/// mesh would visit it, so that its area is summed in the same order), not
/// the whole mesh: the answer is that of finding every region again after
/// each merge, in time proportional to the merged regions.
SPECTRALSEG_INLINE std::size_t make_segments_connected(const Dual_graph& graph, std::vector<int>& labels)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  typedef Dual_graph::size_type Face;
  const std::size_t n = graph.number_of_faces();
  const auto& areas = graph.geometry().areas;
  // Regions are numbered by their smallest face, as a flood of the whole
  // mesh in face order numbers them; a merged region takes the smallest
  // number of its parts, which keeps that order.
  std::vector<int> region(n, -1);
  std::vector<Face> region_seed;
  std::vector<double> region_area;
  std::vector<int> region_label;
  std::vector<char> alive;
  // the faces of the region of `seed`, in the order of the flood of the
  // whole mesh (depth first, from its smallest face), marked as region `r`;
  // returns its area summed in that order
  std::vector<Face> faces, stack;
  std::vector<std::size_t> visit(n, 0);
  std::size_t floods = 0;
  const auto flood = [&](Face seed, int r) {
    ++floods;
    faces.clear();
    double area = 0.;
    visit[seed] = floods;
    region[seed] = r;
    stack.push_back(seed);
    while(!stack.empty())
    {
      const Face f = stack.back();
      stack.pop_back();
      area += areas[f];
      faces.push_back(f);
      graph.for_each_neighbour(f, [&](Face g, Face) {
        if(visit[g] != floods && labels[g] == labels[f])
        {
          visit[g] = floods;
          region[g] = r;
          stack.push_back(g);
        }
      });
    }
    return area;
  };
  for(std::size_t s = 0; s < n; ++s)
    if(region[s] < 0)
    {
      const int r = static_cast<int>(region_seed.size());
      region_seed.push_back(static_cast<Face>(s));
      region_label.push_back(labels[s]);
      alive.push_back(1);
      region_area.push_back(flood(static_cast<Face>(s), r));
    }
  int fresh = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
  std::vector<int> islands, touching;
  for(bool merged = true; merged;)
  {
    merged = false;
    // the largest region of each label keeps it (the first on ties)
    std::map<int, int> main_region;
    for(std::size_t r = 0; r < region_area.size(); ++r)
    {
      if(!alive[r])
        continue;
      auto it = main_region.find(region_label[r]);
      if(it == main_region.end() || region_area[r] > region_area[std::size_t(it->second)])
        main_region[region_label[r]] = int(r);
    }
    // islands, smallest first; merge the smallest one that has a neighbour
    islands.clear();
    for(std::size_t r = 0; r < region_area.size(); ++r)
      if(alive[r] && main_region[region_label[r]] != int(r))
        islands.push_back(int(r));
    std::sort(islands.begin(), islands.end(), [&](int a, int b) {
      return region_area[std::size_t(a)] < region_area[std::size_t(b)] ||
             (region_area[std::size_t(a)] == region_area[std::size_t(b)] && a < b);
    });
    for(int isl : islands)
    {
      flood(region_seed[std::size_t(isl)], isl); // its faces in flood order
      std::map<int, double> boundary; // neighbouring label -> shared edge length
      touching.clear();
      for(const Face f : faces)
        graph.for_each_neighbour(f, [&](Face g, Face e) {
          if(region[g] != isl)
          {
            boundary[labels[g]] += graph.edge(e).length;
            touching.push_back(region[g]);
          }
        });
      int target = fresh;
      double longest = -1.;
      for(const auto& b : boundary)
        if(b.second > longest)
        {
          longest = b.second;
          target = b.first;
        }
      const bool isolated = target == fresh;
      if(isolated)
        ++fresh; // an isolated component: its own segment
      for(const Face f : faces)
        labels[f] = target;
      region_label[std::size_t(isl)] = target;
      if(isolated)
        continue; // nothing else sees it: no need to recompute the regions
      // the island and the regions of the target label it touches are one
      // region now, numbered and flooded from the smallest of them
      int first = isl;
      for(const int r : touching)
        if(region_label[std::size_t(r)] == target)
          first = std::min(first, r);
      for(const int r : touching)
        if(region_label[std::size_t(r)] == target)
          alive[std::size_t(r)] = 0;
      alive[std::size_t(isl)] = 0;
      alive[std::size_t(first)] = 1;
      region_area[std::size_t(first)] = flood(region_seed[std::size_t(first)], first);
      merged = true;
      break; // regions changed: recompute the main regions and islands
    }
  }
  // renumber by smallest face
  std::map<int, int> renumber;
  for(int& l : labels)
  {
    auto it = renumber.try_emplace(l, int(renumber.size())).first;
    l = it->second;
  }
  return renumber.size();
}
#else
;
#endif

} // namespace Refinement
} // namespace SpectralSeg

#endif
