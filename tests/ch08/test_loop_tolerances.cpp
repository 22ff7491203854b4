// Chapter 8, "Ending the loops": the pair-impulse and stage-approach tolerances end GBF's
// loops by what they achieve. With them on, the resting box of B19 holds the same physics
// bounds as GBF's loops (still to 1e-4 m/s and 1e-5 m without gaining energy) with fewer
// impulses.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scenes.hpp"
#include "support/dimensions.hpp"
#include "support/mechanical_energy.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

StepSettings withTolerances() {
  StepSettings s;
  s.pairImpulseTolerance = 0.05;
  s.stageApproachTolerance = 1e-4;
  return s;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("Loop tolerances outside their ranges are rejected with the field name") {
  StepSettings s;
  s.pairImpulseTolerance = 1.0;
  CHECK_THROWS_WITH_AS(validateStepSettings(s, "test"), doctest::Contains("pairImpulseTolerance"),
                       std::invalid_argument);
  s = StepSettings{};
  s.stageApproachTolerance = -1e-3;
  CHECK_THROWS_WITH_AS(validateStepSettings(s, "test"), doctest::Contains("stageApproachTolerance"),
                       std::invalid_argument);
  s = StepSettings{};
  s.shock.pairImpulseTolerance = -0.1;
  CHECK_THROWS_WITH_AS(validateStepSettings(s, "test"), doctest::Contains("shock.pairImpulseTolerance"),
                       std::invalid_argument);
  s = StepSettings{};
  s.shock.levelApproachTolerance = std::nan("");
  CHECK_THROWS_WITH_AS(validateStepSettings(s, "test"), doctest::Contains("shock.levelApproachTolerance"),
                       std::invalid_argument);
}

}  // TEST_SUITE

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

TEST_CASE_TEMPLATE("B19 with loop tolerances: a box at rest for 2 s stays still with fewer impulses", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  DropScene<D> gbf = makeRestingBox<D>(Material{0.5, 0.5, 0.0});
  DropScene<D> scene = makeRestingBox<D>(Material{0.5, 0.5, 0.0});
  const double e0 = mechanicalEnergy<D>(scene.world);
  double maxV = 0.0, maxW = 0.0, maxDh = 0.0, maxE = e0;
  const StepCounters c = simulate<D>(scene.world, withTolerances(), 2.0, [&](const World<D>& w) {
    maxV = std::max(maxV, scene.dropped().velocity.norm());
    maxW = std::max(maxW, scene.dropped().angularVelocity.norm());
    maxDh = std::max(maxDh, std::abs(scene.height()));
    maxE = std::max(maxE, mechanicalEnergy<D>(w));
  });
  const StepCounters reference = simulate<D>(gbf.world, StepSettings{}, 2.0, [](const World<D>&) {});
  CHECK(maxV < 1e-4);
  CHECK(maxW < 1e-4);
  CHECK(maxDh < 1e-5);
  CHECK(maxE - e0 < 1e-12);
  CHECK(c.contact.impulses + c.collision.impulses < reference.contact.impulses + reference.collision.impulses);
}

}  // TEST_SUITE
