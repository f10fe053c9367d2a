// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Fill_reducing_order.h
/// \brief A fill-reducing elimination order of a mesh's vertices or faces,
/// computed once on a whole piece and inherited by the pieces cut from it.
#ifndef SPECTRALSEG_INTERNAL_FILL_REDUCING_ORDER_H
#define SPECTRALSEG_INTERNAL_FILL_REDUCING_ORDER_H

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace SpectralSeg {
namespace internal {

typedef Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> Elimination_permutation;

// The approximate-minimum-degree permutation P of the symmetric pattern
// given by `pairs` on n unknowns (P A P^T is factorised with little fill):
// the permutation Eigen's SimplicialLDLT would apply.
template <typename Index>
Elimination_permutation amd_permutation(std::size_t n, const std::vector<std::pair<Index, Index>>& pairs)
{
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(2 * pairs.size() + n);
  for(const auto& p : pairs)
  {
    t.emplace_back(int(p.first), int(p.second), 1.);
    t.emplace_back(int(p.second), int(p.first), 1.);
  }
  for(std::size_t i = 0; i < n; ++i)
    t.emplace_back(int(i), int(i), 1.);
  Eigen::SparseMatrix<double> pattern(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  pattern.setFromTriplets(t.begin(), t.end());
  Elimination_permutation inverse;
  Eigen::AMDOrdering<int> amd;
  amd(pattern, inverse);
  return inverse.inverse();
}

// Ranks of a mesh's elements (vertices or faces) in the elimination order of
// the piece they were last ordered with. A piece cut from that piece
// eliminates its elements in the same relative order: the order of the
// whole is a good order of each part, and its cost is paid once per
// connected component instead of once per piece and operator.
class Fill_reducing_order
{
public:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  explicit Fill_reducing_order(std::size_t elements = 0) : rank_(elements, none) {}

  // records P (local i goes to position P(i)) for the mesh elements `globals`
  void assign(const std::vector<std::uint32_t>& globals, const Elimination_permutation& p)
  {
    for(std::size_t i = 0; i < globals.size(); ++i)
      rank_[globals[i]] = std::uint32_t(p.indices()(Eigen::Index(i)));
  }

  // the inherited permutation of a piece's elements `globals` (empty when
  // one of them was never ordered); ties, as between components that share
  // a vertex, go by local index
  Elimination_permutation restricted(const std::vector<std::uint32_t>& globals) const
  {
    Elimination_permutation p;
    std::vector<std::uint32_t> local(globals.size());
    std::iota(local.begin(), local.end(), std::uint32_t(0));
    for(std::uint32_t g : globals)
      if(g >= rank_.size() || rank_[g] == none)
        return p;
    std::sort(local.begin(), local.end(), [&](std::uint32_t a, std::uint32_t b) {
      return rank_[globals[a]] < rank_[globals[b]] || (rank_[globals[a]] == rank_[globals[b]] && a < b);
    });
    p.resize(Eigen::Index(globals.size()));
    for(std::size_t k = 0; k < local.size(); ++k)
      p.indices()(Eigen::Index(local[k])) = int(k);
    return p;
  }

private:
  std::vector<std::uint32_t> rank_;
};

// A sparse LDL^T factorisation of P A P^T for a given elimination
// permutation P (empty: the approximate minimum degree of A's pattern),
// solving A x = b.
class Permuted_ldlt
{
public:
  // the permutation to use; call before compute()
  void set_permutation(Elimination_permutation p) { p_ = std::move(p); }

  void compute(const Eigen::SparseMatrix<double>& a)
  {
    if(p_.size() != a.rows())
      p_ = amd_of(a);
    ldlt_.compute(twisted(a));
  }
  Eigen::ComputationInfo info() const { return ldlt_.info(); }
  template <typename In, typename Out>
  void solve(const In& b, Out& x) const
  {
    x = p_.transpose() * ldlt_.solve(p_ * b);
  }

private:
  static Elimination_permutation amd_of(const Eigen::SparseMatrix<double>& a)
  {
    std::vector<std::pair<int, int>> pairs;
    for(Eigen::Index c = 0; c < a.outerSize(); ++c)
      for(Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it)
        if(it.row() < c)
          pairs.emplace_back(int(it.row()), int(c));
    return amd_permutation(std::size_t(a.rows()), pairs);
  }
  Eigen::SparseMatrix<double> twisted(const Eigen::SparseMatrix<double>& a) const
  {
    Eigen::SparseMatrix<double> b;
    b = a.twistedBy(p_);
    return b;
  }

  Elimination_permutation p_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt_;
};

} // namespace internal
} // namespace SpectralSeg

#endif // SPECTRALSEG_INTERNAL_FILL_REDUCING_ORDER_H
