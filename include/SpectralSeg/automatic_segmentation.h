// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file automatic_segmentation.h
/// \brief Segmentation into as many parts as the shape has, by recursive
/// salient cuts of the pieces that pass the segmentability test (thesis ch. 6).
#ifndef SPECTRALSEG_AUTOMATIC_SEGMENTATION_H
#define SPECTRALSEG_AUTOMATIC_SEGMENTATION_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Mesh_piece.h>
#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Blend.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Part_hierarchy.h>
#include <SpectralSeg/Refinement/morphological_closing.h>
#include <SpectralSeg/Salience/Weighted_salience.h>
#include <SpectralSeg/Salient_cut/face_sequence.h>
#include <SpectralSeg/Salient_cut/salient_cut_search.h>
#include <SpectralSeg/Segmentability/segmentability.h>
#include <SpectralSeg/internal/Stage_timer.h>
#include <SpectralSeg/k_way_segmentation.h>
#include <SpectralSeg/named_parameters.h>
#include <SpectralSeg/segment_hybrid.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <boost/math/constants/constants.hpp>

#include <future>
#include <limits>
#include <memory>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegAutomatic
/// \brief Parameters of `segment_automatically()`. The defaults are our
/// improved top-down method; `thesis()` is the thesis's method as published.
///
/// Where the defaults depart from the thesis (figures in doc/benchmarks.md,
/// \ref ss_quality_salient): the salience `Salience::improved_salience()`
/// (size saturating at 10% of the piece, protrusion against the area the
/// cut encloses), so that half of a symmetric body no longer outscores a
/// limb; M's concave weights floored at \f$\epsilon\f$ and the M
/// projection whitened before its contour is drawn
/// (`Segmentability::Projection_options`), so that noisy flat faces do not
/// squeeze it into a needle; below the first cut of each connected
/// component, no cut less salient than 0.5 (`min_cut_salience`), which
/// stops the M test's cuts across a torso; the pieces of a piece that
/// passed an L test pass with an L score above \f$\eta / 2\f$
/// (`continuation_threshold`), so that a body keeps losing its limbs; only
/// cuts along a crease four times as concave as their piece's mean
/// (`min_cut_contrast`), chosen among the sequences of three sample pairs
/// (`sample_pairs`), so that smooth tubes and creased surfaces are not
/// sliced; on a piece with a handle (`Mesh_piece::genus()`), the holes of
/// its projection count in its convexity (`Segmentability::Contour_options::
/// count_holes`), so that a vase's handles are cut off; no part under 2% of
/// its component; below the roots, no test of a patch with less area than
/// the flat disc its longest cut loop bounds (`min_area_over_loop_disc`), so
/// that a surface creased everywhere (curls of hair) is not diced along the
/// outlines of earlier cuts; at most 64 parts.
/// \tparam SalienceModel a model of `Salience`
template <typename SalienceModel = Salience::Thesis_salience>
struct Automatic_segmentation_options
{
  /// \f$\eta\f$, structure-only mode, contour and eigensolver parameters (thesis 6.2)
  Segmentability::Segmentability_options segmentability = improved_segmentability();
  /// how cuts along the face sequence are scored (thesis 6.4)
  SalienceModel salience = Salience::improved_salience();
  /// radii of the successive morphological closings of each cut (thesis
  /// 6.4.3: 3-ring, then 1-ring); empty to keep the raw cut
  std::vector<std::size_t> closing_rings{3, 1};
  /// no more cuts once there are this many parts (0: no limit). Our
  /// addition, a guard against runaway recursion on very bumpy meshes.
  std::size_t max_parts = 64;
  /// pieces with fewer faces are final parts without a test (our addition:
  /// a few faces make no meaningful contour)
  std::size_t min_piece_faces = 30;
  /// no part smaller than this fraction of its connected component's area:
  /// smaller pieces are not tested and cuts that would leave a smaller side
  /// are not considered (our addition; 0, the thesis's behaviour, lets
  /// small pieces be diced into slivers)
  double min_part_area_fraction = 0.02;
  /// a piece whose best cut has a lower salience is a final part (our
  /// addition; 0: every segmentable piece is cut, as in the thesis). The
  /// default 0.5 is the middle of the salience's range: the M test passes
  /// pieces of a torso, whose best cuts run across flat faces and score
  /// 0.3 to 0.45, while a limb's cut scores 0.6 to 0.7.
  double min_cut_salience = 0.5;
  /// whether `min_cut_salience` applies to the first cut of a connected
  /// component too (`false`, the default: the segmentability test alone
  /// decides whether a whole component is cut, as in the thesis, and the
  /// floor only stops the recursion inside it; a fish or a vase whose only
  /// parts meet the body without a crease is then still cut once)
  bool min_cut_salience_at_roots = false;
  /// whether a connected component that fails the segmentability test is
  /// still cut once when its best cut is at least `min_cut_salience` salient
  /// (our addition; `false` in the thesis, where such a component is one
  /// part). No contour of many cups, vases and machine parts passes at the
  /// root; the salience floor then decides, as it does below the first cut.
  /// Below the roots the test alone decides (the same rule there dices
  /// tables and chairs, doc/benchmarks.md).
  bool cut_unsegmentable_roots = true;
  /// below a piece that passed an L test (L or L-MDS), its pieces pass
  /// when an L contour scores above this lower threshold, should no test
  /// pass at \f$\eta\f$ (our addition, a hysteresis on the structure
  /// score; 0 or at least \f$\eta\f$: off, the thesis). Cutting a limb off a body
  /// lowers the body's L score although its other limbs still stick out:
  /// a teddy bear's body with an arm and two legs scores 0.085 against
  /// \f$\eta = 0.1\f$. The default is \f$\eta / 2\f$.
  double continuation_threshold = 0.05;
  /// a cut must run along a crease that stands out of the piece (our
  /// addition; 0: any position is a candidate, the thesis): positions whose
  /// boundary has a mean boundary weight (each edge weighted by its length)
  /// below this multiple of the piece's mean are not candidates. The
  /// weights are the default boundary term's (`Salience::Boundary_strength_term::edge_weight()`)
  /// of the concave angles at the contrast merge's reference resolution
  /// (`Refinement::concave_angle_weights()`), so that a finer copy of the
  /// same surface is judged alike. Parts meet along creases that are deeper
  /// than the surface around them: across a smooth tube no cut does, and on
  /// a creased surface (curls of hair) a cut along one more crease is not a
  /// part boundary either. 4, the contrast merge's limit
  /// (`Hybrid_options::min_boundary_contrast`)
  double min_cut_contrast = 4.;
  /// below the roots, a piece whose area is less than this multiple of the
  /// area of the flat disc bounded by its longest cut loop,
  /// \f$L^2 / 4\pi\f$ with \f$L\f$ = `Mesh_piece::longest_cut_loop()`, is a
  /// final part, not tested (our addition; 0: every piece is tested, the
  /// thesis). A part that sticks out (a limb, a handle, a head) has more
  /// area than that disc, as any surface spanning a planar circle has; a
  /// patch that earlier cuts carved out of a surface (a strip of hair
  /// between two cuts) has less. Such a patch's L projection is its own
  /// flattening, so its contour is the outline the cuts drew, and its
  /// concavities are theirs, not the shape's. 1, the disc itself
  double min_area_over_loop_disc = 1.;
  /// how many pairs of sample faces are tried on each piece, the most
  /// salient of their cuts kept (`Segmentability::bending_sample_face_pairs()`:
  /// one pair per protrusion the contour shows; 1: the thesis's single
  /// pair). With `min_cut_contrast`, one sequence may hold no cut along a
  /// crease while another does: default 3
  std::size_t sample_pairs = 3;
  /// how the faces between two samples are put in sequence (each prefix a
  /// candidate cut)
  enum class Sequence
  {
    /// by \f$d(f, s) - d(f, t)\f$ on `sequence_weights()` (the thesis,
    /// `Salient_cut::face_sequence()`)
    distance_difference,
    /// by a concavity-aware harmonic field from \f$s\f$ to \f$t\f$
    /// (`Salient_cut::harmonic_face_sequence()`, our default): the
    /// candidate cuts gather along concave creases
    concave_harmonic
  };
  /// how the faces between two samples are put in sequence
  Sequence sequence = Sequence::concave_harmonic;
  /// the angle scale \f$s\f$ of `Sequence::concave_harmonic`, in radians:
  /// across a concave edge of dihedral angle \f$\theta\f$ the field's
  /// conductance is multiplied by \f$\exp(-\theta / s)\f$ (0.1, the
  /// scale of `K_way_options::cut_angle_scale`)
  double sequence_angle_scale = 0.1;

  /// the segmentability options of the improved method: the thesis's, with
  /// M's concave weights floored at \f$\epsilon\f$ and the M projection
  /// whitened
  static Segmentability::Segmentability_options improved_segmentability()
  {
    Segmentability::Segmentability_options s;
    s.projection.concave_floor = true;
    s.projection.whiten = Segmentability::Projection_options::Whitening::geometry;
    s.chain_eigenvalue_ratio = 3.;
    s.contour.count_holes = true;
    return s;
  }

  /// the thesis's method as published: its salience (`Salience::thesis_salience()`),
  /// its segmentability test, no part-size limit, no part budget (pieces
  /// under `min_piece_faces` faces are still not tested)
  static Automatic_segmentation_options thesis()
  {
    Automatic_segmentation_options o;
    o.segmentability = Segmentability::Segmentability_options();
    o.salience = Salience::thesis_salience();
    o.min_part_area_fraction = 0.;
    o.max_parts = 0;
    o.min_cut_salience = 0.;
    o.cut_unsegmentable_roots = false;
    o.continuation_threshold = 0.;
    o.min_cut_contrast = 0.;
    o.min_area_over_loop_disc = 0.;
    o.sample_pairs = 1;
    o.sequence = Sequence::distance_difference;
    return o;
  }
};

/// \ingroup PkgSpectralSegAutomatic
/// \brief What `segment_automatically()` produced.
struct Automatic_segmentation_result
{
  /// one part per face, in `[0, number_of_segments)`, numbered by smallest face
  std::vector<int> labels;
  /// number of parts
  std::size_t number_of_segments = 0;
  /// every cut, with the tests and scores behind it
  Part_hierarchy hierarchy;
  /// seconds spent in each stage (summed over the pieces)
  std::vector<std::pair<std::string, double>> timings;
};


/// \ingroup PkgSpectralSegAutomatic
/// \brief The weights of the graph on which faces are sequenced: geodesic
/// and angular distance blended as in the part-aware metric without its
/// volumetric term (\f$\alpha = 0.01\f$, \f$\beta = 0.195\f$, each
/// normalised by its maximum), since pieces cut open have no enclosed
/// volume (thesis 6.3).
SPECTRALSEG_INLINE std::vector<double> sequence_weights(const Dual_graph& graph, const Execution& exec = Execution())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  return Metrics::make_blend(Metrics::Geodesic_weight(), 0.01, Metrics::Angular_weight(), 0.195)(graph, exec);
}
#else
;
#endif

/// \ingroup PkgSpectralSegAutomatic
/// \brief Segments the faces of a dual graph by recursive two-way cuts
/// driven by segmentability and salience (thesis fig. 6.1).
///
/// Each connected component of the graph is a first piece. The largest
/// piece still pending is taken (ties: smallest first face):
/// 1. `Segmentability::test_segmentability()`: if no contour test passes
///    (below a piece that passed an L test: nor an L contour scores above
///    `options.continuation_threshold`), the piece is a final part (with
///    `options.cut_unsegmentable_roots`, a connected component goes on and
///    is cut only by a cut of at least `options.min_cut_salience`);
/// 2. `Segmentability::bending_sample_faces()` picks two faces on different
///    parts (`options.sample_pairs` > 1: `bending_sample_face_pairs()`, each
///    pair through steps 2 and 3, the most salient cut kept),
///    `Salient_cut::harmonic_face_sequence()` orders the faces between them
///    by a concavity-aware harmonic field (`options.sequence`; the thesis's
///    `Salient_cut::face_sequence()` orders them on the graph weighted by
///    `weights`);
/// 3. `Salient_cut::salient_cut_search()` finds the most salient prefix
///    among those whose boundary is `options.min_cut_contrast` times as
///    concave as the piece, with the salience weights of the projection
///    that passed; below a
///    component's first cut, a cut under `options.min_cut_salience` leaves
///    the piece a final part;
/// 4. `Refinement::enhance_cut_boundary()` smooths the cut and makes each
///    side connected; both sides go back to the queue.
///
/// Pieces under `options.min_piece_faces` faces and pieces left when
/// `options.max_parts` is reached become parts without a test.
///
/// \param graph the dual graph of the mesh (outward-oriented faces)
/// \param weights one weight per dual edge, for the face sequences of
///        `Sequence::distance_difference` and for the farthest face of a
///        degenerate contour (default `sequence_weights()`)
/// \param options thresholds, modes and the salience model
/// \param exec threads (the two Dijkstra runs of each sequence) and progress
///        (stage "automatic segmentation": the fraction of the area settled)
/// \throws Invalid_input if `weights` does not have one valid value per dual edge,
///         `options.sequence_angle_scale` is not a positive number or
///         `options.min_cut_contrast` is negative or not finite
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename SalienceModel>
Automatic_segmentation_result segment_automatically(const Dual_graph& graph, const std::vector<double>& weights,
                                                    const Automatic_segmentation_options<SalienceModel>& options,
                                                    const Execution& exec = Execution())
{
  typedef Automatic_segmentation_options<SalienceModel> Options;
  Metrics::check_weights(graph, weights);
  if(options.sequence == Options::Sequence::concave_harmonic &&
     (!(options.sequence_angle_scale > 0.) || !std::isfinite(options.sequence_angle_scale)))
    throw Invalid_input("automatic segmentation: the sequence angle scale must be a positive number");
  if(!(options.min_cut_contrast >= 0.) || !std::isfinite(options.min_cut_contrast))
    throw Invalid_input("automatic segmentation: the minimum cut contrast must be finite and non-negative");
  if(!(options.min_area_over_loop_disc >= 0.) || !std::isfinite(options.min_area_over_loop_disc))
    throw Invalid_input("automatic segmentation: the minimum area over the loop's disc must be finite and non-negative");
  Automatic_segmentation_result r;
  internal::Stage_timer lap(r.timings, true);
  const std::size_t n = graph.number_of_faces();
  Part_hierarchy& h = r.hierarchy;
  h.number_of_faces = n;
  const char* stage = "automatic segmentation";
  exec.report(stage, 0.);

  Segmentability::Principal_curvatures curvatures;
  const bool geometry = !options.segmentability.structure_only;
  if(geometry)
    curvatures = Segmentability::principal_curvatures(graph);
  lap("curvatures");
  // the weights of the cuts' contrast: the boundary term's mapping of the
  // concave angles at the contrast merge's reference resolution
  std::vector<double> contrast_weights;
  if(options.min_cut_contrast > 0.)
  {
    contrast_weights = Refinement::concave_angle_weights(graph, SpectralSeg::internal::default_reference_faces);
    const Salience::Boundary_strength_term boundary;
    for(Dual_graph::size_type d = 0; d < contrast_weights.size(); ++d)
    {
      Dual_graph::Edge e = graph.edge(d);
      e.concave = contrast_weights[d] > 0.;
      e.normal_angle = contrast_weights[d];
      contrast_weights[d] = boundary.edge_weight(e);
    }
  }
  lap("contrast weights");

  // one root per connected component
  h.roots.clear();
  {
    std::vector<std::vector<std::uint32_t>> comp(graph.number_of_components());
    for(std::uint32_t f = 0; f < n; ++f)
      comp[graph.component_of_faces()[f]].push_back(f);
    for(auto& c : comp)
    {
      Part_node node;
      node.faces = std::move(c);
      for(std::uint32_t f : node.faces)
        node.area += graph.geometry().areas[f];
      h.roots.push_back(h.nodes.size());
      h.nodes.push_back(std::move(node));
    }
  }
  const auto larger = [&](std::size_t a, std::size_t b) { // priority: larger area, then smaller first face
    const Part_node& x = h.nodes[a];
    const Part_node& y = h.nodes[b];
    if(x.area != y.area)
      return x.area < y.area;
    return x.faces.front() > y.faces.front();
  };
  std::priority_queue<std::size_t, std::vector<std::size_t>, decltype(larger)> queue(larger);
  for(std::size_t i : h.roots)
    queue.push(i);

  double total_area = 0., settled = 0.;
  for(std::size_t i : h.roots)
    total_area += h.nodes[i].area;
  std::size_t parts = h.roots.size(), cuts = 0;
  SalienceModel salience = options.salience;
  const bool harmonic = options.sequence == Options::Sequence::concave_harmonic;
  // the elimination orders of each component's vertices and faces, made on
  // its root and inherited by its pieces (the sparse factorisations of the
  // projections and of the harmonic field)
  SpectralSeg::internal::Fill_reducing_order vertex_order(graph.geometry().number_of_vertices());
  SpectralSeg::internal::Fill_reducing_order face_order(harmonic ? n : 0);
  for(std::size_t i : h.roots)
  {
    const Mesh_piece piece(graph, h.nodes[i].faces);
    vertex_order.assign(piece.vertices(),
                        SpectralSeg::internal::amd_permutation(piece.number_of_vertices(), piece.vertex_edges()));
    if(!harmonic)
      continue;
    std::vector<std::pair<Mesh_piece::size_type, Mesh_piece::size_type>> face_pairs;
    face_pairs.reserve(piece.edges().size());
    for(const Mesh_piece::Edge& e : piece.edges())
      face_pairs.emplace_back(e.face[0], e.face[1]);
    face_order.assign(piece.faces(), SpectralSeg::internal::amd_permutation(piece.number_of_faces(), face_pairs));
  }
  lap("pieces");
  while(!queue.empty())
  {
    const std::size_t i = queue.top();
    queue.pop();
    auto settle = [&]() {
      settled += h.nodes[i].area;
      exec.report(stage, total_area > 0. ? settled / total_area : 1.);
    };
    std::size_t root = i;
    while(h.nodes[root].parent != Part_node::none)
      root = h.nodes[root].parent;
    const double min_area = options.min_part_area_fraction * h.nodes[root].area;
    if((options.max_parts > 0 && parts >= options.max_parts) ||
       h.nodes[i].faces.size() < std::max<std::size_t>(options.min_piece_faces, 2) || h.nodes[i].area < 2. * min_area)
    {
      settle();
      continue;
    }
    const Mesh_piece piece(graph, h.nodes[i].faces);
    if(options.min_area_over_loop_disc > 0. && h.nodes[i].parent != Part_node::none)
    {
      const double loop = piece.longest_cut_loop();
      if(piece.area() < options.min_area_over_loop_disc * loop * loop / (4. * boost::math::constants::pi<double>()))
      {
        lap("pieces");
        settle();
        continue;
      }
    }
    lap("pieces");
    // the harmonic sequence's system does not depend on the samples: made
    // on a second thread while the piece is tested (the same system either way)
    std::unique_ptr<Salient_cut::internal::Harmonic_system> system;
    std::future<std::unique_ptr<Salient_cut::internal::Harmonic_system>> pending;
    if(harmonic && exec.threads() > 1)
      pending = std::async(std::launch::async, [&piece, &options, &face_order] {
        return std::make_unique<Salient_cut::internal::Harmonic_system>(piece, options.sequence_angle_scale,
                                                                        face_order.restricted(piece.faces()));
      });
    const std::size_t parent = h.nodes[i].parent;
    const bool continued = parent != Part_node::none && options.continuation_threshold > 0. &&
                           (h.nodes[parent].test == Segmentability::Test::structure ||
                            h.nodes[parent].test == Segmentability::Test::structure_normalized);
    const Segmentability::Segmentability_result test = Segmentability::internal::test_segmentability(
      piece, geometry ? &curvatures : nullptr, options.segmentability, vertex_order.restricted(piece.vertices()),
      continued ? options.continuation_threshold : std::numeric_limits<double>::infinity());
    lap("segmentability");
    {
      Part_node& node = h.nodes[i];
      node.tested = true;
      node.test = test.test;
      node.score = test.score;
      node.scores = test.scores;
    }
    const bool is_root = h.nodes[i].parent == Part_node::none;
    if(!test.segmentable && !(is_root && options.cut_unsegmentable_roots))
    {
      settle();
      continue;
    }
    // the most salient cut over the sample pairs (the first one wins ties)
    Salient_cut::Salient_cut cut;
    std::pair<Mesh_piece::size_type, Mesh_piece::size_type> samples(0, 0);
    for(std::pair<Mesh_piece::size_type, Mesh_piece::size_type> st :
        Segmentability::bending_sample_face_pairs(piece, test, std::max<std::size_t>(options.sample_pairs, 1)))
    {
      if(st.first == st.second)
      {
        // a degenerate contour: the face farthest from the first sample
        const std::vector<double> d = Salient_cut::piece_distances(piece, weights, st.first);
        double best = -1.;
        for(Mesh_piece::size_type f = 0; f < d.size(); ++f)
          if(std::isfinite(d[f]) && d[f] > best)
          {
            best = d[f];
            st.second = f;
          }
      }
      if(st.first == st.second)
        continue;
      if(harmonic && !system)
        system = pending.valid() ? pending.get()
                                 : std::make_unique<Salient_cut::internal::Harmonic_system>(
                                     piece, options.sequence_angle_scale, face_order.restricted(piece.faces()));
      const Salient_cut::Face_sequence seq = harmonic ? system->sequence(st.first, st.second)
                                                      : Salient_cut::face_sequence(piece, weights, st.first,
                                                                                   st.second, exec);
      lap("face sequence");
      Salient_cut::Salient_cut c =
        Salient_cut::salient_cut_search(piece, seq.order, salience, test.projection_kind(), false, min_area,
                                        &contrast_weights, options.min_cut_contrast);
      lap("cut search");
      if(c.position != 0 && (cut.position == 0 || c.salience > cut.salience))
      {
        cut = std::move(c);
        samples = st;
      }
    }
    const bool floor = options.min_cut_salience_at_roots || !is_root;
    if(cut.position == 0 || (floor && cut.salience < options.min_cut_salience) ||
       (!test.segmentable && cut.salience < options.min_cut_salience))
    {
      settle();
      continue;
    }
    if(!options.closing_rings.empty())
      Refinement::enhance_cut_boundary(piece, cut.side, options.closing_rings);
    else
      Refinement::make_cut_sides_connected(piece, cut.side);
    lap("boundary enhancement");
    std::array<Part_node, 2> child;
    for(Mesh_piece::size_type f = 0; f < piece.number_of_faces(); ++f)
    {
      Part_node& c = child[cut.side[f] ? 0 : 1];
      c.faces.push_back(piece.faces()[f]);
      c.area += piece.face_area(f);
    }
    if(child[0].faces.empty() || child[1].faces.empty())
    {
      settle();
      continue;
    }
    Part_node& node = h.nodes[i];
    node.cut_salience = cut.salience;
    node.cut_order = cuts++;
    node.samples = {piece.faces()[samples.first], piece.faces()[samples.second]};
    const std::size_t depth = node.depth + 1;
    for(int c = 0; c < 2; ++c)
    {
      std::sort(child[c].faces.begin(), child[c].faces.end());
      child[c].parent = i;
      child[c].depth = depth;
      h.nodes[i].children[c] = h.nodes.size();
      h.nodes.push_back(std::move(child[c]));
      queue.push(h.nodes.size() - 1); // after the node exists: the queue's order reads it
    }
    ++parts;
  }
  h.chosen_cuts = cuts;
  r.labels = h.labels();
  r.number_of_segments = h.number_of_parts();
  exec.report(stage, 1.);
  return r;
}

/// \cond SKIP_IN_MANUAL
#if SPECTRALSEG_DEFAULT_INSTANCES
SPECTRALSEG_INSTANTIATE Automatic_segmentation_result segment_automatically<Salience::Thesis_salience>(
  const Dual_graph&, const std::vector<double>&, const Automatic_segmentation_options<Salience::Thesis_salience>&,
  const Execution&);
#endif
/// \endcond

/// \ingroup PkgSpectralSegAutomatic
/// \brief The methods of `automatic_segmentation()`.
enum class Automatic_method
{
  /// over-segment and merge while the weakest boundary is not both a
  /// concave crease and a jump of the metric (`segment_hybrid()`, our
  /// method): the default, the best on psb-dev (figures in doc/benchmarks.md)
  contrast_merge,
  /// over-segment and merge while the weakest boundary is weakly concave
  /// (`segment_k_way_automatic()`, our earlier rule)
  concave_merge,
  /// recursive salient cuts of the segmentable pieces
  /// (`segment_automatically()`, after the thesis's chapter 6), with our
  /// salience and segmentability test (`Automatic_segmentation_options<>()`)
  salient_cuts,
  /// the same as the thesis published it (`Automatic_segmentation_options<>::thesis()`)
  salient_cuts_thesis
};

/// \ingroup PkgSpectralSegAutomatic
/// \brief Segments a triangle mesh into as many parts as it finds, and
/// returns their number.
///
/// With `Automatic_method::salient_cuts` (after thesis ch. 6; as published
/// with `Automatic_method::salient_cuts_thesis`) the mesh is cut in
/// two recursively, largest piece first, while a piece passes the
/// segmentability test, each time at the most salient place along a face
/// sequence (`segment_automatically()`); the cuts are kept in a
/// `Part_hierarchy` that `part_hierarchy` receives. With
/// `Automatic_method::contrast_merge` (the default) the mesh is
/// over-segmented by spectral clustering of the part-aware metric and
/// segments are merged across weak boundaries (`segment_hybrid()`);
/// `Automatic_method::concave_merge` is `k_way_segmentation_automatic()`.
/// The named parameters of `k_way_segmentation_automatic()` apply to both
/// merge methods (`max_number_of_segments` is the number of clusters of the
/// over-segmentation; `min_boundary_contrast` defaults to 4 for
/// `contrast_merge`).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         with triangle faces oriented outward
/// \tparam SegmentMap a model of `WritablePropertyMap` with the face
///         descriptor as key type and an integer type as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param segments receives the part of each face, in `[0, returned value)`,
///        numbered by smallest face; each part is one connected region
/// \param np an optional sequence of named parameters among those below;
///        with the merge methods, those of `k_way_segmentation_automatic()` too
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{automatic_method}
///     \cgalParamDescription{the method}
///     \cgalParamType{`Automatic_method`}
///     \cgalParamDefault{`Automatic_method::contrast_merge`}
///   \cgalParamNEnd
///   \cgalParamNBegin{automatic_options}
///     \cgalParamDescription{every parameter of the salient-cut method (contour resolution, eigensolver, closing radii, part budget, salience model with its weights); the parameters below, when given, replace the fields they name}
///     \cgalParamType{`Automatic_segmentation_options<SalienceModel>`}
///     \cgalParamDefault{`Automatic_segmentation_options<>()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{segmentability_threshold}
///     \cgalParamDescription{\f$\eta\f$: a piece is cut when a contour's segmentability score exceeds it (thesis 6.2.4)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.1}
///   \cgalParamNEnd
///   \cgalParamNBegin{structure_only}
///     \cgalParamDescription{only the L-projection tests (the thesis's structure-only mode, 6.5)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{min_part_area_fraction}
///     \cgalParamDescription{no part under this fraction of its connected component's area (our addition; 0 for the thesis's behaviour)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.02 (0 with `Automatic_method::salient_cuts_thesis`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_parts}
///     \cgalParamDescription{when given, the answer has this many parts (or as many as the hierarchy has leaves, if fewer): the hierarchy cut there (`Part_hierarchy::labels_with_parts()`; the merge methods then smooth the boundaries by their graph cut) instead of where the method stops}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{none: the method decides}
///   \cgalParamNEnd
///   \cgalParamNBegin{part_hierarchy}
///     \cgalParamDescription{receives the hierarchy behind the answer: the salient-cut method's cuts, or the merge methods' merges from their over-segmentation down to one part per connected component}
///     \cgalParamType{`Part_hierarchy*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads; 0 means all hardware threads. The result does not depend on it}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called with each stage's name and done fraction; returning `false` cancels (`Operation_cancelled`)}
///     \cgalParamType{`SpectralSeg::Progress_callback`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
///     \cgalParamDescription{the vertex positions and the numbering of vertices and faces, as for `extract_mesh_geometry()`}
///     \cgalParamType{property maps as for `extract_mesh_geometry()`}
///     \cgalParamDefault{the mesh's internal maps}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Meshes with several connected components: each component is segmented
/// on its own (the salient-cut method starts with one piece per component).
/// \throws Invalid_input for a non-triangle face, a non-finite coordinate or
///         an invalid parameter
/// \throws Operation_cancelled if the progress callback asks to stop
template <typename TriangleMesh, typename SegmentMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t automatic_segmentation(const TriangleMesh& tm, SegmentMap segments,
                                   const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Automatic_method method =
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::automatic_method), Automatic_method::contrast_merge);
  if(method == Automatic_method::concave_merge)
    return k_way_segmentation_automatic(tm, segments, np);
  if(method == Automatic_method::contrast_merge)
  {
    const internal::Weighted_mesh_graph g(tm, np);
    const auto k_way = internal::k_way_options_from(np);
    Basic_hybrid_options<typename std::decay_t<decltype(k_way)>::Kernel_type> o;
    o.k_way = k_way;
    o.clusters = choose_parameter(get_parameter(np, SpectralSeg::internal_np::max_number_of_segments), o.clusters);
    o.min_boundary_contrast =
      choose_parameter(get_parameter(np, SpectralSeg::internal_np::min_boundary_contrast), o.min_boundary_contrast);
    o.parts = internal::number_of_parts_from(np);
    K_way_result r = segment_hybrid(g.weighted, o, g.exec);
    internal::put_labels(tm, r.labels, segments, np);
    internal::put_hierarchy(std::move(r.hierarchy), np);
    return r.number_of_segments;
  }
  auto o = choose_parameter(get_parameter(np, SpectralSeg::internal_np::automatic_options),
                            method == Automatic_method::salient_cuts_thesis ? Automatic_segmentation_options<>::thesis()
                                                                            : Automatic_segmentation_options<>());
  o.segmentability.threshold = choose_parameter(get_parameter(np, SpectralSeg::internal_np::segmentability_threshold),
                                                o.segmentability.threshold);
  o.segmentability.structure_only =
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::structure_only), o.segmentability.structure_only);
  o.min_part_area_fraction =
    choose_parameter(get_parameter(np, SpectralSeg::internal_np::min_part_area_fraction), o.min_part_area_fraction);
  if(!(o.segmentability.threshold >= 0.) || !std::isfinite(o.segmentability.threshold))
    throw Invalid_input("automatic segmentation: the segmentability threshold must be finite and non-negative");
  if(!(o.min_part_area_fraction >= 0.) || !(o.min_part_area_fraction < 0.5))
    throw Invalid_input("automatic segmentation: the minimum part area fraction must be in [0, 0.5)");
  const std::size_t parts = internal::number_of_parts_from(np);
  const Execution exec = internal::execution_from(np);
  const Dual_graph graph = make_dual_graph(tm, np);
  Automatic_segmentation_result r = segment_automatically(graph, sequence_weights(graph, exec), o, exec);
  if(parts > 0)
  {
    r.labels = r.hierarchy.labels_with_parts(parts);
    r.number_of_segments = std::min(r.hierarchy.number_of_leaves(), std::max(parts, r.hierarchy.roots.size()));
  }
  internal::put_labels(tm, r.labels, segments, np);
  internal::put_hierarchy(std::move(r.hierarchy), np);
  return r.number_of_segments;
}

} // namespace SpectralSeg

#endif // SPECTRALSEG_AUTOMATIC_SEGMENTATION_H
