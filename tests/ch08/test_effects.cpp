// Chapter 8: the effects a step runs. inferEffects() turns an effect off only where running
// it could change nothing; these tests check the inference on representative scenes and
// then the claim itself, bit for bit: a scene that does not need an effect ends in exactly
// the same state whether the effect is skipped or forced on. Each such test has a
// companion in which the scene does need the effect and forcing it off changes the
// result, so that the comparison can fail.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <random>

#include "scenes.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// Runs `seconds` of the scene with the given overrides; returns the state hash and the
/// counters.
template <int D>
std::uint64_t runWith(World<D> world, const EffectOverrides& overrides, double seconds,
                      StepCounters* counters = nullptr) {
  StepSettings settings;
  settings.effects = overrides;
  const StepCounters c = simulate<D>(world, settings, seconds);
  if (counters != nullptr) *counters = c;
  return stateHash<D>(world);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_infer]
TEST_CASE_TEMPLATE("Effects are inferred from the bodies and the pair rule of the materials", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  {  // one body alone in zero gravity: nothing to do but move it
    World<D> w;
    w.addBody(unitBox<D>(), unitBoxShape<D>(), Material{0.5, 0.5, 0.1});
    const Effects e = inferEffects<D>(w);
    CHECK(e.summary() == "none");
  }
  {  // the elastic box on the incline (A1): everything but rolling and shock propagation
    const Effects e = inferEffects<D>(makeIncline<D>(degrees(20.0), 0.5, 1.0).world);
    CHECK(e.summary() == "gravity collision restitution contact friction");
  }
  {  // mu = 0.5 on the ground but 0 on the box: the pair's min is 0, no friction
    InclineScene<D> s = makeIncline<D>(degrees(20.0), 0.0, 0.0);
    s.world.materials[0] = Material{0.7, 0.5, 0.0};
    CHECK(inferEffects<D>(s.world).summary() == "gravity collision contact");
  }
  {  // a rolling coefficient without friction does nothing (it acts after sticking)
    World<D> w = makeTumblingBox<D>(0.0, 0.0, 0.1);
    CHECK_FALSE(inferEffects<D>(w).rollingFriction);
    for (Material& m : w.materials) m.friction = 0.2;
    CHECK(inferEffects<D>(w).rollingFriction);
  }
  {  // two dynamic bodies can rest on each other: shock propagation; two static ones: none
    World<D> w;
    w.addBody(unitBox<D>(), unitBoxShape<D>(), Material{});
    w.addBody(unitBox<D>(), unitBoxShape<D>(), Material{});
    CHECK(inferEffects<D>(w).shockPropagation);
    World<D> still;
    still.gravity = -kG * up<D>();
    still.addBody(makeStaticBody<D>(), unitBoxShape<D>(), Material{1.0, 1.0, 1.0});
    still.addBody(makeStaticBody<D>(), unitBoxShape<D>(), Material{1.0, 1.0, 1.0});
    CHECK(inferEffects<D>(still).summary() == "none");
  }
}
// [test_infer]

TEST_CASE("The largest pair coefficient in O(n) equals the brute-force maximum over pairs") {
  // Random scenes of 1 to 6 bodies, each static with probability 1/3, coefficients drawn
  // from a few values (ties matter): the closed form against max over pairs i < k with at
  // least one dynamic body of min(c_i, c_k).
  std::mt19937 rng(84);
  std::uniform_int_distribution<int> count(1, 6), pick(0, 3), kind(0, 2);
  const double values[4] = {0.0, 0.2, 0.5, 0.9};
  for (int trial = 0; trial < 500; ++trial) {
    World<2> w;
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
      const RigidBody<2> b = kind(rng) == 0 ? makeStaticBody<2>() : unitBox<2>();
      w.addBody(b, unitBoxShape<2>(), Material{0.0, values[pick(rng)], 0.0});
    }
    double brute = 0.0;
    for (int i = 0; i < n; ++i) {
      for (int k = i + 1; k < n; ++k) {
        const auto ui = static_cast<std::size_t>(i), uk = static_cast<std::size_t>(k);
        if (w.bodies[ui].isStatic() && w.bodies[uk].isStatic()) continue;
        brute = std::max(brute, std::min(w.materials[ui].friction, w.materials[uk].friction));
      }
    }
    CAPTURE(trial);
    CHECK(largestPairCoefficient<2>(w, [](const Material& m) { return m.friction; }) == brute);
  }
}

// [test_counters_effects]
TEST_CASE_TEMPLATE("A step reports the effects it ran in its counters", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  World<D> w = makeTumblingBox<D>(0.5, 0.3);
  StepSettings settings;
  StepCounters c = gbfStep<D>(w, settings);
  CHECK(c.effects == inferEffects<D>(w));
  settings.effects.friction = false;
  settings.effects.rollingFriction = true;
  c = gbfStep<D>(w, settings);
  CHECK(c.effects.summary() == "gravity collision restitution contact rolling-friction");
  // shock propagation is inferred for two dynamic bodies but runs only with a hook
  w.addBody(unitBox<D>(), unitBoxShape<D>(), Material{});
  w.bodies.back().position = Vec<D>::Constant(10.0);
  CHECK(inferEffects<D>(w).shockPropagation);
  CHECK_FALSE(gbfStep<D>(w, StepSettings{}).effects.shockPropagation);
  const PostContactHook<D> hook = [](World<D>&, const StepSettings&, StepCounters&) {};
  CHECK(gbfStep<D>(w, StepSettings{}, hook).effects.shockPropagation);
  CHECK(traditionalStep<D>(w, StepSettings{}, hook).effects.shockPropagation);
}
// [test_counters_effects]

// [test_skip_friction]
TEST_CASE_TEMPLATE("A frictionless scene skips the friction code and matches it forced on bit for bit",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const World<D> scene = makeTumblingBox<D>(0.0, 0.3);
  EffectOverrides forced;
  forced.friction = true;
  StepCounters inferred, on;
  const std::uint64_t skipped = runWith<D>(scene, {}, 0.12, &inferred);
  CHECK(inferred.collision.frictionEvaluations + inferred.contact.frictionEvaluations == 0);
  CHECK(inferred.collision.impulses + inferred.contact.impulses > 0);  // it did collide
  CHECK(runWith<D>(scene, forced, 0.12, &on) == skipped);
  CHECK(on.collision.frictionEvaluations + on.contact.frictionEvaluations > 0);  // it did run
}

TEST_CASE_TEMPLATE("Forcing friction off where mu 0.5 acts changes the result", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const World<D> scene = makeTumblingBox<D>(0.5, 0.3);
  EffectOverrides off;
  off.friction = false;
  CHECK(runWith<D>(scene, off, 0.12) != runWith<D>(scene, {}, 0.12));
}
// [test_skip_friction]

TEST_CASE_TEMPLATE("A scene with e 0 everywhere matches the restitution effect forced on bit for bit",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const World<D> scene = makeTumblingBox<D>(0.5, 0.0);
  EffectOverrides forced;
  forced.restitution = true;
  StepCounters inferred, on;
  const std::uint64_t skipped = runWith<D>(scene, {}, 0.12, &inferred);
  CHECK_FALSE(inferred.effects.restitution);
  CHECK(runWith<D>(scene, forced, 0.12, &on) == skipped);
  CHECK(on.effects.restitution);
  CHECK(on.collision.impulses > 0);
  CHECK(on.collision.elasticImpulses == 0);
}

TEST_CASE_TEMPLATE("Forcing restitution off where e 0.5 acts changes the result", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const World<D> scene = makeTumblingBox<D>(0.5, 0.5);
  EffectOverrides off;
  off.restitution = false;
  StepCounters c;
  runWith<D>(scene, {}, 0.12, &c);
  CHECK(c.collision.elasticImpulses > 0);
  CHECK(runWith<D>(scene, off, 0.12) != runWith<D>(scene, {}, 0.12));
}

TEST_CASE_TEMPLATE("A rolling coefficient of 0 forced on matches rolling friction off bit for bit",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const Material m{0.0, 0.5, 0.0};
  const World<D> scene = makeRollingBall<D>(0.25, 0.5, m, m, 200).world;
  EffectOverrides on, off;
  on.rollingFriction = true;
  off.rollingFriction = false;
  StepCounters c;
  const std::uint64_t forced = runWith<D>(scene, on, 0.05, &c);
  CHECK(c.effects.rollingFriction);
  CHECK(c.contact.sticking > 0);  // sticking impulses after which it could have acted
  CHECK(c.contact.rollingImpulses == 0);
  CHECK(forced == runWith<D>(scene, off, 0.05));
}

TEST_CASE_TEMPLATE("Forcing rolling friction off where mu_r 0.05 acts changes the result", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  const Material m{0.0, 0.5, 0.05};
  const World<D> scene = makeRollingBall<D>(0.25, 0.5, m, m, 200).world;
  EffectOverrides off;
  off.rollingFriction = false;
  StepCounters c;
  const std::uint64_t inferred = runWith<D>(scene, {}, 0.05, &c);
  CHECK(c.contact.rollingImpulses > 0);
  CHECK(runWith<D>(scene, off, 0.05) != inferred);
}

}  // TEST_SUITE
