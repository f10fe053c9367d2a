// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file most_typical_merge.h
/// \brief The contrast merge of several over-segmentations of one embedding,
/// and the one whose answer is most typical of them (internal).
#ifndef SPECTRALSEG_INTERNAL_MOST_TYPICAL_MERGE_H
#define SPECTRALSEG_INTERNAL_MOST_TYPICAL_MERGE_H

#include <SpectralSeg/Clustering/Kmeans.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/K_way_options.h>
#include <SpectralSeg/Weighted_dual_graph.h>
#include <SpectralSeg/internal/merge_by_contrast.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace SpectralSeg {
namespace internal {

// The area-weighted Rand distance between two labellings with labels
// 0 .. a-1 and 0 .. b-1: the area-weighted share of pairs of points of the
// surface that one puts in the same segment and the other does not.
SPECTRALSEG_INLINE double rand_distance(const std::vector<int>& x, std::size_t a, const std::vector<int>& y,
                                        std::size_t b, const std::vector<double>& area)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  std::vector<double> ax(a, 0.), ay(b, 0.), axy(a * b, 0.);
  double total = 0.;
  for(std::size_t f = 0; f < area.size(); ++f) // in face order: thread-independent
  {
    ax[std::size_t(x[f])] += area[f];
    ay[std::size_t(y[f])] += area[f];
    axy[std::size_t(x[f]) * b + std::size_t(y[f])] += area[f];
    total += area[f];
  }
  double sx = 0., sy = 0., sxy = 0.;
  for(double v : ax)
    sx += v * v;
  for(double v : ay)
    sy += v * v;
  for(double v : axy)
    sxy += v * v;
  return total > 0. ? std::max(0., sx + sy - 2. * sxy) / (total * total) : 0.;
}
#else
;
#endif

// The index of the medoid of `labellings` (each with `counts[i]` labels):
// the one whose summed rand_distance() to the others is smallest (ties:
// the first). With `eligible` (one flag per labelling, at least one set),
// the one of least sum among those flagged; every labelling still counts
// in the sums. The pairs' distances are computed on `threads` threads and
// summed in one order: the same result on any number.
SPECTRALSEG_INLINE std::size_t medoid_labelling(const std::vector<std::vector<int>>& labellings,
                                                const std::vector<std::size_t>& counts, const std::vector<double>& area,
                                                const std::vector<char>& eligible = std::vector<char>(),
                                                unsigned threads = 1)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t m = labellings.size();
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for(std::size_t i = 0; i < m; ++i)
    for(std::size_t j = i + 1; j < m; ++j)
      pairs.emplace_back(i, j);
  std::vector<double> distance(pairs.size(), 0.);
  parallel_range(0, pairs.size(), threads, [&](std::size_t p) {
    const std::size_t i = pairs[p].first, j = pairs[p].second;
    distance[p] = rand_distance(labellings[i], counts[i], labellings[j], counts[j], area);
  });
  std::vector<double> sum(m, 0.);
  for(std::size_t p = 0; p < pairs.size(); ++p)
  {
    sum[pairs[p].first] += distance[p];
    sum[pairs[p].second] += distance[p];
  }
  std::size_t best = m;
  for(std::size_t i = 0; i < m; ++i)
    if((eligible.empty() || eligible[i]) && (best == m || sum[i] < sum[best]))
      best = i;
  return best == m ? 0 : best;
}
#else
;
#endif

// Coarser over-segmentations of K-means clusters `base` (labels 0 ..
// c-1 on the rows of `points`): the clusters' centroids are joined by
// Ward's rule (the pair whose joining least raises the sum of squared
// distances first; ties: the smallest labels) down to each of `sizes`
// (descending, each below c), and K-means is run again from the point
// nearest each joined centroid (ties: the smallest index); above
// `sample_limit` points, on the subsample and then one round on every
// point (these clusterings only vote for the typical answer; running
// them to a fixed point on every point was most of the merge stage on
// large meshes, doc/benchmarks.md). One K-means result per size.
SPECTRALSEG_INLINE std::vector<Clustering::Kmeans_result> coarser_clusterings(
    const Eigen::MatrixXd& points, const std::vector<int>& base, std::size_t c, const std::vector<std::size_t>& sizes,
    std::size_t max_iterations, std::size_t sample_limit, const Execution& exec)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = base.size();
  std::vector<double> weight(c, 0.);
  Eigen::MatrixXd centre = Eigen::MatrixXd::Zero(Eigen::Index(c), points.cols());
  // column after column, as the points are stored; each sum in point
  // order (thread-independent)
  for(std::size_t f = 0; f < n; ++f)
    weight[std::size_t(base[f])] += 1.;
  for(Eigen::Index j = 0; j < points.cols(); ++j)
  {
    const double* column = points.col(j).data();
    for(std::size_t f = 0; f < n; ++f)
      centre(base[f], j) += column[f];
  }
  std::vector<double> squared(n); // a point's squared distance to its joined centroid
  std::vector<int> joined(c); // what each cluster of `base` became
  std::vector<char> alive(c, 0);
  std::size_t live = 0;
  for(std::size_t a = 0; a < c; ++a)
  {
    joined[a] = int(a);
    if(weight[a] > 0.)
    {
      centre.row(Eigen::Index(a)) /= weight[a];
      alive[a] = 1;
      ++live;
    }
  }
  std::vector<Clustering::Kmeans_result> out;
  for(const std::size_t size : sizes)
  {
    while(live > std::max<std::size_t>(size, 1))
    {
      double cheapest = std::numeric_limits<double>::infinity();
      std::size_t ja = c, jb = c;
      for(std::size_t a = 0; a < c; ++a)
        for(std::size_t b = a + 1; b < c; ++b)
          if(alive[a] && alive[b])
          {
            const double cost = weight[a] * weight[b] / (weight[a] + weight[b]) *
                                (centre.row(Eigen::Index(a)) - centre.row(Eigen::Index(b))).squaredNorm();
            if(cost < cheapest) // strict: ties to the smallest labels
            {
              cheapest = cost;
              ja = a;
              jb = b;
            }
          }
      centre.row(Eigen::Index(ja)) = (weight[ja] * centre.row(Eigen::Index(ja)) + weight[jb] * centre.row(Eigen::Index(jb))) /
                                     (weight[ja] + weight[jb]);
      weight[ja] += weight[jb];
      alive[jb] = 0;
      for(int& t : joined)
        if(t == int(jb))
          t = int(ja);
      --live;
    }
    // the point nearest each joined centroid seeds K-means
    std::vector<std::size_t> nearest(c, n);
    std::vector<double> distance(c, std::numeric_limits<double>::infinity());
    for(Eigen::Index j = 0; j < points.cols(); ++j) // summed over the coordinates in order
    {
      const double* column = points.col(j).data();
      for(std::size_t f = 0; f < n; ++f)
      {
        const double t = column[f] - centre(joined[std::size_t(base[f])], j);
        squared[f] = j == 0 ? t * t : squared[f] + t * t;
      }
    }
    for(std::size_t f = 0; f < n; ++f)
    {
      const std::size_t a = std::size_t(joined[std::size_t(base[f])]);
      const double d = squared[f];
      if(d < distance[a])
      {
        distance[a] = d;
        nearest[a] = f;
      }
    }
    std::vector<std::size_t> seeds;
    for(std::size_t a = 0; a < c; ++a)
      if(alive[a] && nearest[a] < n)
        seeds.push_back(nearest[a]);
    out.push_back(Clustering::kmeans(points, seeds.size(), seeds, max_iterations, exec, sample_limit, 1));
  }
  return out;
}
#else
;
#endif

// The contrast merge of segment_hybrid() (merge_clusters_by_contrast()
// with these settings) on the most typical of `count` over-segmentations:
// `r.clusters` (`clusters` K-means clusters of `r.embedding`) and
// coarser_clusterings() of it with 2, 4, ... fewer clusters (at least 2),
// each merged by contrast; the one whose answer is the medoid_labelling()
// of the answers is kept: `r.labels` are its answer, `r.hierarchy` its
// merges and `r.clusters` its clusters. With `parts` > 0 only those of at
// least `parts` clusters may be kept (all still vote), so that the kept
// hierarchy can be cut at `parts`. The crease regions and concave angles
// are made once for all the merges (or given in `made`, made by
// contrast_merge_shared() with the same settings). With `count` at most 1 (or too few
// clusters), merge_clusters_by_contrast() on `r.clusters` alone. Returns
// the number of segments of the answer.
template <typename AffinityKernel>
std::size_t merge_most_typical_over_segmentation(const Weighted_dual_graph& graph,
                                                 const Basic_K_way_options<AffinityKernel>& k_way,
                                                 std::size_t clusters, std::size_t count, std::size_t min_segments,
                                                 double limit, double neck_scale, std::size_t reference_faces,
                                                 std::size_t parts, K_way_result& r, const Execution& exec,
                                                 const Contrast_merge_shared* made = nullptr)
{
  std::vector<std::size_t> sizes;
  for(std::size_t i = 1; i < count && clusters >= 2 * i + 2; ++i)
    sizes.push_back(clusters - 2 * i);
  std::vector<Clustering::Kmeans_result> members =
    coarser_clusterings(r.embedding.coordinates, r.clusters.labels, clusters, sizes, k_way.kmeans_iterations,
                        k_way.kmeans_sample_limit, exec);
  members.insert(members.begin(), std::move(r.clusters));
  const Contrast_merge_shared own =
    made ? Contrast_merge_shared() : contrast_merge_shared(graph, k_way, reference_faces, exec.threads());
  const Contrast_merge_shared& shared = made ? *made : own;
  // the merges, each on one thread and on its own labels, side by side
  std::vector<std::vector<int>> answers(members.size());
  std::vector<std::size_t> counts(members.size());
  std::vector<Refinement::internal::Merge_history> histories(members.size());
  parallel_range(0, members.size(), exec.threads(), [&](std::size_t i) {
    answers[i] = members[i].labels;
    counts[i] = merge_labels_by_contrast(graph, k_way, min_segments, limit, neck_scale, reference_faces,
                                         r.embedding.coordinates, answers[i], histories[i], shared);
  });
  std::vector<char> eligible(members.size(), 1); // fine enough for `parts`
  if(parts > 0)
    for(std::size_t i = 1; i < members.size(); ++i) // the first has the most clusters
      eligible[i] = sizes[i - 1] >= parts;
  const std::size_t kept =
    members.size() > 1
      ? medoid_labelling(answers, counts, graph.graph().geometry().areas, eligible, exec.threads())
      : 0;
  r.labels = std::move(answers[kept]);
  r.clusters = std::move(members[kept]);
  keep_merges(graph, std::move(histories[kept]), r, nullptr);
  return counts[kept];
}

} // namespace internal
} // namespace SpectralSeg
/// \endcond

#endif // SPECTRALSEG_INTERNAL_MOST_TYPICAL_MERGE_H
