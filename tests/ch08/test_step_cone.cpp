// Chapter 8: one Coulomb cone per step (Eq. (8.13)). The ledger's arithmetic, and
// that bounding the pair's total impulse of the step instead of each impulse keeps
// Coulomb's answers on the incline (slide, stick, stop) and adds no energy.
#include <doctest/doctest.h>

#include <cmath>

#include "scenes.hpp"
#include "support/dimensions.hpp"
#include "support/mechanical_energy.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

StepSettings stepCone(double dt = 1e-3) {
  StepSettings s;
  s.dt = dt;
  s.frictionCone = FrictionConeRule::StepTotal;
  return s;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [ledger_test]
TEST_CASE("The contact ledger sums a pair's impulses on its lower-numbered body and bounds the total") {
  ContactLedger ledger;
  const Vec2 n(0.0, 1.0);  // normal of owner 3, pointing from body 1 into body 3
  ledger.record<2>(BodyPair{1, 3}, 3, Vec2(0.3, 1.0), n);
  // Owner 1 sees the normal -n; its impulse (0.1, -0.5) is (-0.1, 0.5) on body 3.
  ledger.record<2>(BodyPair{3, 1}, 1, Vec2(0.1, -0.5), Vec2(-n));
  const ContactLedger::Total* total = ledger.find(BodyPair{3, 1});
  REQUIRE(total != nullptr);
  CHECK(ledger.size() == 1);
  CHECK(total->normal == doctest::Approx(1.5).epsilon(1e-15));
  // Kept for body 1, the lower number: -(0.3) + 0.1.
  CHECK(total->tangential[0] == doctest::Approx(-0.2).epsilon(1e-15));
  // Total on body 3 after a further (0.4, 0.5): tangential 0.6, normal 2.0, ratio 0.3.
  CHECK(ledger.admits<2>(BodyPair{1, 3}, 3, Vec2(0.4, 0.5), n, 0.31));
  CHECK_FALSE(ledger.admits<2>(BodyPair{1, 3}, 3, Vec2(0.4, 0.5), n, 0.29));
  // One impulse far outside the cone alone (ratio 4) is admitted when the total is not:
  // tangential 0.2 - 0.4 = -0.2 against 0.3 * (1.5 + 0.1) = 0.48.
  CHECK(ledger.admits<2>(BodyPair{1, 3}, 3, Vec2(-0.4, 0.1), n, 0.3));
  CHECK_FALSE(ledger.admits<2>(BodyPair{1, 3}, 3, Vec2(-0.4, 0.1), n, 0.1));
  // Never a pulling impulse, whatever the total.
  CHECK_FALSE(ledger.admits<2>(BodyPair{1, 3}, 3, Vec2(0.0, -0.1), n, 10.0));
  ledger.clear();
  CHECK(ledger.find(BodyPair{1, 3}) == nullptr);
}
// [ledger_test]

// [step_cone_incline_test]
TEST_CASE_TEMPLATE("Under one cone per step the incline still slides at g(sin - mu cos) and sticks below atan mu",
                   Dim, In2D, In3D) {
  // A2 (30 degrees, mu 0.3): s(1 s) = a / 2 to 1 %. A2b (mu 0.5, atan mu = 26.57 degrees):
  // held at 26 degrees, sliding at 27 with a / 2 t^2 to 1 % after 2 s. While a block
  // slides, its step total already lies on the cone, so no sticking trial is admitted.
  constexpr int D = Dim::value;
  const auto slide = [](double theta, double mu) {
    return kG * (std::sin(theta) - mu * std::cos(theta));
  };
  InclineScene<D> a2 = makeIncline<D>(degrees(30.0), 0.3, 0.0);
  simulate<D>(a2.world, stepCone(), 1.0);
  CHECK(a2.travelled() == within(0.5 * slide(degrees(30.0), 0.3), 0.01));

  InclineScene<D> held = makeIncline<D>(degrees(26.0), 0.5, 0.0);
  simulate<D>(held.world, stepCone(), 2.0);
  CHECK(std::abs(held.travelled()) < 1e-4);

  InclineScene<D> slides = makeIncline<D>(degrees(27.0), 0.5, 0.0);
  simulate<D>(slides.world, stepCone(), 2.0);
  CHECK(slides.travelled() == within(0.5 * slide(degrees(27.0), 0.5) * 4.0, 0.01));
}
// [step_cone_incline_test]

TEST_CASE("Under one cone per step a box sliding up to a stop stops where Coulomb says and stays<2D>") {
  // A3: 20 degrees, mu 0.5, 3 m/s down the slope: stops after v^2 / (2 a) = 3.5886 m.
  const double theta = degrees(20.0), mu = 0.5, v0 = 3.0;
  const double decel = kG * (mu * std::cos(theta) - std::sin(theta));
  InclineScene<2> scene = makeIncline<2>(theta, mu, 0.0, 0.0, v0);
  simulate<2>(scene.world, stepCone(), 3.0);
  CHECK(scene.travelled() == within(v0 * v0 / (2.0 * decel), 0.01));
  CHECK(std::abs(scene.speed()) < 1e-6);
}

TEST_CASE_TEMPLATE("Under one cone per step a tumbling box gains no energy",
                   Dim, In2D, In3D) {
  // The box of scenes.hpp (mu 0.5, e 0.3) dropped tilted onto the 20 degree slope: the
  // mechanical energy never rises above its start by more than round-off, step by step.
  constexpr int D = Dim::value;
  World<D> world = makeTumblingBox<D>(0.5, 0.3);
  const double start = mechanicalEnergy<D>(world);
  double highest = start;
  std::size_t pairs = 0;
  std::int64_t admittedByStep = 0;
  const StepSettings settings = stepCone();
  for (int n = 0; n < 1000; ++n) {
    const StepCounters c = gbfStep<D>(world, settings);
    highest = std::max(highest, mechanicalEnergy<D>(world));
    pairs = std::max(pairs, c.contactLedger.size());
    admittedByStep += c.contact.stepConeSticks;
  }
  CHECK(highest <= start + 1e-9 * std::abs(start));
  CHECK(pairs == 1);
  CHECK(admittedByStep > 0);
}

TEST_CASE("With GBF's cone on each impulse the step keeps no ledger") {
  World<2> world = makeTumblingBox<2>(0.5, 0.3);
  std::size_t largest = 0;
  for (int n = 0; n < 300; ++n) largest = std::max(largest, gbfStep<2>(world, StepSettings{}).contactLedger.size());
  CHECK(largest == 0);
}

}  // TEST_SUITE
