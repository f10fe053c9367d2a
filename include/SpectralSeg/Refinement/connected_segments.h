// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file connected_segments.h
/// \brief Making every segment one connected region.
#ifndef SPECTRALSEG_REFINEMENT_CONNECTED_SEGMENTS_H
#define SPECTRALSEG_REFINEMENT_CONNECTED_SEGMENTS_H

#include <SpectralSeg/Dual_graph.h>

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
inline std::size_t make_segments_connected(const Dual_graph& graph, std::vector<int>& labels)
{
  const std::size_t n = graph.number_of_faces();
  const auto& areas = graph.geometry().areas;
  for(bool merged = true; merged;)
  {
    merged = false;
    // connected regions of equal labels
    std::vector<int> region(n, -1);
    std::vector<double> region_area;
    std::vector<int> region_label;
    std::vector<std::vector<Dual_graph::size_type>> region_faces;
    std::vector<Dual_graph::size_type> stack;
    for(std::size_t s = 0; s < n; ++s)
    {
      if(region[s] >= 0)
        continue;
      const int r = static_cast<int>(region_area.size());
      region_area.push_back(0.);
      region_label.push_back(labels[s]);
      region_faces.emplace_back();
      region[s] = r;
      stack.push_back(static_cast<Dual_graph::size_type>(s));
      while(!stack.empty())
      {
        const auto f = stack.back();
        stack.pop_back();
        region_area[std::size_t(r)] += areas[f];
        region_faces[std::size_t(r)].push_back(f);
        graph.for_each_neighbour(f, [&](Dual_graph::size_type g, Dual_graph::size_type) {
          if(region[g] < 0 && labels[g] == labels[f])
          {
            region[g] = r;
            stack.push_back(g);
          }
        });
      }
    }
    // the largest region of each label keeps it
    std::map<int, int> main_region;
    for(std::size_t r = 0; r < region_area.size(); ++r)
    {
      auto it = main_region.find(region_label[r]);
      if(it == main_region.end() || region_area[r] > region_area[std::size_t(it->second)])
        main_region[region_label[r]] = int(r);
    }
    // islands, smallest first; merge the smallest one that has a neighbour
    std::vector<int> islands;
    for(std::size_t r = 0; r < region_area.size(); ++r)
      if(main_region[region_label[r]] != int(r))
        islands.push_back(int(r));
    std::sort(islands.begin(), islands.end(), [&](int a, int b) {
      return region_area[std::size_t(a)] < region_area[std::size_t(b)] ||
             (region_area[std::size_t(a)] == region_area[std::size_t(b)] && a < b);
    });
    int fresh = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
    for(int isl : islands)
    {
      std::map<int, double> boundary; // neighbouring label -> shared edge length
      for(const Dual_graph::size_type f : region_faces[std::size_t(isl)])
        graph.for_each_neighbour(f, [&](Dual_graph::size_type g, Dual_graph::size_type e) {
          if(region[g] != isl)
            boundary[labels[g]] += graph.edge(e).length;
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
      for(const Dual_graph::size_type f : region_faces[std::size_t(isl)])
        labels[f] = target;
      if(isolated)
        continue; // nothing else sees it: no need to recompute the regions
      merged = true;
      break; // regions changed: recompute
    }
  }
  // renumber by smallest face
  std::map<int, int> renumber;
  for(int& l : labels)
  {
    auto it = renumber.emplace(l, int(renumber.size())).first;
    l = it->second;
  }
  return renumber.size();
}

} // namespace Refinement
} // namespace SpectralSeg

#endif
