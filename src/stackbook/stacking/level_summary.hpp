#pragma once
/// \file
/// \brief Counts and a printable summary of a layering of the contact graph (chapter 9):
/// levels, their sizes, the cycles found, and how many supporting contacts the layering
/// gets backwards.

#include <algorithm>
#include <cstddef>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/contact_levels.hpp"
#include "stackbook/stacking/strongly_connected_components.hpp"

namespace stackbook {

// [level_summary]
/// What a layering does with a contact graph, in numbers.
struct LevelSummary {
  std::size_t bodyCount = 0;
  std::size_t edgeCount = 0;     ///< supporting contacts (edges) in the graph
  std::size_t levelCount = 0;
  /// Pairs over all levels: edgeCount minus one per mutual pair (a -> b and b -> a).
  std::size_t pairCount = 0;
  std::size_t largestLevel = 0;  ///< bodies in the most populated level
  std::size_t cycleCount = 0;    ///< strongly connected components of two or more bodies
  std::size_t largestCycle = 0;  ///< bodies in the largest such component (0 if none)
  /// Edges u -> v with level(u) > level(v): the supporter is processed, and frozen, after
  /// the body it holds up. Always 0 for topological levels.
  std::size_t supportersProcessedLater = 0;
  /// Cycles whose bodies do not all share one level. Always 0 for topological levels.
  std::size_t cyclesSplitAcrossLevels = 0;
};
// [level_summary]

/// The counts of LevelSummary for `levels`, which must be a layering of `graph`.
/// O(n + m) after the strongly connected components.
inline LevelSummary summarizeLevels(const ContactGraph& graph, const ContactLevels& levels) {
  const int n = graph.bodyCount();
  if (levels.levelOfBody.size() != static_cast<std::size_t>(n)) {
    throw std::invalid_argument("summarizeLevels: levels.levelOfBody has " +
                                std::to_string(levels.levelOfBody.size()) +
                                " entries, the graph has " + std::to_string(n) + " bodies");
  }
  auto levelOf = [&](int body) { return levels.levelOfBody[static_cast<std::size_t>(body)]; };
  LevelSummary s;
  s.bodyCount = static_cast<std::size_t>(n);
  s.edgeCount = graph.edgeCount();
  s.levelCount = levels.levelCount();
  for (std::size_t l = 0; l < levels.levelCount(); ++l) {
    s.pairCount += levels.pairs(l).size();
    s.largestLevel = std::max(s.largestLevel, levels.bodies(l).size());
  }
  for (const ContactPair& e : graph.edges()) {
    if (levelOf(e.below) > levelOf(e.above)) ++s.supportersProcessedLater;
  }
  const StronglyConnectedComponents components = stronglyConnectedComponents(graph);
  for (std::size_t c = 0; c < components.componentCount(); ++c) {
    const std::span<const int> members = components.members(c);
    if (members.size() < 2) continue;
    ++s.cycleCount;
    s.largestCycle = std::max(s.largestCycle, members.size());
    const bool split = std::any_of(members.begin(), members.end(),
                                   [&](int b) { return levelOf(b) != levelOf(members.front()); });
    if (split) ++s.cyclesSplitAcrossLevels;
  }
  return s;
}

/// How much of a layering describeLevels lists (the counts are always complete).
struct LevelListing {
  std::size_t maxLevels = 12;          ///< levels listed before "... and N more levels"
  std::size_t maxItemsPerLevel = 8;    ///< bodies (and pairs) listed per level
};

// [describe_levels]
/// A printable summary: the counts of summarizeLevels, then one line per level with its
/// bodies and its pairs "below->above", cut short as `listing` says. Deterministic.
inline std::string describeLevels(const ContactGraph& graph, const ContactLevels& levels,
                                  const LevelListing& listing = {}) {
  const LevelSummary s = summarizeLevels(graph, levels);
  std::ostringstream out;
  out << s.bodyCount << " bodies, " << s.edgeCount << " supporting contacts, " << s.levelCount
      << " levels, " << s.pairCount << " pairs, largest level " << s.largestLevel << " bodies\n";
  out << "cycles of mutual support: " << s.cycleCount;
  if (s.cycleCount > 0) out << " (largest " << s.largestCycle << " bodies)";
  out << ", split across levels: " << s.cyclesSplitAcrossLevels << "\n";
  out << "supporting contacts whose supporter comes at a later level: "
      << s.supportersProcessedLater << "\n";
  const std::size_t listed = std::min(listing.maxLevels, levels.levelCount());
  for (std::size_t l = 0; l < listed; ++l) {
    const std::span<const int> bodies = levels.bodies(l);
    const std::span<const ContactPair> pairs = levels.pairs(l);
    out << "level " << l << ": bodies";
    for (std::size_t i = 0; i < std::min(listing.maxItemsPerLevel, bodies.size()); ++i) {
      out << ' ' << bodies[i];
    }
    if (bodies.size() > listing.maxItemsPerLevel) {
      out << " ... (" << bodies.size() << " in all)";
    }
    out << "; pairs";
    if (pairs.empty()) out << " none";
    for (std::size_t i = 0; i < std::min(listing.maxItemsPerLevel, pairs.size()); ++i) {
      out << ' ' << pairs[i].below << "->" << pairs[i].above;
    }
    if (pairs.size() > listing.maxItemsPerLevel) out << " ... (" << pairs.size() << " in all)";
    out << "\n";
  }
  if (levels.levelCount() > listed) {
    out << "... and " << (levels.levelCount() - listed) << " more levels\n";
  }
  return out.str();
}
// [describe_levels]

}  // namespace stackbook
