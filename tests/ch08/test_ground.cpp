// Chapter 8: bodies dropped on or resting on a horizontal ground (validation cases A5,
// B10, B19, B5(a)). The ball is turned so that one surface sample points straight down,
// so heights are measured from the centre height at which that sample touches y = 0.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "scenes.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// The apex heights of a bouncing body: the heights at which the upward speed changes
/// from positive to not positive.
template <int D>
std::vector<double> apexes(DropScene<D>& scene, const StepSettings& settings, double seconds) {
  std::vector<double> out;
  double previous = scene.upSpeed();
  simulate<D>(scene.world, settings, seconds, [&](const World<D>&) {
    const double v = scene.upSpeed();
    if (previous > 0.0 && v <= 0.0) out.push_back(scene.height());
    previous = v;
  });
  return out;
}

/// Kinetic plus potential energy of the dropped body (potential from the contact height).
template <int D>
double energy(const DropScene<D>& scene) {
  return scene.dropped().kineticEnergy() + kG * scene.height() / scene.dropped().inverseMass;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_a5_first]
TEST_CASE_TEMPLATE("A5: a ball with e 0.8 dropped 1 m first rises to e^2 h0 = 0.64 m", Dim, In2D,
                   In3D) {
  // Impact speed sqrt(2 g h0), rebound e sqrt(2 g h0), apex e^2 h0. Semi-implicit Euler
  // loses (e^2 + e) |v| dt / 2 = 0.5 % of it at dt = 1e-3 (see the slow A5 case below).
  constexpr int D = Dim::value;
  DropScene<D> scene = makeBallDrop<D>(0.25, 1.0, Material{0.8, 0.0, 0.0});
  const std::vector<double> h = apexes<D>(scene, StepSettings{}, 0.9);
  REQUIRE(h.size() == 1);
  CHECK(h[0] == within(0.64, 0.01));
}
// [test_a5_first]

// [test_b10]
TEST_CASE("B10: a ball with e 0 does not bounce and comes to rest on the ground<2D>") {
  const double dt = 1e-3;
  DropScene<2> scene = makeBallDrop<2>(0.25, 0.2, Material{0.0, 0.0, 0.0});
  double maxUp = 0.0, firstImpact = -1.0, restAt = -1.0, previous = 0.0;
  long n = 0;
  simulate<2>(scene.world, StepSettings{}, 0.5, [&](const World<2>&) {
    ++n;
    const double t = static_cast<double>(n) * dt;
    maxUp = std::max(maxUp, scene.upSpeed());
    // In free fall each step lowers the vertical speed by g dt; an impulse raises it.
    if (firstImpact < 0.0 && scene.upSpeed() > previous) firstImpact = t;
    previous = scene.upSpeed();
    if (restAt < 0.0 && firstImpact >= 0.0 && scene.dropped().velocity.norm() < 1e-9 &&
        scene.height() < kG * dt * dt) {
      restAt = t;
    }
  });
  CHECK(maxUp < 1e-12);  // e = 0: the normal velocity is stopped, never reversed
  REQUIRE(firstImpact > 0.0);
  REQUIRE(restAt > 0.0);
  // The impact is detected up to |v| dt early, so the ball may hover that high after it
  // and fall again, a geometric series of ever smaller drops; 50 ms covers it.
  CHECK(restAt - firstImpact < 0.05);
  // At rest the ball is not inside the ground, and less than g dt^2 above it (closer
  // than that, the contact stage's prediction x - g dt^2 reaches the ground).
  CHECK(scene.height() >= -1e-12);
  CHECK(scene.height() < kG * dt * dt);
  CHECK(scene.dropped().velocity.norm() < 1e-9);
}
// [test_b10]

// [test_b19]
TEST_CASE("B19: a box at rest on the ground stays at rest without gaining energy<2D>") {
  DropScene<2> scene = makeRestingBox<2>(Material{0.5, 0.5, 0.0});
  const double e0 = energy<2>(scene);
  double maxV = 0.0, maxW = 0.0, maxDh = 0.0, maxE = e0;
  simulate<2>(scene.world, StepSettings{}, 0.25, [&](const World<2>&) {
    maxV = std::max(maxV, scene.dropped().velocity.norm());
    maxW = std::max(maxW, scene.dropped().angularVelocity.norm());
    maxDh = std::max(maxDh, std::abs(scene.height()));
    maxE = std::max(maxE, energy<2>(scene));
  });
  CHECK(maxV < 1e-4);
  CHECK(maxW < 1e-4);
  CHECK(maxDh < 1e-5);
  CHECK(maxE - e0 < 1e-12);
}
// [test_b19]

// [test_b5a]
TEST_CASE_TEMPLATE("B5a: a ball dropped straight down onto its lowest sample never spins", Dim,
                   In2D, In3D) {
  // The impulse acts at the sample below the centre along the vertical normal: r x j = 0,
  // and with u_t = 0 the sticking impulse K^{-1}(-e u_n n - u) is vertical too, because
  // K n = n / m when r is parallel to n.
  constexpr int D = Dim::value;
  DropScene<D> scene = makeBallDrop<D>(0.25, 0.1, Material{0.5, 0.5, 0.0});
  double maxW = 0.0;
  int bounces = 0;
  double previous = 0.0;
  simulate<D>(scene.world, StepSettings{}, 0.4, [&](const World<D>&) {
    maxW = std::max(maxW, scene.dropped().angularVelocity.norm());
    if (previous <= 0.0 && scene.upSpeed() > 0.0) ++bounces;
    previous = scene.upSpeed();
  });
  CHECK(bounces >= 1);  // it did hit the ground
  CHECK(maxW < 1e-12);
}
// [test_b5a]

}  // TEST_SUITE

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

// [test_a5]
TEST_CASE_TEMPLATE("A5: a ball with e 0.8 reaches the apexes e^(2n) h0 for n up to 4", Dim, In2D,
                   In3D) {
  // Semi-implicit Euler itself loses height: falling from rest for n steps drops
  // g dt^2 n (n + 1) / 2 = v^2 / (2 g) + |v| dt / 2, and a rise from speed u peaks at
  // u^2 / (2 g) - u dt / 2. So apex 1 is about e^2 h0 - (e^2 + e) |v| dt / 2, 0.5 % low at
  // dt = 1e-3, and the relative loss grows as the bounces shrink (2.3 % at n = 4). The
  // error is first order: at dt = 2.5e-4 all four apexes are within 1 %, and the 4th
  // apex's error is at least 2.5 times smaller than at 1e-3 (first order predicts 4).
  constexpr int D = Dim::value;
  double error4[2] = {0.0, 0.0};
  const double steps[2] = {1e-3, 2.5e-4};
  for (int run = 0; run < 2; ++run) {
    DropScene<D> scene = makeBallDrop<D>(0.25, 1.0, Material{0.8, 0.0, 0.0});
    StepSettings settings;
    settings.dt = steps[run];
    // Impacts at 0.4515, 1.1740, 1.7519, 2.2143 s (case A5); the 4th apex follows
    // at 2.2143 + e^4 sqrt(2 h0 / g) = 2.40 s.
    const std::vector<double> h = apexes<D>(scene, settings, 2.5);
    REQUIRE(h.size() >= 4);
    error4[run] = std::abs(h[3] - std::pow(0.8, 8)) / std::pow(0.8, 8);
    if (run == 1) {
      for (int n = 1; n <= 4; ++n) {
        CAPTURE(n);
        CHECK(h[static_cast<std::size_t>(n - 1)] == within(std::pow(0.8, 2 * n), 0.01));
      }
    }
  }
  CHECK(error4[0] > 2.5 * error4[1]);
}
// [test_a5]

TEST_CASE_TEMPLATE("B19: a box at rest on the ground for 2 s stays still", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  DropScene<D> scene = makeRestingBox<D>(Material{0.5, 0.5, 0.0});
  const double e0 = energy<D>(scene);
  double maxV = 0.0, maxW = 0.0, maxDh = 0.0, maxE = e0;
  simulate<D>(scene.world, StepSettings{}, 2.0, [&](const World<D>&) {
    maxV = std::max(maxV, scene.dropped().velocity.norm());
    maxW = std::max(maxW, scene.dropped().angularVelocity.norm());
    maxDh = std::max(maxDh, std::abs(scene.height()));
    maxE = std::max(maxE, energy<D>(scene));
  });
  CHECK(maxV < 1e-4);
  CHECK(maxW < 1e-4);
  CHECK(maxDh < 1e-5);
  CHECK(maxE - e0 < 1e-12);
}

}  // TEST_SUITE
