// Chapter 9 exercises: suite ch09_exercises, skipped by default. The exercises preset builds
// them into build/exercises/tests/ch09/test_ch09_exercises. It registers one CTest entry per
// exercise, ex09.1 to ex09.3, with the labels exercise and ch09. Run all of them, or one, with
//   ctest --preset exercises -L ch09
//   ctest --preset exercises -R ex09.2
// An entry runs its tests once its stub has no "// TODO(reader)" comment left. The binary
// runs them at any time:
//   build/exercises/tests/ch09/test_ch09_exercises --no-skip -ts=ch09_exercises -tc="Exercise 9.2*"
// They fail until you solve the exercise (the stub returns a neutral value).
// The main build runs them against the reference solutions: ctest --preset solutions -L ch09
#include <doctest/doctest.h>

#include <cstddef>
#include <random>
#include <stdexcept>
#include <vector>

#include "../ch08/scenes.hpp"
#include "ch09/stack_scenes.hpp"
#include "stackbook/exercises/ex09_1_longest_path_levels.hpp"
#include "stackbook/exercises/ex09_2_softened_freezing.hpp"
#include "stackbook/exercises/ex09_3_contact_islands.hpp"
#include "stackbook/stacking/strongly_connected_components.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;

namespace {

/// Runs one GBF step of `world` and hands the world after its contact stage to `work`.
template <int D, class Work>
void afterContact(World<D>& world, Work&& work) {
  StepSettings settings;
  settings.effects.shockPropagation = true;
  gbfStep<D>(world, settings, [&work](World<D>& w, const StepSettings& s, StepCounters&) { work(w, s); });
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER "_exercises" * doctest::skip()) {

TEST_CASE("Exercise 9.1: longest-path levels keep the order guarantee with fewer levels") {
  // The plank scene: ground 0; left 1 2; right 3 4 5 6; plank 7. Longest paths: 0 | 1 3 |
  // 2 4 | 5 | 6 | 7, six levels instead of eight.
  const ContactGraph plank(8, std::vector<ContactPair>{{0, 1}, {1, 2}, {2, 7}, {0, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}});
  const ContactLevels levels = longestPathLevels(plank);
  REQUIRE(levels.levelOfBody.size() == 8);
  CHECK(levels.levelOfBody == std::vector<int>{0, 1, 2, 1, 2, 3, 4, 5});
  CHECK(levels.levelCount() == 6);
  CHECK(levels.pairList.size() == 8);
  // Seeded random graphs with cycles: Eq. (9.1) holds for every edge.
  std::mt19937_64 engine(90101);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    std::uniform_int_distribution<int> size(1, 12);
    const int n = size(engine);
    std::uniform_int_distribution<int> body(0, n - 1);
    std::vector<ContactPair> edges;
    for (int k = 0; k < 2 * n; ++k) {
      const int a = body(engine);
      const int b = body(engine);
      if (a != b) edges.push_back({a, b});
    }
    const ContactGraph graph(n, edges);
    const StronglyConnectedComponents scc = stronglyConnectedComponents(graph);
    const ContactLevels l = longestPathLevels(graph);
    REQUIRE(l.levelOfBody.size() == static_cast<std::size_t>(n));
    CHECK(l.levelCount() <= topologicalLevels(graph).levelCount());
    CHECK(l.pairList.size() == topologicalLevels(graph).pairList.size());
    for (const ContactPair& e : graph.edges()) {
      const int lu = l.levelOfBody[static_cast<std::size_t>(e.below)];
      const int lv = l.levelOfBody[static_cast<std::size_t>(e.above)];
      const bool same = scc.componentOfBody[static_cast<std::size_t>(e.below)] ==
                        scc.componentOfBody[static_cast<std::size_t>(e.above)];
      CHECK(lu <= lv);
      CHECK((lu == lv) == same);
    }
  }
}

TEST_CASE_TEMPLATE("Exercise 9.2: softness 0 is the chapter's pass and softness 1 freezes nothing", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  World<D> world = stacks::boxStack<D>(4, Material{0.0, 0.5, 0.0});
  afterContact<D>(world, [](World<D>& w, const StepSettings& s) {
    const ContactGraph graph = worldContactGraph<D>(w, stepGraphSettings(s, resolveEffects<D>(w, s.effects)));
    const ContactLevels levels = topologicalLevels(graph);
    StageCounters counters;
    // Softness 0: bit-identical to the chapter's pass.
    World<D> chapter = w;
    shockPropagationPass<D>(chapter, graph, levels, s, counters);
    World<D> soft0 = w;
    softenedShockPass<D>(soft0, graph, levels, s, 0.0, counters);
    CHECK(testing::stateHash<D>(soft0) == testing::stateHash<D>(chapter));
    CHECK(testing::stateHash<D>(soft0) != testing::stateHash<D>(w));  // the pass did something
    // Softness 1: the levels' pairs swept in order with nobody frozen.
    World<D> soft1 = w;
    softenedShockPass<D>(soft1, graph, levels, s, 1.0, counters);
    World<D> plain = w;
    std::vector<CollisionBody<D>> views = stageViews<D>(plain, Lookahead::Velocity, s.dt);
    StageSpec spec{Lookahead::Velocity, s.shock.sweepsPerLevel, s.shock.pairIterations,
                   [&s](int k, const PairMaterial&) { return s.shock.restitutionAt(k); }};
    for (std::size_t l = 0; l < levels.levelCount(); ++l) {
      std::vector<BodyPair> pairs;
      for (const ContactPair& c : levels.pairs(l)) pairs.push_back(BodyPair{c.below, c.above});
      for (int k = 1; k <= s.shock.sweepsPerLevel && !pairs.empty(); ++k) {
        sweepPairs<D>(plain, views, pairs, spec, k, s.dt, s, counters);
      }
    }
    CHECK(testing::stateHash<D>(soft1) == testing::stateHash<D>(plain));
    // Softness 0.3: masses restored exactly; a bad softness is refused.
    World<D> soft3 = w;
    softenedShockPass<D>(soft3, graph, levels, s, 0.3, counters);
    for (std::size_t k = 0; k < w.bodies.size(); ++k) {
      CHECK(soft3.bodies[k].inverseMass == w.bodies[k].inverseMass);
      CHECK(soft3.bodies[k].inverseInertia == w.bodies[k].inverseInertia);
    }
    CHECK(testing::stateHash<D>(soft3) != testing::stateHash<D>(chapter));
    World<D> bad = w;
    CHECK_THROWS_AS(softenedShockPass<D>(bad, graph, levels, s, 1.5, counters), std::invalid_argument);
  });
}

TEST_CASE("Exercise 9.3: two stacks on one ground are two islands") {
  // Ground 0 (static); stack 0 -> 1 -> 2; stack 0 -> 3 -> 4 -> 5; box 6 alone in the air;
  // planks 7 <-> 8 leaning on each other on box 5 (5 -> 7, 5 -> 8).
  const ContactGraph graph(9, std::vector<ContactPair>{{0, 1}, {1, 2}, {0, 3}, {3, 4}, {4, 5}, {5, 7}, {5, 8}, {7, 8}, {8, 7}});
  std::vector<bool> isStatic(9, false);
  isStatic[0] = true;
  const std::vector<std::vector<int>> expected{{1, 2}, {3, 4, 5, 7, 8}, {6}};
  CHECK(contactIslands(graph, isStatic) == expected);
  // A static body in the middle cuts the island in two.
  isStatic[4] = true;
  const std::vector<std::vector<int>> cut{{1, 2}, {3}, {5, 7, 8}, {6}};
  CHECK(contactIslands(graph, isStatic) == cut);
  CHECK_THROWS_AS(contactIslands(graph, std::vector<bool>(3, false)), std::invalid_argument);
  // A long chain (no recursion): one island of 100000 bodies.
  std::vector<ContactPair> chain;
  for (int k = 1; k < 100000; ++k) chain.push_back({k - 1, k});
  const std::vector<std::vector<int>> one = contactIslands(ContactGraph(100000, chain), std::vector<bool>(100000, false));
  REQUIRE(one.size() == 1);
  CHECK(one.front().size() == 100000);
}

}  // TEST_SUITE
