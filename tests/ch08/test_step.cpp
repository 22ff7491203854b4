// Chapter 8: the step as an API. Free motion is exactly chapter 5's step, the hook runs
// between contact and the position update, the restitution ramp and the pair rule are
// what the chapter states, runs are bit-for-bit repeatable, and bad input is rejected
// with a message that names the body and the field.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "scenes.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// The tumbling box of scenes.hpp with mu 0.5 and e 0.3.
template <int D>
World<D> tumblingBox() {
  return makeTumblingBox<D>(0.5, 0.3);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("A body that touches nothing moves exactly as chapter 5's free step", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  World<D> world;
  world.gravity = -kG * up<D>();
  RigidBody<D> body = makeDynamicBody<D>(2.0, AngVec<D>::LinSpaced(0.5, 0.7));
  body.velocity = Vec<D>::LinSpaced(1.0, 2.0);
  body.setAngularVelocity(AngVec<D>::LinSpaced(3.0, -1.0));
  world.addBody(body, unitBoxShape<D>(), Material{0.5, 0.5, 0.0});
  RigidBody<D> reference = body;
  StepSettings settings;
  for (int n = 0; n < 20; ++n) {
    gbfStep<D>(world, settings);
    advanceFreeBody<D>(reference, settings.dt, gravityLoads<D>(world.gravity));
  }
  const RigidBody<D>& b = world.bodies[0];
  CHECK(b.position == reference.position);
  CHECK(b.velocity == reference.velocity);
  CHECK(b.angularMomentum == reference.angularMomentum);
  CHECK(rotationMatrix<D>(b.orientation) == rotationMatrix<D>(reference.orientation));
}

TEST_CASE("The post-contact hook runs once per step after the velocity update and before positions<2D>") {
  World<2> world;
  world.gravity = Vec2(0.0, -kG);
  world.addBody(unitBox<2>(), unitBoxShape<2>());
  StepSettings settings;
  settings.effects.shockPropagation = true;  // the hook is the shock-propagation effect
  int calls = 0;
  Vec2 seen = Vec2::Zero();
  const PostContactHook<2> stop = [&](World<2>& w, const StepSettings&, StepCounters&) {
    ++calls;
    seen = w.bodies[0].velocity;
    w.bodies[0].velocity.setZero();
  };
  for (int n = 0; n < 3; ++n) gbfStep<2>(world, settings, stop);
  CHECK(calls == 3);
  CHECK(seen.y() == -kG * settings.dt);          // gravity was added before the hook
  CHECK(world.bodies[0].position == Vec2::Zero());  // and positions moved after it
}

TEST_CASE("The default contact restitution ramp is -1 + k/N and ends at exactly 0") {
  StepSettings s;
  REQUIRE(s.contactIterations == 10);
  for (int k = 1; k <= 10; ++k) CHECK(s.contactRestitutionAt(k) == doctest::Approx(-1.0 + 0.1 * k));
  CHECK(s.contactRestitutionAt(10) == 0.0);
  s.contactIterations = 4;
  CHECK(s.contactRestitutionAt(1) == -0.75);
  s.contactRestitution = {-0.5, -0.25, 0.0, 0.0};
  CHECK(s.contactRestitutionAt(2) == -0.25);
}

TEST_CASE("A pair takes the smaller restitution and the smaller friction of its two materials") {
  const Material rubber{0.8, 1.0, 0.0}, ice{0.1, 0.02, 0.0};
  const PairMaterial ab = combineMaterials(rubber, ice), ba = combineMaterials(ice, rubber);
  CHECK(ab.restitution == 0.1);
  CHECK(ab.friction == 0.02);
  CHECK(ba.restitution == ab.restitution);
  CHECK(ba.friction == ab.friction);
}

// [test_determinism]
TEST_CASE_TEMPLATE("Two runs of the same scene end in bit-identical states", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  World<D> first = tumblingBox<D>(), second = tumblingBox<D>();
  const std::uint64_t initial = stateHash<D>(first);
  StepSettings settings;
  const StepCounters c = simulate<D>(first, settings, 0.12);
  simulate<D>(second, settings, 0.12);
  CHECK(c.collision.impulses + c.contact.impulses > 0);  // it did collide
  CHECK(stateHash<D>(first) != initial);
  CHECK(stateHash<D>(first) == stateHash<D>(second));
}
// [test_determinism]

// [test_bad_input]
TEST_CASE("A bad world or bad settings is rejected with a message naming the body and field<2D>") {
  const auto make = [] { return makeIncline<2>(degrees(20.0), 0.5, 0.5).world; };
  const StepSettings good;
  {
    World<2> w = make();
    w.bodies[1].position.x() = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH_AS(gbfStep<2>(w, good), doctest::Contains("body 1: position"),
                         std::invalid_argument);
  }
  {
    World<2> w = make();
    w.materials[1].friction = -0.1;
    CHECK_THROWS_WITH_AS(gbfStep<2>(w, good), doctest::Contains("body 1: material.friction"),
                         std::invalid_argument);
  }
  {
    World<2> w = make();
    w.materials[0].restitution = 1.5;
    CHECK_THROWS_WITH_AS(traditionalStep<2>(w, good),
                         doctest::Contains("body 0: material.restitution"), std::invalid_argument);
  }
  {
    World<2> w = make();
    w.materials[1].rollingFriction = -0.01;
    CHECK_THROWS_WITH_AS(gbfStep<2>(w, good), doctest::Contains("body 1: material.rollingFriction"),
                         std::invalid_argument);
  }
  {
    World<2> w = make();
    w.shapes[1] = nullptr;
    CHECK_THROWS_WITH_AS(gbfStep<2>(w, good), doctest::Contains("body 1: shape is null"),
                         std::invalid_argument);
  }
  for (double dt : {0.0, -1e-3, std::numeric_limits<double>::infinity()}) {
    World<2> w = make();
    StepSettings bad;
    bad.dt = dt;
    CHECK_THROWS_WITH_AS(gbfStep<2>(w, bad), doctest::Contains("settings.dt"), std::invalid_argument);
  }
  {
    World<2> w = make();
    StepSettings bad;
    bad.contactRestitution = {-0.5, 0.0};
    CHECK_THROWS_WITH_AS(gbfStep<2>(w, bad), doctest::Contains("settings.contactRestitution"),
                         std::invalid_argument);
  }
  {
    World<2> w = make();
    const World<2> before = w;
    w.materials[1].friction = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS(gbfStep<2>(w, good));
    CHECK(w.bodies[1].position == before.bodies[1].position);  // nothing moved
  }
}
// [test_bad_input]

}  // TEST_SUITE
