// Chapter 11 exercises: suite ch11_exercises, skipped by default. The exercises preset builds
// them into build/exercises/tests/ch11/test_ch11_exercises. It registers one CTest entry per
// exercise, ex11.1 to ex11.4, with the labels exercise and ch11. Run all of them, or one, with
//   ctest --preset exercises -L ch11
//   ctest --preset exercises -R ex11.1
// An entry runs its tests once its stub has no "// TODO(reader)" comment left. The binary
// runs them at any time:
//   build/exercises/tests/ch11/test_ch11_exercises --no-skip -ts=ch11_exercises -tc="Exercise 11.1*"
// They fail until you solve the exercise (the stubs return empty or negative results).
// The main build runs them against the reference solutions: ctest --preset solutions -L ch11
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "stackbook/exercises/ex11_1_observed_order.hpp"
#include "stackbook/exercises/ex11_2_apex_heights.hpp"
#include "stackbook/exercises/ex11_3_windowed_error.hpp"
#include "stackbook/exercises/ex11_4_envelope_order.hpp"

using namespace stackbook;

TEST_SUITE(STACKBOOK_CHAPTER "_exercises" * doctest::skip()) {

TEST_CASE("Exercise 11.1: first- and second-order curves have observed orders 1 and 2") {
  const std::vector<double> dt = {4e-3, 2e-3, 1e-3, 5e-4};
  std::vector<double> first, second;
  for (double h : dt) {
    first.push_back(0.3 * h);
    second.push_back(7.0 * h * h);
  }
  const std::vector<double> p1 = observedOrders(dt, first), p2 = observedOrders(dt, second);
  REQUIRE(p1.size() == 3);
  REQUIRE(p2.size() == 3);
  for (double p : p1) CHECK(p == doctest::Approx(1.0).epsilon(1e-12));
  for (double p : p2) CHECK(p == doctest::Approx(2.0).epsilon(1e-12));
}

TEST_CASE("Exercise 11.1: bad curves are rejected") {
  CHECK_THROWS_AS(observedOrders({1e-3}, {1e-4}), std::invalid_argument);
  CHECK_THROWS_AS(observedOrders({1e-3, 5e-4}, {1e-4}), std::invalid_argument);
  CHECK_THROWS_AS(observedOrders({1e-3, 5e-4}, {1e-4, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(observedOrders({1e-3, 1e-3}, {1e-4, 2e-4}), std::invalid_argument);
}

TEST_CASE("Exercise 11.2: the apexes of an exactly bouncing ball are e^(2k) h0") {
  // A ball dropped from 1 m with e = 0.8, sampled every millisecond from the closed form.
  const double g = 9.81, e = 0.8, h0 = 1.0, dt = 1e-3;
  std::vector<double> heights;
  double v = 0.0, h = h0;
  for (int k = 0; k < 4000; ++k) {
    heights.push_back(h);
    v -= g * dt;
    h += v * dt;
    if (h < 0.0) {
      h = -h;
      v = -e * v;
    }
  }
  const std::vector<double> apexes = apexHeights(heights);
  REQUIRE(apexes.size() >= 3);
  CHECK(apexes[0] == doctest::Approx(e * e * h0).epsilon(0.02));
  CHECK(apexError(heights, h0, e, 3) < 0.03);
  CHECK(apexError(heights, h0, 0.5, 3) > 0.5);
  CHECK_THROWS_AS(apexError(heights, h0, e, 100), std::invalid_argument);
}

TEST_CASE("Exercise 11.3: the windowed error of symplectic Euler on a spring is first order") {
  // x'' = -x with symplectic Euler; the windowed error halves with dt.
  const Integrator step = [](const State1& s0, double duration, double dt) {
    State1 s = s0;
    const long n = std::lround(duration / dt);
    for (long k = 0; k < n; ++k) {
      s.v -= dt * s.x;
      s.x += dt * s.v;
    }
    return s;
  };
  const State1 start{1.0, 0.0};
  const double e1 = windowedError(step, start, 20, 0.5, 1e-2, 1e-4);
  const double e2 = windowedError(step, start, 20, 0.5, 5e-3, 1e-4);
  REQUIRE(e1 > 0.0);
  CHECK(e1 / e2 == doctest::Approx(2.0).epsilon(0.05));
  CHECK_THROWS_AS(windowedError(step, start, 0, 0.5, 1e-2, 1e-4), std::invalid_argument);
  CHECK_THROWS_AS(windowedError(step, start, 5, 0.5, 1e-4, 1e-2), std::invalid_argument);
}

TEST_CASE("Exercise 11.4: the envelope of a zigzag curve has the order of its upper line") {
  // Every other point lies on 0.3 dt; the others fall below it and below the next finer point
  // on the line, so the envelope is the line's points and its order is exactly 1.
  const std::vector<double> dt = {0.016, 0.008, 0.004, 0.002, 0.001, 0.0005};
  const std::vector<double> error = {0.3 * 0.016, 0.1 * 0.008, 0.3 * 0.004, 0.1 * 0.002, 0.3 * 0.001, 0.1 * 0.0005};
  const std::vector<std::size_t> envelope = upperEnvelope(dt, error);
  CHECK(envelope == std::vector<std::size_t>{0, 2, 4, 5});
  // The finest point is never beaten (no smaller dt), so it belongs to the envelope too:
  // the slope through (1e-3, 3e-4) and (5e-4, 5e-5) pulls the fit above 1.
  const double all = envelopeOrder(dt, error);
  CHECK(all > 1.0);
  // Without the last point the envelope is the line alone: order 1 to rounding.
  const std::vector<double> dt5(dt.begin(), dt.end() - 1), error5(error.begin(), error.end() - 1);
  CHECK(envelopeOrder(dt5, error5) == doctest::Approx(1.0).epsilon(1e-12));
  // A second-order curve is its own envelope.
  std::vector<double> second;
  for (double h : dt) second.push_back(7.0 * h * h);
  CHECK(upperEnvelope(dt, second).size() == dt.size());
  CHECK(envelopeOrder(dt, second) == doctest::Approx(2.0).epsilon(1e-12));
  CHECK_THROWS_AS(envelopeOrder({1e-3}, {1e-4}), std::invalid_argument);
  CHECK_THROWS_AS(envelopeOrder({1e-3, 1e-3}, {1e-4, 2e-4}), std::invalid_argument);
  CHECK_THROWS_AS(envelopeOrder({1e-3, 5e-4}, {1e-4, 0.0}), std::invalid_argument);
  // A curve that rises as dt falls has a one-point envelope: no order.
  CHECK_THROWS_AS(envelopeOrder({1e-3, 5e-4}, {1e-4, 2e-4}), std::invalid_argument);
}

}  // TEST_SUITE
