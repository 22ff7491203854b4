// Chapter 9: strongly connected components and the levels of shock propagation.
// Expected levels of the named scenes are derived by hand in the comments; the property
// tests compare against a brute-force transitive closure (graph_scenes.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "ch09/graph_scenes.hpp"
#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/contact_levels.hpp"
#include "stackbook/stacking/level_summary.hpp"
#include "stackbook/stacking/strongly_connected_components.hpp"

using namespace stackbook;
using stackbook::testing::levelBodies;
using stackbook::testing::PlankOnTwoStacks;
using stackbook::testing::toVector;

namespace {

int levelOf(const ContactLevels& levels, int body) {
  return levels.levelOfBody[static_cast<std::size_t>(body)];
}

/// Random graphs for the property tests: half acyclic, half with cycles and mutual pairs.
struct RandomGraphCase {
  int n = 0;
  std::vector<ContactPair> edges;
};

RandomGraphCase randomGraphCase(std::mt19937_64& engine, int trial) {
  RandomGraphCase c;
  c.n = testing::uniformInt(engine, 1, 40);
  const int draws = testing::uniformInt(engine, 0, 3 * c.n);
  if (trial % 2 == 0) {
    c.edges = testing::randomAcyclicEdges(engine, c.n, draws);
  } else {
    c.edges = testing::randomCyclicEdges(engine, c.n, draws / 2, testing::uniformInt(engine, 0, 3));
  }
  return c;
}

bool mutuallyReachable(const std::vector<std::vector<char>>& reach, int u, int v) {
  return reach[static_cast<std::size_t>(u)][static_cast<std::size_t>(v)] &&
         reach[static_cast<std::size_t>(v)][static_cast<std::size_t>(u)];
}

/// Every edge of the graph, as an unordered pair {min, max}, once each, sorted.
std::vector<ContactPair> unorderedEdges(const std::vector<ContactPair>& edges) {
  std::vector<ContactPair> pairs;
  for (const ContactPair& e : edges) {
    pairs.push_back({std::min(e.below, e.above), std::max(e.below, e.above)});
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

/// Checks the pair rule of ContactLevels for any layering of `graph`: each pair is an edge
/// whose upper body lies in the pair's level, the pairs of a level follow the order of its
/// bodies, and over all levels every edge appears in exactly one pair.
void checkPairsListEveryContactOnce(const ContactGraph& graph, const std::vector<ContactPair>& edges,
                                    const ContactLevels& levels) {
  std::vector<ContactPair> listed;
  for (std::size_t l = 0; l < levels.levelCount(); ++l) {
    const std::span<const ContactPair> pairs = levels.pairs(l);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const ContactPair& p = pairs[i];
      CAPTURE(l);
      CAPTURE(p.below);
      CAPTURE(p.above);
      CHECK(graph.hasEdge(p.below, p.above));
      CHECK(levelOf(levels, p.above) == static_cast<int>(l));
      if (i > 0) {  // ordered by body, then by parent
        const ContactPair& q = pairs[i - 1];
        CHECK(std::tie(q.above, q.below) < std::tie(p.above, p.below));
      }
      listed.push_back({std::min(p.below, p.above), std::max(p.below, p.above)});
    }
  }
  std::sort(listed.begin(), listed.end());
  const bool noPairTwice = std::adjacent_find(listed.begin(), listed.end()) == listed.end();
  CHECK(noPairTwice);
  CHECK(listed == unorderedEdges(edges));
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [vertical_stack]
TEST_CASE("a vertical stack gets one level per box in order from the ground") {
  // Bodies numbered out of order on purpose: from the ground up the stack is 3 0 4 1 2, so
  // the levels must follow the edges and not the body numbers.
  const std::vector<int> fromGround{3, 0, 4, 1, 2};
  ContactGraph graph(5);
  for (std::size_t k = 1; k < fromGround.size(); ++k) graph.addEdge(fromGround[k - 1], fromGround[k]);

  for (const ContactLevels& levels : {topologicalLevels(graph), bfsDepthLevels(graph)}) {
    REQUIRE(levels.levelCount() == 5);
    for (std::size_t k = 0; k < fromGround.size(); ++k) {
      CAPTURE(k);
      CHECK(toVector(levels.bodies(k)) == std::vector<int>{fromGround[k]});
      const std::vector<ContactPair> expectedPairs =
          k == 0 ? std::vector<ContactPair>{} : std::vector<ContactPair>{{fromGround[k - 1], fromGround[k]}};
      CHECK(toVector(levels.pairs(k)) == expectedPairs);
    }
  }
}
// [vertical_stack]

// [plank_topological]
TEST_CASE("the plank on a 2-box and a 4-box stack of equal height is placed after all of its supporters") {
  const ContactGraph graph = PlankOnTwoStacks::graph();
  const ContactLevels levels = topologicalLevels(graph);
  // Every body except the plank holds it up, directly or through the boxes above it.
  for (int supporter = 0; supporter < PlankOnTwoStacks::plank; ++supporter) {
    CAPTURE(supporter);
    CHECK(levelOf(levels, supporter) < levelOf(levels, PlankOnTwoStacks::plank));
  }
  CHECK(levelOf(levels, PlankOnTwoStacks::plank) == 7);
  // The plank's level sweeps both of its contacts: with the short and with the tall stack.
  const std::vector<ContactPair> plankPairs{{PlankOnTwoStacks::topOfShortStack, PlankOnTwoStacks::plank},
                                            {PlankOnTwoStacks::topOfTallStack, PlankOnTwoStacks::plank}};
  CHECK(toVector(levels.pairs(7)) == plankPairs);
  CHECK(summarizeLevels(graph, levels).supportersProcessedLater == 0);
}
// [plank_topological]

// [plank_bfs_failure]
TEST_CASE("BFS depth places the plank before a box that holds it up") {
  const ContactGraph graph = PlankOnTwoStacks::graph();
  const ContactLevels depth = bfsDepthLevels(graph);
  // Shortest paths from the ground: 1 and 3 at one edge, 2 and 4 at two, the plank (via 2)
  // and 5 at three, and 6, the top of the tall stack, at four.
  const std::vector<int> expectedDepth{0, 1, 2, 1, 2, 3, 4, 3};
  CHECK(depth.levelOfBody == expectedDepth);
  REQUIRE(graph.hasEdge(PlankOnTwoStacks::topOfTallStack, PlankOnTwoStacks::plank));
  CHECK(levelOf(depth, PlankOnTwoStacks::plank) < levelOf(depth, PlankOnTwoStacks::topOfTallStack));
  CHECK(summarizeLevels(graph, depth).supportersProcessedLater == 1);
}
// [plank_bfs_failure]

// [cycle_levels]
TEST_CASE("bodies in a cycle share one level") {
  // Ground 0; box 1 on it; planks 2 and 3 lean on each other (2 <-> 3) and both stand on 1;
  // box 4 rests on both planks; a ring of three bodies 5 -> 6 -> 7 -> 5 rests on 4.
  // Components: {0} {1} {2 3} {4} {5 6 7}, so five levels in that order.
  const std::vector<ContactPair> edges{{0, 1}, {1, 2}, {1, 3}, {2, 3}, {3, 2}, {2, 4},
                                       {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 5}};
  const ContactGraph graph(8, edges);
  const StronglyConnectedComponents components = stronglyConnectedComponents(graph);
  CHECK(components.cycleCount() == 2);
  const ContactLevels levels = topologicalLevels(graph, components);
  const std::vector<std::vector<int>> expectedBodies{{0}, {1}, {2, 3}, {4}, {5, 6, 7}};
  CHECK(levelBodies(levels) == expectedBodies);
  // Level 2: body 2 with parent 1 (parent 3 is mutual and larger: listed at body 3); body 3
  // with parents 1 and 2. Level 4: body 5 with parents 4 and 7, body 6 with 5, body 7 with 6.
  const std::vector<ContactPair> level2{{1, 2}, {1, 3}, {2, 3}};
  const std::vector<ContactPair> level4{{4, 5}, {7, 5}, {5, 6}, {6, 7}};
  CHECK(toVector(levels.pairs(2)) == level2);
  CHECK(toVector(levels.pairs(4)) == level4);
  const LevelSummary summary = summarizeLevels(graph, levels);
  CHECK(summary.cyclesSplitAcrossLevels == 0);
  CHECK(summary.largestCycle == 3);
  CHECK(summary.pairCount == edges.size() - 1);  // one mutual pair, listed once
}
// [cycle_levels]

TEST_CASE("BFS depth splits a cycle across levels") {
  // The scene above: by shortest path the ring 5 -> 6 -> 7 gets depths 4 5 6, and its edge
  // 7 -> 5 points from depth 6 back to depth 4.
  const std::vector<ContactPair> edges{{0, 1}, {1, 2}, {1, 3}, {2, 3}, {3, 2}, {2, 4},
                                       {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 5}};
  const ContactGraph graph(8, edges);
  const ContactLevels depth = bfsDepthLevels(graph);
  const std::vector<int> expectedDepth{0, 1, 2, 2, 3, 4, 5, 6};
  CHECK(depth.levelOfBody == expectedDepth);
  const LevelSummary summary = summarizeLevels(graph, depth);
  CHECK(summary.cyclesSplitAcrossLevels == 1);  // the ring; the planks 2 3 stay together
  CHECK(summary.supportersProcessedLater == 1);  // 7 -> 5
}

TEST_CASE("a cycle that rests on nothing is one level and BFS depth puts it last") {
  // Box 1 on ground 0, and planks 2 <-> 3 leaning on each other in the air. Topological
  // order: {0} {1} {2 3}. BFS depth: 0 and 1 are reached; 2 and 3 are not (each has a
  // parent, but no path from a parentless body), so they form one extra level after 1.
  const ContactGraph graph(4, std::vector<ContactPair>{{0, 1}, {2, 3}, {3, 2}});
  const std::vector<std::vector<int>> expected{{0}, {1}, {2, 3}};
  CHECK(levelBodies(topologicalLevels(graph)) == expected);
  CHECK(levelBodies(bfsDepthLevels(graph)) == expected);
  const ContactGraph floating(2, std::vector<ContactPair>{{0, 1}, {1, 0}});
  CHECK(levelBodies(bfsDepthLevels(floating)) == std::vector<std::vector<int>>{{0, 1}});
}

TEST_CASE("among bodies free to go next the smallest goes first") {
  // Ground 5; stack 5 -> 3 -> 1; stack 5 -> 0 -> 4; body 2 alone. Free at the start: 2 and
  // 5, so 2 then 5; then 0 and 3 are free: 0; then 3 and 4: 3; then 1 and 4: 1; then 4.
  const ContactGraph graph(6, std::vector<ContactPair>{{5, 3}, {3, 1}, {5, 0}, {0, 4}});
  const std::vector<std::vector<int>> expected{{2}, {5}, {0}, {3}, {1}, {4}};
  CHECK(levelBodies(topologicalLevels(graph)) == expected);
}

// [scc_property]
TEST_CASE("strongly connected components match mutual reachability on seeded random graphs") {
  std::mt19937_64 engine(20030727);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const RandomGraphCase c = randomGraphCase(engine, trial);
    const ContactGraph graph(c.n, c.edges);
    const StronglyConnectedComponents scc = stronglyConnectedComponents(graph);
    const std::vector<std::vector<char>> reach = testing::reachability(c.n, c.edges);
    std::size_t cycles = 0;
    for (int u = 0; u < c.n; ++u) {
      bool inCycle = false;
      for (int v = 0; v < c.n; ++v) {
        const bool same = scc.componentOfBody[static_cast<std::size_t>(u)] ==
                          scc.componentOfBody[static_cast<std::size_t>(v)];
        if (same != mutuallyReachable(reach, u, v)) {
          FAIL_CHECK("bodies " << u << " and " << v << " disagree with reachability");
        }
        inCycle = inCycle || (u != v && same);
      }
      // Count each cycle at its smallest body: the first body u of its class.
      bool smallestOfClass = true;
      for (int v = 0; v < u; ++v) smallestOfClass = smallestOfClass && !mutuallyReachable(reach, u, v);
      if (inCycle && smallestOfClass) ++cycles;
    }
    CHECK(scc.cycleCount() == cycles);
    // Canonical numbering: members ascending, components ordered by their smallest body.
    for (std::size_t k = 0; k < scc.componentCount(); ++k) {
      CHECK(std::is_sorted(scc.members(k).begin(), scc.members(k).end()));
      if (k > 0) CHECK(scc.members(k - 1).front() < scc.members(k).front());
    }
  }
}
// [scc_property]

// [topological_property]
TEST_CASE("levels are a topological order of the condensation") {
  std::mt19937_64 engine(882262);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const RandomGraphCase c = randomGraphCase(engine, trial);
    const ContactGraph graph(c.n, c.edges);
    const ContactLevels levels = topologicalLevels(graph);
    const std::vector<std::vector<char>> reach = testing::reachability(c.n, c.edges);
    // For every edge u -> v: level(u) <= level(v), with equality iff same SCC.
    for (const ContactPair& e : c.edges) {
      CAPTURE(e.below);
      CAPTURE(e.above);
      CHECK(levelOf(levels, e.below) <= levelOf(levels, e.above));
      CHECK((levelOf(levels, e.below) == levelOf(levels, e.above)) ==
            mutuallyReachable(reach, e.below, e.above));
    }
    // Each level is exactly one SCC: its bodies reach each other, and no two levels do.
    for (int u = 0; u < c.n; ++u) {
      for (int v = 0; v < c.n; ++v) {
        if ((levelOf(levels, u) == levelOf(levels, v)) != mutuallyReachable(reach, u, v)) {
          FAIL_CHECK("bodies " << u << " and " << v << ": shared level and shared SCC disagree");
        }
      }
    }
    if (trial % 2 == 0) CHECK(levels.levelCount() == static_cast<std::size_t>(c.n));  // acyclic
  }
}
// [topological_property]

// [pairs_once]
TEST_CASE("each level's pairs list every supporting contact exactly once") {
  std::mt19937_64 engine(871878);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const RandomGraphCase c = randomGraphCase(engine, trial);
    const ContactGraph graph(c.n, c.edges);
    const ContactLevels levels = topologicalLevels(graph);
    checkPairsListEveryContactOnce(graph, c.edges, levels);
    // In topological levels a pair's supporter is never at a later level.
    for (std::size_t l = 0; l < levels.levelCount(); ++l) {
      for (const ContactPair& p : levels.pairs(l)) {
        CHECK(levelOf(levels, p.below) <= static_cast<int>(l));
      }
    }
    // The pair rule holds for any layering: BFS depth too.
    checkPairsListEveryContactOnce(graph, c.edges, bfsDepthLevels(graph));
  }
}
// [pairs_once]

// [determinism]
TEST_CASE("the same graph built from edges in a different order gives identical levels and pairs") {
  std::mt19937_64 engine(4242);
  for (int trial = 0; trial < 50; ++trial) {
    CAPTURE(trial);
    const RandomGraphCase c = randomGraphCase(engine, 2 * trial + 1);  // with cycles
    const ContactGraph reference(c.n, c.edges);
    const StronglyConnectedComponents referenceScc = stronglyConnectedComponents(reference);
    const ContactLevels referenceLevels = topologicalLevels(reference);
    const ContactLevels referenceDepth = bfsDepthLevels(reference);
    const std::string referenceText = describeLevels(reference, referenceLevels);
    for (int shuffle = 0; shuffle < 4; ++shuffle) {
      std::vector<ContactPair> edges = c.edges;
      edges.insert(edges.end(), c.edges.begin(), c.edges.begin() + static_cast<long>(c.edges.size() / 2));
      testing::shuffleInPlace(edges, engine);
      ContactGraph graph(c.n);
      for (const ContactPair& e : edges) graph.addEdge(e);
      CHECK(graph == reference);
      CHECK(stronglyConnectedComponents(graph) == referenceScc);
      CHECK(topologicalLevels(graph) == referenceLevels);
      CHECK(bfsDepthLevels(graph) == referenceDepth);
      CHECK(describeLevels(graph, topologicalLevels(graph)) == referenceText);
    }
  }
}
// [determinism]

TEST_CASE("a level assignment with a gap or the wrong length is refused") {
  const ContactGraph graph(3, std::vector<ContactPair>{{0, 1}});
  using testing::invalidArgumentMessage;
  const std::string shortList = invalidArgumentMessage([&] { levelsFromAssignment(graph, {0, 1}); });
  CHECK(shortList.find("2 entries") != std::string::npos);
  const std::string gap = invalidArgumentMessage([&] { levelsFromAssignment(graph, {0, 2, 2}); });
  CHECK(gap.find("level 1 has no body") != std::string::npos);
  const std::string negative = invalidArgumentMessage([&] { levelsFromAssignment(graph, {0, -1, 1}); });
  CHECK(negative.find("levelOfBody[1] = -1") != std::string::npos);
  // Components that are not this graph's SCCs leave a cycle between components.
  const ContactGraph cycle(2, std::vector<ContactPair>{{0, 1}, {1, 0}});
  const StronglyConnectedComponents wrong = stronglyConnectedComponents(ContactGraph(2));
  const std::string mismatch = invalidArgumentMessage([&] { topologicalLevels(cycle, wrong); });
  CHECK(mismatch.find("cycle in the condensed graph") != std::string::npos);
}

// [summary_text]
TEST_CASE("the summary reports levels and cycles and contacts whose supporter comes later") {
  const ContactGraph graph = PlankOnTwoStacks::graph();
  const std::string depthText = describeLevels(graph, bfsDepthLevels(graph));
  CHECK(depthText.find("8 bodies, 8 supporting contacts, 5 levels, 8 pairs, largest level 2 bodies\n") == 0);
  CHECK(depthText.find("supporting contacts whose supporter comes at a later level: 1\n") !=
        std::string::npos);
  // Depth 3 holds box 5 and the plank; the plank's contact with box 6 (depth 4) is swept here.
  CHECK(depthText.find("level 3: bodies 5 7; pairs 4->5 2->7 6->7\n") != std::string::npos);

  const std::string levelText =
      describeLevels(graph, topologicalLevels(graph), LevelListing{.maxLevels = 2, .maxItemsPerLevel = 8});
  CHECK(levelText.find("cycles of mutual support: 0, split across levels: 0\n") != std::string::npos);
  CHECK(levelText.find("level 0: bodies 0; pairs none\nlevel 1: bodies 1; pairs 0->1\n") != std::string::npos);
  CHECK(levelText.find("... and 6 more levels\n") != std::string::npos);
}
// [summary_text]

}  // TEST_SUITE
