// Chapter 8: a block rocking on a floor (Housner 1963; validation catalogue A22). An
// inelastic, non-slipping impact that moves the pivot from one corner to the other keeps the
// angular momentum about the new corner, so the block goes on rocking with
// r = 1 - (3/2) sin^2(alpha) of its angular velocity, alpha = atan(b / h) (Eq. (8.20)); its
// energy above rest keeps r^2. The block is released from rest on one corner (edge in 3D),
// e = 0 and mu = 1, and the ratio is measured across its first landing from the energy
// above rest just before it and once the old pivot has left the floor (Landing in
// rocking_block.hpp). Tolerance: 1 %, the continuum-analytic tier, at every time step.
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "rocking_block.hpp"
#include "scenes.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

constexpr std::array<double, 5> kTimeSteps{1e-3, 7e-4, 5e-4, 4e-4, 2.5e-4};

/// The first landing of a block of half-width 0.1 m and aspect b / h, released at theta0 degrees.
template <int D>
Landing rockOnce(double aspect, double theta0Degrees, const StepSettings& settings) {
  RockingBlock<D> scene = makeRockingBlock<D>(0.1, 0.1 / aspect, degrees(theta0Degrees));
  ContactRecorder recorder;
  StepSettings recorded = settings;
  recorded.contactRecorder = &recorder;
  return firstLanding<D>(scene, settings.dt, recorder, [&](World<D>& w) { step<D>(w, recorded); });
}

/// Every case of the grid: aspect 1/2, 1/3, 1/5, released at 5 and 10 degrees, at the five
/// time steps; each landing within 1 % of Housner's ratio and with no step that raises the
/// block's energy (the invariants tier: 1e-9 of E per step).
template <int D>
void checkHousnerGrid(StepSettings settings) {
  for (const double aspect : {0.5, 1.0 / 3.0, 0.2}) {
    for (const double theta0 : {5.0, 10.0}) {
      for (const double dt : kTimeSteps) {
        settings.dt = dt;
        const Landing landing = rockOnce<D>(aspect, theta0, settings);
        CAPTURE(aspect);
        CAPTURE(theta0);
        CAPTURE(dt);
        REQUIRE(landing.found);
        CHECK(landing.ratio() == doctest::Approx(housnerRatio(0.1, 0.1 / aspect)).epsilon(0.01));
        CHECK(landing.largestRise <= 1e-9 * landing.before);
      }
    }
  }
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [rocking_test]
// GBF's step with the landing rules of the default step (withLandingRules()): lever arms at the
// start pose (Eq. (8.22)), held samples and tied landing (chapter 12).
TEST_CASE_TEMPLATE("With the landing rules a rocking block keeps Housner's ratio r = 1 - 3/2 sin^2(alpha) across its first landing "
                   "within 1 % for b/h = 1/2 and 1/3 and 1/5 released at 5 and 10 degrees at every dt from 1e-3 "
                   "to 2.5e-4 and no step of the landing raises its energy",
                   Dim, In2D, In3D) {
  checkHousnerGrid<Dim::value>(withLandingRules(StepSettings{}));
}
// [rocking_test]

TEST_CASE("StepSettings{} keeps the paper's pair rule and withLandingRules() turns the three rules on") {
  const ImpulsePointSettings paper;
  CHECK(paper.arms == LeverArms::AtTestedPose);
  CHECK_FALSE(paper.heldSamples);
  CHECK_FALSE(paper.tiedLanding);
  const ImpulsePointSettings rules = withLandingRules(paper);
  CHECK(rules.arms == LeverArms::AtStartPose);
  CHECK(rules.heldSamples);
  CHECK(rules.tiedLanding);
}

TEST_CASE("The landing is one impulse at the landing corner and the old pivot leaves the floor in the same step") {
  RockingBlock<2> scene = makeRockingBlock<2>(0.1, 0.3, degrees(10.0));
  ContactRecorder recorder;
  StepSettings settings = withLandingRules(StepSettings{});
  settings.dt = 5e-4;
  settings.contactRecorder = &recorder;
  int landingImpulses = 0, elsewhere = 0;
  const Landing landing = firstLanding<2>(scene, settings.dt, recorder, [&](World<2>& w) {
    step<2>(w, settings);
    bool landed = false;
    for (const ContactRecord& r : recorder.records()) landed = landed || r.point[0] > scene.b;
    if (!landed && landingImpulses == 0) return;  // still rocking on the first corner
    for (const ContactRecord& r : recorder.records()) {
      if (r.point[0] > 1.5 * scene.b) {
        ++landingImpulses;
      } else {
        ++elsewhere;
      }
    }
  });
  REQUIRE(landing.found);
  CHECK(landing.steps == 1);
  CHECK(landingImpulses == 1);
  CHECK(elsewhere == 0);
}

TEST_CASE("Eq. (8.21): with lever arms at the tested pose the pivot sinks by the summed drift and at the start "
          "pose it stays on the floor") {
  // The contact stage stops the velocity at the tested pose's arm r' = R' R^T r; the pivot's own
  // point then moves at dt omega^2 r, and the exponential map lifts it back by half of that:
  // a sink of dt^2 omega^2 (x_C - x_A) . y / 2 per step (Eq. (8.21)).
  for (const LeverArms arms : {LeverArms::AtTestedPose, LeverArms::AtStartPose}) {
    RockingBlock<2> scene = makeRockingBlock<2>(0.1, 0.3, degrees(10.0));
    StepSettings settings;
    settings.dt = 7e-4;
    settings.impulsePoint.arms = arms;
    double lowest = 0.0, predicted = 0.0;
    // Until the landing corner is within two steps' travel of the floor.
    while (scene.cornerHeight(1.0) > 2.0 * 0.2 * std::abs(scene.rockingRate()) * settings.dt) {
      const double omega = scene.rockingRate();
      predicted -= 0.5 * settings.dt * settings.dt * omega * omega * (scene.body().position[1] - scene.cornerHeight(-1.0));
      step<2>(scene.world, settings);
      lowest = std::min(lowest, scene.cornerHeight(-1.0));
    }
    CAPTURE(static_cast<int>(arms));
    CAPTURE(predicted);
    if (arms == LeverArms::AtTestedPose) {
      CHECK(lowest == doctest::Approx(predicted).epsilon(0.1));  // the drift of Eq. (8.21), small angles
    } else {
      CHECK(lowest > 1e-3 * predicted);  // a thousandth of it at most
    }
  }
}

TEST_CASE("Without held samples the sample next to the pivot takes the landing at some time step and the ratio "
          "misses by more than 5 %") {
  StepSettings settings = withLandingRules(StepSettings{});
  settings.impulsePoint.heldSamples = false;
  double worst = 0.0;
  for (const double dt : kTimeSteps) {
    settings.dt = dt;
    const Landing landing = rockOnce<2>(1.0 / 3.0, 10.0, settings);
    REQUIRE(landing.found);
    worst = std::max(worst, std::abs(landing.ratio() / housnerRatio(0.1, 0.3) - 1.0));
  }
  CHECK(worst > 0.05);
}

TEST_CASE("Without the tied landing a 3D block lands on one end of its edge and twists and its ratio is more "
          "than 1.5 % high") {
  StepSettings settings = withLandingRules(StepSettings{});
  settings.impulsePoint.tiedLanding = false;
  settings.dt = 1e-3;
  const Landing landing = rockOnce<3>(0.2, 10.0, settings);
  REQUIRE(landing.found);
  CHECK(landing.ratio() / housnerRatio(0.1, 0.5) - 1.0 > 0.015);
}

}  // TEST_SUITE
