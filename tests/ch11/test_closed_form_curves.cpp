// Chapter 11 (the closed-form curves): rolling down an incline and torque-free precession.
// Each measure is checked against a trajectory built here from its closed form (not from the
// simulator), then the simulator against the closed forms with tolerances from the physics.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/sweep.hpp"

using namespace stackbook;

namespace {

const std::string kCurveSweeps = std::string(STACKBOOK_SOURCE_DIR) + "/docs/sweeps/";

/// The rolling acceleration down a slope of angle theta: a = g sin(theta) / (1 + k),
/// k = I / (m r^2) (from m a = m g sin - F and I alpha = F r with a = alpha r).
double rollingAcceleration(double g, double theta, double k) { return g * std::sin(theta) / (1.0 + k); }

/// One body moving along the unit direction `d` from `x0` under a constant acceleration `a`
/// by symplectic Euler (v_{n+1} = v_n + a dt, x_{n+1} = x_n + dt v_{n+1}): after n steps
/// v_n = a n dt and x_n = x0 + a dt^2 n (n + 1) / 2, so x_N = x0 + a T^2 / 2 + a T dt / 2.
SweepTrajectory eulerRoll(const Eigen::Vector3d& x0, const Eigen::Vector3d& d, double a, double dt, int steps) {
  SweepTrajectory t;
  t.dimension = 3;
  t.gravity = Eigen::Vector3d(0, 0, -9.81);
  t.isStatic = {false};
  for (int n = 0; n <= steps; ++n) {
    SweepBodyState s;
    s.position = x0 + d * (a * dt * dt * n * (n + 1) / 2.0);
    s.velocity = d * (a * n * dt);
    t.times.push_back(n * dt);
    t.frames.push_back({s});
    t.energies.push_back(0.0);
  }
  return t;
}

/// The closed form of torque-free motion of a body with I1 = I2 (symmetry axis z in the body
/// frame): R(t) = Rot(L, rate t) R0 Rot_z(-Omega_b t) with rate = |L| / I1 and
/// Omega_b = (I3 - I1) / I1 w3 (then R' R^T = [L / I1 + (I1 - I3) / (I1 I3) (L.e3) e3]_x, the
/// world angular velocity, and L = I omega is constant). `lag` scales the rate of the space
/// cone, rate (1 + lag), to make a trajectory with a known phase error.
SweepTrajectory symmetricTop(const Eigen::Vector3d& inertia, const Eigen::Matrix3d& r0, const Eigen::Vector3d& omega0,
                             double dt, int steps, double lag) {
  const Eigen::Vector3d L = r0 * inertia.asDiagonal() * r0.transpose() * omega0;
  const double i1 = inertia.x(), i3 = inertia.z();
  const double w3 = (r0.transpose() * omega0).z();
  const double omegaB = (i3 - i1) / i1 * w3;
  SweepTrajectory t;
  t.dimension = 3;
  t.isStatic = {false};
  t.inertia = {inertia};
  for (int n = 0; n <= steps; ++n) {
    const double time = n * dt;
    SweepBodyState s;
    s.rotation = Eigen::AngleAxisd((1.0 + lag) * L.norm() / i1 * time, L.normalized()).toRotationMatrix() * r0 *
                 Eigen::AngleAxisd(-omegaB * time, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    s.angularVelocity = s.rotation * inertia.cwiseInverse().asDiagonal() * s.rotation.transpose() * L;
    t.times.push_back(time);
    t.frames.push_back({s});
    t.energies.push_back(0.5 * s.angularVelocity.dot(L));
  }
  return t;
}

SweepError makeError(const std::string& quantity, int body, double expected) {
  SweepError e;
  e.name = quantity;
  e.quantity = quantity;
  e.body = body;
  e.hasExpected = true;
  e.expected = expected;
  return e;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("distance and speed: a ball rolled by symplectic Euler ends dt / T too far and exactly as fast") {
  // Down a slope that is not along any axis: the distance is measured along the motion.
  const double g = 9.81, theta = 20.0 * std::numbers::pi / 180.0, a = rollingAcceleration(g, theta, 0.4);
  const Eigen::Vector3d d = Eigen::Vector3d(2.0, -1.0, -0.5).normalized();
  const double dt = 1e-3;
  const int steps = 1500;
  const double T = steps * dt;
  const SweepTrajectory t = eulerRoll(Eigen::Vector3d(-3.0, 1.0, 0.25), d, a, dt, steps);
  // Eq. (11.3): the relative error of the distance is (a T dt / 2) / (a T^2 / 2) = dt / T.
  CHECK(measureSweepTrajectory(makeError("distance", 0, a * T * T / 2.0), t, "t") ==
        doctest::Approx(dt / T).epsilon(1e-9));
  CHECK(measureSweepTrajectory(makeError("speed", 0, a * T), t, "t") < 1e-12);
  // Without an expected value they are the distance and the speed themselves.
  SweepError raw = makeError("distance", 0, 0.0);
  raw.hasExpected = false;
  CHECK(measureSweepTrajectory(raw, t, "t") == doctest::Approx(a * T * (T + dt) / 2.0).epsilon(1e-12));
  raw.body = 1;
  CHECK_THROWS_WITH(measureSweepTrajectory(raw, t, "t"),
                    "t: error \"distance\": body 1 is not in the scene (1 bodies)");
}

TEST_CASE("precession: the closed form's own motion has no error and a phase lag eps has error eps") {
  // A prolate box's moments (I1 = I2 = 1/30, I3 = 1/150), turned and spun off its axis.
  const Eigen::Vector3d inertia(1.0 / 30.0, 1.0 / 30.0, 1.0 / 150.0);
  const Eigen::Matrix3d r0 = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  const Eigen::Vector3d omega0 = r0 * Eigen::Vector3d(3.0, 1.0, 10.0);
  const double dt = 1e-3;
  const int steps = 10000;
  SweepError e;
  e.name = "precession";
  e.quantity = "precession";
  e.axis = 2;
  e.tolerance = 1e-12;
  CHECK(measureSweepTrajectory(e, symmetricTop(inertia, r0, omega0, dt, steps, 0.0), "t") < 1e-12);
  // A cone rate too fast by eps: after the run the axis is eps phi behind in phase, phi the
  // precession angle |L| T / I1, on a cone of half-angle c about L; the two axes are then
  // acos(cos^2 c + sin^2 c cos(eps phi)) apart, the largest miss of the run (it grows while
  // eps phi < pi), and the error divides it by the arc sin(c) phi.
  const double eps = 1e-3;
  const Eigen::Vector3d L = r0 * inertia.asDiagonal() * r0.transpose() * omega0;
  const double c = std::acos(L.normalized().dot(r0.col(2)));
  const double phi = L.norm() / inertia.x() * steps * dt;
  const double miss = std::acos(std::cos(c) * std::cos(c) + std::sin(c) * std::sin(c) * std::cos(eps * phi));
  CHECK(measureSweepTrajectory(e, symmetricTop(inertia, r0, omega0, dt, steps, eps), "t") ==
        doctest::Approx(miss / (std::sin(c) * phi)).epsilon(1e-6));
  CHECK(miss / (std::sin(c) * phi) == doctest::Approx(eps).epsilon(1e-3));
}

TEST_CASE("precession: the measure's one-line errors") {
  const Eigen::Vector3d inertia(1.0 / 30.0, 1.0 / 30.0, 1.0 / 150.0);
  SweepError e;
  e.name = "p";
  e.quantity = "precession";
  // Not axisymmetric about the axis asked for.
  e.axis = 0;
  const SweepTrajectory t = symmetricTop(inertia, Eigen::Matrix3d::Identity(), Eigen::Vector3d(3, 0, 10), 1e-2, 10, 0.0);
  CHECK_THROWS_WITH(measureSweepTrajectory(e, t, "t"),
                    doctest::Contains("t: the precession error needs an axisymmetric body"));
  // A spin along the symmetry axis does not precess.
  e.axis = 2;
  const SweepTrajectory still = symmetricTop(inertia, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 10), 1e-2, 10, 0.0);
  CHECK_THROWS_WITH(measureSweepTrajectory(e, still, "t"),
                    doctest::Contains("t: the precession error needs a spin off the symmetry axis"));
  // A peer that reports no inertia, and 2D.
  SweepTrajectory bare = t;
  bare.inertia.clear();
  CHECK_THROWS_WITH(measureSweepTrajectory(e, bare, "t"),
                    "t: error \"p\": precession needs the bodies' moments of inertia");
  bare.dimension = 2;
  CHECK_THROWS_WITH(measureSweepTrajectory(e, bare, "t"), "t: error \"p\": precession needs a 3D scene");
}

TEST_CASE("the incline and precession specs' expected values are the closed forms") {
  const double g = 9.81, theta = 20.0 * std::numbers::pi / 180.0, T = 1.5;
  const SweepSpec disk = loadSweepSpec(kCurveSweeps + "roll_incline_2d_sweep.json");
  const SweepSpec ball = loadSweepSpec(kCurveSweeps + "roll_incline_3d_sweep.json");
  for (const auto& [spec, k] : {std::pair{&disk, 0.5}, std::pair{&ball, 0.4}}) {
    const double a = rollingAcceleration(g, theta, k);
    CHECK(spec->errors.at(0).expected == doctest::Approx(a * T * T / 2.0).epsilon(1e-14));
    CHECK(spec->errors.at(1).expected == doctest::Approx(a * T).epsilon(1e-14));
    CHECK(loadScene(spec->scene).duration == T);
  }
  const SweepSpec top = loadSweepSpec(kCurveSweeps + "precession_sweep.json");
  CHECK(top.errors.at(0).quantity == "precession");
  CHECK_NOTHROW(loadScene(top.scene));
}

}  // TEST_SUITE

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("rolling down an incline on the exact deepest point: exact speed and the distance dt / T long") {
  // Rolling without slipping, the contact stage's friction impulse leaves the contact point at
  // rest each step, so each step adds exactly a dt = g sin(theta) dt / (1 + k) to the speed and
  // the position is symplectic Euler's: the speed is the closed form to rounding and the
  // distance is a T dt / 2 too long, a relative error dt / T (Eq. (11.3)), first order.
  for (const char* name : {"roll_incline_2d_sweep.json", "roll_incline_3d_sweep.json"}) {
    SweepSpec spec = loadSweepSpec(kCurveSweeps + name);
    spec.knobs = {SweepKnob{"dt", {0.004, 0.001}}};
    spec.sets = {"solver.surfaceQuery=\"deepestPoint\""};
    for (const SweepRun& run : sweepRuns(spec)) {
      const double dt = std::stod(run.value), T = 1.5;
      const SweepRow row = runSweepRun(spec, run);
      INFO(name << " dt " << dt);
      CHECK(row.errors[0] == doctest::Approx(dt / T).epsilon(1e-6));
      CHECK(row.errors[1] < 1e-9);
    }
  }
}

TEST_CASE("rolling down an incline on samples: a polygon's error that the time step does not move and each "
          "doubling of the samples halves") {
  SweepSpec spec = loadSweepSpec(kCurveSweeps + "roll_incline_samples_2d_sweep.json");
  // The default 48 samples at a coarse and a fine step: above 1 % at both, and not falling.
  spec.knobs = {SweepKnob{"dt", {0.004, 0.00025}}};
  const std::vector<SweepRun> coarse = sweepRuns(spec);
  const double e4 = runSweepRun(spec, coarse[0]).errors[0], e025 = runSweepRun(spec, coarse[1]).errors[0];
  CHECK(e4 > 0.01);
  CHECK(e025 > 0.01);
  CHECK(e025 > 0.5 * e4);
  // The error is first order in the sample spacing h (the loss per vertex of order (h / r)^2,
  // 1 / h vertices per metre): 96 -> 192 -> 384 samples at dt = 2.5e-4 halve it each time.
  spec.knobs = {SweepKnob{"bodies.1.shape.samples", {96, 192, 384}}, SweepKnob{"dt", {0.00025}}};
  std::vector<double> e;
  for (const SweepRun& run : sweepRuns(spec)) e.push_back(runSweepRun(spec, run).errors[0]);
  REQUIRE(e.size() == 3);
  CHECK(e[0] / e[1] == doctest::Approx(2.0).epsilon(0.15));
  CHECK(e[1] / e[2] == doctest::Approx(2.0).epsilon(0.15));
}

TEST_CASE("precession: the exponential map gains energy at the rate its second-order term predicts and the "
          "midpoint rule none") {
  // For I1 = I2 the world angular velocity is w = L / I1 + s e3, s = (I1 - I3) / (I1 I3) (L.e3).
  // One step of the exponential map turns e3 about w instead of about L / I1 (the exact flow):
  // the two differ by dt^2 s e3 x (L / I1 x e3) / 2, which changes L.e3 by
  // dt^2 s |L|^2 sin^2(c) / (2 I1) per step (c the cone angle), and the energy
  // E = |L|^2 / (2 I1) + s (L.e3) / 2 at dE/dt = dt s^2 |L|^2 sin^2(c) / (2 I1) > 0.
  const double i1 = 1.0 / 30.0, i3 = 1.0 / 150.0, dt = 1e-3;
  const Eigen::Vector3d w0(3.0, 0.0, 10.0), L(i1 * w0.x(), i1 * w0.y(), i3 * w0.z());
  const double s = (i1 - i3) / (i1 * i3) * L.z();
  const double sin2 = 1.0 - L.z() * L.z() / L.squaredNorm();
  const double e0 = 0.5 * w0.dot(L);
  const double rate = dt * s * s * L.squaredNorm() * sin2 / (2.0 * i1) / e0;  // relative gain per second
  SweepSpec spec = loadSweepSpec(kCurveSweeps + "precession_sweep.json");
  spec.sets = {"duration=1"};
  spec.knobs = {SweepKnob{"solver.rotation", {"exponentialMap", "implicitMidpoint"}}, SweepKnob{"dt", {dt}}};
  const std::vector<SweepRun> runs = sweepRuns(spec);
  REQUIRE(runs.size() == 2);
  // Over 1 s L.e3 moves by about 2 %, and s and sin^2(c) with it: the rate holds within 10 %.
  CHECK(runSweepRun(spec, runs[0]).errors[1] == doctest::Approx(rate * 1.0).epsilon(0.1));
  CHECK(runSweepRun(spec, runs[1]).errors[1] < 1e-12);
}

TEST_CASE("precession: the exponential map is first order in the time step and the midpoint rule second order") {
  SweepSpec spec = loadSweepSpec(kCurveSweeps + "precession_sweep.json");
  spec.knobs = {SweepKnob{"dt", {0.002, 0.001, 0.0005}}, spec.knobs.at(1)};
  std::vector<double> e;
  for (const SweepRun& run : sweepRuns(spec)) e.push_back(runSweepRun(spec, run).errors[0]);
  REQUIRE(e.size() == 6);
  for (int k = 0; k < 2; ++k) {
    INFO("exponential map, halving " << k);
    CHECK(e[k] / e[k + 1] == doctest::Approx(2.0).epsilon(0.1));
    INFO("implicit midpoint, halving " << k);
    CHECK(e[3 + k] / e[3 + k + 1] == doctest::Approx(4.0).epsilon(0.05));
  }
  // At the same step the midpoint rule is far closer: at 1e-3 below 1e-4, the map above 1e-3.
  CHECK(e[4] < 1e-4);
  CHECK(e[1] > 1e-3);
}

}  // TEST_SUITE
