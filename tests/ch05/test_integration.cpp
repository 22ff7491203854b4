// Chapter 5: the semi-implicit Euler step, its two halves, the exponential map and pose
// prediction, against closed forms of the same discrete scheme (T2) and of the continuum (T3).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "stackbook/body/integrate.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;

namespace {

template <int D>
Vec<D> gravity() {
  Vec<D> g = Vec<D>::Zero();
  g[D - 1] = -9.81;
  return g;
}

/// A body with an isotropic inertia (a disk in 2D, a ball in 3D): its angular velocity is
/// L / I whatever the orientation, so its rotation has a closed form.
template <int D>
RigidBody<D> isotropicBody(double mass, double moment) {
  return makeDynamicBody<D>(mass, AngVec<D>::Constant(moment));
}

/// The orientation q0 turned by the angle `angle` about the unit angular direction `axis`.
template <int D>
Mat<D> rotatedClosedForm(const Orientation<D>& q0, const AngVec<D>& axis, double angle) {
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(q0.angle() + axis[0] * angle).toRotationMatrix();
  } else {
    return (Eigen::AngleAxisd(angle, axis) * q0).toRotationMatrix();
  }
}

/// Bit-identical orientations.
template <int D>
bool identical(const Orientation<D>& a, const Orientation<D>& b) {
  if constexpr (D == 2) {
    return a.angle() == b.angle();
  } else {
    return a.coeffs() == b.coeffs();
  }
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_free_fall_discrete]
TEST_CASE_TEMPLATE("free fall follows the discrete semi-implicit Euler solution exactly",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(500 + D);
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    const double inertia = random.uniform(0.1, 2.0);  // drawn first, one draw per statement:
    const double mass = random.logUniform(0.1, 10.0);  // argument order is unspecified
    RigidBody<D> body = isotropicBody<D>(mass, inertia);
    body.position = random.vector<D>(-2.0, 2.0);
    body.velocity = random.vector<D>(-3.0, 3.0);
    body.orientation = random.orientation<D>();
    body.setAngularVelocity(random.angularVector<D>(-5.0, 5.0));
    const RigidBody<D> start = body;
    const Vec<D> g = gravity<D>();
    const double dt = 1e-3;
    const int n = 1000;
    for (int step = 0; step < n; ++step) advanceFreeBody<D>(body, dt, gravityLoads<D>(g));
    // Eqs. (5.7), (5.8) summed: v_n = v_0 + n dt g, x_n = x_0 + n dt v_0 + n(n+1)/2 dt^2 g.
    const double N = n;
    CHECK_EIGEN_NEAR(body.velocity, Vec<D>(start.velocity + N * dt * g), 1e-12);
    CHECK_EIGEN_NEAR(body.position,
                     Vec<D>(start.position + N * dt * start.velocity + 0.5 * N * (N + 1) * dt * dt * g),
                     1e-12);
    // Torque-free and isotropic: omega is constant, so n exponential-map steps turn the body
    // by n dt |omega| about the fixed axis omega / |omega|, Eq. (5.9).
    const AngVec<D> w = start.angularVelocity;
    CHECK_EIGEN_NEAR(rotationMatrix<D>(body.orientation),
                     rotatedClosedForm<D>(start.orientation, AngVec<D>(w.normalized()), N * dt * w.norm()),
                     1e-12);
    CHECK_EIGEN_NEAR(body.angularMomentum, start.angularMomentum, 0.0);
  }
}
// [test_free_fall_discrete]

// [test_free_fall_continuum]
TEST_CASE_TEMPLATE("free fall converges to x0 + v0 t + g t^2/2 at first order",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const Vec<D> g = gravity<D>();
  Vec<D> x0 = Vec<D>::Zero(), v0 = Vec<D>::Zero();
  x0[D - 1] = 10.0;
  v0[0] = 1.5;
  v0[D - 1] = 2.0;
  const double T = 1.0;
  const Vec<D> exact = x0 + T * v0 + 0.5 * T * T * g;  // the continuum solution
  std::vector<double> errors;
  for (const double dt : {1e-3, 5e-4, 2.5e-4}) {
    RigidBody<D> body = makeDynamicBody<D>(2.0, AngVec<D>::Constant(0.5));
    body.position = x0;
    body.velocity = v0;
    const int n = static_cast<int>(std::lround(T / dt));
    for (int step = 0; step < n; ++step) advanceFreeBody<D>(body, dt, gravityLoads<D>(g));
    errors.push_back((body.position - exact).norm());
  }
  // T3: within 1 % of the continuum at dt = 1e-3 (the error is g dt T / 2, 4.9 mm) ...
  CHECK(errors[0] < 0.01 * exact.norm());
  CHECK(errors[0] == doctest::Approx(0.5 * g.norm() * 1e-3 * T).epsilon(1e-6));
  // ... and first order: halving dt halves the error.
  CHECK(errors[0] / errors[1] == doctest::Approx(2.0).epsilon(0.01));
  CHECK(errors[1] / errors[2] == doctest::Approx(2.0).epsilon(0.01));
}
// [test_free_fall_continuum]

TEST_CASE_TEMPLATE("a constant torque follows the discrete solution exactly", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(520 + D);
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    const double I = random.uniform(0.1, 2.0);
    RigidBody<D> body = isotropicBody<D>(1.0, I);
    body.orientation = random.orientation<D>();
    AngVec<D> u = AngVec<D>::Ones();
    if constexpr (D == 3) u = random.unitVector<3>();
    const double L0 = random.uniform(-2.0, 2.0), tau = random.uniform(-3.0, 3.0);
    body.angularMomentum = L0 * u;
    body.syncAngularVelocity();
    ExternalLoads<D> loads;
    loads.torque = tau * u;
    const Orientation<D> q0 = body.orientation;
    const double dt = 1e-3;
    const int n = 1000;
    for (int step = 0; step < n; ++step) advanceFreeBody<D>(body, dt, loads);
    // L_k = (L0 + k dt tau) u about a fixed axis; the angle is dt sum_k |L_k| / I.
    const double N = n;
    CHECK_EIGEN_NEAR(body.angularMomentum, AngVec<D>((L0 + N * dt * tau) * u), 1e-12);
    const double angle = dt / I * (N * L0 + dt * tau * 0.5 * N * (N + 1));
    CHECK_EIGEN_NEAR(rotationMatrix<D>(body.orientation), rotatedClosedForm<D>(q0, u, angle), 1e-12);
  }
}

// [test_semi_implicit_order]
TEST_CASE_TEMPLATE("one step from rest moves the body by dt^2 g: velocity first then position",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RigidBody<D> body = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
  const Vec<D> g = gravity<D>();
  const double dt = 0.01;
  advanceFreeBody<D>(body, dt, gravityLoads<D>(g));
  // Explicit Euler (position first) would not move at all; the continuum moves dt^2 g / 2.
  CHECK_EIGEN_NEAR(body.position, Vec<D>(dt * dt * g), 1e-15);
  CHECK_EIGEN_NEAR(body.velocity, Vec<D>(dt * g), 1e-15);
}
// [test_semi_implicit_order]

TEST_CASE_TEMPLATE("the velocity update adds dt F/m and dt tau and leaves the pose alone",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(540 + D);
  for (int trial = 0; trial < 50; ++trial) {
    CAPTURE(trial);
    RigidBody<D> body = random.dynamicBody<D>();
    const RigidBody<D> before = body;
    ExternalLoads<D> loads;
    loads.acceleration = random.vector<D>(-10.0, 10.0);
    loads.force = random.vector<D>(-10.0, 10.0);
    loads.torque = random.angularVector<D>(-10.0, 10.0);
    const double dt = random.uniform(1e-4, 1e-1);
    advanceVelocity<D>(body, dt, loads);
    CHECK_EIGEN_NEAR(body.velocity,
                     Vec<D>(before.velocity + dt * (loads.acceleration + loads.force / before.mass())),
                     1e-12);
    CHECK_EIGEN_NEAR(body.angularMomentum, AngVec<D>(before.angularMomentum + dt * loads.torque), 1e-12);
    CHECK_EIGEN_NEAR(body.angularVelocity, AngVec<D>(body.inverseInertiaWorld() * body.angularMomentum), 1e-12);
    CHECK(body.position == before.position);
    CHECK_EIGEN_NEAR(rotationMatrix<D>(body.orientation), rotationMatrix<D>(before.orientation), 1e-15);
  }
}

TEST_CASE_TEMPLATE("the position update moves with the current velocities and re-derives omega from L",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(560 + D);
  for (int trial = 0; trial < 50; ++trial) {
    CAPTURE(trial);
    RigidBody<D> body = random.dynamicBody<D>();
    const RigidBody<D> before = body;
    const double dt = random.uniform(1e-4, 1e-1);
    advancePosition<D>(body, dt);
    CHECK_EIGEN_NEAR(body.position, Vec<D>(before.position + dt * before.velocity), 1e-15);
    const AngVec<D> w = before.angularVelocity;
    CHECK_EIGEN_NEAR(rotationMatrix<D>(body.orientation),
                     rotatedClosedForm<D>(before.orientation, AngVec<D>(w.normalized()), dt * w.norm()),
                     1e-14);
    // Velocities are the velocity update's business: v and L are untouched ...
    CHECK(body.velocity == before.velocity);
    CHECK(body.angularMomentum == before.angularMomentum);
    // ... and omega follows L to the new orientation, Eq. (5.12).
    const AngMat<D> R = angularRotationMatrix<D>(body.orientation);
    CHECK_EIGEN_NEAR(body.angularVelocity,
                     AngVec<D>(R * body.inverseInertia.asDiagonal() * R.transpose() * before.angularMomentum),
                     1e-12);
  }
}

// [test_predict_pose]
TEST_CASE_TEMPLATE("predictPose gives the pose of the position update without changing the body",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(580 + D);
  for (int trial = 0; trial < 50; ++trial) {
    CAPTURE(trial);
    RigidBody<D> body = random.dynamicBody<D>();
    const double dt = random.uniform(1e-4, 1e-1);
    ExternalLoads<D> loads = gravityLoads<D>(random.vector<D>(-10.0, 10.0));
    loads.torque = random.angularVector<D>(-1.0, 1.0);

    const RigidBody<D> before = body;
    const Pose<D> predicted = predictPose<D>(body, dt);
    const Pose<D> predictedWithLoads = predictPose<D>(body, dt, loads);
    CHECK(body.position == before.position);
    CHECK(body.velocity == before.velocity);
    CHECK(body.angularMomentum == before.angularMomentum);
    CHECK(identical<D>(body.orientation, before.orientation));

    RigidBody<D> moved = body;
    advancePosition<D>(moved, dt);
    CHECK(predicted.position == moved.position);
    CHECK_EIGEN_NEAR(rotationMatrix<D>(predicted.orientation), rotationMatrix<D>(moved.orientation), 0.0);

    RigidBody<D> stepped = body;
    advanceFreeBody<D>(stepped, dt, loads);
    CHECK(predictedWithLoads.position == stepped.position);
    CHECK_EIGEN_NEAR(rotationMatrix<D>(predictedWithLoads.orientation),
                     rotationMatrix<D>(stepped.orientation), 0.0);
  }
}
// [test_predict_pose]

TEST_CASE_TEMPLATE("a static body keeps a bit-identical pose under gravity", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(600 + D);
  RigidBody<D> ground = makeStaticBody<D>(random.vector<D>(-1.0, 1.0), random.orientation<D>());
  const RigidBody<D> start = ground;
  for (int step = 0; step < 10000; ++step) {
    advanceFreeBody<D>(ground, 1e-3, gravityLoads<D>(gravity<D>()));
  }
  CHECK(ground.position == start.position);
  CHECK(identical<D>(ground.orientation, start.orientation));
  CHECK(ground.velocity == Vec<D>::Zero());

  // Given a velocity it moves as a kinematic body, and forces still do not act on it.
  ground.velocity = Vec<D>::Ones();
  advanceFreeBody<D>(ground, 0.5, gravityLoads<D>(gravity<D>()));
  CHECK_EIGEN_NEAR(ground.position, Vec<D>(start.position + 0.5 * Vec<D>::Ones()), 1e-15);
  CHECK(ground.velocity == Vec<D>::Ones());
}

// [test_exponential_map]
TEST_CASE("the exponential map is the exact rotation by dt omega in 3D") {
  RandomSource random(620);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const Eigen::Quaterniond q = random.orientation<3>();
    // Angles from 1e-9 to 3 rad: both sides of the small-angle series at 1e-4.
    const double angle = random.logUniform(1e-9, 3.0);
    const Vec3 axis = random.unitVector<3>();
    const double dt = random.uniform(0.1, 2.0);
    const Vec3 omega = angle / dt * axis;
    const Eigen::Quaterniond turned = rotateByAngularVelocity<3>(q, omega, dt);
    CHECK(std::abs(turned.norm() - 1.0) < 1e-15);
    CHECK_EIGEN_NEAR(turned.toRotationMatrix(),
                     (Eigen::AngleAxisd(angle, axis) * q).toRotationMatrix(), 1e-15, 1e-15);
    // The exponential of a constant omega composes: two steps of dt are one step of 2 dt.
    const Eigen::Quaterniond twice =
        rotateByAngularVelocity<3>(rotateByAngularVelocity<3>(q, omega, 0.5 * dt), omega, 0.5 * dt);
    CHECK_EIGEN_NEAR(twice.toRotationMatrix(), turned.toRotationMatrix(), 1e-14, 1e-15);
  }
}
// [test_exponential_map]

TEST_CASE("in 2D the exponential map adds dt omega to the angle and wraps it") {
  const Eigen::Rotation2Dd q(3.0);
  const Eigen::Rotation2Dd turned = rotateByAngularVelocity<2>(q, AngVec<2>::Constant(2.0), 0.25);
  CHECK(turned.angle() == doctest::Approx(3.5 - 2.0 * M_PI).epsilon(1e-15));
  CHECK(std::abs(turned.angle()) <= M_PI);
}

// [test_quaternion_hygiene]
TEST_CASE("the quaternion stays unit and R orthonormal while spinning at 100 rad/s") {
  RandomSource random(640);
  RigidBody<3> body = makeDynamicBody<3>(1.0, random.principalInertia<3>(1.0));
  body.orientation = random.orientation<3>();
  body.setAngularVelocity(100.0 * random.unitVector<3>());
  double worstNorm = 0.0, worstOrthogonality = 0.0;
  for (int step = 0; step < 10000; ++step) {
    advanceFreeBody<3>(body, 1e-3);
    const Mat3 R = body.orientation.toRotationMatrix();
    worstNorm = std::max(worstNorm, std::abs(body.orientation.norm() - 1.0));
    worstOrthogonality =
        std::max(worstOrthogonality, (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff());
  }
  CHECK(worstNorm < 1e-12);
  CHECK(worstOrthogonality < 1e-12);
}

TEST_CASE("a quaternion set with the wrong length gives the trajectory of its normalised version") {
  RandomSource random(660);
  const Vec3 moments = random.principalInertia<3>(2.0);
  const Eigen::Quaterniond q = random.orientation<3>();
  const Vec3 L = random.vector<3>(-1.0, 1.0);
  const auto run = [&](double scale) {
    RigidBody<3> body = makeDynamicBody<3>(2.0, moments);
    body.orientation = Eigen::Quaterniond(scale * q.coeffs());
    body.angularMomentum = L;  // omega is derived by the first velocity update
    for (int step = 0; step < 1000; ++step) advanceFreeBody<3>(body, 1e-3);
    return body;
  };
  const RigidBody<3> reference = run(1.0);
  for (const double scale : {2.0, 0.5, 1.0 + 1e-6, 1e3}) {
    CAPTURE(scale);
    const RigidBody<3> body = run(scale);
    CHECK_EIGEN_NEAR(body.orientation.toRotationMatrix(), reference.orientation.toRotationMatrix(),
                     1e-12);
    CHECK_EIGEN_NEAR(body.angularVelocity, reference.angularVelocity, 1e-12);
  }
  RigidBody<3> broken = makeDynamicBody<3>(2.0, moments);
  broken.orientation = Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0);
  CHECK_THROWS_WITH_AS(advanceFreeBody<3>(broken, 1e-3),
                       doctest::Contains("zero or non-finite norm"), std::invalid_argument);
}
// [test_quaternion_hygiene]

}  // TEST_SUITE

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

TEST_CASE("the quaternion stays unit over a million steps at 100 rad/s") {
  RandomSource random(641);
  RigidBody<3> body = makeDynamicBody<3>(1.0, random.principalInertia<3>(1.0));
  body.orientation = random.orientation<3>();
  body.setAngularVelocity(100.0 * random.unitVector<3>());
  const double L0 = body.angularMomentum.norm();
  double worstNorm = 0.0, worstOrthogonality = 0.0;
  for (int step = 0; step < 1000000; ++step) {
    advanceFreeBody<3>(body, 1e-3);
    const Mat3 R = body.orientation.toRotationMatrix();
    worstNorm = std::max(worstNorm, std::abs(body.orientation.norm() - 1.0));
    worstOrthogonality =
        std::max(worstOrthogonality, (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff());
  }
  CHECK(worstNorm < 1e-12);
  CHECK(worstOrthogonality < 1e-12);
  CHECK(body.angularMomentum.norm() == doctest::Approx(L0).epsilon(1e-12));
}

}  // TEST_SUITE
