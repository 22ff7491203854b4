// Chapter 5: torque-free rotation. Angular momentum is exact because it is the state; the
// energy drifts only through the orientation update, at the rate Eq. (5.14) predicts; the
// symmetric top precesses at the rates of Eq. (5.15); the intermediate axis flips with the
// period of Eq. (5.16), itself checked against an independent Runge-Kutta integration.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "stackbook/body/integrate.hpp"
#include "stackbook/body/torque_free.hpp"
#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::RandomSource;

namespace {

/// A body with the given principal moments, world orientation q and body-frame angular
/// velocity omegaBody.
RigidBody<3> spinningBody(const Vec3& moments, const Vec3& omegaBody,
                          const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  RigidBody<3> body = makeDynamicBody<3>(1.0, moments);
  body.orientation = q;
  body.setAngularVelocity(q * omegaBody);
  return body;
}

Vec3 bodyAngularVelocity(const RigidBody<3>& body) {
  return body.orientation.inverse() * body.angularVelocity;
}

/// Angle a - b wrapped into [-pi, pi].
double angleDifference(double a, double b) { return std::remainder(a - b, 2.0 * M_PI); }

/// Times at which component `axis` of the body-frame angular velocity changes sign, found by
/// linear interpolation between samples. `step` advances the state by dt and returns the
/// new body-frame angular velocity.
std::vector<double> signChanges(const Vec3& omega0, int axis, double dt, double duration,
                                const std::function<Vec3()>& step) {
  std::vector<double> times;
  double previous = omega0[axis];
  const int n = static_cast<int>(std::lround(duration / dt));
  for (int k = 1; k <= n; ++k) {
    const double current = step()[axis];
    if ((previous > 0.0) != (current > 0.0)) {
      times.push_back((k - 1 + previous / (previous - current)) * dt);
    }
    previous = current;
  }
  return times;
}

/// The box of the intermediate-axis tests: sides 0.1 x 0.2 x 0.3 m, mass 1 kg.
Vec3 boxMoments() {
  const double a = 0.1, b = 0.2, c = 0.3;
  return Vec3(b * b + c * c, a * a + c * c, a * a + b * b) / 12.0;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_momentum_exact]
TEST_CASE("torque-free motion keeps the world angular momentum exactly") {
  RandomSource random(700);
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    RigidBody<3> body = random.dynamicBody<3>();
    const Vec3 L0 = body.angularMomentum;
    for (int step = 0; step < 1000; ++step) advanceFreeBody<3>(body, 1e-3);
    // L is the state: with no torque nothing ever writes it.
    CHECK(body.angularMomentum == L0);
    // Its body-frame image turns with the body but keeps its length: R stays a rotation.
    const Vec3 Lbody = body.orientation.inverse() * body.angularMomentum;
    CHECK(Lbody.norm() == doctest::Approx(L0.norm()).epsilon(1e-12));
  }
}
// [test_momentum_exact]

// [test_energy_rate]
TEST_CASE("one step gains the energy dt^2/2 a^T I^-1 a with a = L x omega in the body frame") {
  RandomSource random(710);
  for (int trial = 0; trial < 50; ++trial) {
    CAPTURE(trial);
    RigidBody<3> body = random.dynamicBody<3>();
    const Vec3 Lb = body.orientation.inverse() * body.angularMomentum;
    const Vec3 wb = body.inverseInertia.cwiseProduct(Lb);
    const Vec3 a = Lb.cross(wb);
    const double dt = 1e-5;
    const double predicted = 0.5 * dt * dt * a.dot(body.inverseInertia.cwiseProduct(a));  // Eq. (5.14)
    if (predicted < 1e-12 * body.kineticEnergy()) continue;  // nearly a principal-axis spin
    const double E0 = body.kineticEnergy();
    advanceFreeBody<3>(body, dt);
    // The neglected terms are O(dt^3 |omega|^3) against O(dt^2 |omega|^2): relative dt |omega|.
    CHECK((body.kineticEnergy() - E0) / predicted ==
          doctest::Approx(1.0).epsilon(10.0 * dt * wb.norm() + 1e-4));
  }
}
// [test_energy_rate]

// [test_symmetric_top]
TEST_CASE("a torque-free symmetric top precesses at s = 5 and p = 5.099 rad/s") {
  const double I = 0.04, J = 0.02;
  const Vec3 omega0(1.0, 0.0, 10.0);
  const SymmetricTopRates rates = symmetricTopRates(I, J, omega0);  // Eq. (5.15)
  REQUIRE(rates.bodyRate == doctest::Approx(5.0).epsilon(1e-15));
  REQUIRE(rates.spaceRate == doctest::Approx(std::sqrt(0.04 * 0.04 + 0.2 * 0.2) / 0.04));
  RandomSource random(720);
  const Eigen::Quaterniond q0 = random.orientation<3>();
  const double T = 10.0;

  struct Errors {
    double bodyPhase, spacePhase, energy, spin;
  };
  const auto run = [&](double dt) {
    RigidBody<3> top = spinningBody(Vec3(I, I, J), omega0, q0);
    const Vec3 L = top.angularMomentum, Lhat = L.normalized();
    const double E0 = top.kineticEnergy();
    // The symmetry axis e3 = R z circles L: measure its angle in the plane normal to L.
    const Vec3 e30 = top.orientation * Vec3::UnitZ();
    const Vec3 b1 = (e30 - e30.dot(Lhat) * Lhat).normalized(), b2 = Lhat.cross(b1);
    double bodyPhase = 0.0, spacePhase = 0.0, bodyAngle = 0.0, spaceAngle = 0.0;
    const int n = static_cast<int>(std::lround(T / dt));
    for (int step = 0; step < n; ++step) {
      advanceFreeBody<3>(top, dt);
      // (w1, w2) = w (cos s t, -sin s t) in the body frame.
      const Vec3 wb = bodyAngularVelocity(top);
      const double b = std::atan2(-wb.y(), wb.x());
      bodyPhase += angleDifference(b, bodyAngle);
      bodyAngle = b;
      const Vec3 e3 = top.orientation * Vec3::UnitZ();
      const double s = std::atan2(e3.dot(b2), e3.dot(b1));
      spacePhase += angleDifference(s, spaceAngle);
      spaceAngle = s;
    }
    CHECK(top.angularMomentum == L);
    return Errors{bodyPhase - rates.bodyRate * T, spacePhase - rates.spaceRate * T,
                  top.kineticEnergy() - E0, bodyAngularVelocity(top).z() - omega0.z()};
  };
  const Errors coarse = run(1e-3), fine = run(5e-4);
  // T3: the phases within 1 % after 10 s (50 and 51 rad) ...
  CHECK(std::abs(coarse.bodyPhase) < 0.01 * rates.bodyRate * T);
  CHECK(std::abs(coarse.spacePhase) < 0.01 * rates.spaceRate * T);
  // ... the body-frame phase converging at first order. The space phase is far better: its
  // error per step is odd in dt (Pitfalls), and p = |L|/I does not depend on the drifting
  // energy, so after 10 s it is off by 6e-11 rad.
  CHECK(coarse.bodyPhase / fine.bodyPhase == doctest::Approx(2.0).epsilon(0.15));
  CHECK(std::abs(coarse.spacePhase) < 1e-6);
  // The energy grows at the rate of Eq. (5.14); at t = 0, a = L x omega = (0, 0.2, 0) in
  // the body frame and a^T I^-1 a = 1, so dE/dt = dt/2. The rate falls as the drift tilts
  // L toward the symmetry axis, so T dt / 2 bounds the gain from above.
  const double bound = T * 1e-3 / 2.0;
  CHECK(coarse.energy > 0.5 * bound);
  CHECK(coarse.energy <= bound);
  CHECK(coarse.energy / fine.energy == doctest::Approx(2.0).epsilon(0.05));
  // Euler's equations keep w3 constant; the drift moves it by well under 1 %.
  CHECK(std::abs(coarse.spin) < 0.01 * omega0.z());
}
// [test_symmetric_top]

// [test_gyroscopic_box]
TEST_CASE("a tumbling box gains under 1 % energy in 5 s at dt = 1e-3 and keeps L exactly") {
  // Validation case B23: a box of half-sizes (0.1, 0.2, 0.3) m, omega = (1, 2, 3) rad/s.
  TriangleMesh mesh = boxMesh(Vec3(0.2, 0.4, 0.6));
  RigidBody<3> box = makeBodyFromMesh<3>(mesh, 1000.0);
  box.setAngularVelocity(Vec3(1.0, 2.0, 3.0));
  const double E0 = box.kineticEnergy();
  const Vec3 L0 = box.angularMomentum;
  double Emax = E0;
  for (int step = 0; step < 5000; ++step) {
    advanceFreeBody<3>(box, 1e-3);
    Emax = std::max(Emax, box.kineticEnergy());
  }
  CHECK(Emax <= 1.01 * E0);
  CHECK_EIGEN_NEAR(box.angularMomentum, L0, 1e-12);
}
// [test_gyroscopic_box]

// [test_polhode_reference]
TEST_CASE("the Landau-Lifshitz period matches a Runge-Kutta integration of Euler's equations") {
  const Vec3 I = boxMoments();
  // Two starts near the intermediate axis, one on each side of the separatrix.
  for (const Vec3& omega0 : {Vec3(0.3, 1.0, 0.3), Vec3(0.05, 1.0, 0.3)}) {
    CAPTURE(omega0.transpose());
    const TorqueFreeInvariants inv = torqueFreeInvariants(I, omega0);
    const PolhodePeriod period = polhodePeriod(I, inv.energy, inv.momentumSquared);
    const double dt = period.period / 40000.0;
    Vec3 w = omega0;
    const std::vector<double> flips = signChanges(omega0, 1, dt, 1.6 * period.period, [&] {
      w = eulerEquationsRk4Step(I, w, dt);
      return w;
    });
    REQUIRE(flips.size() >= 3);
    // The intermediate component is A sn(lambda t): it changes sign every half period.
    CHECK(flips[2] - flips[0] == doctest::Approx(period.period).epsilon(1e-7));
    CHECK(flips[1] - flips[0] == doctest::Approx(0.5 * period.period).epsilon(1e-7));
    const TorqueFreeInvariants after = torqueFreeInvariants(I, w);
    CHECK(after.energy == doctest::Approx(inv.energy).epsilon(1e-10));
  }
  // The first start circles the axis of the largest moment (x), the second that of the smallest.
  const TorqueFreeInvariants a = torqueFreeInvariants(I, Vec3(0.3, 1.0, 0.3));
  const TorqueFreeInvariants b = torqueFreeInvariants(I, Vec3(0.05, 1.0, 0.3));
  CHECK(polhodePeriod(I, a.energy, a.momentumSquared).circledAxis == 0);
  CHECK(polhodePeriod(I, b.energy, b.momentumSquared).circledAxis == 2);
}
// [test_polhode_reference]

// [test_dzhanibekov]
TEST_CASE("a spin near the intermediate axis flips with the Landau-Lifshitz period") {
  const Vec3 I = boxMoments();
  const Vec3 omega0(0.3, 1.0, 0.3);
  const TorqueFreeInvariants inv = torqueFreeInvariants(I, omega0);
  const double T = polhodePeriod(I, inv.energy, inv.momentumSquared).period;  // Eq. (5.16)
  const auto measuredPeriod = [&](double dt) {
    RigidBody<3> box = spinningBody(I, omega0);
    const Vec3 Lhat = box.angularMomentum.normalized();
    double lowestAlignment = 1.0;  // of the body's y axis with L
    const std::vector<double> flips = signChanges(omega0, 1, dt, 1.25 * T, [&] {
      advanceFreeBody<3>(box, dt);
      lowestAlignment = std::min(lowestAlignment, (box.orientation * Vec3::UnitY()).dot(Lhat));
      return bodyAngularVelocity(box);
    });
    REQUIRE(flips.size() >= 3);
    // The flip: the intermediate axis starts along L and turns to point against it.
    CHECK((Vec3::UnitY()).dot(Lhat) > 0.9);
    CHECK(lowestAlignment < -0.9);
    return flips[2] - flips[0];
  };
  const double coarse = measuredPeriod(1e-3), fine = measuredPeriod(5e-4);
  // First order: the period error halves with dt (it is 2.6 % and 1.2 % here; Pitfalls).
  CHECK((coarse - T) / (fine - T) == doctest::Approx(2.0).epsilon(0.15));
  // Richardson extrapolation removes the first-order term and lands on T.
  CHECK(2.0 * fine - coarse == doctest::Approx(T).epsilon(0.005));
}
// [test_dzhanibekov]

// [test_stable_axes]
TEST_CASE("spins near the largest and smallest moments stay inside their exact polhodes") {
  const Vec3 I = boxMoments();
  for (const int axis : {0, 2}) {
    CAPTURE(axis);
    Vec3 omega0 = Vec3::Constant(0.01);
    omega0[axis] = 1.0;
    const TorqueFreeInvariants inv = torqueFreeInvariants(I, omega0);
    // The widest angle between the spin axis and L in the exact motion: where the polhode
    // crosses a principal plane, L_k^2 / I_k + L_i^2 / I_i = 2E with L_k^2 + L_i^2 = L^2.
    double widest = 0.0;
    for (int i = 0; i < 3; ++i) {
      if (i == axis) continue;
      const double Lk2 = (2.0 * inv.energy - inv.momentumSquared / I[i]) / (1.0 / I[axis] - 1.0 / I[i]);
      widest = std::max(widest, std::acos(std::sqrt(Lk2 / inv.momentumSquared)));
    }
    RigidBody<3> body = spinningBody(I, omega0);
    const Vec3 Lhat = body.angularMomentum.normalized();
    double largest = 0.0;
    for (int step = 0; step < 30000; ++step) {
      advanceFreeBody<3>(body, 1e-3);
      const double c = (body.orientation * Vec3::Unit(axis)).dot(Lhat);
      largest = std::max(largest, std::acos(std::min(1.0, c)));
    }
    // The energy drift widens the polhode about the largest moment by 2 % in 30 s.
    CHECK(largest == doctest::Approx(widest).epsilon(0.03));
  }
}
// [test_stable_axes]

}  // TEST_SUITE

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

TEST_CASE("at dt = 2.5e-4 the flip period is within 1 % of Landau-Lifshitz") {
  const Vec3 I = boxMoments();
  const Vec3 omega0(0.3, 1.0, 0.3);
  const TorqueFreeInvariants inv = torqueFreeInvariants(I, omega0);
  const double T = polhodePeriod(I, inv.energy, inv.momentumSquared).period;
  const double dt = 2.5e-4;
  RigidBody<3> box = spinningBody(I, omega0);
  const std::vector<double> flips = signChanges(omega0, 1, dt, 1.25 * T, [&] {
    advanceFreeBody<3>(box, dt);
    return bodyAngularVelocity(box);
  });
  REQUIRE(flips.size() >= 3);
  CHECK(flips[2] - flips[0] == doctest::Approx(T).epsilon(0.01));
}

TEST_CASE("the symmetric top meets a 1e-3 J energy bound over 10 s at dt = 1.25e-4 but not at 5e-4") {
  const auto drift = [](double dt) {
    RigidBody<3> top = spinningBody(Vec3(0.04, 0.04, 0.02), Vec3(1.0, 0.0, 10.0));
    const double E0 = top.kineticEnergy();
    const int n = static_cast<int>(std::lround(10.0 / dt));
    for (int step = 0; step < n; ++step) advanceFreeBody<3>(top, dt);
    return top.kineticEnergy() - E0;
  };
  // Eq. (5.14) bounds the gain by T dt / 2 = 5e3 dt J.
  CHECK(drift(5e-4) > 1e-3);
  CHECK(drift(1.25e-4) < 1e-3);
}

}  // TEST_SUITE
