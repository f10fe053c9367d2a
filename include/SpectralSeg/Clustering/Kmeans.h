// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Kmeans.h
/// \brief K-means in the spectral embedding, with max-min seeding (thesis 4.3, fig. 4.6).
#ifndef SPECTRALSEG_CLUSTERING_KMEANS_H
#define SPECTRALSEG_CLUSTERING_KMEANS_H

#include <SpectralSeg/Execution.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace SpectralSeg {
namespace Clustering {

/// \ingroup PkgSpectralSegClustering
/// \brief The result of `kmeans()`.
struct Kmeans_result
{
  /// the cluster of each point, in `[0, k)`
  std::vector<int> labels;
  /// one centroid (proxy) per row
  Eigen::MatrixXd centroids;
  /// the points that seeded the clusters
  std::vector<std::size_t> seeds;
  /// assignment/update rounds run
  std::size_t iterations = 0;
  /// whether the labels stopped changing before `max_iterations`
  bool converged = false;
};

/// \ingroup PkgSpectralSegClustering
/// \brief Max-min seeds: the first two points are the ends of an
/// approximate diameter (from point `start`, hop to the farthest point until
/// the pair is stable), each next one the point farthest from all chosen
/// ones. Ties go to the smallest index.
SPECTRALSEG_INLINE std::vector<std::size_t> max_min_seeds(const Eigen::MatrixXd& points, std::size_t k,
                                                          std::size_t start = 0)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const Eigen::Index n = points.rows();
  std::vector<std::size_t> seeds;
  if(n == 0 || k == 0)
    return seeds;
  auto farthest_from = [&](const Eigen::VectorXd& d) {
    Eigen::Index arg = 0;
    d.maxCoeff(&arg);
    return static_cast<std::size_t>(arg);
  };
  auto distances_to = [&](std::size_t i) {
    return Eigen::VectorXd((points.rowwise() - points.row(Eigen::Index(i))).rowwise().squaredNorm());
  };
  std::size_t a = start, b = farthest_from(distances_to(a));
  for(int hop = 0; hop < 10; ++hop)
  {
    const std::size_t c = farthest_from(distances_to(b));
    if(c == a)
      break;
    a = b;
    b = c;
  }
  seeds.push_back(a);
  Eigen::VectorXd nearest = distances_to(a);
  while(seeds.size() < k)
  {
    const std::size_t next = seeds.size() == 1 ? b : farthest_from(nearest);
    if(nearest(Eigen::Index(next)) <= 0. && seeds.size() > 1)
      break; // every remaining point coincides with a seed
    seeds.push_back(next);
    nearest = nearest.cwiseMin(distances_to(next));
  }
  return seeds;
}
#else
;
#endif

namespace internal {

// Lloyd's rounds on n points of `dims` coordinates, point i's at
// p[i * step + j * coordinate_step] for j = 0, ..., dims - 1, from the
// centroids in `r.centroids`; sets r.labels, r.iterations and r.converged.
SPECTRALSEG_INLINE void lloyd(const double* p, std::size_t n, std::size_t dims, std::size_t step,
                              std::size_t coordinate_step, Kmeans_result& r, std::size_t max_iterations,
                              const Execution& exec)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t kk = static_cast<std::size_t>(r.centroids.rows());
  r.labels.assign(n, -1);
  r.converged = false;
  // the centroids point after point, and coordinate after coordinate
  std::vector<double> centre(kk * dims), across(kk * dims);
  constexpr std::size_t block_centroids = 64;
  std::vector<char> changed(n, 0);
  // x's coordinates `x_step` apart, y's next to each other
  const auto squared_distance = [dims](const double* x, const double* y, std::size_t x_step = 1) {
    double d = 0.;
    if(dims > 0)
    {
      d = (x[0] - y[0]) * (x[0] - y[0]);
      for(std::size_t j = 1; j < dims; ++j)
        d += (x[j * x_step] - y[j]) * (x[j * x_step] - y[j]);
    }
    return d;
  };
  const std::size_t cs = coordinate_step;
  // Hamerly's bounds: an upper bound of each point's distance to its
  // centroid and a lower bound of its distance to every other one; a point
  // whose upper bound is below both its lower bound and half the distance
  // from its centroid to the nearest other is provably still nearest its
  // centroid, and is skipped. A relative margin covers the rounding of the
  // bounds, so the labels are exactly those of Lloyd's full assignment.
  const double margin = 1. + 1e-9;
  std::vector<double> upper(n, std::numeric_limits<double>::infinity()), lower(n, 0.);
  std::vector<double> half_gap(kk), moved(kk);
  std::vector<double> previous(kk * dims);
  // small blocks: in the late rounds only a few points change cluster, and
  // only their blocks are summed again
  const std::size_t block = 1024;
  std::vector<double> block_sum;
  std::vector<std::size_t> block_count;
  for(r.iterations = 0; r.iterations < max_iterations; ++r.iterations)
  {
    for(std::size_t c = 0; c < kk; ++c)
      for(std::size_t j = 0; j < dims; ++j)
      {
        centre[c * dims + j] = r.centroids(Eigen::Index(c), Eigen::Index(j));
        across[j * kk + c] = centre[c * dims + j];
      }
    for(std::size_t c = 0; c < kk; ++c)
    {
      double nearest = std::numeric_limits<double>::infinity();
      for(std::size_t o = 0; o < kk; ++o)
        if(o != c)
          nearest = std::min(nearest, squared_distance(centre.data() + c * dims, centre.data() + o * dims));
      half_gap[c] = 0.5 * std::sqrt(nearest);
    }
    ::SpectralSeg::internal::parallel_range(0, n, exec.threads(), [&](std::size_t i) {
      const double* x = p + i * step;
      const int own = r.labels[i];
      if(own >= 0)
      {
        const double bound = std::max(half_gap[std::size_t(own)], lower[i]);
        if(upper[i] * margin < bound)
        {
          changed[i] = 0;
          return;
        }
        upper[i] = std::sqrt(squared_distance(x, centre.data() + std::size_t(own) * dims, cs));
        if(upper[i] * margin < bound)
        {
          changed[i] = 0;
          return;
        }
      }
      // the distances to every centroid, coordinate after coordinate over
      // the centroids (a loop the compiler vectorises; each distance sums
      // its coordinates in the same order as squared_distance()); with more
      // centroids than the block holds, one centroid after the other
      double near[block_centroids];
      const bool blocked = kk <= block_centroids && dims > 0;
      if(blocked)
      {
        const double* t = across.data();
        for(std::size_t c = 0; c < kk; ++c)
        {
          const double e = x[0] - t[c];
          near[c] = e * e;
        }
        for(std::size_t j = 1; j < dims; ++j)
        {
          t = across.data() + j * kk;
          const double xj = x[j * cs];
          for(std::size_t c = 0; c < kk; ++c)
          {
            const double e = xj - t[c];
            near[c] += e * e;
          }
        }
      }
      int best = 0;
      double best_d = std::numeric_limits<double>::infinity(), second_d = std::numeric_limits<double>::infinity();
      for(std::size_t c = 0; c < kk; ++c)
      {
        const double d = blocked ? near[c] : squared_distance(x, centre.data() + c * dims, cs);
        if(d < best_d)
        {
          second_d = best_d;
          best_d = d;
          best = int(c);
        }
        else if(d < second_d)
          second_d = d;
      }
      changed[i] = own != best;
      r.labels[i] = best;
      upper[i] = std::sqrt(best_d);
      lower[i] = std::sqrt(second_d);
    });
    bool any = false;
    for(char c : changed)
      any = any || c;
    if(!any)
    {
      r.converged = true;
      break;
    }
    // the sums of fixed blocks of points in parallel, each in point order,
    // then the blocks' sums in block order: the same sums whatever the
    // number of threads (one block below `block` points: point order). A
    // block none of whose points changed cluster keeps its sums of the
    // round before, which are the ones it would make again.
    const std::size_t blocks = (n + block - 1) / block;
    if(block_sum.empty())
    {
      block_sum.assign(blocks * kk * dims, 0.);
      block_count.assign(blocks * kk, 0);
    }
    ::SpectralSeg::internal::parallel_range(0, blocks, exec.threads(), [&](std::size_t b) {
      const std::size_t end = std::min(n, (b + 1) * block);
      if(std::find(changed.begin() + std::ptrdiff_t(b * block), changed.begin() + std::ptrdiff_t(end), char(1)) ==
         changed.begin() + std::ptrdiff_t(end))
        return;
      double* s = block_sum.data() + b * kk * dims;
      std::size_t* m = block_count.data() + b * kk;
      std::fill(s, s + kk * dims, 0.);
      std::fill(m, m + kk, std::size_t(0));
      for(std::size_t i = b * block; i < end; ++i)
      {
        const std::size_t c = std::size_t(r.labels[i]);
        for(std::size_t j = 0; j < dims; ++j)
          s[c * dims + j] += p[i * step + j * cs];
        ++m[c];
      }
    });
    std::vector<double> sum(block_sum.begin(), block_sum.begin() + std::ptrdiff_t(kk * dims));
    std::vector<std::size_t> count(block_count.begin(), block_count.begin() + std::ptrdiff_t(kk));
    for(std::size_t b = 1; b < blocks; ++b)
    {
      for(std::size_t t = 0; t < kk * dims; ++t)
        sum[t] += block_sum[b * kk * dims + t];
      for(std::size_t c = 0; c < kk; ++c)
        count[c] += block_count[b * kk + c];
    }
    for(std::size_t c = 0; c < kk; ++c)
      if(count[c] > 0)
        for(std::size_t j = 0; j < dims; ++j)
          r.centroids(Eigen::Index(c), Eigen::Index(j)) = sum[c * dims + j] / double(count[c]);
    // the bounds follow the centroids' moves
    std::size_t farthest = 0;
    for(std::size_t c = 0; c < kk; ++c)
    {
      for(std::size_t j = 0; j < dims; ++j)
        previous[c * dims + j] = r.centroids(Eigen::Index(c), Eigen::Index(j));
      moved[c] = std::sqrt(squared_distance(previous.data() + c * dims, centre.data() + c * dims));
      if(moved[c] > moved[farthest])
        farthest = c;
    }
    double second = 0.;
    for(std::size_t c = 0; c < kk; ++c)
      if(c != farthest)
        second = std::max(second, moved[c]);
    ::SpectralSeg::internal::parallel_range(0, n, exec.threads(), [&](std::size_t i) {
      const std::size_t own = std::size_t(r.labels[i]);
      upper[i] += moved[own];
      lower[i] -= own == farthest ? second : moved[farthest];
    });
  }
}
#else
;
#endif

} // namespace internal

/// \ingroup PkgSpectralSegClustering
/// \brief Lloyd's K-means on the rows of `points`, seeded with the given
/// rows (or with `max_min_seeds()` when `seeds` is empty).
///
/// Each round assigns every point to its nearest centroid (ties to the
/// smaller cluster index) and moves every centroid to the mean of its
/// points; a cluster that loses all its points keeps its centroid. Sums are
/// taken in point order, so the result does not depend on the thread count.
///
/// With more than `sample_limit` points (0: no limit), the rounds first run
/// on every \f$\lceil n / \f$`sample_limit`\f$\rceil\f$-th point from the
/// seeds, and then on all the points from the centroids found: the answer
/// is still a fixed point of Lloyd's rounds on all the points, reached in
/// fewer rounds over all of them. `Kmeans_result::iterations` counts the
/// rounds on all the points. With `full_rounds` above 0 and a subsample
/// taken, at most that many rounds run on all the points after the
/// subsample's (1: every point assigned to the subsample's centroids, which
/// then move to their points' means once); the labels need not be a fixed
/// point then, and `Kmeans_result::converged` is true only when a round on
/// all the points changed none.
///
/// \throws Invalid_input if `k` is 0 or exceeds the number of points
SPECTRALSEG_INLINE Kmeans_result kmeans(const Eigen::MatrixXd& points, std::size_t k,
                                        std::vector<std::size_t> seeds = {}, std::size_t max_iterations = 100,
                                        const Execution& exec = Execution(), std::size_t sample_limit = 0,
                                        std::size_t full_rounds = 0)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const std::size_t n = static_cast<std::size_t>(points.rows());
  if(k == 0 || k > n)
    throw Invalid_input("K-means: cannot make " + std::to_string(k) + " clusters of " + std::to_string(n) + " points");
  if(seeds.empty())
    seeds = max_min_seeds(points, k);
  Kmeans_result r;
  r.seeds = seeds;
  const std::size_t kk = seeds.size();
  r.centroids.resize(static_cast<Eigen::Index>(kk), points.cols());
  for(std::size_t c = 0; c < kk; ++c)
    r.centroids.row(Eigen::Index(c)) = points.row(Eigen::Index(seeds[c]));
  // all the points read in place (column after column, no copy: 120 MB
  // at 832,000 faces), distances summed in coordinate order
  const std::size_t dims = static_cast<std::size_t>(points.cols());
  if(sample_limit > 0 && n > sample_limit)
  {
    // every stride-th point, copied point after point: read in place, each
    // of its coordinates would be a cache line of its own in every round
    // (the same sums in the same order either way)
    const std::size_t stride = (n + sample_limit - 1) / sample_limit, m = (n + stride - 1) / stride;
    std::vector<double> sample(m * dims);
    ::SpectralSeg::internal::parallel_range(0, m, exec.threads(), [&](std::size_t i) {
      for(std::size_t j = 0; j < dims; ++j)
        sample[i * dims + j] = points(Eigen::Index(i * stride), Eigen::Index(j));
    });
    internal::lloyd(sample.data(), m, dims, dims, 1, r, max_iterations, exec);
    if(full_rounds > 0)
      max_iterations = std::min(max_iterations, full_rounds);
  }
  internal::lloyd(points.data(), n, dims, 1, n, r, max_iterations, exec);
  return r;
}
#else
;
#endif

} // namespace Clustering
} // namespace SpectralSeg

#endif
