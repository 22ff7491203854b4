// Chapter 8: rolling friction on a ball rolling on level ground (Eq. (8.8)), and what the
// discretisation itself costs a rolling ball. The ball is the tests' (makeRollingBall in
// tests/ch08/scene_builders.hpp): its samples are a ring in its rolling plane, so it rolls
// as a regular polygon of `segments` sides. Printed as Markdown for the course page
// (\include{doc} ch08_rolling.out).
#include <cmath>
#include <cstdio>

#include "../../tests/ch08/scene_builders.hpp"  // the rolling ball of the tests

using namespace stackbook;
using stackbook::testing::kG;

namespace {

struct Run {
  double speed = 0.0;
  StepCounters counters;
};

/// A ball of radius R rolling at v0 along axis 0 for `seconds`; returns its final speed.
template <int D>
Run roll(double v0, double muR, double dt, int segments, double seconds) {
  const Material m{0.0, 0.5, muR};
  testing::RollingScene<D> scene = testing::makeRollingBall<D>(0.25, v0, m, m, segments);
  StepSettings settings;
  settings.dt = dt;
  Run out;
  const long steps = std::lround(seconds / dt);
  for (long n = 0; n < steps; ++n) out.counters += gbfStep<D>(scene.world, settings);
  out.speed = scene.speed();
  return out;
}

}  // namespace

int main() {
  const double R = 0.25, muR = 0.05, v0 = 0.5, T = 0.1;
  std::printf("Rolling friction mu_r = %g m, R = %g m, v0 = %g m/s, measured over %g s "
              "(1000-gon):\n\n", muR, R, v0, T);
  std::printf("| dimension | dt (s) | predicted a (m/s^2) | measured (v0 - v) / T | error |\n"
              "|---|---|---|---|---|\n");
  for (const double dt : {1e-3, 5e-4}) {
    for (const int d : {2, 3}) {
      const double k = d == 3 ? 0.4 : 0.5, a = muR * kG / (R * (1.0 + k));  // Eq. (8.8)
      const Run r = d == 2 ? roll<2>(v0, muR, dt, 1000, T) : roll<3>(v0, muR, dt, 1000, T);
      const double measured = (v0 - r.speed) / T;
      std::printf("| %dD | %g | %.4f | %.4f | %+.2f %% |\n", d, dt, a, measured,
                  100.0 * (measured - a) / a);
    }
  }
  const Run counted = roll<2>(v0, muR, 1e-3, 1000, T);
  std::printf("\nIn the 2D run at dt = 1e-3 (%lld steps) the contact stage applied %lld sticking "
              "impulses and %lld rolling-friction impulse pairs; %lld of its pair loops stopped "
              "at the cap of %d.\n\n",
              static_cast<long long>(counted.counters.steps),
              static_cast<long long>(counted.counters.contact.sticking),
              static_cast<long long>(counted.counters.contact.rollingImpulses),
              static_cast<long long>(counted.counters.contact.pairIterationCapHits),
              StepSettings{}.contactPairIterations);
  std::printf("Without rolling friction (2D, v0 = 1 m/s, 0.1 s): the speed lost to the "
              "discretisation alone.\n\n| polygon sides | dt (s) | v0 - v (m/s) |\n|---|---|---|\n");
  for (const int segments : {1000, 2000, 4000}) {
    for (const double dt : {1e-3, 5e-4}) {
      std::printf("| %d | %g | %.2e |\n", segments, dt, 1.0 - roll<2>(1.0, 0.0, dt, segments, 0.1).speed);
    }
  }
}
