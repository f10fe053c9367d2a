// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file merge_segments.h
/// \brief Merging the adjacent segments with the weakest boundary.
#ifndef SPECTRALSEG_REFINEMENT_MERGE_SEGMENTS_H
#define SPECTRALSEG_REFINEMENT_MERGE_SEGMENTS_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Refinement {

/// \ingroup PkgSpectralSegRefinement
/// \brief The embedding-separation factor of `merge_weakest_boundaries()`
/// (our addition): how far apart two segments lie in the spectral embedding,
/// against their spread.
///
/// For segments \f$a\f$ and \f$b\f$ with area-weighted mean embedding
/// coordinates \f$\mu_a, \mu_b\f$ and mean squared distances to them
/// \f$\sigma_a^2, \sigma_b^2\f$, the separation is \f$r = |\mu_a -
/// \mu_b|^2 / (\sigma_a^2 + \sigma_b^2)\f$ and the boundary strength is
/// multiplied by \f$\min(1, r / \mathrm{scale})^{\mathrm{exponent}}\f$.
/// Two pieces of one round body that K-means cut apart overlap in the
/// embedding (\f$r\f$ about 1), a limb and the body do not (\f$r\f$ of 2 to
/// 10): on a bumpy surface, where a seam across the body can be as concave
/// as a limb's junction, the body pieces are merged first.
struct Embedding_separation
{
  /// one row of embedding coordinates per face (`K_way_result::embedding`);
  /// null: no factor
  const Eigen::MatrixXd* coordinates = nullptr;
  /// separations of at least this much leave the strength as it is
  double scale = 2.;
  /// the power of the factor; 0: no factor
  double exponent = 1.;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// What a merge knows of the boundary between two segments: its length and
// the length-weighted sums of the concave dihedral angle and of a per-edge
// weight along it.
struct Segment_boundary
{
  double length = 0., concave = 0., weight = 0.;
};

// The area-weighted sums of one segment's embedding coordinates and of their
// squared norms, for Embedding_separation.
struct Segment_moments
{
  Eigen::RowVectorXd sum;
  double squares = 0., area = 0.;

  void add(const Segment_moments& o)
  {
    sum += o.sum;
    squares += o.squares;
    area += o.area;
  }
};

// |mu_a - mu_b|^2 / (sigma_a^2 + sigma_b^2) (see Embedding_separation);
// infinite when both spreads are 0 and the means differ.
SPECTRALSEG_INLINE double embedding_separation(const Segment_moments& a, const Segment_moments& b)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(!(a.area > 0.) || !(b.area > 0.))
    return std::numeric_limits<double>::infinity();
  const Eigen::RowVectorXd ma = a.sum / a.area, mb = b.sum / b.area;
  const double spread =
    std::max(0., a.squares / a.area - ma.squaredNorm()) + std::max(0., b.squares / b.area - mb.squaredNorm());
  const double gap = (ma - mb).squaredNorm();
  return gap > 0. ? (spread > 0. ? gap / spread : std::numeric_limits<double>::infinity()) : 0.;
}
#else
;
#endif

// What a merge order says of one pair of adjacent segments: `order`
// ranks the pairs (the lowest is merged first) and `strength` is what the
// limit applies to.
struct Merge_cost
{
  double order = 0., strength = 0.;
};

// One merge: segment `absorbed` joined `kept` (both labels of the segments
// before the first merge, dense from 0 in order of first face), across a
// boundary of `strength`.
struct Merge_step
{
  std::size_t kept = 0, absorbed = 0;
  double strength = 0.;
};

// Every merge of merge_cheapest_boundaries(), those of its answer first
// (`answer` of them), then those that go on to one segment per connected
// set of touching segments; `labels` are the segments before the first.
struct Merge_history
{
  std::vector<int> labels;
  std::vector<Merge_step> steps;
  std::size_t answer = 0;
};

// Merges adjacent segments, cheapest boundary first: segments under
// `min_area_fraction` of the area first (smallest first, whatever their
// boundary), then the pair with the lowest `cost(boundary, smaller,
// separation, outer, thicker).order` among those whose `.strength` is below `limit`,
// where `smaller` is the area of the pair's smaller segment over the mesh's
// area, `separation` the pair's embedding_separation() in `coordinates` (one
// row per face; infinite when `coordinates` is null) and `outer` the length
// of the boundary of the two segments together with the others, while more than
// `min_segments` are left. `weights` may be empty (then
// Segment_boundary::weight is 0). Ties go to the pair with the smallest
// labels. Labels are renumbered 0 .. count-1 by their smallest face;
// returns the number of segments. With `history`, the merges go on past the
// answer, in the same order without the limit and the count, down to one
// segment per connected set, and every merge is recorded there.
// Segment_boundary::concave sums `concave_angles` (one per dual edge) when
// given, else each edge's concave dihedral angle (concave_angle_weights()).
// A boundary whose mean concave angle is below `flat_angle` (radians; 0:
// none) is a flat seam: with no fold along it, it says nothing of a part
// boundary, so flat seams go after the small segments and before every
// other boundary, whatever their cost and the limit, and among them the
// one whose smaller segment is largest goes first (a seam kept wrongly
// between two large pieces splits the most pairs of faces).
// `thicker` (the last argument) is the ratio of the pair's area-weighted mean
// thicknesses, the thicker over the thinner, from `face_thickness` (one
// value per face, NaN where unknown, left out); 1 without it.
template <typename Cost>
std::size_t merge_cheapest_boundaries(const Dual_graph& graph, const std::vector<double>& weights,
                                      std::vector<int>& labels, std::size_t min_segments, double min_area_fraction,
                                      double limit, const Cost& cost, const Eigen::MatrixXd* coordinates = nullptr,
                                      Merge_history* history = nullptr,
                                      const std::vector<double>* concave_angles = nullptr, double flat_angle = 0.,
                                      const std::vector<double>* face_thickness = nullptr)
{
  const std::size_t n = graph.number_of_faces();
  // dense labels 0 .. s-1 in order of first face
  std::map<int, int> dense;
  for(int& l : labels)
    l = dense.try_emplace(l, int(dense.size())).first->second;
  const std::size_t s = dense.size();
  if(history)
  {
    history->labels = labels;
    history->steps.clear();
    history->answer = 0;
  }
  // per segment: neighbour -> boundary; sparse, since a mesh with many
  // components has many segments
  std::vector<std::map<std::size_t, Segment_boundary>> boundary(s);
  for(std::size_t d = 0; d < graph.number_of_edges(); ++d)
  {
    const Dual_graph::Edge& e = graph.edge(static_cast<Dual_graph::size_type>(d));
    const std::size_t a = std::size_t(labels[e.face[0]]), b = std::size_t(labels[e.face[1]]);
    if(a == b)
      continue;
    for(Segment_boundary* x : {&boundary[a][b], &boundary[b][a]})
    {
      x->length += e.length;
      x->concave += concave_angles ? e.length * (*concave_angles)[d] : e.concave ? e.length * e.normal_angle : 0.;
      x->weight += weights.empty() ? 0. : e.length * weights[d];
    }
  }
  std::vector<std::size_t> target(s); // what each dense label became
  for(std::size_t i = 0; i < s; ++i)
    target[i] = i;
  // each segment's boundary length with the others
  std::vector<double> perimeter(s, 0.);
  for(std::size_t a = 0; a < s; ++a)
    for(const auto& nb : boundary[a])
      perimeter[a] += nb.second.length;
  std::vector<double> area(s, 0.);
  double total_area = 0.;
  for(std::size_t f = 0; f < n; ++f)
  {
    area[std::size_t(labels[f])] += graph.geometry().areas[f];
    total_area += graph.geometry().areas[f];
  }
  const double small = min_area_fraction * total_area;
  std::vector<Segment_moments> moments(coordinates ? s : 0);
  if(coordinates)
  {
    const Eigen::Index dims = coordinates->cols();
    for(Segment_moments& m : moments)
      m.sum = Eigen::RowVectorXd::Zero(dims);
    const std::vector<double>& areas = graph.geometry().areas;
    // column after column, as the coordinates are stored; every sum still
    // in face order (thread-independent), each face's squared norm summed
    // over its coordinates in order
    std::vector<double> norm(n, 0.);
    for(Eigen::Index j = 0; j < dims; ++j)
    {
      const double* column = coordinates->col(j).data();
      for(std::size_t f = 0; f < n; ++f)
      {
        moments[std::size_t(labels[f])].sum[j] += areas[f] * column[f];
        norm[f] = j == 0 ? column[f] * column[f] : norm[f] + column[f] * column[f];
      }
    }
    for(std::size_t f = 0; f < n; ++f)
    {
      Segment_moments& m = moments[std::size_t(labels[f])];
      m.squares += areas[f] * norm[f];
      m.area += areas[f];
    }
  }
  // each segment's area-weighted sum of thickness and the area it covers
  const bool thick = face_thickness && face_thickness->size() == n;
  std::vector<double> thickness(thick ? s : 0, 0.), thickness_area(thick ? s : 0, 0.);
  if(thick)
    for(std::size_t f = 0; f < n; ++f)
      if(!std::isnan((*face_thickness)[f]))
      {
        thickness[std::size_t(labels[f])] += graph.geometry().areas[f] * (*face_thickness)[f];
        thickness_area[std::size_t(labels[f])] += graph.geometry().areas[f];
      }
  std::vector<std::size_t> answer; // `target` where the answer ends
  bool past = false;               // past the answer: no limit, no count
  for(std::size_t count = s; count > 1; --count)
  {
    if(!past && count <= min_segments)
    {
      if(!history)
        break;
      answer = target;
      past = true;
    }
    // the order of a pair: (0, small segments by area), (1, flat seams,
    // largest first), (2, the others by cost); lowest first
    int cheapest_rank = 3;
    double cheapest = std::numeric_limits<double>::infinity(), strength = 0.;
    std::size_t wa = s, wb = s;
    for(std::size_t a = 0; a < s; ++a)
      for(const auto& nb : boundary[a]) // merged segments have no neighbours left
      {
        const std::size_t b = nb.first;
        if(b < a || nb.second.length <= 0.)
          continue;
        const double smaller = std::min(area[a], area[b]);
        double ratio = 1.;
        if(thick && thickness[a] > 0. && thickness[b] > 0.)
        {
          const double ta = thickness[a] / thickness_area[a], tb = thickness[b] / thickness_area[b];
          ratio = std::max(ta, tb) / std::min(ta, tb);
        }
        const Merge_cost c = cost(nb.second, smaller / total_area,
                                  coordinates ? embedding_separation(moments[a], moments[b])
                                              : std::numeric_limits<double>::infinity(),
                                  std::max(0., perimeter[a] + perimeter[b] - 2. * nb.second.length), ratio);
        int rank = 2;
        double order = c.order;
        if(smaller < small)
        {
          rank = 0;
          order = smaller;
        }
        else if(nb.second.concave < flat_angle * nb.second.length)
        {
          rank = 1;
          order = -smaller;
        }
        else if((!past && !(c.strength < limit)) || std::isnan(order))
          continue; // too strong to merge
        if(rank < cheapest_rank || (rank == cheapest_rank && order < cheapest)) // strict: ties go to the smallest labels
        {
          cheapest_rank = rank;
          cheapest = order;
          strength = c.strength;
          wa = a;
          wb = b;
        }
      }
    if(wa == s && !past && history)
    {
      // every boundary is too strong: the answer ends here
      answer = target;
      past = true;
      ++count;
      continue;
    }
    if(wa == s)
      break; // no two segments touch, or every boundary is too strong
    if(history)
    {
      history->steps.push_back({wa, wb, strength});
      if(!past)
        ++history->answer;
    }
    // b joins a: b's boundaries become a's
    boundary[wa].erase(wb);
    for(const auto& nb : boundary[wb])
    {
      if(nb.first == wa)
        continue;
      Segment_boundary& x = boundary[wa][nb.first];
      x.length += nb.second.length;
      x.concave += nb.second.concave;
      x.weight += nb.second.weight;
      boundary[nb.first].erase(wb);
      boundary[nb.first][wa] = x;
    }
    perimeter[wa] = std::max(0., perimeter[wa] + perimeter[wb] - 2. * boundary[wb][wa].length);
    boundary[wb].clear();
    area[wa] += area[wb];
    if(thick)
    {
      thickness[wa] += thickness[wb];
      thickness_area[wa] += thickness_area[wb];
    }
    if(coordinates)
      moments[wa].add(moments[wb]);
    for(std::size_t& t : target)
      if(t == wb)
        t = wa;
  }
  if(past)
    target = std::move(answer);
  std::map<int, int> renumber;
  for(int& l : labels)
    l = renumber.try_emplace(int(target[std::size_t(l)]), int(renumber.size())).first->second;
  return renumber.size();
}

// merge_weakest_boundaries() without its checks, recording its merges in
// `history` (see merge_cheapest_boundaries()).
SPECTRALSEG_INLINE std::size_t merge_weakest(const Dual_graph& graph, const std::vector<double>& weights,
                                             std::vector<int>& labels, std::size_t k, double strength_limit,
                                             double min_area_fraction, double size_exponent,
                                             const Embedding_separation& separation, Merge_history* history = nullptr,
                                             double flat_angle = 0.)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const bool separate = separation.coordinates && separation.exponent > 0. && separation.coordinates->cols() > 0;
  return merge_cheapest_boundaries(
    graph, weights, labels, k, min_area_fraction, strength_limit,
    [size_exponent, &separation](const Segment_boundary& b, double smaller, double r, double, double) {
      const double mean = b.weight / b.length;
      double c = size_exponent > 0. ? mean * std::pow(smaller, size_exponent) : mean;
      if(r < separation.scale) // r is infinite without coordinates
        c *= std::pow(r / separation.scale, separation.exponent);
      return Merge_cost{c, mean};
    },
    separate ? separation.coordinates : nullptr, history, nullptr, flat_angle);
}
#else
;
#endif

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegRefinement
/// \brief Merges adjacent segments, weakest boundary first, until at most
/// `k` segments are left; returns the number of segments.
///
/// The strength of the boundary between two adjacent segments is the mean of
/// the dual-edge weights `weights` along it, each edge counted with the
/// length of its mesh edge. With `concave_angle_weights()` (what
/// `segment_k_way()` uses) a cut through a smooth stretch of surface is weak
/// and the concave junction of a limb is strong, so repeatedly joining the
/// two segments across the weakest boundary undoes the splits that K-means
/// makes in large bodies. Any other per-edge weight can serve as the
/// boundary strength (doc/benchmarks.md compares some). With a positive
/// `size_exponent` the strength is multiplied by \f$a^e\f$, \f$a\f$ the
/// area of the pair's smaller segment over the mesh's area and \f$e\f$ the
/// exponent: of two boundaries about as strong, the one around the smaller
/// part goes first, since giving up a small part changes less of the
/// surface than joining two large ones. With `separation.coordinates` the
/// strength is also multiplied by the embedding-separation factor
/// (`Embedding_separation`), so that pieces of one body go before parts.
/// Ties go to the pair with the smallest
/// labels, so the result is deterministic. Segments with no neighbour (whole
/// connected components) are never merged, so more than `k` may remain.
/// Labels are renumbered `0 .. count-1` by their smallest face.
///
/// \param graph the dual graph
/// \param weights one weight per dual edge (indexed like `Dual_graph::edges()`)
/// \param labels one label per face, in and out
/// \param k the number of segments wanted
/// \param strength_limit merging also stops once the weakest boundary has
///        at least this strength
/// \param min_area_fraction segments with less than this fraction of the
///        total area are merged first, smallest first, whatever their
///        boundary (thin flaps such as ears have sharp creases but are
///        rarely parts), even across a boundary above `strength_limit`
/// \param size_exponent the exponent \f$e \ge 0\f$ of the area factor
///        (0: the strength alone; `segment_k_way()` uses
///        `K_way_options::merge_size_exponent`); `strength_limit` applies to
///        the strength before the factor
/// \param separation the embedding-separation factor (default: none;
///        `segment_k_way()` uses `K_way_options::merge_separation_scale`);
///        `strength_limit` applies to the strength before the factor
/// \throws Invalid_input if the sizes do not match the graph,
///         `size_exponent` or `separation.exponent` is negative or not a
///         number, or `separation.scale` is not positive
SPECTRALSEG_INLINE std::size_t merge_weakest_boundaries(const Dual_graph& graph, const std::vector<double>& weights,
                                                        std::vector<int>& labels, std::size_t k,
                                                        double strength_limit = std::numeric_limits<double>::infinity(),
                                                        double min_area_fraction = 0., double size_exponent = 0.,
                                                        const Embedding_separation& separation = Embedding_separation())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  if(labels.size() != graph.number_of_faces() || weights.size() != graph.number_of_edges())
    throw Invalid_input("merge_weakest_boundaries: expected " + std::to_string(graph.number_of_faces()) +
                        " labels and " + std::to_string(graph.number_of_edges()) + " weights");
  if(!(size_exponent >= 0.))
    throw Invalid_input("merge_weakest_boundaries: the size exponent must be a number of at least 0");
  if(separation.coordinates &&
     separation.coordinates->rows() != static_cast<Eigen::Index>(graph.number_of_faces()))
    throw Invalid_input("merge_weakest_boundaries: expected " + std::to_string(graph.number_of_faces()) +
                        " rows of embedding coordinates, got " + std::to_string(separation.coordinates->rows()));
  if(separation.coordinates && !(separation.exponent >= 0. && separation.scale > 0.))
    throw Invalid_input(
      "merge_weakest_boundaries: the separation scale must be positive and its exponent a number of at least 0");
  return internal::merge_weakest(graph, weights, labels, k, strength_limit, min_area_fraction, size_exponent,
                                separation);
}
#else
;
#endif

/// \ingroup PkgSpectralSegRefinement
/// \brief A boundary-strength weight per dual edge for
/// `merge_weakest_boundaries()`: the angle between the two face normals
/// where the fold is concave, 0 where it is flat or convex.
///
/// Parts meet along concave creases (the minima rule); a seam through a
/// smooth or convex stretch of surface has a mean of about 0.
SPECTRALSEG_INLINE std::vector<double> concave_angle_weights(const Dual_graph& graph)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<double> w(graph.number_of_edges());
  for(std::size_t d = 0; d < w.size(); ++d)
  {
    const Dual_graph::Edge& e = graph.edge(static_cast<Dual_graph::size_type>(d));
    w[d] = e.concave ? e.normal_angle : 0.;
  }
  return w;
}
#else
;
#endif

/// \ingroup PkgSpectralSegRefinement
/// \brief `concave_angle_weights()` as they would be measured on the same
/// surface tessellated with at most `reference_faces` faces (our addition).
///
/// On a finer mesh a smooth fold turns by smaller angles across each of its
/// shorter edges, while a sharp crease keeps its angle: ratios of concave
/// angles (such as the concave contrast of `segment_hybrid()`) then depend on
/// the resolution. Here, on a mesh of \f$F\f$ faces with \f$F\f$ above
/// `reference_faces`, each face's area-weighted normal is first averaged
/// with its neighbours' \f$s = \mathrm{round}((F / F_{ref} - 1) / 0.75)\f$
/// times (each step: the face and its up to three neighbours, equally), so
/// that the average spreads over about the face spacing of a mesh of
/// \f$F_{ref}\f$ faces; the fold of each dual edge (concave or not, and
/// its angle) is then judged with the averaged normals. A mesh with at most
/// `reference_faces` faces, or `reference_faces` 0, gets
/// `concave_angle_weights()` exactly. The averaging stays within connected
/// components, does not depend on the face order beyond the rounding of
/// sums, and costs \f$s\f$ passes over the faces, each on `threads` threads
/// (0: all hardware threads); the result does not depend on their number.
SPECTRALSEG_INLINE std::vector<double> concave_angle_weights(const Dual_graph& graph, std::size_t reference_faces,
                                                         unsigned threads = 1)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = graph.number_of_faces();
  if(reference_faces == 0 || n <= reference_faces)
    return concave_angle_weights(graph);
  const std::size_t steps =
    static_cast<std::size_t>(std::lround((double(n) / double(reference_faces) - 1.) / 0.75));
  if(steps == 0)
    return concave_angle_weights(graph);
  const Mesh_geometry& geo = graph.geometry();
  std::vector<Eigen::Vector3d> normal(n), next(n);
  for(std::size_t f = 0; f < n; ++f)
    normal[f] = geo.areas[f] * geo.normals[f];
  const unsigned workers = Execution(threads).threads();
  for(std::size_t step = 0; step < steps; ++step)
  {
    // each face's sum in the same order on any thread
    ::SpectralSeg::internal::parallel_range(0, n, workers, [&](std::size_t f) {
      Eigen::Vector3d sum = normal[f];
      graph.for_each_neighbour(static_cast<Dual_graph::size_type>(f),
                               [&](Dual_graph::size_type g, Dual_graph::size_type) { sum += normal[g]; });
      next[f] = 0.25 * sum;
    });
    normal.swap(next);
  }
  std::vector<double> w(graph.number_of_edges(), 0.);
  ::SpectralSeg::internal::parallel_range(0, w.size(), workers, [&](std::size_t d) {
    const Dual_graph::Edge& e = graph.edge(static_cast<Dual_graph::size_type>(d));
    // judged as Dual_graph judges the faces' own normals (a zero average
    // stays undefined: no fold)
    const ::SpectralSeg::internal::Fold fold = ::SpectralSeg::internal::fold_between(
      normal[e.face[0]].normalized(), normal[e.face[1]].normalized(), geo.centroids[e.face[0]], geo.centroids[e.face[1]]);
    if(fold.concave)
      w[d] = fold.angle;
  });
  return w;
}
#else
;
#endif

} // namespace Refinement
} // namespace SpectralSeg

#endif
