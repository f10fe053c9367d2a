// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file graph_cut_boost_backends.h
/// \brief Boost's Boykov-Kolmogorov max-flow as backends of the graph cut
/// (`Refinement::Graph_cut_backend::boost_adjacency_list` and
/// `boost_compressed_sparse_row`).
///
/// Include this header in one translation unit of a program that selects
/// one of these backends in `Refinement::Graph_cut_options::backend` (with
/// `SPECTRALSEG_USE_MAXFLOW` defined; without it `graph_cut_boundaries.h`
/// includes it, since the compressed-sparse-row backend is then the
/// default). Programs that do not include it do not compile Boost's
/// max-flow (doc/benchmarks.md, "Compile time") and, with GCC 12 and
/// Boost 1.74, are spared `-Wmaybe-uninitialized`
/// false positives that `boykov_kolmogorov_max_flow.hpp` gives on the
/// adjacency list, which no diagnostic pragma silences: add
/// `-Wno-maybe-uninitialized` to programs that include this header.
#ifndef SPECTRALSEG_REFINEMENT_GRAPH_CUT_BOOST_BACKENDS_H
#define SPECTRALSEG_REFINEMENT_GRAPH_CUT_BOOST_BACKENDS_H

#include <SpectralSeg/Refinement/graph_cut_boundaries.h>
#include <SpectralSeg/Refinement/internal/alpha_expansion.h>

#include <CGAL/boost/graph/alpha_expansion_graphcut.h>

#include <vector>

namespace SpectralSeg {
namespace Refinement {
/// \cond SKIP_IN_MANUAL
namespace internal {

inline void boost_adjacency_list_max_flow(const Potts_problem& problem, std::vector<std::size_t>& l, unsigned threads,
                                          std::size_t sweeps)
{
  alpha_expansion<CGAL::Alpha_expansion_boost_adjacency_list_impl>(problem, l, threads, sweeps);
}

inline void boost_compressed_sparse_row_max_flow(const Potts_problem& problem, std::vector<std::size_t>& l,
                                                 unsigned threads, std::size_t sweeps)
{
  alpha_expansion<CGAL::Alpha_expansion_boost_compressed_sparse_row_impl>(problem, l, threads, sweeps);
}

// Registers both backends before main() in every program that includes
// this header.
inline const bool boost_max_flow_backends_registered = [] {
  boost_max_flow_backends()[0] = &boost_adjacency_list_max_flow;
  boost_max_flow_backends()[1] = &boost_compressed_sparse_row_max_flow;
  return true;
}();

} // namespace internal
/// \endcond
} // namespace Refinement
} // namespace SpectralSeg

#endif // SPECTRALSEG_REFINEMENT_GRAPH_CUT_BOOST_BACKENDS_H
