// Chapter 1 exercises: suite ch01_exercises, skipped by default. The exercises preset builds
// them into build/exercises/tests/ch01/test_ch01_exercises. It registers one CTest entry per
// exercise, ex01.1 to ex01.3, with the labels exercise and ch01. Run all of them, or one, with
//   ctest --preset exercises -L ch01
//   ctest --preset exercises -R ex01.2
// An entry runs its tests once its stub has no "// TODO(reader)" comment left. The binary
// runs them at any time:
//   build/exercises/tests/ch01/test_ch01_exercises --no-skip -ts=ch01_exercises -tc="Exercise 1.2*"
// They fail until you solve the exercise (the stub returns a neutral value).
// The main build runs them against the reference solutions: ctest --preset solutions -L ch01
#include <cmath>
#include <limits>

#include <doctest/doctest.h>
#include <Eigen/Eigenvalues>

#include "stackbook/exercises/ex01_1_effective_mass.hpp"
#include "stackbook/exercises/ex01_2_locked_rotation.hpp"
#include "stackbook/exercises/ex01_3_measured_k.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::kTierImpulseAlgebra;
using stackbook::testing::RandomSource;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Two random bodies touching at a random world point; b is static when asked.
template <int D>
struct Contact {
  RigidBody<D> a, b;
  Vec<D> ra, rb;
  Mat<D> K;  ///< the assembled K_T
};

template <int D>
Contact<D> randomContact(RandomSource& random, bool staticB) {
  Contact<D> c;
  c.a = random.dynamicBody<D>();
  c.b = staticB ? makeStaticBody<D>(random.vector<D>(-3.0, 3.0), random.orientation<D>())
                : random.dynamicBody<D>();
  const Vec<D> p = random.vector<D>(-3.0, 3.0);
  c.ra = p - c.a.position;
  c.rb = p - c.b.position;
  c.K = pairCollisionMatrix<D>(c.a, c.ra, c.b, c.rb);
  return c;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER "_exercises" * doctest::skip()) {

// ---- Exercise 1.1: effective mass ------------------------------------------------------

TEST_CASE_TEMPLATE("Exercise 1.1: the effective mass along r is the full mass m", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  RandomSource random(1101 + D);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const RigidBody<D> body = random.dynamicBody<D>();
    const Vec<D> r = random.vector<D>(-2.0, 2.0);
    const Mat<D> K = collisionMatrix<D>(body, r);
    const double m = body.mass();
    // K r = r/m up to rounding of a few eps |K| in K's entries.
    const double tolerance = 16 * kEps * K.norm() * m;
    CHECK(effectiveMass<D>(K, r) == doctest::Approx(m).epsilon(tolerance));
    CHECK(effectiveMass<D>(K, Vec<D>(-3.0 * r)) == doctest::Approx(m).epsilon(tolerance));
  }
}

TEST_CASE_TEMPLATE(
    "Exercise 1.1: across r the effective mass of an isotropic body is 1/(1/m + |r|^2/I)", Dim,
    In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(1111 + D);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const double m = random.logUniform(0.1, 10.0);
    const double I = random.logUniform(0.01, 10.0);
    RigidBody<D> body = makeDynamicBody<D>(m, AngVec<D>::Constant(I));
    body.orientation = random.orientation<D>();
    const Vec<D> r = random.vector<D>(-2.0, 2.0);
    // A direction perpendicular to r.
    Vec<D> across = random.vector<D>(-1.0, 1.0);
    across -= across.dot(r) / r.squaredNorm() * r;
    const Mat<D> K = collisionMatrix<D>(body, r);
    const double expected = 1.0 / (1.0 / m + r.squaredNorm() / I);
    CHECK(effectiveMass<D>(K, across) == doctest::Approx(expected).epsilon(1e-12));
    // It is the lightest direction: K has the eigenvalue 1/m + |r|^2/I across r.
    const EffectiveMassExtremes<D> extremes = effectiveMassExtremes<D>(K);
    CHECK(extremes.lightest == doctest::Approx(expected).epsilon(1e-12));
    CHECK(std::abs(extremes.lightestDirection.dot(r)) <= 1e-12 * r.norm());
  }
  if constexpr (D == 3) {
    // The worked example: a unit cube of mass 2 touched at a corner, pushed vertically.
    const RigidBody<3> cube = makeDynamicBody<3>(2.0, Vec3::Constant(1.0 / 3.0));
    const Mat3 K = collisionMatrix<3>(cube, Vec3(0.5, 0.5, -0.5));
    CHECK(effectiveMass<3>(K, Vec3::UnitZ()) == doctest::Approx(0.5).epsilon(1e-14));
  }
}

TEST_CASE_TEMPLATE("Exercise 1.1: every direction's effective mass lies between the extremes",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(1121 + D);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const Contact<D> c = randomContact<D>(random, trial % 3 == 0);
    const EffectiveMassExtremes<D> x = effectiveMassExtremes<D>(c.K);
    REQUIRE(x.lightest > 0.0);
    REQUIRE(x.lightest <= x.heaviest);
    CHECK(x.lightestDirection.norm() == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(x.heaviestDirection.norm() == doctest::Approx(1.0).epsilon(1e-14));
    // The extremes are reached along their directions ...
    CHECK(effectiveMass<D>(c.K, x.lightestDirection) == doctest::Approx(x.lightest).epsilon(1e-10));
    CHECK(effectiveMass<D>(c.K, x.heaviestDirection) == doctest::Approx(x.heaviest).epsilon(1e-10));
    // ... and no direction goes beyond them.
    for (int k = 0; k < 20; ++k) {
      const double mEff = effectiveMass<D>(c.K, random.unitVector<D>());
      CHECK(mEff >= x.lightest * (1.0 - 1e-10));
      CHECK(mEff <= x.heaviest * (1.0 + 1e-10));
    }
  }
}

TEST_CASE_TEMPLATE("Exercise 1.1: no effective mass exceeds the reduced mass", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(1131 + D);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const Contact<D> c = randomContact<D>(random, trial % 3 == 0);
    const double reducedMass = 1.0 / (c.a.inverseMass + c.b.inverseMass);
    const EffectiveMassExtremes<D> x = effectiveMassExtremes<D>(c.K);
    CHECK(x.heaviest > 0.0);
    CHECK(x.heaviest <= reducedMass * (1.0 + 1e-10));
  }
  // Two static bodies: no impulse moves them, the effective mass is infinite.
  CHECK(effectiveMass<D>(Mat<D>::Zero(), Vec<D>::UnitX()) == kInf);
  CHECK(effectiveMassExtremes<D>(Mat<D>::Zero()).lightest == kInf);
}

TEST_CASE_TEMPLATE("Exercise 1.1: an impulse of m_eff dv along d changes the velocity along d by dv",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(1141 + D);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    Contact<D> c = randomContact<D>(random, trial % 3 == 0);
    const Vec<D> d = random.unitVector<D>();
    const double dv = random.uniform(-2.0, 2.0);
    const Vec<D> before = relativeVelocity<D>(c.a, c.ra, c.b, c.rb);
    applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, Vec<D>(effectiveMass<D>(c.K, d) * dv * d));
    const Vec<D> after = relativeVelocity<D>(c.a, c.ra, c.b, c.rb);
    CHECK(d.dot(after - before) ==
          doctest::Approx(dv).epsilon(1e-10).scale(before.norm() + after.norm()));
  }
}

// ---- Exercise 1.2: locked and hinged rotation --------------------------------------------

TEST_CASE("Exercise 1.2: locking a principal axis is zeroing its inverse moment") {
  RandomSource random(1201);
  for (int trial = 0; trial < 60; ++trial) {
    CAPTURE(trial);
    const RigidBody<3> body = random.dynamicBody<3>();
    const int k = trial % 3;
    const Vec3 axis = body.orientation * Vec3(Vec3::Unit(k));
    RigidBody<3> zeroed = body;
    zeroed.inverseInertia[k] = 0.0;
    CHECK_EIGEN_NEAR(inverseInertiaLockedAbout(body, axis), zeroed.inverseInertiaWorld(), 1e-12);
  }
}

TEST_CASE("Exercise 1.2: a locked body turns across the lock and the bearing torque lies along it") {
  RandomSource random(1211);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const RigidBody<3> body = random.dynamicBody<3>();
    const Vec3 a = random.unitVector<3>();
    const Vec3 tau = random.vector<3>(-2.0, 2.0);
    const Vec3 dw = inverseInertiaLockedAbout(body, a) * tau;
    const Mat3 I = body.inertiaWorld();
    const double scale = (I.norm() * dw.norm() + tau.norm());
    // No rotation about a ...
    CHECK(std::abs(a.dot(dw)) <= 1e-12 * dw.norm() + kEps);
    // ... and the torque the bearing adds, I dw - tau, is along a.
    const Vec3 reaction = I * dw - tau;
    CHECK((reaction - reaction.dot(a) * a).norm() <= 1e-12 * scale);
    // A lock can only take away response: the energy tau^T W tau / 2 does not grow.
    CHECK(tau.dot(dw) <= tau.dot(body.inverseInertiaWorld() * tau) * (1.0 + 1e-12));
  }
}

TEST_CASE("Exercise 1.2: a hinged body turns only about the hinge and the hinge torque does no work") {
  RandomSource random(1221);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const RigidBody<3> body = random.dynamicBody<3>();
    const Vec3 a = random.unitVector<3>();
    const Vec3 tau = random.vector<3>(-2.0, 2.0);
    const Vec3 dw = inverseInertiaHingedAbout(body, a) * tau;
    const Mat3 I = body.inertiaWorld();
    CHECK((dw - dw.dot(a) * a).norm() <= 1e-12 * dw.norm() + kEps);
    // The hinge torque I dw - tau is perpendicular to a: it does no work on a turn about a.
    const Vec3 reaction = I * dw - tau;
    CHECK(std::abs(reaction.dot(a)) <= 1e-12 * (I.norm() * dw.norm() + tau.norm()));
    CHECK(dw.norm() > 0.0);  // a random tau has a component along a
  }
}

TEST_CASE("Exercise 1.2: a wheel on a fixed axle has the singular K (a x r)(a x r)^T / (a^T I a)") {
  // A body on a fixed axle through its centre of mass (a wheel, a turnstile): translation
  // locked (1/m = 0) and rotation only about a. The contact point can only move along
  // a x r, so K has rank one: the singular K that chapter 3 has to handle.
  RandomSource random(1231);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const RigidBody<3> wheel = random.dynamicBody<3>();
    const Vec3 a = random.unitVector<3>();
    const Vec3 r = random.vector<3>(-1.0, 1.0);
    const Mat3 K = collisionMatrix<3>(0.0, inverseInertiaHingedAbout(wheel, a), r);
    const Vec3 t = a.cross(r);
    const Mat3 expected = t * t.transpose() / a.dot(wheel.inertiaWorld() * a);
    CHECK_EIGEN_NEAR(K, expected, 1e-12);
    const Vec3 lambda = Eigen::SelfAdjointEigenSolver<Mat3>(K).eigenvalues();
    CHECK(lambda[2] > 0.0);
    CHECK(std::abs(lambda[0]) <= 1e-12 * lambda[2]);
    CHECK(std::abs(lambda[1]) <= 1e-12 * lambda[2]);
  }
}

// ---- Exercise 1.3: K measured column by column --------------------------------------------

/// Rounding in u' - u: a few eps times the velocities involved, divided by the impulse s.
template <int D>
double measurementTolerance(const Contact<D>& c, double s) {
  auto speed = [](const RigidBody<D>& body, const Vec<D>& r) {
    return body.velocity.norm() + body.angularVelocity.norm() * r.norm();
  };
  return 64 * kEps * (speed(c.a, c.ra) + speed(c.b, c.rb) + s * c.K.norm()) / s;
}

TEST_CASE_TEMPLATE("Exercise 1.3: the measured K_T equals the assembled K_T", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(1301 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const Contact<D> c = randomContact<D>(random, trial % 3 == 0);
    const Mat<D> measured = measuredCollisionMatrix<D>(c.a, c.ra, c.b, c.rb);
    CHECK_EIGEN_NEAR(measured, c.K, 0.0, measurementTolerance<D>(c, 1.0));
  }
}

TEST_CASE_TEMPLATE("Exercise 1.3: the measured K_T is symmetric as reciprocity demands", Dim,
                   In2D, In3D) {
  // Nothing in the experiment is symmetric by construction: the velocity change along e_i
  // from a push along e_k equals the change along e_k from a push along e_i.
  constexpr int D = Dim::value;
  RandomSource random(1311 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const Contact<D> c = randomContact<D>(random, trial % 3 == 0);
    const Mat<D> measured = measuredCollisionMatrix<D>(c.a, c.ra, c.b, c.rb);
    CHECK(measured.diagonal().minCoeff() >= (c.a.inverseMass + c.b.inverseMass) * (1.0 - 1e-9));
    CHECK_EIGEN_NEAR(measured, Mat<D>(measured.transpose()), 0.0,
                     2.0 * measurementTolerance<D>(c, 1.0));
  }
}

TEST_CASE_TEMPLATE("Exercise 1.3: the measurement does not depend on the impulse size", Dim,
                   In2D, In3D) {
  // The velocity change is exactly linear in j: no truncation error, only rounding.
  constexpr int D = Dim::value;
  RandomSource random(1321 + D);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const Contact<D> c = randomContact<D>(random, trial % 3 == 0);
    for (double s : {1e-3, 1.0, 1e3}) {
      CAPTURE(s);
      const Mat<D> measured = measuredCollisionMatrix<D>(c.a, c.ra, c.b, c.rb, s);
      CHECK_EIGEN_NEAR(measured, c.K, 0.0, measurementTolerance<D>(c, s));
    }
  }
}

}  // TEST_SUITE
