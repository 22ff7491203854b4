// Chapter 12, "Freezing only what carries its load": the support region and the centre of load
// (Eqs. (12.1)-(12.4), loadCarrying()), the joined graph (Eq. (12.5), joinUncarried()), and the
// carrying pass against the sticking-patch pass it extends where every body carries.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "../support/dimensions.hpp"
#include "ch09/stack_scenes.hpp"
#include "stackbook/stacking/load_carrying.hpp"
#include "stackbook/stacking/solver_preset.hpp"

using namespace stackbook;

namespace {

/// The contact graph, its GBF levels and loadCarrying() of a world at rest, as the pass sees it.
template <int D>
LoadCarrying<D> carryingAtRest(const World<D>& world, ContactGraph* graphOut = nullptr) {
  ContactGraphSettings g;
  g.dt = 1e-3;
  const ContactGraph graph = worldContactGraph<D>(world, g);
  if (graphOut != nullptr) *graphOut = graph;
  return loadCarrying<D>(world, graph, topologicalLevels(graph), g.dt, g.rotation, g.narrow, 0.0);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [two_box_carrying_test]
TEST_CASE_TEMPLATE("Eq. (12.4): a box on a box is carried while its centre lies over the patch, not past it", T,
                   testing::In2D, testing::In3D) {
  constexpr int D = T::value;
  // Two unit boxes on the ground, the top one offset by s along x. The patch between them is
  // x in [s - 0.5, 0.5]: the top box's centre x = s lies on it for s = 0.3 and past it for
  // s = 0.6. The lower box carries its own weight at 0 and the upper one's at the patch point
  // nearest to s (0.3, or 0.5 for s = 0.6): its centre of load 0.15 or 0.25 lies on its base.
  for (const double s : {0.3, 0.6}) {
    CAPTURE(s);
    World<D> world = stacks::boxStack<D>(2, Material{0.0, 0.5, 0.0}, s);
    ContactGraph graph;
    const LoadCarrying<D> c = carryingAtRest<D>(world, &graph);
    REQUIRE(graph.hasEdge(0, 1));
    REQUIRE(graph.hasEdge(1, 2));
    CHECK(c.carries[0] == 1);  // the ground: static
    CHECK(c.carries[1] == 1);
    CHECK(c.carries[2] == (s < 0.5 ? 1 : 0));
    CHECK(c.uncarried == (s < 0.5 ? 0 : 1));
  }
}
// [two_box_carrying_test]

TEST_CASE_TEMPLATE("Eq. (12.4): in the leaning tower boxes 2 to 6 do not carry their load and a straight tower carries all",
                   T, testing::In2D, testing::In3D) {
  constexpr int D = T::value;
  // Offset 0.2 per box, box k centred at x = 0.2 (k - 1). Top down: boxes 10, 9, 8 carry (centres
  // of load 1.8, 1.7, 1.6 on patches ending at 2.1, 1.9, 1.7). Box 7's centre of load, 1.5, lies on
  // the end of its patch, 1.5: either answer is right there, so the test does not ask. Box 6 with
  // the load of four boxes at 1.5: 1.4 past 1.3; box 5, its load at the patch end 1.3: 1.217 past
  // 1.1; then 1.029 past 0.9, 0.838 past 0.7, 0.644 past 0.5; box 1 on the ground: 0.45 inside 0.5.
  World<D> tilted = stacks::boxStack<D>(10, Material{0.0, 0.5, 0.0}, 0.2);
  const LoadCarrying<D> c = carryingAtRest<D>(tilted);
  for (const int k : {1, 2, 3, 4, 5, 6, 8, 9, 10}) {
    CAPTURE(k);
    CHECK(c.carries[static_cast<std::size_t>(k)] == (k >= 2 && k <= 6 ? 0 : 1));
  }
  // The centres of load of Eq. (12.2), from the top: (sum of the weights at their entry points) / W.
  const double expected[11] = {0.0,       4.5 / 10.0, 5.8 / 9.0, 6.7 / 8.0, 7.2 / 7.0, 7.3 / 6.0,
                               7.0 / 5.0, 1.5,        1.6,       1.7,       1.8};
  for (int k = 1; k <= 10; ++k) {
    CAPTURE(k);
    CHECK(c.centre[static_cast<std::size_t>(k)][0] == doctest::Approx(expected[k]).epsilon(1e-9));
    CHECK(c.weight[static_cast<std::size_t>(k)] == doctest::Approx(11.0 - k).epsilon(1e-12));
  }
  CHECK(carryingAtRest<D>(stacks::boxStack<D>(10, Material{0.0, 0.5, 0.0})).uncarried == 0);
}

TEST_CASE("Eq. (12.5): a body that does not carry joins its supporters and everything above it") {
  // Ground 0 under 1, 1 under 2 and 4, 2 under 3. Body 2 does not carry: 1, 2 and 3 become one
  // level; 4 rests on 1 only and keeps a level of its own. With every body carrying nothing changes.
  const ContactGraph graph(5, std::vector<ContactPair>{{0, 1}, {1, 2}, {1, 4}, {2, 3}});
  const std::vector<char> isStatic{1, 0, 0, 0, 0};
  const ContactLevels levels = topologicalLevels(graph);
  const ContactGraph joined = joinUncarried(graph, std::vector<char>{1, 1, 0, 1, 1}, isStatic, levels);
  const ContactLevels after = topologicalLevels(joined);
  CHECK(after.levelOfBody[1] == after.levelOfBody[2]);
  CHECK(after.levelOfBody[2] == after.levelOfBody[3]);
  CHECK(after.levelOfBody[4] > after.levelOfBody[1]);
  CHECK(after.levelOfBody[0] < after.levelOfBody[1]);
  CHECK(joinUncarried(graph, std::vector<char>(5, 1), isStatic, levels) == graph);
}

TEST_CASE("The support region: an interval in 2D, the convex hull in 3D, with clamp() to its nearest point") {
  using Flat3 = SupportRegion<3>::Flat;
  const SupportRegion<3> square({Flat3(0, 0), Flat3(1, 0), Flat3(1, 1), Flat3(0, 1), Flat3(0.5, 0.5)});
  CHECK(square.contains(Flat3(0.5, 0.2), 0.0));
  CHECK_FALSE(square.contains(Flat3(1.2, 0.5), 0.0));
  CHECK(square.contains(Flat3(1.2, 0.5), 0.25));
  CHECK((square.clamp(Flat3(2.0, 0.5)) - Flat3(1.0, 0.5)).norm() < 1e-15);
  const SupportRegion<3> point({Flat3(0.3, 0.3)});  // a single contact point: only it is inside
  CHECK(point.contains(Flat3(0.3, 0.3), 0.0));
  CHECK_FALSE(point.contains(Flat3(0.31, 0.3), 0.0));
  using Flat2 = SupportRegion<2>::Flat;
  const SupportRegion<2> segment({Flat2(-0.2), Flat2(0.5), Flat2(0.1)});
  CHECK(segment.contains(Flat2(0.5), 0.0));
  CHECK_FALSE(segment.contains(Flat2(0.6), 0.0));
  CHECK(segment.clamp(Flat2(-1.0))[0] == -0.2);
  CHECK_FALSE(SupportRegion<2>({}).contains(Flat2(0.0), 1.0));
}

// [carrying_exact_test]
TEST_CASE_TEMPLATE("Where every body carries its load, the carrying pass is the sticking-patch pass bit for bit", T,
                   testing::In2D, testing::In3D) {
  constexpr int D = T::value;
  // A straight stack of 5 at 60 Hz for 1 s (and in 2D a pyramid of base 6): no body is joined,
  // so the levels and every impulse are the sticking-patch pass's; only the test's work is added.
  StepSettings patch = passAsContactStagePatch();
  patch.dt = 1.0 / 60.0;
  const StepSettings carrying = carryingPass(patch);
  std::vector<World<D>> worlds{stacks::boxStack<D>(5, Material{0.0, 0.6, 0.0})};
  if constexpr (D == 2) worlds.push_back(stacks::pyramid2d(6, Material{0.0, 0.6, 0.0}));
  for (const World<D>& start : worlds) {
    World<D> a = start;
    World<D> b = start;
    StepCounters counters;
    for (int n = 0; n < 60; ++n) {
      stackingStep<D>(a, patch);
      counters += stackingStep<D>(b, carrying);
    }
    CHECK(counters.shock.uncarried == 0);
    CHECK(counters.shock.detection.pairQueries > 0);
    for (std::size_t k = 0; k < a.bodies.size(); ++k) {
      CHECK(a.bodies[k].position == b.bodies[k].position);
      CHECK(a.bodies[k].velocity == b.bodies[k].velocity);
      CHECK(a.bodies[k].angularMomentum == b.bodies[k].angularMomentum);
    }
  }
}
// [carrying_exact_test]

}  // TEST_SUITE
