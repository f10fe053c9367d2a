// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Part_hierarchy.h
/// \brief The binary hierarchy of parts behind an automatic segmentation:
/// the cuts of the salient-cut method, the merges of the merge methods.
#ifndef SPECTRALSEG_PART_HIERARCHY_H
#define SPECTRALSEG_PART_HIERARCHY_H

#include <SpectralSeg/Segmentability/Test.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegAutomatic
/// \brief One piece of the hierarchy: a root (a connected component of the
/// mesh), an inner node (a piece that was cut in two, or that two segments
/// merged into) or a leaf (a piece never cut: a final part of the
/// salient-cut method, a segment of the merge methods' over-segmentation).
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
  /// the test that passed (`Segmentability::Test::none` if none did: a
  /// leaf, or a component cut by `cut_unsegmentable_roots`)
  Segmentability::Test test = Segmentability::Test::none;
  /// score of the passing test, or the largest score of those run
  double score = 0.;
  /// the score of every test (NaN for those not run)
  std::array<double, 4> scores{{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                                std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()}};
  /// salience of the cut that split this node (inner nodes of the
  /// salient-cut method)
  double cut_salience = 0.;
  /// strength of the boundary between the two children when they were
  /// merged, in the merge method's own measure, the one its limit applies
  /// to (inner nodes of the merge methods): the boundary contrast for
  /// `Automatic_method::contrast_merge`, the mean concave dihedral angle in
  /// radians for `Automatic_method::concave_merge` and `segment_k_way()`
  double boundary_strength = 0.;
  /// rank of that cut among all cuts, from 0 (inner nodes; a merge
  /// hierarchy's last merge is its first cut)
  std::size_t cut_order = none;
  /// the two sample faces of the cut (mesh faces; inner nodes)
  std::array<std::uint32_t, 2> samples{{0, 0}};
  /// whether this node is a final part
  bool is_leaf() const { return children[0] == none; }
};

/// \ingroup PkgSpectralSegAutomatic
/// \brief The parts of an automatic segmentation and the steps that led to
/// them, as a forest of binary trees, one tree per connected component of
/// the mesh (or per group of touching segments).
///
/// The salient-cut method cuts pieces in two, largest first: its cuts are
/// numbered in the order they were made and its leaves are its parts. The
/// merge methods join segments of an over-segmentation, weakest boundary
/// first, and their hierarchy goes on merging past their answer, down to the
/// roots: a merge is a cut read backwards (the last merge is cut 0), the
/// leaves are the over-segmentation's segments, and the answer is the first
/// `chosen_cuts` cuts. So `labels_with_parts(k)` gives any number of parts
/// from one run, and `labels_at_depth(d)` stops each branch at depth `d`.
/// The pieces of a merge hierarchy are those before the graph cut that
/// smooths the answer's boundaries.
class Part_hierarchy
{
public:
  /// all nodes; roots first, in order of their smallest face
  std::vector<Part_node> nodes;
  /// the root of each connected component
  std::vector<std::size_t> roots;
  /// number of faces of the mesh
  std::size_t number_of_faces = 0;
  /// number of cuts of the method's answer (the first ones): every cut for
  /// the salient-cut method, fewer for the merge methods
  std::size_t chosen_cuts = 0;

  /// number of cuts made
  std::size_t number_of_cuts() const
  {
    std::size_t c = 0;
    for(const Part_node& n : nodes)
      c += n.is_leaf() ? 0 : 1;
    return c;
  }
  /// number of parts of the method's answer
  std::size_t number_of_parts() const { return roots.size() + std::min(chosen_cuts, number_of_cuts()); }
  /// number of leaves
  std::size_t number_of_leaves() const { return roots.size() + number_of_cuts(); }

  /// The answer's labels, one per face, `labels_after_cuts(chosen_cuts)`;
  /// parts are numbered by their smallest face, from 0.
  std::vector<int> labels() const { return labels_after_cuts(chosen_cuts); }

  /// The labels after the first `cuts` cuts only.
  std::vector<int> labels_after_cuts(std::size_t cuts) const
  {
    return labels_where([&](const Part_node& n) { return n.cut_order < cuts; });
  }

  /// The labels with `parts` parts (or as many as there are leaves, if
  /// fewer; at least one per root): the first cuts, in order.
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
    // (built forward and reversed: g++ 12 warns, wrongly, about freeing a
    // vector made from reverse iterators, -Wfree-nonheap-object)
    std::vector<std::size_t> stack(roots);
    std::reverse(stack.begin(), stack.end());
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

/// \cond SKIP_IN_MANUAL
namespace internal {

// The hierarchy of a sequence of merges: `labels` numbers the first
// segments densely from 0 in order of their first face, each step joins
// segment `absorbed` into `kept` (labels of the first segments) across a
// boundary of strength `strength`, and the first `answer` steps are the
// method's answer. `face_areas` has one area per face.
template <typename Step>
Part_hierarchy hierarchy_from_merges(const std::vector<int>& labels, const std::vector<double>& face_areas,
                                     const std::vector<Step>& steps, std::size_t answer)
{
  // every face list allocated at its size: on large meshes the lists of
  // all the nodes are the largest part of the hierarchy
  std::vector<std::size_t> count;
  for(int label : labels)
  {
    if(std::size_t(label) >= count.size())
      count.resize(std::size_t(label) + 1, 0);
    ++count[std::size_t(label)];
  }
  std::vector<Part_node> nodes(count.size());
  nodes.reserve(count.size() + steps.size());
  for(std::size_t l = 0; l < count.size(); ++l)
    nodes[l].faces.reserve(count[l]);
  for(std::size_t f = 0; f < labels.size(); ++f)
  {
    const std::size_t l = std::size_t(labels[f]);
    nodes[l].faces.push_back(std::uint32_t(f));
    nodes[l].area += face_areas[f];
  }
  std::vector<std::size_t> current(nodes.size());
  for(std::size_t i = 0; i < current.size(); ++i)
    current[i] = i;
  for(std::size_t i = 0; i < steps.size(); ++i)
  {
    std::size_t a = current[steps[i].kept], b = current[steps[i].absorbed];
    if(nodes[b].faces.front() < nodes[a].faces.front())
      std::swap(a, b);
    Part_node node;
    node.faces.reserve(nodes[a].faces.size() + nodes[b].faces.size());
    std::merge(nodes[a].faces.begin(), nodes[a].faces.end(), nodes[b].faces.begin(), nodes[b].faces.end(),
               std::back_inserter(node.faces));
    node.area = nodes[a].area + nodes[b].area;
    node.children = {{a, b}};
    node.boundary_strength = steps[i].strength;
    node.cut_order = steps.size() - 1 - i;
    nodes[a].parent = nodes[b].parent = nodes.size();
    current[steps[i].kept] = nodes.size();
    nodes.push_back(std::move(node));
  }
  // renumbered breadth first from the roots, roots in order of their
  // smallest face
  std::vector<std::size_t> order;
  for(std::size_t i = 0; i < nodes.size(); ++i)
    if(nodes[i].parent == Part_node::none)
      order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return nodes[x].faces.front() < nodes[y].faces.front(); });
  Part_hierarchy h;
  h.number_of_faces = labels.size();
  h.chosen_cuts = steps.size() - std::min(answer, steps.size());
  for(std::size_t r = 0; r < order.size(); ++r)
    h.roots.push_back(r);
  for(std::size_t next = 0; next < order.size(); ++next)
    for(std::size_t c : nodes[order[next]].children)
      if(c != Part_node::none)
        order.push_back(c);
  std::vector<std::size_t> index(nodes.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    index[order[i]] = i;
  h.nodes.resize(nodes.size());
  for(std::size_t i = 0; i < order.size(); ++i)
  {
    Part_node& n = h.nodes[i];
    n = std::move(nodes[order[i]]);
    if(n.parent != Part_node::none)
    {
      n.parent = index[n.parent];
      n.depth = h.nodes[n.parent].depth + 1; // parents come first
    }
    for(std::size_t& c : n.children)
      if(c != Part_node::none)
        c = index[c];
  }
  return h;
}

} // namespace internal
/// \endcond

} // namespace SpectralSeg

#endif // SPECTRALSEG_PART_HIERARCHY_H
