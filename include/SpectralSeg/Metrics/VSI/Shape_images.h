// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Shape_images.h
/// \brief Volumetric shape images: the local reach of the shape around each
/// reference point along fixed directions (thesis 3.4.3).
#ifndef SPECTRALSEG_METRICS_VSI_SHAPE_IMAGES_H
#define SPECTRALSEG_METRICS_VSI_SHAPE_IMAGES_H

#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Metrics/VSI/ray_directions.h>
#include <SpectralSeg/Metrics/VSI/spread_samples.h>
#include <SpectralSeg/internal/Point_neighbours.h>
#include <SpectralSeg/internal/parallel_for.h>
#include <SpectralSeg/internal/separate_compilation.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace SpectralSeg {
namespace Metrics {
namespace VSI {

/// \ingroup PkgSpectralSegVSI
/// \brief Parameters of the volumetric shape images.
struct Shape_image_options
{
  /// antipodal ray pairs per image (the thesis's \f$m = 100\f$ rays)
  std::size_t ray_pairs = 50;
  /// fraction of the faces whose image is computed by casting rays; the
  /// others are interpolated (thesis: 1%); 1 computes every image
  double sample_fraction = 0.01;
  /// but never fewer than this many sampled faces (or all faces, if fewer):
  /// 1% of a small mesh is too few to follow its parts (our addition)
  std::size_t minimum_samples = 500;
  /// sampled images mixed, by inverse squared distance between reference
  /// points, to interpolate the image of a face that is not sampled
  std::size_t interpolation_neighbours = 4;
};

/// \ingroup PkgSpectralSegVSI
/// \brief One image per face: row `f` holds the local reaches \f$l^{(k)}\f$
/// of face `f`, the distance between the two surface points hit by the
/// \f$k\f$-th antipodal ray pair from its reference point. A pair with a ray
/// that hits nothing (open meshes) is `NaN` and ignored by comparisons.
struct Shape_images
{
  /// faces x ray pairs, row-major
  Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> reaches;
  /// the faces whose image was computed by casting rays
  std::vector<std::uint32_t> sampled_faces;
};

/// \ingroup PkgSpectralSegVSI
/// \brief Computes the shape image of every face from its reference point.
///
/// Images of a spread-out sample of faces (`spread_samples()` on the
/// reference points) are measured by casting `2 * ray_pairs` rays in fixed
/// global directions (`antipodal_directions()`); every other face's image is
/// the inverse-squared-distance mix of the images of the sampled faces with
/// the nearest reference points, component by component, skipping `NaN`
/// components.
///
/// \tparam RayCaster a model of `RayCaster`
template <typename RayCaster>
Shape_images compute_shape_images(const std::vector<Eigen::Vector3d>& reference_points, const RayCaster& caster,
                                  const Shape_image_options& options = Shape_image_options(),
                                  const Execution& exec = Execution())
{
  const std::size_t n = reference_points.size();
  const std::size_t m = options.ray_pairs;
  Shape_images out;
  out.reaches.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
  if(n == 0 || m == 0)
    return out;
  const double fraction = std::min(1., std::max(0., options.sample_fraction));
  const std::size_t wanted =
    std::min(n, std::max<std::size_t>({options.minimum_samples, static_cast<std::size_t>(std::ceil(fraction * double(n))), 1}));
  out.sampled_faces = spread_samples(reference_points, wanted);
  const std::size_t s = out.sampled_faces.size();

  const std::vector<Eigen::Vector3d> dirs = antipodal_directions(m);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> sampled(static_cast<Eigen::Index>(s),
                                                                               static_cast<Eigen::Index>(m));
  internal::parallel_for(s, exec, "shape images", [&](std::size_t i) {
    std::vector<double> t(dirs.size());
    caster.first_hits(reference_points[out.sampled_faces[i]], dirs.data(), dirs.size(), RayCaster::no_face,
                      t.data());
    for(std::size_t k = 0; k < m; ++k)
    {
      const double reach = t[2 * k] + t[2 * k + 1];
      sampled(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) =
        std::isfinite(reach) ? static_cast<float>(reach) : nan;
    }
  });

  if(s == n)
  {
    for(std::size_t i = 0; i < s; ++i)
      out.reaches.row(out.sampled_faces[i]) = sampled.row(static_cast<Eigen::Index>(i));
    return out;
  }

  std::vector<Eigen::Vector3d> sample_points;
  for(std::uint32_t f : out.sampled_faces)
    sample_points.push_back(reference_points[f]);
  const internal::Point_neighbours knn(sample_points);
  const std::size_t k_nb = std::max<std::size_t>(1, options.interpolation_neighbours);
  internal::parallel_for(n, exec, "shape image interpolation", [&](std::size_t f) {
    // each thread's storage, reused from face to face
    thread_local std::vector<std::pair<std::size_t, double>> nearest;
    thread_local std::vector<double> sum, wsum;
    knn.nearest(reference_points[f], k_nb, nearest);
    if(!nearest.empty() && nearest.front().second == 0.)
      nearest.resize(1); // a sampled face (or a coincident point) keeps its own image
    sum.assign(m, 0.);
    wsum.assign(m, 0.);
    for(const auto& q : nearest)
    {
      const double w = q.second > 0 ? 1. / q.second : 1.;
      for(std::size_t k = 0; k < m; ++k)
      {
        const float v = sampled(static_cast<Eigen::Index>(q.first), static_cast<Eigen::Index>(k));
        if(!std::isnan(v))
        {
          sum[k] += w * v;
          wsum[k] += w;
        }
      }
    }
    for(std::size_t k = 0; k < m; ++k)
      out.reaches(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(k)) =
        wsum[k] > 0 ? static_cast<float>(sum[k] / wsum[k]) : nan;
  });
  return out;
}

/// \ingroup PkgSpectralSegVSI
/// \brief The difference of two shape images (thesis eq. 3.3 and 3.4).
///
/// With \f$d_k = (l_i^{(k)} - l_j^{(k)})^2\f$ over the pairs measured in
/// both images, \f$u\f$ their mean and \f$s\f$ their standard deviation,
/// each \f$d_k\f$ gets the weight \f$w_k = e^{-(d_k - u)^2 / (2 s^2)}\f$ if
/// \f$d_k < u + 2s\f$ and 0 otherwise (all weights are 1 when \f$s = 0\f$),
/// and the difference is \f$\sum_k w_k d_k / \sum_k w_k\f$.
/// Returns `NaN` when no pair is measured in both images.
SPECTRALSEG_INLINE double image_difference(const float* a, const float* b, std::size_t m)
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  double d[512];
  std::vector<double> big;
  double* dk = d;
  if(m > 512)
  {
    big.resize(m);
    dk = big.data();
  }
  std::size_t c = 0;
  double mean = 0.;
  for(std::size_t k = 0; k < m; ++k)
  {
    if(std::isnan(a[k]) || std::isnan(b[k]))
      continue;
    const double diff = double(a[k]) - double(b[k]);
    dk[c] = diff * diff;
    mean += dk[c];
    ++c;
  }
  if(c == 0)
    return std::numeric_limits<double>::quiet_NaN();
  mean /= double(c);
  double var = 0.;
  for(std::size_t k = 0; k < c; ++k)
    var += (dk[k] - mean) * (dk[k] - mean);
  var /= double(c);
  if(!(var > 0))
    return mean;
  const double sd = std::sqrt(var);
  double num = 0., den = 0.;
  for(std::size_t k = 0; k < c; ++k)
  {
    if(dk[k] >= mean + 2. * sd)
      continue;
    const double w = std::exp(-(dk[k] - mean) * (dk[k] - mean) / (2. * var));
    num += w * dk[k];
    den += w;
  }
  return den > 0 ? num / den : mean;
}
#else
;
#endif

/// \ingroup PkgSpectralSegVSI
/// \brief The median of each face's local reaches, the chords through its
/// reference point (`NaN` for a face with no measured pair).
///
/// From the middle of a part, the median chord is twice the thickness of a
/// plate, 1.15 times the diameter of a long cylinder and the diameter of a
/// ball. A rough surface shortens only the chords that run along it.
SPECTRALSEG_INLINE std::vector<double> median_reaches(const Shape_images& images, const Execution& exec = Execution())
#if SPECTRALSEG_DEFINE_FUNCTIONS
{
  const auto& reaches = images.reaches;
  std::vector<double> out(static_cast<std::size_t>(reaches.rows()), std::numeric_limits<double>::quiet_NaN());
  internal::parallel_for(out.size(), exec, "median reaches", [&](std::size_t f) {
    thread_local std::vector<float> row;
    row.clear();
    for(Eigen::Index k = 0; k < reaches.cols(); ++k)
    {
      const float v = reaches(static_cast<Eigen::Index>(f), k);
      if(!std::isnan(v))
        row.push_back(v);
    }
    if(row.empty())
      return;
    const auto upper = row.begin() + static_cast<std::ptrdiff_t>(row.size() / 2);
    std::nth_element(row.begin(), upper, row.end());
    double median = *upper;
    if(row.size() % 2 == 0)
      median = 0.5 * (median + double(*std::max_element(row.begin(), upper)));
    out[f] = median;
  });
  return out;
}
#else
;
#endif

} // namespace VSI
} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_VSI_SHAPE_IMAGES_H
