// Chapter 9: the contact graph of a world, the freeze guard and the shock-propagation
// pass, on scenes small enough for the everyday suite.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "../ch08/scenes.hpp"
#include "../support/dimensions.hpp"
#include "stack_scenes.hpp"
#include "stackbook/stacking/level_summary.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;

namespace {

/// The contact graph seen by the hook of one GBF step (after the contact stage).
template <int D>
ContactGraph graphAfterContact(World<D>& world, StepSettings settings) {
  settings.effects.shockPropagation = true;
  ContactGraph graph;
  gbfStep<D>(world, settings, [&graph](World<D>& w, const StepSettings& s, StepCounters& c) {
    graph = worldContactGraph<D>(w, stepGraphSettings(s, c.effects));
  });
  return graph;
}

template <int D>
std::vector<ContactPair> chainEdges(int n) {
  std::vector<ContactPair> edges;
  for (int k = 1; k <= n; ++k) edges.push_back(ContactPair{k - 1, k});
  return edges;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [stack_graph]
TEST_CASE_TEMPLATE("a stack's contact graph is the chain from the ground to the top", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const Material material{0.0, 0.5, 0.0};
  World<D> world = stacks::boxStack<D>(5, material);
  // At the start (all at rest, faces exactly touching): box k advanced by dt^2 g sinks into
  // box k-1 and approaches it; box k-1 advanced moves away from box k. So k-1 -> k only.
  const ContactGraph initial = worldContactGraph<D>(world, ContactGraphSettings{});
  CHECK(initial.edges() == chainEdges<D>(5));
  // After the contact stage of a step (the hook's view) the same chain.
  const ContactGraph afterContact = graphAfterContact<D>(world, StepSettings{});
  CHECK(afterContact.edges() == chainEdges<D>(5));
  const ContactLevels levels = topologicalLevels(afterContact);
  CHECK(levels.levelCount() == 6);
  for (int k = 0; k <= 5; ++k) CHECK(levels.levelOfBody[static_cast<std::size_t>(k)] == k);
}
// [stack_graph]

TEST_CASE_TEMPLATE("boxes side by side get no edge between them", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const Material material{0.0, 0.5, 0.0};
  for (const double gap : {0.0, 1e-3}) {
    CAPTURE(gap);
    World<D> world = stacks::groundWorld<D>(material);
    for (const double x : {-0.5 - 0.5 * gap, 0.5 + 0.5 * gap}) {
      Vec<D> c = 0.5 * stacks::up<D>();
      c[0] = x;
      stacks::addBox<D>(world, Vec<D>::Ones(), 1.0, c, material);
    }
    const std::vector<ContactPair> expected{{0, 1}, {0, 2}};
    CHECK(worldContactGraph<D>(world, ContactGraphSettings{}).edges() == expected);
    CHECK(graphAfterContact<D>(world, StepSettings{}).edges() == expected);
  }
}

TEST_CASE("without loads the direction is lost and an approaching pair gets both edges") {
  // Loads off: the advanced body keeps its velocity, so a stack at rest has no edges at all.
  // Give box 2 a downward speed: advancing box 2 or advancing box 1 is now the same motion,
  // each finds the other approaching, and the pair becomes a cycle 1 <-> 2. The direction
  // of an edge comes from the loads alone.
  World<2> world = stacks::boxStack<2>(2, Material{0.0, 0.5, 0.0});
  ContactGraphSettings settings;
  settings.loads = false;
  CHECK(worldContactGraph<2>(world, settings).edgeCount() == 0);
  world.bodies[2].velocity = Vec2(0.0, -0.01);
  const std::vector<ContactPair> both{{1, 2}, {2, 1}};
  CHECK(worldContactGraph<2>(world, settings).edges() == both);
}

// [freeze_guard_test]
TEST_CASE_TEMPLATE("the freeze guard restores inverse masses bit for bit even on an exception", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  World<D> world = stacks::boxStack<D>(3, Material{});
  world.bodies[2].inverseMass = 0.3;  // not a round number
  world.bodies[2].inverseInertia = AngVec<D>::Constant(1.0 / 7.0);
  const World<D> before = world;
  try {
    FreezeGuard<D> guard(world);
    CHECK_FALSE(guard.freeze(0));  // the ground is static already
    CHECK(guard.freeze(2));
    CHECK(guard.freeze(3));
    CHECK(guard.frozenCount() == 2);
    CHECK(world.bodies[2].isStatic());
    CHECK(collisionMatrix<D>(world.bodies[2], Vec<D>::Ones()).isZero(0.0));  // Eq. (1.9)
    throw std::runtime_error("leave the pass");
  } catch (const std::runtime_error&) {
  }
  for (std::size_t k = 0; k < world.bodies.size(); ++k) {
    CHECK(world.bodies[k].inverseMass == before.bodies[k].inverseMass);
    CHECK(world.bodies[k].inverseInertia == before.bodies[k].inverseInertia);
    CHECK(world.bodies[k].angularVelocity == before.bodies[k].angularVelocity);
  }
}
// [freeze_guard_test]

// [frozen_partner]
TEST_CASE_TEMPLATE("against a frozen body the whole correction goes to the other body", Dim, In2D, In3D) {
  // Box 2 falls at 1 m/s onto box 1, which sinks at 0.2 m/s and is frozen. The pair loop
  // (e = 0) must leave box 1 exactly as it was and end with no approaching sample: box 2
  // alone absorbed the correction, as if box 1 were infinitely heavy.
  constexpr int D = Dim::value;
  World<D> world = stacks::boxStack<D>(2, Material{0.0, 0.0, 0.0});  // frictionless
  world.bodies[1].velocity = -0.2 * stacks::up<D>();
  world.bodies[2].velocity = -1.0 * stacks::up<D>();
  const RigidBody<D> lower = world.bodies[1];
  StepSettings settings;
  std::vector<CollisionBody<D>> views = stageViews<D>(world, Lookahead::Velocity, settings.dt);
  StageSpec spec{Lookahead::Velocity, 1, 20, [](int, const PairMaterial&) { return 0.0; }};
  StageCounters counters;
  {
    FreezeGuard<D> guard(world);
    guard.freeze(1);
    CHECK(resolvePair<D>(world, views, BodyPair{1, 2}, spec, 1, settings.dt, settings, counters) >= 1);
    // What is left approaching is round-off (the loop may spend its cap on 1e-17 m/s).
    double approach = 0.0;
    for (const InterferenceSample<D>& sample : pairInterference<D>(views, BodyPair{1, 2})) {
      approach = std::max(approach, -normalRelativeVelocity<D>(sample, views));
    }
    CHECK(approach < 1e-9);
  }
  CHECK(world.bodies[1].velocity == lower.velocity);
  CHECK(world.bodies[1].angularMomentum == lower.angularMomentum);
  CHECK(world.bodies[1].inverseMass == lower.inverseMass);
  // Box 2's centre no longer moves down faster than box 1 (it was 0.8 m/s faster).
  CHECK(world.bodies[2].velocity[D - 1] > -0.2 - 1e-9);
}
// [frozen_partner]

// [bit_identical]
TEST_CASE_TEMPLATE("shock propagation forced on changes nothing where no body rests on a dynamic body", Dim, In2D, In3D) {
  // One box resting on the ground, and two boxes 6 m apart dropped from 0.02 m (they land
  // after sqrt(2 * 0.02 / 9.81) = 0.064 s and rest): the graph has only ground -> box edges,
  // the pass sweeps pairs the contact stage left not approaching, and the result must be
  // bit-identical to chapter 8's step.
  constexpr int D = Dim::value;
  const Material material{0.0, 0.5, 0.0};
  World<D> single = stacks::boxStack<D>(1, material);
  World<D> apart = stacks::groundWorld<D>(material);
  for (const double x : {-3.0, 3.0}) {
    Vec<D> c = 0.52 * stacks::up<D>();
    c[0] = x;
    stacks::addBox<D>(apart, Vec<D>::Ones(), 1.0, c, material);
  }
  for (World<D>* start : {&single, &apart}) {
    World<D> off = *start;
    World<D> on = *start;
    StepSettings settings;
    settings.effects.shockPropagation = false;
    StepSettings forced = settings;
    forced.effects.shockPropagation = true;
    StepCounters onCounters;
    for (int n = 0; n < 100; ++n) {
      gbfStep<D>(off, settings);
      onCounters += stackingStep<D>(on, forced);
    }
    CHECK(onCounters.effects.shockPropagation);
    CHECK(testing::stateHash<D>(on) == testing::stateHash<D>(off));
  }
}
// [bit_identical]

// [changes_stack]
TEST_CASE_TEMPLATE("shock propagation changes a real stack and reduces its sag", Dim, In2D, In3D) {
  // The same five-box stack 0.05 s with and without the pass: the states differ (so the test
  // above can fail), and the top sags less with the pass than without.
  constexpr int D = Dim::value;
  const Material material{0.0, 0.5, 0.0};
  const World<D> start = stacks::boxStack<D>(5, material);
  World<D> off = start;
  World<D> on = start;
  stacks::run<D>(off, StepSettings{}, 0.05, false);
  const StepCounters c = stacks::run<D>(on, StepSettings{}, 0.05, true);
  CHECK(testing::stateHash<D>(on) != testing::stateHash<D>(off));
  const double sagOff = stacks::measureStack<D>(start, off, 1, 5).sag;
  const double sagOn = stacks::measureStack<D>(start, on, 1, 5).sag;
  CHECK(sagOn < 0.5 * sagOff);
  // Work: 6 levels, 5 with pairs, 2 sweeps each, so 10 sweeps and 10 pair visits per step.
  CHECK(c.shock.sweeps == 10 * c.steps);
  CHECK(c.shock.pairVisits == 10 * c.steps);
}
// [changes_stack]

}  // TEST_SUITE
