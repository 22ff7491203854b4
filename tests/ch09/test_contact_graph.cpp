// Chapter 9: the contact graph itself (storage, determinism of adjacency, bad input).
#include <doctest/doctest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "ch09/graph_scenes.hpp"
#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/contact_levels.hpp"
#include "stackbook/stacking/level_summary.hpp"
#include "stackbook/stacking/strongly_connected_components.hpp"

using namespace stackbook;
using stackbook::testing::invalidArgumentMessage;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [graph_duplicates]
TEST_CASE("a contact added twice is stored once") {
  ContactGraph graph(3);
  CHECK(graph.addEdge(0, 1));
  CHECK_FALSE(graph.addEdge(0, 1));
  CHECK(graph.addEdge(ContactPair{1, 2}));
  CHECK_FALSE(graph.addEdge(ContactPair{1, 2}));
  CHECK(graph.edgeCount() == 2);
  CHECK(testing::toVector(graph.children(0)) == std::vector<int>{1});
  CHECK(testing::toVector(graph.parents(1)) == std::vector<int>{0});

  const std::vector<ContactPair> repeated{{0, 1}, {1, 2}, {0, 1}, {0, 1}, {1, 2}};
  const ContactGraph bulk(3, repeated);
  CHECK(bulk.edgeCount() == 2);
  CHECK(bulk == graph);
}
// [graph_duplicates]

TEST_CASE("an edge says which body rests on which") {
  ContactGraph graph(3);
  graph.addEdge(0, 1);  // 1 rests on 0
  CHECK(graph.hasEdge(0, 1));
  CHECK_FALSE(graph.hasEdge(1, 0));
  CHECK_FALSE(graph.hasEdge(0, 2));
  CHECK_FALSE(graph.hasEdge(-1, 0));
  CHECK_FALSE(graph.hasEdge(0, 3));
  CHECK(testing::toVector(graph.children(1)).empty());
  CHECK(testing::toVector(graph.parents(0)).empty());
}

TEST_CASE("children and parents are kept in ascending order whatever the insertion order") {
  ContactGraph graph(6);
  for (const ContactPair e : {ContactPair{0, 5}, ContactPair{0, 2}, ContactPair{3, 4},
                              ContactPair{0, 4}, ContactPair{1, 4}, ContactPair{5, 4}}) {
    graph.addEdge(e);
  }
  CHECK(testing::toVector(graph.children(0)) == std::vector<int>{2, 4, 5});
  CHECK(testing::toVector(graph.parents(4)) == std::vector<int>{0, 1, 3, 5});
  const std::vector<ContactPair> expected{{0, 2}, {0, 4}, {0, 5}, {1, 4}, {3, 4}, {5, 4}};
  CHECK(graph.edges() == expected);
}

TEST_CASE("the bulk constructor and edge-by-edge insertion build the same graph") {
  std::mt19937_64 engine(9001);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const int n = testing::uniformInt(engine, 1, 30);
    std::vector<ContactPair> edges = testing::randomCyclicEdges(engine, n, 3 * n, n / 3);
    ContactGraph incremental(n);
    for (const ContactPair& e : edges) incremental.addEdge(e);
    const ContactGraph bulk(n, edges);
    CHECK(bulk == incremental);
    testing::shuffleInPlace(edges, engine);
    CHECK(ContactGraph(n, edges) == bulk);
  }
}

TEST_CASE("a contact naming a body outside the graph or a body resting on itself is refused") {
  ContactGraph graph(3);
  const std::string outside = invalidArgumentMessage([&] { graph.addEdge(0, 3); });
  CHECK(contains(outside, "ContactGraph::addEdge"));
  CHECK(contains(outside, "above = 3"));
  CHECK(contains(outside, "0..2"));
  const std::string negative = invalidArgumentMessage([&] { graph.addEdge(-1, 2); });
  CHECK(contains(negative, "below = -1"));
  const std::string self = invalidArgumentMessage([&] { graph.addEdge(1, 1); });
  CHECK(contains(self, "cannot rest on itself"));
  const std::vector<ContactPair> bad{{0, 1}, {2, 2}};
  CHECK(contains(invalidArgumentMessage([&] { ContactGraph(3, bad); }), "cannot rest on itself"));
  CHECK(contains(invalidArgumentMessage([] { ContactGraph(-2); }), "bodyCount = -2"));
  CHECK(contains(invalidArgumentMessage([&] { (void)graph.children(7); }), "body = 7"));
  ContactGraph empty;
  CHECK(contains(invalidArgumentMessage([&] { empty.addEdge(0, 1); }), "no bodies"));
  CHECK(graph.edgeCount() == 0);  // nothing was half-added
}

// [empty_and_isolated]
TEST_CASE("an empty graph has no levels and isolated bodies each get a level of their own") {
  const ContactGraph empty;
  CHECK(stronglyConnectedComponents(empty).componentCount() == 0);
  CHECK(topologicalLevels(empty).levelCount() == 0);
  CHECK(bfsDepthLevels(empty).levelCount() == 0);
  const LevelSummary none = summarizeLevels(empty, topologicalLevels(empty));
  CHECK(none.bodyCount == 0);
  CHECK(none.levelCount == 0);

  // Four bodies, no contacts: four one-body components, so four levels in body order;
  // nothing rests on anything, so no pairs. By BFS depth all four are on the ground: one
  // level of depth 0.
  const ContactGraph isolated(4);
  const ContactLevels levels = topologicalLevels(isolated);
  REQUIRE(levels.levelCount() == 4);
  for (int body = 0; body < 4; ++body) {
    CHECK(levels.levelOfBody[static_cast<std::size_t>(body)] == body);
    CHECK(testing::toVector(levels.bodies(static_cast<std::size_t>(body))) ==
          std::vector<int>{body});
    CHECK(levels.pairs(static_cast<std::size_t>(body)).empty());
  }
  const ContactLevels depth = bfsDepthLevels(isolated);
  REQUIRE(depth.levelCount() == 1);
  CHECK(testing::toVector(depth.bodies(0)) == std::vector<int>{0, 1, 2, 3});
  CHECK(depth.pairs(0).empty());
}
// [empty_and_isolated]

TEST_CASE("a loop cap reports an internal error instead of running past its bound") {
  detail::LoopCap cap(2, "test loop");
  cap.step();
  cap.step();
  CHECK_THROWS_AS(cap.step(), std::logic_error);
}

}  // TEST_SUITE
