// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Blend.h
/// \brief A weighted mix of normalised metrics (thesis 3.5).
#ifndef SPECTRALSEG_METRICS_BLEND_H
#define SPECTRALSEG_METRICS_BLEND_H

#include <SpectralSeg/Dual_graph.h>
#include <SpectralSeg/Execution.h>
#include <SpectralSeg/Metrics/metric_values.h>
#include <SpectralSeg/Metrics/normalize_weights.h>
#include <SpectralSeg/exceptions.h>

#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace Metrics {

/// \ingroup PkgSpectralSegMetrics
/// \brief Mixes several dual-edge metrics: each component's weights are
/// normalised into \f$[0, 1]\f$ by `normalize_weights()` (by default by
/// their maximum, as in the thesis; see `set_normalization()`), then summed
/// with the blend coefficients (\f$\alpha\f$, \f$\beta\f$, \f$\gamma\f$, ...
/// in the thesis).
///
/// The coefficients must be finite and non-negative, not all zero; they are
/// divided by their sum, so that they add up to 1 as in the thesis. A
/// component whose coefficient is zero is not computed at all.
///
/// \tparam Components models of `DualEdgeWeight`
///
/// \cgalModels `DualEdgeWeight`
template <typename... Components>
class Blend
{
public:
  /// number of components
  static constexpr std::size_t size = sizeof...(Components);

  /// \param coefficients one coefficient per component
  /// \param components the component metrics
  explicit Blend(const std::array<double, size>& coefficients, Components... components)
    : coefficients_(coefficients), components_(std::move(components)...)
  {
    double sum = 0;
    for(double c : coefficients_)
    {
      if(!(c >= 0) || !std::isfinite(c))
        throw Invalid_input("Blend: coefficients must be finite and non-negative");
      sum += c;
    }
    if(!(sum > 0))
      throw Invalid_input("Blend: at least one coefficient must be positive");
    for(double& c : coefficients_)
      c /= sum;
  }

  /// the coefficients, normalised to add up to 1
  const std::array<double, size>& coefficients() const { return coefficients_; }

  /// how each component is brought into [0, 1] (default: by its maximum)
  const Normalization& normalization() const { return normalization_; }
  /// sets the normalisation of the components
  void set_normalization(const Normalization& n) { normalization_ = n; }
  /// the components
  const std::tuple<Components...>& components() const { return components_; }

  /// `"blend(name1*c1 + ...)"`
  std::string name() const
  {
    std::string s = "blend(";
    append_names(s, std::index_sequence_for<Components...>());
    return s + ")";
  }

  /// one weight per dual edge of `graph`
  std::vector<double> operator()(const Dual_graph& graph, const Execution& exec = Execution()) const
  {
    return (*this)(graph, exec, nullptr);
  }

  /// one weight per dual edge of `graph`; with `face_thickness`, the faces'
  /// thickness reported by the first component computed that reports it
  /// (left empty if none does; see `Metrics::metric_values()`)
  std::vector<double> operator()(const Dual_graph& graph, const Execution& exec,
                                 std::vector<double>* face_thickness) const
  {
    std::vector<double> w(graph.number_of_edges(), 0.);
    if(face_thickness)
      face_thickness->clear();
    accumulate(graph, exec, w, face_thickness, std::index_sequence_for<Components...>());
    return w;
  }

private:
  template <std::size_t... I>
  void accumulate(const Dual_graph& graph, const Execution& exec, std::vector<double>& w,
                  std::vector<double>* face_thickness, std::index_sequence<I...>) const
  {
    (add_component(std::get<I>(components_), coefficients_[I], normalization_, graph, exec, w, face_thickness),
     ...);
  }

  template <typename C>
  static void add_component(const C& c, double coefficient, const Normalization& normalization,
                            const Dual_graph& graph, const Execution& exec, std::vector<double>& w,
                            std::vector<double>* face_thickness)
  {
    if(coefficient == 0.)
      return;
    Metric_values v;
    if(face_thickness && face_thickness->empty())
      v = metric_values(c, graph, exec);
    else
      v.weights = c(graph, exec);
    if(!v.face_thickness.empty())
      *face_thickness = std::move(v.face_thickness);
    std::vector<double>& cw = v.weights;
    check_weights(graph, cw, c.name());
    normalize_weights(cw, normalization);
    for(std::size_t e = 0; e < w.size(); ++e)
      w[e] += coefficient * cw[e];
  }

  template <std::size_t... I>
  void append_names(std::string& s, std::index_sequence<I...>) const
  {
    std::size_t k = 0;
    ((s += (k++ ? " + " : "") + std::get<I>(components_).name() + "*" +
           std::to_string(coefficients_[I])),
     ...);
  }

  std::array<double, size> coefficients_;
  std::tuple<Components...> components_;
  Normalization normalization_ = Normalization::maximum();
};

/// \ingroup PkgSpectralSegMetrics
/// \brief Builds a `Blend` from alternating components and coefficients:
/// `make_blend(Geodesic_weight(), 0.01, Angular_weight(), 0.99)`.
template <typename... Args>
auto make_blend(Args&&... args);

/// \cond SKIP_IN_MANUAL
} // namespace Metrics

namespace internal {
template <typename... C, std::size_t... I, typename Tuple>
Metrics::Blend<C...> make_blend_impl(std::index_sequence<I...>, Tuple&& t)
{
  return Metrics::Blend<C...>({static_cast<double>(std::get<2 * I + 1>(t))...}, std::get<2 * I>(t)...);
}
template <typename Tuple, std::size_t... I>
auto make_blend_from_tuple(Tuple&& t, std::index_sequence<I...> seq)
{
  return make_blend_impl<std::decay_t<std::tuple_element_t<2 * I, std::decay_t<Tuple>>>...>(seq, t);
}
} // namespace internal

namespace Metrics {

template <typename... Args>
auto make_blend(Args&&... args)
{
  static_assert(sizeof...(Args) % 2 == 0, "make_blend takes (metric, coefficient) pairs");
  return ::SpectralSeg::internal::make_blend_from_tuple(std::make_tuple(std::forward<Args>(args)...),
                                         std::make_index_sequence<sizeof...(Args) / 2>());
}
/// \endcond

} // namespace Metrics
} // namespace SpectralSeg

#endif // SPECTRALSEG_METRICS_BLEND_H
