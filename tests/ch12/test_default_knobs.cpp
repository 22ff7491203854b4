// Chapter 12, "Accurate where it is cheap": the default step turns bodies by chapter 5's implicit
// midpoint rule and asks round shapes for their exact deepest point (SurfaceQuery::RoundShapes),
// while boxes and meshes keep their samples bit for bit.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "../support/dimensions.hpp"
#include "ch09/stack_scenes.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"
#include "default_settings.hpp"
#include "stackbook/stacking/solver_preset.hpp"

using namespace stackbook;

namespace {

/// A ball (disk in 2D) of radius 0.25 m and 1 kg, launched at v0 along x with no spin on a static
/// floor sampled at its corners only, mu for both; returns its speed after `seconds`.
template <int D>
double speedAfterSlideAndRoll(double v0, double mu, const StepSettings& settings, double seconds) {
  World<D> world;
  world.gravity = -stacks::kG * stacks::up<D>();
  const Material m{0.0, mu, 0.0};
  Vec<D> size = Vec<D>::Constant(40.0);
  size[D - 1] = 1.0;
  SampleMeshSettings corners;
  corners.boxSubdivisions = 1;
  world.addBody(makeStaticBody<D>(Vec<D>(-0.5 * stacks::up<D>())),
                std::make_shared<BoxShape<D>>(makeBoxShape<D>(size, corners)), m);
  const double radius = 0.25;
  const double k = D == 3 ? 0.4 : 0.5;  // I / (m r^2) of a solid ball and of a disk
  RigidBody<D> ball = makeDynamicBody<D>(1.0, AngVec<D>::Constant(k * radius * radius));
  ball.position = radius * stacks::up<D>();
  ball.position[0] = -15.0;
  ball.velocity = Vec<D>::Zero();
  ball.velocity[0] = v0;
  world.addBody(ball, std::make_shared<SphereShape<D>>(makeSphereShape<D>(radius)), m);
  const long steps = std::lround(seconds / settings.dt);
  for (long n = 0; n < steps; ++n) stackingStep<D>(world, settings);
  return world.bodies[1].velocity[0];
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [default_knobs_test]
TEST_CASE("The default's knobs: the implicit midpoint rotation rule and exact deepest points for round shapes only") {
  const StepSettings s = applySolverPreset(kDefaultScenePreset, StepSettings{});
  CHECK(s.rotation == RotationUpdate::ImplicitMidpoint);
  CHECK(s.detection.narrow.surfaceQuery == SurfaceQuery::RoundShapes);
  // Every other preset is GBF's in both (a scene's own fields still change them).
  for (const auto& entry : kSolverPresets) {
    if (entry.first == SolverPreset::CarryingPass) continue;
    const StepSettings other = applySolverPreset(entry.first, s);
    CHECK(other.rotation == RotationUpdate::ExponentialMap);
    CHECK(other.detection.narrow.surfaceQuery == SurfaceQuery::Samples);
  }
  CHECK(makeSphereShape<3>(0.5).roundSurface());
  CHECK(makeSphereShape<2>(0.5).roundSurface());
  CHECK_FALSE(BoxShape<3>(makeBoxShape<3>(Vec3(1.0, 1.0, 1.0))).roundSurface());
}
// [default_knobs_test]

TEST_CASE("Under the default a free box tumbling about its middle axis keeps its energy within 1e-9 over 100 s") {
  // Half-extents (0.1, 0.2, 0.3) m, 1 kg, spun at 10 rad/s about the intermediate (y) axis with a
  // 0.1 rad/s nudge on the others: it flips over and over (chapter 11). No gravity, no contact.
  World<3> world;
  const Vec3 h(0.1, 0.2, 0.3);
  const Vec3 moments = Vec3(h.y() * h.y() + h.z() * h.z(), h.x() * h.x() + h.z() * h.z(), h.x() * h.x() + h.y() * h.y()) / 3.0;
  RigidBody<3> box = makeDynamicBody<3>(1.0, moments);
  box.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3(1.0, 2.0, -1.0).normalized()));
  box.setAngularVelocity(box.orientation * Vec3(0.1, 10.0, 0.1));
  world.addBody(box, std::make_shared<BoxShape<3>>(makeBoxShape<3>(Vec3(0.2, 0.4, 0.6))));
  const StepSettings settings = testing::defaultStepAt(1e-3);
  const double e0 = world.bodies[0].kineticEnergy();
  double largest = 0.0;
  for (int n = 0; n < 100000; ++n) {
    stackingStep<3>(world, settings);
    largest = std::max(largest, std::abs(world.bodies[0].kineticEnergy() / e0 - 1.0));
  }
  CHECK(largest < 1e-9);
}

// [default_rolls_test]
TEST_CASE_TEMPLATE("Under the default a disk and a ball launched sliding end rolling at 2 v0 / 3 and 5 v0 / 7 within 0.5 %",
                   T, testing::In2D, testing::In3D) {
  constexpr int D = T::value;
  // Sliding at v0 = 5 m/s with mu = 0.2, friction slows the centre and spins the body up until the
  // contact point stops slipping, at v0 / (1 + k), k = I / (m r^2): 2 v0 / 3 for a disk, 5 v0 / 7
  // for a solid ball; after that it rolls on at that speed. At 60 Hz for 3 s (rolling from 0.85 s
  // and 0.73 s).
  const double v0 = 5.0;
  const double expected = D == 3 ? 5.0 * v0 / 7.0 : 2.0 * v0 / 3.0;
  CHECK(speedAfterSlideAndRoll<D>(v0, 0.2, testing::defaultStepAt(1.0 / 60.0), 3.0) == doctest::Approx(expected).epsilon(0.005));
}
// [default_rolls_test]

TEST_CASE("Round shapes only: a scene of boxes runs under the default exactly as with samples everywhere") {
  // A 2D pyramid of base 6 and a 3D pyramid of 14 cubes at 60 Hz for 1 s: RoundShapes asks no
  // deepest point of a box, so the bits are those of SurfaceQuery::Samples.
  const StepSettings byDefault = testing::defaultStepAt(1.0 / 60.0);
  StepSettings samples = byDefault;
  samples.detection.narrow.surfaceQuery = SurfaceQuery::Samples;
  World<2> a = stacks::pyramid2d(6, Material{0.0, 0.6, 0.0});
  World<2> b = a;
  World<3> c = stacks::pyramid3d(3, Material{0.0, 0.6, 0.0});
  World<3> d = c;
  for (int n = 0; n < 60; ++n) {
    stackingStep<2>(a, byDefault);
    stackingStep<2>(b, samples);
    stackingStep<3>(c, byDefault);
    stackingStep<3>(d, samples);
  }
  for (std::size_t k = 0; k < a.bodies.size(); ++k) CHECK(a.bodies[k].position == b.bodies[k].position);
  for (std::size_t k = 0; k < c.bodies.size(); ++k) {
    CHECK(c.bodies[k].position == d.bodies[k].position);
    CHECK(c.bodies[k].orientation.coeffs() == d.bodies[k].orientation.coeffs());
  }
}

}  // TEST_SUITE
