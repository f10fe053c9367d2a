// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Memory and work estimates of a segmentation, checked before it starts:
// what would not fit is refused with the figure and the option to change.
#ifndef SPECTRALSEG_TOOLS_WORK_LIMITS_H
#define SPECTRALSEG_TOOLS_WORK_LIMITS_H

#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

namespace spectralseg_cli {

// Documented limits (user manual, "Limits"), measured on the 52,000-face
// armadillo (2 cores): 50 clusters take 20 s, 200 more than 5 minutes
// (K-means and the graph cut grow with their square); 1,000 Nyström samples
// take 2 minutes (one Dijkstra run per sample, twice).
constexpr std::size_t max_clusters = 100;
constexpr std::size_t max_samples = 2000;
constexpr double max_sample_face_pairs = 1e8; // samples x faces

// The memory this process may use, in bytes: the smallest of the physical
// memory, the address-space limit (ulimit -v) and the cgroup limit.
inline double memory_budget_bytes()
{
  double budget = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
  struct rlimit r;
  if(getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
    budget = std::min(budget, double(r.rlim_cur));
  for(const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"})
  {
    std::ifstream in(path);
    double limit = 0.;
    if(in >> limit && limit > 0.)
      budget = std::min(budget, limit);
  }
  return budget;
}

inline std::string gigabytes(double bytes)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f GB", bytes / 1e9);
  return text;
}

// The embedding `segment` will compute on `faces` faces with `clusters`
// K-means clusters (k + extra clusters, or --max-k for --k auto), as
// k_way_segmentation.h chooses it, and the memory it needs.
struct Segment_plan
{
  bool exact = false;
  std::size_t samples = 0;
  double bytes = 0.;
};

inline Segment_plan plan_segmentation(std::size_t faces, std::size_t clusters, const std::string& sampling,
                                      std::size_t samples, std::size_t exact_face_limit)
{
  Segment_plan p;
  const std::size_t dims = std::min(clusters, faces - 1);
  p.samples = samples > 0 ? samples : dims + 1;
  p.exact = sampling == "exact" || (sampling == "auto" && faces <= exact_face_limit) || p.samples > faces;
  const double n = double(faces), l = double(p.samples);
  // exact: the n x n distances turned affinities, their symmetrised copy
  // and the solver's dense copy; Nyström: the l x n sample rows, their
  // extension to every face (n x l), the l x l blocks; both: the embedding
  p.bytes = 8. * (p.exact ? 3. * n * n : 2. * l * n + 3. * l * l) + 8. * n * double(dims);
  return p;
}

// Refuses, before any work, a segmentation that would not fit in memory or
// would run for hours. Throws Invalid_input (exit code 1) naming the figure
// and the option to change.
inline void check_segmentation_fits(std::size_t faces, std::size_t clusters, const std::string& sampling,
                                    std::size_t samples, std::size_t exact_face_limit)
{
  if(clusters > max_clusters)
    throw SpectralSeg::Invalid_input("k-way segmentation into " + std::to_string(clusters) +
                                     " clusters (k plus --extra-clusters or --alternative-extra-clusters, --contrast-merge-clusters, or --max-k): at most " +
                                     std::to_string(max_clusters) +
                                     " are supported (K-means and the graph cut grow with their square)");
  const Segment_plan p = plan_segmentation(faces, clusters, sampling, samples, exact_face_limit);
  if(!p.exact && double(p.samples) * double(faces) > max_sample_face_pairs)
    throw SpectralSeg::Invalid_input(std::to_string(p.samples) + " Nyström samples on " + std::to_string(faces) +
                                     " faces: samples x faces is limited to 10^8 (about " +
                                     std::to_string(std::size_t(max_sample_face_pairs / double(faces))) +
                                     " samples here; each sample costs two Dijkstra runs over every face); use "
                                     "fewer --samples (the default, k + extra clusters + 1, is usually enough)");
  const double budget = memory_budget_bytes();
  if(p.bytes > 0.8 * budget)
  {
    const std::string what = p.exact ? "the exact embedding of " + std::to_string(faces) + " faces (3 matrices of " +
                                         std::to_string(faces) + " x " + std::to_string(faces) + " doubles)"
                                     : "the Nyström embedding with " + std::to_string(p.samples) + " samples of " +
                                         std::to_string(faces) + " faces";
    const std::string instead = p.exact ? (sampling == "exact" ? "use --sampling nystrom (memory grows as faces times samples)"
                                                               : "use fewer --samples, below the number of faces")
                                        : "use fewer --samples or a smaller --k";
    throw SpectralSeg::Invalid_input(what + " needs about " + gigabytes(p.bytes) + " of memory but " +
                                     gigabytes(budget) + " are available (80% may be used): " + instead);
  }
}

} // namespace spectralseg_cli

#endif
