// Chapter 8: a box on an incline, GBF's own argument for its step order (validation
// cases A1, A2, A2b and A3). Reference values are the closed forms of a block on a
// plane with Coulomb friction (mu_s = mu_k = mu):
//   sticks iff tan(theta) <= mu;  sliding down: a = g (sin(theta) - mu cos(theta));
//   sliding to a stop from v0: decel = g (mu cos(theta) -+ sin(theta)), d = v0^2 / (2 decel),
//   t = v0 / decel (minus for a down-slope start, plus for an up-slope one).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "scenes.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// The largest |lift| and the smallest speed down the slope seen after each step.
struct Extremes {
  double maxLift = 0.0;
  double minSpeed = 0.0;
  double maxAbsTravel = 0.0;
};

template <int D>
Extremes runIncline(InclineScene<D>& scene, const StepSettings& settings, double seconds) {
  Extremes x;
  x.minSpeed = scene.speed();
  simulate<D>(scene.world, settings, seconds, [&](const World<D>&) {
    x.maxLift = std::max(x.maxLift, std::abs(scene.lift()));
    x.minSpeed = std::min(x.minSpeed, scene.speed());
    x.maxAbsTravel = std::max(x.maxAbsTravel, std::abs(scene.travelled()));
  });
  return x;
}

double slideAcceleration(double theta, double mu) {
  return kG * (std::sin(theta) - mu * std::cos(theta));
}

StepSettings withOrder(StepOrder order, double dt = 1e-3) {
  StepSettings s;
  s.dt = dt;
  s.order = order;
  return s;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_a1_gbf]
TEST_CASE("A1: in GBF order an elastic box at rest on a 20 degree incline stays still<2D>") {
  // tan(20 deg) = 0.364 <= mu = 0.5: static friction holds it, and with e = 1 nothing may
  // bounce. A body at rest has zero velocity when the collision stage looks at it, so
  // e = 1 has nothing to reflect; the contact stage then stops what gravity added.
  InclineScene<2> scene = makeIncline<2>(degrees(20.0), 0.5, 1.0);
  const Extremes x = runIncline<2>(scene, withOrder(StepOrder::Gbf), 0.2);
  CHECK(x.maxAbsTravel < 1e-6);
  CHECK(x.maxLift < 1e-6);
  CHECK(std::abs(scene.speed()) < 1e-9);
}
// [test_a1_gbf]

// [test_a1_traditional]
TEST_CASE("A1: in the traditional order the same elastic box hops off the incline<2D>") {
  // Moving first sinks the box by dt^2 g cos(theta) and gives it the approach speed
  // dt g cos(theta) = 9.2e-3 m/s; the collision stage reflects it with e = 1, so the box
  // leaves the slope every few steps. A hop of 0.1 mm is 100 times the GBF bound above.
  InclineScene<2> scene = makeIncline<2>(degrees(20.0), 0.5, 1.0);
  const Extremes x = runIncline<2>(scene, withOrder(StepOrder::Traditional), 0.2);
  CHECK(x.maxLift > 1e-4);
}
// [test_a1_traditional]

TEST_CASE("A3: a box pushed up a 20 degree incline stops after v0^2/(2 decel) and stays<2D>") {
  const double theta = degrees(20.0), mu = 0.5, v0 = 3.0, dt = 1e-3;
  const double decel = kG * (std::sin(theta) + mu * std::cos(theta));
  const double distance = v0 * v0 / (2.0 * decel), stopTime = v0 / decel;
  REQUIRE(distance == within(0.5650, 1e-4));  // the catalogue's closed form, case A3
  REQUIRE(stopTime == within(0.3767, 1e-4));
  InclineScene<2> scene = makeIncline<2>(theta, mu, 0.0, 0.0, -v0);
  double stoppedAt = -1.0, maxSpeedAfterStop = 0.0, maxSpeed = -v0;
  long n = 0;
  simulate<2>(scene.world, withOrder(StepOrder::Gbf, dt), 0.45, [&](const World<2>&) {
    ++n;
    const double v = scene.speed();  // negative while moving up the slope
    maxSpeed = std::max(maxSpeed, v);
    if (stoppedAt < 0.0 && std::abs(v) < 1e-6) stoppedAt = static_cast<double>(n) * dt;
    if (stoppedAt >= 0.0) maxSpeedAfterStop = std::max(maxSpeedAfterStop, std::abs(v));
  });
  CHECK(-scene.travelled() == within(distance, 0.01));
  CHECK(std::abs(stoppedAt - stopTime) <= 2.0 * dt);
  CHECK(maxSpeedAfterStop < 1e-6);
  CHECK(maxSpeed < 1e-6);  // never slides back down
}

}  // TEST_SUITE

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

TEST_CASE_TEMPLATE("A1: GBF keeps an elastic box still on a 20 degree incline for 2 s", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  InclineScene<D> scene = makeIncline<D>(degrees(20.0), 0.5, 1.0);
  const Extremes x = runIncline<D>(scene, withOrder(StepOrder::Gbf), 2.0);
  CHECK(x.maxAbsTravel < 1e-6);
  CHECK(x.maxLift < 1e-6);
}

TEST_CASE_TEMPLATE("A1: the traditional order makes the elastic box creep down the incline", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  InclineScene<D> scene = makeIncline<D>(degrees(20.0), 0.5, 1.0);
  const Extremes x = runIncline<D>(scene, withOrder(StepOrder::Traditional), 1.0);
  CHECK(x.maxLift > 1e-4);
  CHECK(scene.travelled() > 1e-3);  // hops land further down: it creeps
}

// [test_a2]
TEST_CASE_TEMPLATE("A2: a box on a 30 degree incline with mu 0.3 slides with g(sin - mu cos)", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  const double theta = degrees(30.0), mu = 0.3;
  const double a = slideAcceleration(theta, mu);
  REQUIRE(a == within(2.3563, 1e-4));  // the catalogue's closed form, case A2
  const double exact = 0.5 * a;                         // s(1 s)
  double error[2] = {0.0, 0.0};
  for (int halving = 0; halving < 2; ++halving) {
    const double dt = 1e-3 / (1 << halving);
    InclineScene<D> scene = makeIncline<D>(theta, mu, 0.0);
    const Extremes x = runIncline<D>(scene, withOrder(StepOrder::Gbf, dt), 1.0);
    error[halving] = std::abs(scene.travelled() - exact) / exact;
    CHECK(scene.travelled() == within(exact, 0.01));
    CHECK(scene.speed() == within(a, 0.01));
    CHECK(x.maxLift < 1e-6);  // it slides, it does not hop
    // Semi-implicit Euler at constant a gives s_n = a dt^2 n (n + 1) / 2: the ramp's ten
    // sliding impulses remove exactly the normal approach and mu times it tangentially.
    // Not to rounding: the corner-by-corner impulses pitch the box by ~1e-6 rad in 3D.
    const double n = std::round(1.0 / dt);
    CHECK(scene.travelled() == within(0.5 * a * dt * dt * n * (n + 1.0), 1e-5));
  }
  // First order in dt: halving dt roughly halves the error.
  CHECK(error[0] / error[1] == within(2.0, 0.2));
}
// [test_a2]

TEST_CASE("A2b: with mu 0.5 a box stays at 26 degrees and slides at 27 degrees<2D>") {
  const double mu = 0.5;
  REQUIRE(std::atan(mu) * 180.0 / M_PI == within(26.565, 1e-4));
  InclineScene<2> below = makeIncline<2>(degrees(26.0), mu, 0.0);
  runIncline<2>(below, withOrder(StepOrder::Gbf), 2.0);
  CHECK(std::abs(below.travelled()) < 1e-4);

  const double a = slideAcceleration(degrees(27.0), mu);
  REQUIRE(a == within(0.08326, 1e-3));
  InclineScene<2> above = makeIncline<2>(degrees(27.0), mu, 0.0);
  runIncline<2>(above, withOrder(StepOrder::Gbf), 2.0);
  CHECK(above.travelled() == within(0.5 * a * 4.0, 0.01));
}

// [test_a3]
TEST_CASE("A3: a box sliding down a 20 degree incline at 3 m/s stops at 3.5886 m and stays<2D>") {
  const double theta = degrees(20.0), mu = 0.5, v0 = 3.0, dt = 1e-3;
  const double decel = kG * (mu * std::cos(theta) - std::sin(theta));
  const double distance = v0 * v0 / (2.0 * decel), stopTime = v0 / decel;
  REQUIRE(distance == within(3.5886, 1e-4));  // the catalogue's closed form, case A3
  REQUIRE(stopTime == within(2.3924, 1e-4));
  InclineScene<2> scene = makeIncline<2>(theta, mu, 0.0, 0.0, v0);
  double stoppedAt = -1.0, maxSpeedAfterStop = 0.0, minSpeed = v0;
  long n = 0;
  simulate<2>(scene.world, withOrder(StepOrder::Gbf, dt), 3.0, [&](const World<2>&) {
    ++n;
    const double v = scene.speed();
    minSpeed = std::min(minSpeed, v);
    if (stoppedAt < 0.0 && std::abs(v) < 1e-6) stoppedAt = static_cast<double>(n) * dt;
    if (stoppedAt >= 0.0) maxSpeedAfterStop = std::max(maxSpeedAfterStop, std::abs(v));
  });
  CHECK(scene.travelled() == within(distance, 0.01));
  CHECK(std::abs(stoppedAt - stopTime) <= 2.0 * dt);
  CHECK(maxSpeedAfterStop < 1e-6);
  CHECK(minSpeed > -1e-6);  // the velocity never reverses
}
// [test_a3]

}  // TEST_SUITE
