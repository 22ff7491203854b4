#pragma once
/// \file
/// \brief The colours of one sweep (chapter 10, "Colours"): the pairs of a sweep split into
/// classes in which no two pairs share a dynamic body, by the greedy rule in the sweep's
/// order. A sweep that visits its pairs colour by colour (PairOrder::Colours) may run each
/// colour's pairs at the same time, even when they all form one island.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "stackbook/collision/broad_phase.hpp"
#include "stackbook/stepping/pair_islands.hpp"
#include "stackbook/stepping/world.hpp"

namespace stackbook {

// [pair_colours]
/// The colours of a list of pairs, in compressed form: colour c holds the pair indices
/// pairs[begin[c]] .. pairs[begin[c + 1] - 1], ascending (the sweep's order). Colours
/// 0 .. kPairColours - 1 are independent: no two pairs of one share a dynamic body. The
/// last class, kPairColours, takes the pairs that found all of those taken by their bodies;
/// its pairs may share bodies, so it is swept in order on one thread.
struct PairColours {
  static constexpr int kPairColours = 64;  ///< independent colours (one bit each per body)
  std::vector<std::size_t> begin;          ///< size kPairColours + 2
  std::vector<std::size_t> pairs;          ///< pair indices, colour by colour

  std::size_t classCount() const { return begin.empty() ? 0 : begin.size() - 1; }
  std::size_t size(std::size_t c) const { return begin[c + 1] - begin[c]; }
  bool independent(std::size_t c) const { return c < static_cast<std::size_t>(kPairColours); }
};

/// Greedy colouring in list order (Eq. (10.10)): pair k takes the smallest colour that no
/// earlier pair sharing one of its dynamic bodies took. A static body (including one frozen
/// by shock propagation) constrains nothing, as for islands (Eq. (10.8)): impulses never
/// change it. A pair with no dynamic body takes colour 0. Depends only on the list and on
/// which bodies are static, never on threads. O(p) per call, through a per-thread table of
/// the world's size, filled with 0 once and put back entry by entry (as pairIslands()).
template <int D>
PairColours pairColours(const World<D>& world, const std::vector<BodyPair>& pairs) {
  constexpr std::size_t kOverflow = PairColours::kPairColours;
  thread_local std::vector<std::uint64_t> takenBy;  // per body: bit c set when a pair of it has colour c
  if (takenBy.size() < world.bodies.size()) takenBy.resize(world.bodies.size(), 0);
  std::vector<int> touched;  // bodies whose entry is not 0
  struct PutBack {
    std::vector<std::uint64_t>& table;
    const std::vector<int>& bodies;
    ~PutBack() {
      for (const int b : bodies) table[static_cast<std::size_t>(b)] = 0;
    }
  } putBack{takenBy, touched};
  const auto dynamic = [&world](int i) { return !world.bodies[static_cast<std::size_t>(i)].isStatic(); };
  std::vector<std::size_t> colourOf(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const int bodies[2] = {pairs[k].first, pairs[k].second};
    std::uint64_t taken = 0;
    for (const int b : bodies) {
      if (dynamic(b)) taken |= takenBy[static_cast<std::size_t>(b)];
    }
    // The lowest colour free at both bodies; none free: the overflow class.
    const std::size_t c = taken == ~std::uint64_t{0} ? kOverflow : static_cast<std::size_t>(std::countr_one(taken));
    colourOf[k] = c;
    if (c == kOverflow) continue;
    for (const int b : bodies) {
      if (!dynamic(b)) continue;
      std::uint64_t& bits = takenBy[static_cast<std::size_t>(b)];
      if (bits == 0) touched.push_back(b);
      bits |= std::uint64_t{1} << c;
    }
  }
  PairColours out;
  detail::groupPairsByClass(colourOf, kOverflow + 1, out.begin, out.pairs);  // the colours, then the overflow
  return out;
}
// [pair_colours]

}  // namespace stackbook
