// Chapter 8: where a pair's impulse acts (Eqs. (8.10)-(8.12)). GBF's deepest approaching
// sample, or the depth-weighted centre of the approaching samples that share its normal:
// the centre's arithmetic on hand-made samples, its two fallbacks, and what it changes in a
// simulation (a box that lands flat bounces without spin).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "scenes.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// A unit box (body 1) above a static ground slab (body 0) moving down at 1 m/s, and the
/// collision views of both at their current poses.
struct FallingBox {
  World<2> world;
  std::vector<CollisionBody<2>> views;

  FallingBox() {
    world.gravity = Vec2::Zero();
    addSlab<2>(world, 0.0, Material{});
    RigidBody<2> box = unitBox<2>();
    box.position = Vec2(0.0, 0.5);
    box.velocity = Vec2(0.0, -1.0);
    world.addBody(box, unitBoxShape<2>(), Material{});
    views = stageViews<2>(world, Lookahead::Current, 1e-3);
  }
};

InterferenceSample<2> sample(int owner, int other, Vec2 point, double depth, Vec2 normal, int index) {
  InterferenceSample<2> s;
  s.owner = owner;
  s.other = other;
  s.point = point;
  s.depth = depth;
  s.normal = normal.normalized();
  s.sampleIndex = index;
  return s;
}

ImpulsePointSettings centreRule(double normalCosine = 0.99) {
  return ImpulsePointSettings{ImpulsePointRule::DepthWeightedCentre, normalCosine};
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [impulse_point_test]
TEST_CASE("The impulse point is the depth-weighted centre of the samples that share the deepest normal") {
  // Box corners at x = -1/2 (depth 1 mm) and +1/2 (3 mm), a ground sample inside the box
  // at x = 0 (2 mm, normal down: turned to the box it is up), and a deeper-than-most sample
  // whose normal leans 37 degrees away. Eq. (8.10): x = (-0.5 * 1 + 0.5 * 3 + 0 * 2) / 6.
  const FallingBox scene;
  const std::vector<InterferenceSample<2>> samples{
      sample(1, 0, Vec2(-0.5, 0.0), -1e-3, Vec2(0.0, 1.0), 0),
      sample(1, 0, Vec2(0.5, 0.0), -3e-3, Vec2(0.0, 1.0), 1),
      sample(0, 1, Vec2(0.0, 0.0), -2e-3, Vec2(0.0, -1.0), 7),
      sample(1, 0, Vec2(0.2, 0.0), -2.5e-3, Vec2(0.6, 0.8), 2)};
  const auto deepest = impulsePoint<2>(samples, scene.views, ImpulsePointSettings{});
  REQUIRE(deepest.has_value());
  CHECK(deepest->sampleIndex == 1);
  CHECK(deepest->point == Vec2(0.5, 0.0));

  const auto centre = impulsePoint<2>(samples, scene.views, centreRule());
  REQUIRE(centre.has_value());
  CHECK(centre->point.x() == doctest::Approx(1.0 / 6.0).epsilon(1e-15));
  CHECK(centre->point.y() == 0.0);
  CHECK(centre->owner == 1);
  CHECK(centre->other == 0);
  CHECK(centre->normal == Vec2(0.0, 1.0));
  CHECK(centre->depth == -3e-3);
  CHECK(centre->sampleIndex == -1);
}
// [impulse_point_test]

TEST_CASE("A lone approaching sample is its own impulse point under both rules") {
  // The second corner separates (the box turns about the first one), so only one sample
  // is left to average: the centre rule returns GBF's sample unchanged.
  FallingBox scene;
  scene.world.bodies[1].velocity = Vec2(0.0, 0.0);
  scene.world.bodies[1].setAngularVelocity(AngVec<2>(2.0));  // left corner down, right up
  scene.views = stageViews<2>(scene.world, Lookahead::Current, 1e-3);
  const std::vector<InterferenceSample<2>> samples{
      sample(1, 0, Vec2(-0.5, 0.0), -1e-3, Vec2(0.0, 1.0), 0),
      sample(1, 0, Vec2(0.5, 0.0), -3e-3, Vec2(0.0, 1.0), 1)};
  const auto deepest = impulsePoint<2>(samples, scene.views, ImpulsePointSettings{});
  const auto centre = impulsePoint<2>(samples, scene.views, centreRule());
  REQUIRE(deepest.has_value());
  REQUIRE(centre.has_value());
  CHECK(deepest->sampleIndex == 0);
  CHECK(centre->sampleIndex == 0);
  CHECK(centre->point == deepest->point);
}

TEST_CASE("A normal cosine of one admits only samples whose normal is exactly the deepest one") {
  const FallingBox scene;
  const std::vector<InterferenceSample<2>> samples{
      sample(1, 0, Vec2(-0.5, 0.0), -1e-3, Vec2(0.0, 1.0), 0),
      sample(1, 0, Vec2(0.5, 0.0), -1e-3, Vec2(1e-3, 1.0), 1)};
  const auto strict = impulsePoint<2>(samples, scene.views, centreRule(1.0));
  const auto loose = impulsePoint<2>(samples, scene.views, centreRule(0.99));
  REQUIRE(strict.has_value());
  REQUIRE(loose.has_value());
  CHECK(strict->sampleIndex == 0);  // equal depths: the first one is the deepest
  CHECK(loose->point.x() == doctest::Approx(0.0).scale(1.0).epsilon(1e-15));
}

TEST_CASE("No approaching sample gives no impulse point under either rule") {
  FallingBox scene;
  scene.world.bodies[1].velocity = Vec2(0.0, 1.0);  // moving away from the ground
  scene.views = stageViews<2>(scene.world, Lookahead::Current, 1e-3);
  const std::vector<InterferenceSample<2>> samples{
      sample(1, 0, Vec2(-0.5, 0.0), -1e-3, Vec2(0.0, 1.0), 0)};
  CHECK_FALSE(impulsePoint<2>(samples, scene.views, ImpulsePointSettings{}).has_value());
  CHECK_FALSE(impulsePoint<2>(samples, scene.views, centreRule()).has_value());
}

TEST_CASE("A normal cosine outside zero to one is rejected with the field name") {
  StepSettings s;
  s.impulsePoint.normalCosine = 0.0;
  CHECK_THROWS_WITH_AS(validateStepSettings(s, "test"),
                       doctest::Contains("settings.impulsePoint.normalCosine must be in (0, 1]"),
                       std::invalid_argument);
  s.impulsePoint.normalCosine = 1.5;
  CHECK_THROWS_AS(validateStepSettings(s, "test"), std::invalid_argument);
}

// [flat_landing_test]
TEST_CASE_TEMPLATE("A box that lands flat bounces straight up without spin when impulses act at the centre",
                   Dim, In2D, In3D) {
  // Eq. (8.12): all the bottom face's corners touch in the same step at the same depth, so
  // the centre is the face's middle, below the centre of mass: the impulse has no torque
  // and the rebound is exactly -e times the impact speed, whatever order the shape lists
  // its samples in (GBF's rule takes the first of the tied samples: a corner spins the
  // box, a face sample in the middle does not).
  constexpr int D = Dim::value;
  const Material bouncy{0.5, 0.5, 0.0};
  const auto land = [&](ImpulsePointRule rule, double& rebound, double& impact) {
    // Returns |omega| after the step with the first collision impulse.
    DropScene<D> scene = makeRestingBox<D>(bouncy);
    scene.world.bodies[static_cast<std::size_t>(scene.body)].position[D - 1] += 0.05;
    StepSettings settings;
    settings.impulsePoint.rule = rule;
    for (int n = 0; n < 200; ++n) {
      const double before = scene.upSpeed();
      const StepCounters c = gbfStep<D>(scene.world, settings);
      if (c.collision.impulses > 0) {
        impact = before;
        rebound = scene.upSpeed() + kG * settings.dt;  // the velocity update came after
        break;
      }
    }
    return scene.dropped().angularVelocity.norm();
  };
  double rebound = 0.0, impact = 0.0;
  const double spinCentre = land(ImpulsePointRule::DepthWeightedCentre, rebound, impact);
  CHECK(impact < -0.9);
  CHECK(spinCentre < 1e-12);
  CHECK(rebound == doctest::Approx(-0.5 * impact).epsilon(1e-9));
}
// [flat_landing_test]

}  // TEST_SUITE
