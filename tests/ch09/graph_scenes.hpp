#pragma once
// Contact graphs for the chapter 9 tests: the named scenes, whose levels are derived by
// hand in the comments; seeded random graphs; and a brute-force reachability that shares
// no code with the library, as the independent reference for the property tests.

#include <cstdint>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/contact_levels.hpp"

namespace stackbook::testing {

/// The plank on two stacks of equal height. Bodies: ground 0; the short stack 1, 2 (two
/// boxes of height h); the tall stack 3, 4, 5, 6 (four boxes of height h/2); the plank 7
/// on boxes 2 and 6. The chapter's worked example of why BFS depth fails.
struct PlankOnTwoStacks {
  static constexpr int ground = 0;
  static constexpr int topOfShortStack = 2;
  static constexpr int topOfTallStack = 6;
  static constexpr int plank = 7;
  static constexpr int bodyCount = 8;
  static std::vector<ContactPair> edges() {
    return {{0, 1}, {1, 2}, {2, 7}, {0, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}};
  }
  static ContactGraph graph() { return ContactGraph(bodyCount, edges()); }
};

/// Uniform integer in [lo, hi] from the raw 64-bit output of the engine. (The standard
/// distributions are not specified bit for bit, so the same seed could give different
/// graphs on different standard libraries; this cannot.)
inline int uniformInt(std::mt19937_64& engine, int lo, int hi) {
  const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1;
  return lo + static_cast<int>(engine() % span);
}

/// Fisher-Yates shuffle driven by uniformInt (std::shuffle is not portable bit for bit).
template <class T>
void shuffleInPlace(std::vector<T>& items, std::mt19937_64& engine) {
  for (std::size_t i = items.size(); i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(uniformInt(engine, 0, static_cast<int>(i - 1)));
    std::swap(items[i - 1], items[j]);
  }
}

/// `edgeDraws` random edges over n bodies that never close a cycle: the bodies get a random
/// rank and every edge points from the lower rank to the higher. Duplicates may occur.
inline std::vector<ContactPair> randomAcyclicEdges(std::mt19937_64& engine, int n, int edgeDraws) {
  std::vector<int> rank(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) rank[static_cast<std::size_t>(i)] = i;
  shuffleInPlace(rank, engine);
  std::vector<ContactPair> edges;
  for (int draw = 0; draw < edgeDraws && n > 1; ++draw) {
    const int a = uniformInt(engine, 0, n - 1);
    const int b = uniformInt(engine, 0, n - 1);
    if (a == b) continue;
    const bool aLower = rank[static_cast<std::size_t>(a)] < rank[static_cast<std::size_t>(b)];
    edges.push_back(aLower ? ContactPair{a, b} : ContactPair{b, a});
  }
  return edges;
}

/// `edgeDraws` random edges in random directions, so cycles of every length occur, plus
/// `mutualDraws` mutual pairs (a -> b and b -> a). Duplicates may occur.
inline std::vector<ContactPair> randomCyclicEdges(std::mt19937_64& engine, int n, int edgeDraws,
                                                  int mutualDraws) {
  std::vector<ContactPair> edges;
  for (int draw = 0; draw < edgeDraws + mutualDraws && n > 1; ++draw) {
    const int a = uniformInt(engine, 0, n - 1);
    const int b = uniformInt(engine, 0, n - 1);
    if (a == b) continue;
    edges.push_back(ContactPair{a, b});
    if (draw >= edgeDraws) edges.push_back(ContactPair{b, a});
  }
  return edges;
}

/// reach[u][v]: v can be reached from u along zero or more edges. Warshall's transitive
/// closure of the raw edge list, O(n^3): the brute-force reference for small graphs.
inline std::vector<std::vector<char>> reachability(int n, const std::vector<ContactPair>& edges) {
  const std::size_t nn = static_cast<std::size_t>(n);
  std::vector<std::vector<char>> reach(nn, std::vector<char>(nn, 0));
  for (std::size_t u = 0; u < nn; ++u) reach[u][u] = 1;
  for (const ContactPair& e : edges) {
    reach[static_cast<std::size_t>(e.below)][static_cast<std::size_t>(e.above)] = 1;
  }
  for (std::size_t k = 0; k < nn; ++k) {
    for (std::size_t u = 0; u < nn; ++u) {
      if (!reach[u][k]) continue;
      for (std::size_t v = 0; v < nn; ++v) {
        if (reach[k][v]) reach[u][v] = 1;
      }
    }
  }
  return reach;
}

/// A span's elements as a vector, for comparisons in CHECKs.
template <class T>
std::vector<T> toVector(std::span<const T> items) {
  return std::vector<T>(items.begin(), items.end());
}

/// The bodies of every level, level by level.
inline std::vector<std::vector<int>> levelBodies(const ContactLevels& levels) {
  std::vector<std::vector<int>> all;
  for (std::size_t l = 0; l < levels.levelCount(); ++l) all.push_back(toVector(levels.bodies(l)));
  return all;
}

/// The message of the std::invalid_argument that `call` throws ("" if it throws nothing).
template <class Call>
std::string invalidArgumentMessage(Call&& call) {
  try {
    call();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

}  // namespace stackbook::testing
