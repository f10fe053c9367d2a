// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Part_hierarchy.h
/// \brief The binary hierarchy of parts built by the automatic segmentation.
#ifndef SPECTRALSEG_PART_HIERARCHY_H
#define SPECTRALSEG_PART_HIERARCHY_H

#include <SpectralSeg/Segmentability/segmentability.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegAutomatic
/// \brief One piece of the hierarchy: a root (a connected component of the
/// mesh), an inner node (a piece that was cut in two) or a leaf (a final
/// part).
struct Part_node
{
  /// value of `parent`, `children` and `cut_order` where there is none
  static constexpr std::size_t none = static_cast<std::size_t>(-1);
  /// the mesh faces of the piece, ascending
  std::vector<std::uint32_t> faces;
  /// its area
  double area = 0.;
  /// the node it was cut from (`none` for a root)
  std::size_t parent = none;
  /// the two pieces it was cut into (`none` for a leaf)
  std::array<std::size_t, 2> children{{none, none}};
  /// number of cuts between the root and this node
  std::size_t depth = 0;
  /// whether the segmentability test ran on this piece (small pieces and
  /// pieces left when the part budget ran out are not tested)
  bool tested = false;
  /// the test that passed (`Segmentability::Test::none` if none did)
  Segmentability::Test test = Segmentability::Test::none;
  /// score of the passing test, or the largest score of those run
  double score = 0.;
  /// the score of every test (NaN for those not run)
  std::array<double, 4> scores{{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                                std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()}};
  /// salience of the cut that split this node (inner nodes)
  double cut_salience = 0.;
  /// rank of that cut among all cuts, from 0 (inner nodes)
  std::size_t cut_order = none;
  /// the two sample faces of the cut (mesh faces; inner nodes)
  std::array<std::uint32_t, 2> samples{{0, 0}};
  /// whether this node is a final part
  bool is_leaf() const { return children[0] == none; }
};

/// \ingroup PkgSpectralSegAutomatic
/// \brief The cuts of an automatic segmentation as a forest of binary trees,
/// one tree per connected component of the mesh. Leaves are the parts.
///
/// Cuts are numbered in the order they were made (largest piece first), so
/// `labels_with_parts(k)` replays the first cuts only, and
/// `labels_at_depth(d)` stops each branch at depth `d`.
class Part_hierarchy
{
public:
  /// all nodes; roots first, in order of their smallest face
  std::vector<Part_node> nodes;
  /// the root of each connected component
  std::vector<std::size_t> roots;
  /// number of faces of the mesh
  std::size_t number_of_faces = 0;

  /// number of cuts made
  std::size_t number_of_cuts() const
  {
    std::size_t c = 0;
    for(const Part_node& n : nodes)
      c += n.is_leaf() ? 0 : 1;
    return c;
  }
  /// number of leaves (final parts)
  std::size_t number_of_parts() const { return roots.size() + number_of_cuts(); }

  /// One label per face: the leaves in which a node is kept decide. Leaves
  /// are numbered by their smallest face, from 0.
  std::vector<int> labels() const
  {
    return labels_where([](const Part_node&) { return true; });
  }

  /// The labels after the first `cuts` cuts only.
  std::vector<int> labels_after_cuts(std::size_t cuts) const
  {
    return labels_where([&](const Part_node& n) { return n.cut_order < cuts; });
  }

  /// The labels with `parts` parts (or as many as there are, if fewer;
  /// at least one per connected component): the first cuts, in order.
  std::vector<int> labels_with_parts(std::size_t parts) const
  {
    return labels_after_cuts(parts > roots.size() ? parts - roots.size() : 0);
  }

  /// The labels of the pieces at depth `depth` (a branch that ends earlier
  /// gives its leaf).
  std::vector<int> labels_at_depth(std::size_t depth) const
  {
    return labels_where([&](const Part_node& n) { return n.depth < depth; });
  }

private:
  // Descends from each root while `descend(node)` allows, labels each
  // reached piece, renumbers labels by smallest face.
  template <typename Descend>
  std::vector<int> labels_where(const Descend& descend) const
  {
    std::vector<int> labels(number_of_faces, -1);
    int next = 0;
    std::vector<std::size_t> stack(roots.rbegin(), roots.rend());
    while(!stack.empty())
    {
      const std::size_t i = stack.back();
      stack.pop_back();
      const Part_node& n = nodes[i];
      if(!n.is_leaf() && descend(n))
      {
        stack.push_back(n.children[1]);
        stack.push_back(n.children[0]);
        continue;
      }
      for(std::uint32_t f : n.faces)
        labels[f] = next;
      ++next;
    }
    // renumber by smallest face
    std::vector<int> map(static_cast<std::size_t>(next), -1);
    int count = 0;
    for(int& l : labels)
      if(l >= 0)
      {
        if(map[std::size_t(l)] < 0)
          map[std::size_t(l)] = count++;
        l = map[std::size_t(l)];
      }
    return labels;
  }
};

} // namespace SpectralSeg

#endif // SPECTRALSEG_PART_HIERARCHY_H
