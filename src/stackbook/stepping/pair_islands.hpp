#pragma once
/// \file
/// \brief The islands of one sweep (chapter 10, "Threads"): the pairs of a sweep grouped
/// into connected components over the dynamic bodies they touch. An impulse changes only
/// the velocities of its pair's dynamic bodies and the tested poses of those bodies, so
/// two pairs of different islands read and write disjoint data and may run at the same
/// time; within an island the pairs keep the sweep's order.

#include <algorithm>
#include <cstddef>
#include <vector>

#include "stackbook/collision/broad_phase.hpp"
#include "stackbook/stepping/world.hpp"

namespace stackbook {

namespace detail {

/// The pairs 0 .. classOf.size() - 1 grouped by class, in compressed form: class c holds
/// pairs[begin[c]] .. pairs[begin[c + 1] - 1], ascending (a counting sort, stable).
inline void groupPairsByClass(const std::vector<std::size_t>& classOf, std::size_t classes,
                              std::vector<std::size_t>& begin, std::vector<std::size_t>& pairs) {
  begin.assign(classes + 1, 0);
  for (const std::size_t c : classOf) ++begin[c + 1];
  for (std::size_t c = 0; c < classes; ++c) begin[c + 1] += begin[c];
  pairs.resize(classOf.size());
  std::vector<std::size_t> next(begin.begin(), begin.end() - 1);
  for (std::size_t k = 0; k < classOf.size(); ++k) pairs[next[classOf[k]]++] = k;
}

}  // namespace detail

// [pair_islands]
/// The islands of a list of pairs, in compressed form: island c holds the pair indices
/// pairs[begin[c]] .. pairs[begin[c + 1] - 1], ascending (the sweep's order). Islands are
/// numbered by their first pair in the list, so the numbering depends only on the list
/// and on which bodies are static, never on threads.
struct PairIslands {
  std::vector<std::size_t> begin;  ///< size islandCount() + 1
  std::vector<std::size_t> pairs;  ///< pair indices, island by island

  std::size_t islandCount() const { return begin.empty() ? 0 : begin.size() - 1; }
  std::size_t size(std::size_t c) const { return begin[c + 1] - begin[c]; }
};

/// Union-find over the dynamic bodies of `pairs` (Eq. (10.8)): two pairs share an island
/// when a chain of pairs links them through dynamic bodies. A static body (1/m = 0 and
/// I^{-1} = 0, which includes bodies frozen by shock propagation) joins nothing: impulses
/// never change it. A pair of two static bodies is an island of its own. O(p) per call, for
/// any number n of bodies in the world (O(n) once per thread for the table).
template <int D>
PairIslands pairIslands(const World<D>& world, const std::vector<BodyPair>& pairs) {
  // The dynamic bodies the pairs touch get local numbers 0, 1, ... in order of first
  // appearance, through a per-thread table of the world's size that is filled with -1 once
  // and put back entry by entry, so that a sweep costs O(p) however many bodies the world
  // has: the pass sweeps each level of a few dozen pairs up to 20 times (chapter 9).
  const std::size_t n = world.bodies.size();
  thread_local std::vector<int> localOf;
  if (localOf.size() < n) localOf.resize(n, -1);
  std::vector<int> touched;  // local number -> body
  struct PutBack {
    std::vector<int>& table;
    const std::vector<int>& bodies;
    ~PutBack() {
      for (const int b : bodies) table[static_cast<std::size_t>(b)] = -1;
    }
  } putBack{localOf, touched};
  const auto dynamic = [&world](int i) { return !world.bodies[static_cast<std::size_t>(i)].isStatic(); };
  const auto local = [&](int body) {
    int& slot = localOf[static_cast<std::size_t>(body)];
    if (slot < 0) {
      slot = static_cast<int>(touched.size());
      touched.push_back(body);
    }
    return slot;
  };
  std::vector<int> parent;  // union-find over local numbers
  const auto find = [&parent](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      int& p = parent[static_cast<std::size_t>(i)];
      p = parent[static_cast<std::size_t>(p)];  // path halving
      i = p;
    }
    return i;
  };
  std::vector<int> pairBody(pairs.size(), -1);  // a dynamic body of each pair, local; -1: none
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const BodyPair& p = pairs[k];
    const bool first = dynamic(p.first), second = dynamic(p.second);
    if (!first && !second) continue;
    const int a = first ? local(p.first) : -1, b = second ? local(p.second) : -1;
    while (parent.size() < touched.size()) parent.push_back(static_cast<int>(parent.size()));  // new roots
    pairBody[k] = first ? a : b;
    if (first && second) {
      const int ra = find(a), rb = find(b);
      if (ra != rb) parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
  }
  // Island of each pair, numbered in order of first appearance in the list.
  std::vector<int> islandOfRoot(touched.size(), -1);
  std::vector<std::size_t> islandOfPair(pairs.size());
  std::size_t islands = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (pairBody[k] < 0) {
      islandOfPair[k] = islands++;
      continue;
    }
    int& island = islandOfRoot[static_cast<std::size_t>(find(pairBody[k]))];
    if (island < 0) island = static_cast<int>(islands++);
    islandOfPair[k] = static_cast<std::size_t>(island);
  }
  PairIslands out;
  detail::groupPairsByClass(islandOfPair, islands, out.begin, out.pairs);
  return out;
}
// [pair_islands]

}  // namespace stackbook
