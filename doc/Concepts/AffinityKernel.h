// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Documentation only: this file describes a concept. It is read by Doxygen and
// never included by code.

/// \ingroup PkgSpectralSegConcepts
/// \cgalConcept
///
/// \brief Turns the distance between two faces into an affinity (a
/// similarity in \f$[0, 1]\f$) for the spectral embedding.
///
/// The embedding (`SpectralSeg::Embedding::exact_spectral_embedding()`,
/// `SpectralSeg::Embedding::nystrom_spectral_embedding()`) first computes
/// the mean \f$\bar G\f$ of all the finite distances it has (the whole
/// distance matrix, or the rows of the Nyström samples), asks the kernel
/// for a width \f$\sigma\f$ = `width(`\f$\bar G\f$`)`, and then replaces
/// every finite distance \f$G_{ij}\f$ by
/// `operator()(`\f$G_{ij}\f$`, `\f$\sigma\f$`)`. Infinite distances (faces in
/// different connected components) get affinity 0 without calling the
/// kernel. When the mean distance is 0, the width is 1.
///
/// Requirements on the model:
/// - the affinity of a face with itself (distance 0) is 1, and the
///   affinity decreases as the distance grows;
/// - `width()` returns a positive value for a positive mean distance;
/// - both functions are `const`, thread-safe and cheap: the call operator
///   runs once per entry of the matrix, in parallel;
/// - the model is copyable (it is passed by value in named parameters).
///
/// The Nyström quality measure (`SpectralSeg::Embedding::nystrom_gamma()`)
/// assumes that the affinity of a face with itself is 1.
///
/// \cgalHasModel
/// - `SpectralSeg::Kernels::Exponential_kernel` (the default):
///   \f$e^{-G / (2\sigma^2)}\f$ with \f$\sigma = \sqrt{\bar G}\f$
/// - `SpectralSeg::Kernels::Gaussian_kernel`:
///   \f$e^{-G^2 / (2\sigma^2)}\f$ with \f$\sigma = \bar G\f$
/// - `SpectralSeg::Kernels::Any_kernel`: any of them, chosen at run time
class AffinityKernel
{
public:
  /// A short name, e.g. `"exponential"`.
  std::string name() const;

  /// The kernel width \f$\sigma\f$ for a mean distance `mean_distance`
  /// (positive).
  double width(double mean_distance) const;

  /// The affinity of two faces at the finite, non-negative distance
  /// `distance`, for the kernel width `width` returned by `width()`.
  double operator()(double distance, double width) const;
};
