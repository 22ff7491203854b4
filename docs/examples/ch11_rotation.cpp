// Chapter 11: the rotation knob. The fast intermediate-axis spin of chapter 5 (a 0.2 x 0.4 x
// 0.6 m box of 1 kg at omega = (0.1, 10, 0.1) rad/s) over 100 s under both rotation rules:
// the flip period against Landau and Lifshitz (Eq. (5.16)), the energy error, and the cost
// of one position update of each rule (the two rules timed in alternation, the minimum of
// seven repeats, since the machine is shared). Printed as Markdown
// (\include{doc} ch11_rotation.out).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "stackbook/body/integrate.hpp"
#include "stackbook/body/torque_free.hpp"

using namespace stackbook;

namespace {

const Vec3 kMoments = Vec3(0.4 * 0.4 + 0.6 * 0.6, 0.2 * 0.2 + 0.6 * 0.6, 0.2 * 0.2 + 0.4 * 0.4) / 12.0;
const Vec3 kOmega0(0.1, 10.0, 0.1);

struct Tumble {
  double period = 0.0;       ///< 2 x mean time between sign changes of the body y rate
  int flips = 0;
  double energyError = 0.0;  ///< largest |E/E0 - 1|
};

Tumble tumble(double dt, double seconds, RotationUpdate rule) {
  RigidBody<3> box = makeDynamicBody<3>(1.0, kMoments);
  box.setAngularVelocity(kOmega0);
  const double E0 = box.kineticEnergy();
  std::vector<double> flips;
  double previous = kOmega0.y();
  Tumble t;
  const long n = std::lround(seconds / dt);
  for (long k = 1; k <= n; ++k) {
    advanceFreeBody<3>(box, dt, ExternalLoads<3>{}, rule);
    const double w = (box.orientation.conjugate() * box.angularVelocity).y();
    if ((previous > 0.0) != (w > 0.0)) flips.push_back((static_cast<double>(k - 1) + previous / (previous - w)) * dt);
    previous = w;
    t.energyError = std::max(t.energyError, std::abs(box.kineticEnergy() / E0 - 1.0));
  }
  t.flips = static_cast<int>(flips.size());
  if (flips.size() >= 2) t.period = 2.0 * (flips.back() - flips.front()) / static_cast<double>(flips.size() - 1);
  return t;
}

/// Nanoseconds per position update of `rule`, over `steps` steps of the tumbling box.
double nanosecondsPerUpdate(RotationUpdate rule, int steps) {
  RigidBody<3> box = makeDynamicBody<3>(1.0, kMoments);
  box.setAngularVelocity(kOmega0);
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) advancePosition<3>(box, 1e-3, rule);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!box.orientation.coeffs().allFinite()) std::printf("(non-finite)\n");
  return 1e9 * s / steps;
}

}  // namespace

int main() {
  const TorqueFreeInvariants inv = torqueFreeInvariants(kMoments, kOmega0);
  const double T = polhodePeriod(kMoments, inv.energy, inv.momentumSquared).period;
  std::printf("Closed-form period T = %.6f s (Eq. (5.16)): %.1f flips in 100 s.\n\n", T, 200.0 / T);
  std::printf("| rule | dt (s) | flips in 100 s | measured period (s) | period error | largest energy error |\n"
              "|---|---|---|---|---|---|\n");
  for (const RotationUpdate rule : {RotationUpdate::ExponentialMap, RotationUpdate::ImplicitMidpoint}) {
    for (const double dt : {4e-3, 2e-3, 1e-3, 5e-4}) {
      const Tumble t = tumble(dt, 100.0, rule);
      std::printf("| %s | %g | %d | %.6f | %+.3g %% | %.2g |\n", rotationUpdateName(rule), dt, t.flips, t.period,
                  100.0 * (t.period / T - 1.0), t.energyError);
    }
  }
  double exponential = 1e300, midpoint = 1e300;
  for (int repeat = 0; repeat < 7; ++repeat) {
    exponential = std::min(exponential, nanosecondsPerUpdate(RotationUpdate::ExponentialMap, 200000));
    midpoint = std::min(midpoint, nanosecondsPerUpdate(RotationUpdate::ImplicitMidpoint, 200000));
  }
  int iterations = 0;
  {
    const Vec3 Pi = kMoments.cwiseProduct(kOmega0);
    midpointBodyMomentum(Pi, kMoments.cwiseInverse(), 1e-3, MidpointSolve{}, &iterations);
  }
  std::printf("\nCost of one position update of this box (minimum of 7 alternating repeats of 200,000 "
              "updates): exponential map %.0f ns, implicit midpoint %.0f ns (%.1f times as much; %d Newton "
              "corrections at dt = 1e-3).\n",
              exponential, midpoint, midpoint / exponential, iterations);
}
