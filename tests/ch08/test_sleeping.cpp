// Chapter 8, "Sleeping": a scene in motion is bit for bit the same with sleeping on and off;
// a body at rest falls asleep after the set time and then does not move; a sleeping stack
// that a dropped box wakes ends where the same stack kept awake ends; sleeping never adds
// energy.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "support/dimensions.hpp"
#include "support/mechanical_energy.hpp"
#include "scene_builders.hpp"
#include "stackbook/stacking/shock_propagation.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

StepSettings sleepAfter(double time) {
  StepSettings s;
  s.sleep.enabled = true;
  s.sleep.time = time;
  return s;
}

/// A column of `count` unit boxes on a static slab (top face y = 0), exactly touching,
/// mu 0.6, and one more unit box `gap` metres above the column's top, at rest.
template <int D>
World<D> columnWithDroppedBox(int count, double gap) {
  World<D> world;
  world.gravity = -kG * up<D>();
  const Material wood{0.0, 0.6, 0.0};
  addSlab<D>(world, 0.0, wood);
  for (int k = 0; k <= count; ++k) {
    RigidBody<D> box = unitBox<D>();
    box.position = (0.5 + k + (k == count ? gap : 0.0)) * up<D>();
    world.addBody(box, unitBoxShape<D>(), wood);
  }
  return world;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("Sleeping never changes a scene in motion: bit for bit with sleeping on and off",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // A block that starts at rest and slides down 30 degrees (mu 0.3): slower than the rest
  // thresholds for its first steps, then faster. And a ball bouncing with e = 0.8, whose
  // apexes are slow for a few steps each.
  StepSettings off;
  StepSettings on = sleepAfter(0.5);
  InclineScene<D> a = makeIncline<D>(degrees(30.0), 0.3, 0.0);
  InclineScene<D> b = a;
  simulate<D>(a.world, off, 1.0);
  const StepCounters c = simulate<D>(b.world, on, 1.0);
  CHECK(stateHash<D>(a.world) == stateHash<D>(b.world));
  CHECK(c.sleep.fellAsleep == 0);
  CHECK(c.effects.sleeping);

  DropScene<D> ball = makeBallDrop<D>(0.25, 0.5, Material{0.8, 0.0, 0.0});
  DropScene<D> ball2 = ball;
  simulate<D>(ball.world, off, 1.5);
  const StepCounters cb = simulate<D>(ball2.world, on, 1.5);
  CHECK(stateHash<D>(ball.world) == stateHash<D>(ball2.world));
  CHECK(cb.sleep.fellAsleep == 0);
  CHECK(cb.sleep.sleepingBodySteps == 0);
}

TEST_CASE_TEMPLATE("A body at rest falls asleep after the set time and then does not move", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  InclineScene<D> scene = makeIncline<D>(0.0, 0.5, 0.0);  // a box resting on level ground
  const StepSettings s = sleepAfter(0.2);                     // 200 steps of 1 ms
  simulate<D>(scene.world, s, 0.195);
  CHECK(scene.world.asleep.at(1) == 0);
  const StepCounters c = simulate<D>(scene.world, s, 0.010);
  CHECK(scene.world.asleep.at(1) == 1);
  CHECK(c.sleep.fellAsleep == 1);
  const RigidBody<D> before = scene.world.bodies[1];
  const std::uint64_t stateBefore = stateHash<D>(scene.world);
  CHECK(before.velocity.isZero(0.0));
  const StepCounters later = simulate<D>(scene.world, s, 0.1);
  CHECK(later.sleep.sleepingBodySteps == 100);
  CHECK(later.sleep.sleepingAtEnd == 1);
  CHECK(later.collision.pairVisits == 0);  // the ground and a sleeper: nothing to simulate
  const RigidBody<D>& after = scene.world.bodies[1];
  CHECK(stateHash<D>(scene.world) == stateBefore);  // pose and (zero) velocities, bit for bit
  CHECK(after.inverseMass == before.inverseMass);  // made heavy only during each step
}

// [sleep_woken_stack]
TEST_CASE_TEMPLATE("A sleeping stack woken by a dropped box ends where the awake stack ends, "
                   "without energy gain", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Three boxes, and a fourth released 1.5 m above them: it lands after 0.55 s, when the
  // stack has slept since 0.3 s.
  World<D> awake = columnWithDroppedBox<D>(3, 1.5);
  World<D> sleepy = awake;
  const StepSettings off;
  const StepSettings on = sleepAfter(0.3);
  // The same step without falling asleep: sleep.time so long that no island is ever ready.
  // Everything else in the step is the same (the sleepers stay asleep, the rest times are
  // kept), so it ends where the sleeping step ends before fallAsleep() zeroes velocities.
  StepSettings neverReady = on;
  neverReady.sleep.time = std::numeric_limits<double>::max();
  const double e0 = mechanicalEnergy<D>(sleepy);
  std::int64_t asleepBeforeImpact = 0, sleepSteps = 0;
  StepCounters c;
  const long steps = 1500;
  for (long n = 0; n < steps; ++n) {
    stackingStep<D>(awake, off);
    World<D> probe = sleepy;
    const StepCounters k = stackingStep<D>(sleepy, on);
    if (k.sleep.fellAsleep > 0) {
      // Falling asleep keeps every pose and sets v = 0 and L = 0 (Eq. (8.15)): it removes
      // the kinetic energy of the bodies that fell asleep and adds none. The rest of the step
      // is GBF's step on awake bodies, whose energy sleeping does not own (a box settling on
      // another moves by its approach speed times dt, far above round-off), so the claim is
      // checked against the same step without falling asleep, not against the step's start.
      ++sleepSteps;
      stackingStep<D>(probe, neverReady);
      double removed = 0.0;
      for (std::size_t i = 0; i < sleepy.bodies.size(); ++i) {
        CAPTURE(i);
        CHECK(sleepy.bodies[i].position == probe.bodies[i].position);  // bit for bit
        if (sleepy.asleep[i] != 0 && probe.asleep[i] == 0) {
          CHECK(sleepy.bodies[i].velocity.isZero(0.0));
          removed += probe.bodies[i].kineticEnergy();
        } else {
          CHECK(sleepy.bodies[i].velocity == probe.bodies[i].velocity);
        }
      }
      // Rounding is monotone, so a sum with some terms lowered is not larger: exact.
      CHECK(mechanicalEnergy<D>(sleepy) <= mechanicalEnergy<D>(probe));
      // The difference is the removed kinetic energy, to the round-off of sums of terms of
      // size E0 (the invariant tier, 1e-9 E0).
      CHECK(std::abs(mechanicalEnergy<D>(probe) - mechanicalEnergy<D>(sleepy) - removed) <= 1e-9 * std::abs(e0));
    }
    c += k;
    if (n == 500) asleepBeforeImpact = k.sleep.sleepingAtEnd;
  }
  CHECK(asleepBeforeImpact == 3);  // the stack slept; the falling box did not
  CHECK(c.sleep.wokenUp >= 3);     // the landing box woke all three
  CHECK(sleepSteps >= 2);          // the column fell asleep, and again after the landing
  CHECK(mechanicalEnergy<D>(sleepy) <= e0);
  // The same end within 1 mm (a tenth of the 1 cm position tolerance engines use for
  // resting bodies): the sleeping column did not creep while it slept and the awake one did,
  // so the box lands on poses that differ by that creep, and the impact carries the
  // difference into all four boxes.
  for (std::size_t i = 1; i < awake.bodies.size(); ++i) {
    CAPTURE(i);
    CHECK((awake.bodies[i].position - sleepy.bodies[i].position).norm() < 1e-3);
  }
}
// [sleep_woken_stack]

TEST_CASE("Sleep settings out of range are rejected naming the field") {
  World<2> world;
  StepSettings s;
  s.sleep.time = -1.0;
  CHECK_THROWS_WITH_AS(gbfStep<2>(world, s), doctest::Contains("settings.sleep.time must be finite and >= 0"),
                       std::invalid_argument);
  s.sleep.time = 0.5;
  s.sleep.linearSpeed = std::nan("");
  CHECK_THROWS_WITH_AS(gbfStep<2>(world, s), doctest::Contains("sleep.linearSpeed"), std::invalid_argument);
}

}  // TEST_SUITE
