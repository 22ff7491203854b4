#pragma once
/// \file
/// \brief The levels of shock propagation (chapter 9): the order in which the bottom-up
/// pass processes and freezes bodies, and the contact pairs swept at each level. Two
/// layerings side by side: topological levels of the condensed graph (GBF), and BFS depth
/// from the ground (the variant that fails under a plank on two unequal stacks).

#include <algorithm>
#include <cstddef>
#include <functional>
#include <queue>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/strongly_connected_components.hpp"

namespace stackbook {

// [contact_levels]
/// An ordering of the bodies into levels, processed from level 0 upwards, and the contact
/// pairs swept at each level. Stored flat: one array of bodies and one of pairs, each cut
/// into levels by an array of offsets (the compressed layout of sparse graphs).
struct ContactLevels {
  /// levelOfBody[b]: the level of body b.
  std::vector<int> levelOfBody;
  /// All bodies, ordered by level and ascending inside each level.
  std::vector<int> bodyList;
  /// Level l owns bodyList[bodyStart[l] .. bodyStart[l+1]); size levelCount()+1.
  std::vector<std::size_t> bodyStart{0};
  /// All pairs, level by level. Inside level l: for each body of the level (ascending), one
  /// pair {parent, body} per parent (ascending). A mutual pair (each body rests on the
  /// other) is listed once: in the later of the two levels, and inside one level as
  /// {smaller, larger} at the larger body. So every edge belongs to exactly one pair.
  std::vector<ContactPair> pairList;
  /// Level l owns pairList[pairStart[l] .. pairStart[l+1]); size levelCount()+1.
  std::vector<std::size_t> pairStart{0};

  std::size_t levelCount() const { return bodyStart.size() - 1; }
  /// The bodies of level l, ascending.
  std::span<const int> bodies(std::size_t l) const {
    return std::span<const int>(bodyList).subspan(bodyStart[l],
                                                  bodyStart[l + 1] - bodyStart[l]);
  }
  /// The contacts swept at level l, in the order described at pairList.
  std::span<const ContactPair> pairs(std::size_t l) const {
    return std::span<const ContactPair>(pairList).subspan(pairStart[l],
                                                          pairStart[l + 1] - pairStart[l]);
  }

  friend bool operator==(const ContactLevels&, const ContactLevels&) = default;
};
// [contact_levels]

// [level_pairs]
/// The levels and pairs of a given level assignment: levelOfBody has one entry per body,
/// and the levels used are exactly 0..L-1 (no empty level). Both layerings below are built
/// by this function, so they differ only in the assignment. O(n + m log d).
inline ContactLevels levelsFromAssignment(const ContactGraph& graph, std::vector<int> levelOfBody) {
  const int n = graph.bodyCount();
  const std::size_t nn = static_cast<std::size_t>(n);
  if (levelOfBody.size() != nn) {
    throw std::invalid_argument("levelsFromAssignment: levelOfBody has " +
                                std::to_string(levelOfBody.size()) + " entries, the graph has " +
                                std::to_string(n) + " bodies");
  }
  std::size_t levelCount = 0;
  for (std::size_t b = 0; b < nn; ++b) {  // bound: n
    if (levelOfBody[b] < 0) {
      throw std::invalid_argument("levelsFromAssignment: levelOfBody[" + std::to_string(b) +
                                  "] = " + std::to_string(levelOfBody[b]) + " is negative");
    }
    levelCount = std::max(levelCount, static_cast<std::size_t>(levelOfBody[b]) + 1);
  }
  // Counting sort of the bodies by level; bodies are scanned ascending, so each level's
  // bodies come out ascending.
  ContactLevels result;
  result.bodyStart.assign(levelCount + 1, 0);
  for (std::size_t b = 0; b < nn; ++b) {  // bound: n
    ++result.bodyStart[static_cast<std::size_t>(levelOfBody[b]) + 1];
  }
  for (std::size_t l = 0; l < levelCount; ++l) {  // bound: L <= n
    if (result.bodyStart[l + 1] == 0) {
      throw std::invalid_argument("levelsFromAssignment: level " + std::to_string(l) +
                                  " has no body (levels must be 0.." +
                                  std::to_string(levelCount - 1) + " without gaps)");
    }
    result.bodyStart[l + 1] += result.bodyStart[l];
  }
  result.bodyList.resize(nn);
  std::vector<std::size_t> fill(result.bodyStart.begin(), result.bodyStart.end() - 1);
  for (int body = 0; body < n; ++body) {  // bound: n
    const std::size_t level = static_cast<std::size_t>(levelOfBody[static_cast<std::size_t>(body)]);
    result.bodyList[fill[level]++] = body;
  }

  result.pairList.reserve(graph.edgeCount());
  result.pairStart.assign(levelCount + 1, 0);
  // Bound: each body is visited once and each edge once, from its upper end: n + m.
  detail::LoopCap pairCap(nn + graph.edgeCount(), "levelsFromAssignment: pairs");
  for (std::size_t l = 0; l < levelCount; ++l) {
    const int level = static_cast<int>(l);
    for (const int body : result.bodies(l)) {
      pairCap.step();
      for (const int parent : graph.parents(body)) {
        pairCap.step();
        if (graph.hasEdge(body, parent)) {
          // Mutual support: keep one of the two edges, the one seen at the later level,
          // and inside one level the one seen at the larger body.
          const int parentLevel = levelOfBody[static_cast<std::size_t>(parent)];
          if (parentLevel > level || (parentLevel == level && parent > body)) continue;
        }
        result.pairList.push_back(ContactPair{parent, body});
      }
    }
    result.pairStart[l + 1] = result.pairList.size();
  }
  result.levelOfBody = std::move(levelOfBody);
  return result;
}
// [level_pairs]

// [topological_levels]
/// GBF's levels (PhysBAM Generate_Levels): each strongly connected component becomes one
/// level, in a topological order of the condensed graph. Then for every edge u -> v,
/// level(u) <= level(v), with equality exactly when u and v lie on a common cycle.
///
/// Why a topological order and not the BFS depth from the ground: a plank resting on a
/// stack of 2 boxes and on a stack of 4 half-height boxes (equal heights) has BFS depth 3
/// through the short stack, while the top box of the tall stack, directly under the plank,
/// has depth 4. The pass would process and freeze the plank before a body that holds it
/// up. A topological order places a body after all of its supporters, whatever the path
/// lengths: the plank comes after all 7 of its supporters, the 6 boxes and the ground.
///
/// Among the condensed nodes that are free to go next (all their supporters placed), the
/// one with the smallest body goes first (Kahn's algorithm with a min-heap), so the order
/// depends on the edge set only. O(n log n + m). `components` must be
/// stronglyConnectedComponents(graph); the one-argument overload computes them.
inline ContactLevels topologicalLevels(const ContactGraph& graph,
                                       const StronglyConnectedComponents& components) {
  const int n = graph.bodyCount();
  const std::size_t k = components.componentCount();
  if (components.componentOfBody.size() != static_cast<std::size_t>(n)) {
    throw std::invalid_argument("topologicalLevels: components cover " +
                                std::to_string(components.componentOfBody.size()) +
                                " bodies, the graph has " + std::to_string(n));
  }
  auto componentOf = [&](int body) {
    return components.componentOfBody[static_cast<std::size_t>(body)];
  };
  // [kahn_levels]
  // Supporters still to be placed, per component, counting each edge between components.
  std::vector<std::size_t> waitingFor(k, 0);
  for (int body = 0; body < n; ++body) {  // bound: n bodies and m edges
    for (const int child : graph.children(body)) {
      const int cc = componentOf(child);
      if (cc != componentOf(body)) ++waitingFor[static_cast<std::size_t>(cc)];
    }
  }
  // Components are numbered by their smallest body, so the smallest number is the
  // component with the smallest body.
  std::priority_queue<int, std::vector<int>, std::greater<int>> ready;
  for (std::size_t c = 0; c < k; ++c) {
    if (waitingFor[c] == 0) ready.push(static_cast<int>(c));
  }
  std::vector<int> levelOfComponent(k, -1);
  int nextLevel = 0;
  // Bound: each component enters the heap once (when its count reaches 0) and leaves it
  // once, and each edge is relaxed once, from its lower end: at most k + m iterations.
  detail::LoopCap orderCap(k + graph.edgeCount(), "topologicalLevels: ordering");
  while (!ready.empty()) {
    orderCap.step();
    const int c = ready.top();
    ready.pop();
    levelOfComponent[static_cast<std::size_t>(c)] = nextLevel++;
    for (const int body : components.members(static_cast<std::size_t>(c))) {
      for (const int child : graph.children(body)) {
        const int cc = componentOf(child);
        if (cc == c) continue;
        orderCap.step();
        if (--waitingFor[static_cast<std::size_t>(cc)] == 0) ready.push(cc);
      }
    }
  }
  if (static_cast<std::size_t>(nextLevel) != k) {  // [kahn_levels]
    // Only possible if `components` are not the SCCs of `graph` (a cycle between them).
    throw std::invalid_argument("topologicalLevels: the components leave a cycle in the "
                                "condensed graph; pass stronglyConnectedComponents(graph)");
  }
  std::vector<int> levelOfBody(static_cast<std::size_t>(n));
  for (int body = 0; body < n; ++body) {
    const std::size_t c = static_cast<std::size_t>(componentOf(body));
    levelOfBody[static_cast<std::size_t>(body)] = levelOfComponent[c];
  }
  return levelsFromAssignment(graph, std::move(levelOfBody));
}

/// As above, computing the strongly connected components first.
inline ContactLevels topologicalLevels(const ContactGraph& graph) {
  return topologicalLevels(graph, stronglyConnectedComponents(graph));
}
// [topological_levels]

// [bfs_depth_levels]
/// The flawed layering, kept callable so that the chapter can compare: the level of a body
/// is its BFS depth, the fewest edges on a path from a body that rests on nothing (the
/// ground, or an isolated body). It places a body before a supporter whenever a shorter
/// path reaches it: the plank on a 2-box and a 4-box stack gets depth 3 while the box under
/// it has depth 4. Bodies that no such path reaches (a cycle of mutual support with nothing
/// under it) have no depth; they are put together in one extra level after the deepest.
/// Pairs follow the same rule as for every layering (levelsFromAssignment), so a parent
/// can now sit at a later level than its child: exactly the defect. O(n + m log d).
inline ContactLevels bfsDepthLevels(const ContactGraph& graph) {
  const int n = graph.bodyCount();
  constexpr int kUnreached = -1;
  std::vector<int> depth(static_cast<std::size_t>(n), kUnreached);
  std::vector<int> queue;
  queue.reserve(static_cast<std::size_t>(n));
  for (int body = 0; body < n; ++body) {
    if (graph.parents(body).empty()) {
      depth[static_cast<std::size_t>(body)] = 0;
      queue.push_back(body);
    }
  }
  // Bound: each body enters the queue once and each edge is examined once: n + m.
  detail::LoopCap bfsCap(static_cast<std::size_t>(n) + graph.edgeCount(), "bfsDepthLevels");
  int deepest = -1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    bfsCap.step();
    const int body = queue[head];
    const int d = depth[static_cast<std::size_t>(body)];
    deepest = std::max(deepest, d);
    for (const int child : graph.children(body)) {
      bfsCap.step();
      if (depth[static_cast<std::size_t>(child)] == kUnreached) {
        depth[static_cast<std::size_t>(child)] = d + 1;
        queue.push_back(child);
      }
    }
  }
  for (int& d : depth) {
    if (d == kUnreached) d = deepest + 1;
  }
  return levelsFromAssignment(graph, std::move(depth));
}
// [bfs_depth_levels]

}  // namespace stackbook
