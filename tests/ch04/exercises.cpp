// Chapter 4 exercises: suite ch04_exercises, skipped by default. The exercises preset builds
// them into build/exercises/tests/ch04/test_ch04_exercises. It registers one CTest entry per
// exercise, ex04.1 to ex04.3, with the labels exercise and ch04. Run all of them, or one, with
//   ctest --preset exercises -L ch04
//   ctest --preset exercises -R ex04.1
// An entry runs its tests once its stub has no "// TODO(reader)" comment left. The binary
// runs them at any time:
//   build/exercises/tests/ch04/test_ch04_exercises --no-skip -ts=ch04_exercises -tc="Exercise 4.1*"
// The main build runs them against the reference solutions: ctest --preset solutions -L ch04
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "stackbook/exercises/ex04_1_contact_frame.hpp"
#include "stackbook/exercises/ex04_2_four_dimensions.hpp"
#include "stackbook/exercises/ex04_3_cramer_fast_path.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using namespace stackbook::exercises;
using stackbook::testing::RandomSource;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

/// A single-body 2D K with 1/m = 1, |r| = 1 at angle phi and 1/I = kappa - 1:
/// K = delta + (kappa - 1)(delta - r r^T), eigenvalues 1 (along r) and kappa (along r-perp),
/// so its condition number is kappa (Eq. (4.4)).
Mat2 conditionedK(double kappa, double phi) {
  const Vec2 r(std::cos(phi), std::sin(phi));
  return Mat2::Identity() + (kappa - 1.0) * (Mat2::Identity() - r * r.transpose());
}

/// A uniform box with random sides in [0.1, 2] and random mass and pose, placed so that
/// the point p lies inside it: a physical body touched at p. Its K at p has condition
/// number at most 1 + m |r|^2 / I <= 4 (Eq. (4.4)).
RigidBody<2> boxAroundPoint(RandomSource& random, const Vec2& p) {
  const double m = random.logUniform(0.1, 10.0);
  const double a = random.uniform(0.1, 2.0), b = random.uniform(0.1, 2.0);
  RigidBody<2> body = makeDynamicBody<2>(m, AngVec<2>::Constant(m * (a * a + b * b) / 12.0));
  body.orientation = random.orientation<2>();
  const double y = random.uniform(-0.5 * b, 0.5 * b);  // one draw per statement, y first as
  const double x = random.uniform(-0.5 * a, 0.5 * a);  // before: argument order is unspecified
  const Vec2 inside(x, y);
  body.position = p - body.orientation * inside;
  body.velocity = random.vector<2>(-2.0, 2.0);
  body.setAngularVelocity(random.angularVector<2>(-3.0, 3.0));
  return body;
}

/// The stiff eigenvector r-perp of conditionedK: the right-hand side that Cramer's rule
/// handles worst.
Vec2 stiffDirection(double phi) { return Vec2(-std::sin(phi), std::cos(phi)); }

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER "_exercises" * doctest::skip()) {

// ---------------------------------------------------------------------------------------
// Exercise 4.1: K in the contact frame.

TEST_CASE("Exercise 4.1: the contact-frame entries equal the pair K turned into the frame") {
  RandomSource random(421);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const RigidBody<2> a = random.dynamicBody<2>();
    const RigidBody<2> b = trial % 4 == 0 ? makeStaticBody<2>() : random.dynamicBody<2>();
    const Vec2 p = random.vector<2>(-3.0, 3.0);
    const Vec2 ra = p - a.position, rb = p - b.position;
    const Vec2 n = random.unitVector<2>(), t(-n.y(), n.x());
    const Mat2 K = pairCollisionMatrix<2>(a, ra, b, rb);
    const ContactFrameK k = contactFrameK(a, ra, b, rb, n);
    const double scale = K.cwiseAbs().maxCoeff();
    CHECK(std::abs(k.nn - n.dot(K * n)) <= 1e-12 * scale);
    CHECK(std::abs(k.nt - n.dot(K * t)) <= 1e-12 * scale);
    CHECK(std::abs(k.tt - t.dot(K * t)) <= 1e-12 * scale);
  }
}

TEST_CASE("Exercise 4.1: a uniform rod on its end has K_nn = 1 + 3 cos^2 and K_nt = 3 sin cos") {
  // Rod of length 1, m = 1, I = 1/12, at angle theta above a static floor (n = +y), touching
  // it with its lower end r = -(cos, sin)/2 (validation case A21). With t = (-1, 0):
  // K_nn = 1 + 3 cos^2, K_nt = 3 sin cos, K_tt = 1 + 3 sin^2.
  const RigidBody<2> rod = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 12.0));
  const RigidBody<2> floor = makeStaticBody<2>();
  const Vec2 n(0.0, 1.0);
  for (int step = 1; step < 90; ++step) {
    const double theta = step * M_PI / 180.0;
    CAPTURE(theta);
    const double c = std::cos(theta), s = std::sin(theta);
    const Vec2 r = -0.5 * Vec2(c, s);
    const ContactFrameK k = contactFrameK(rod, r, floor, Vec2::Zero(), n);
    CHECK(k.nn == doctest::Approx(1.0 + 3.0 * c * c).epsilon(1e-12));
    CHECK(k.nt == doctest::Approx(3.0 * s * c).epsilon(1e-12));
    CHECK(k.tt == doctest::Approx(1.0 + 3.0 * s * s).epsilon(1e-12));
  }
}

TEST_CASE("Exercise 4.1: the rod's Painleve coefficient is smallest at tan theta = 2 where it is 4/3") {
  const RigidBody<2> rod = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 12.0));
  const RigidBody<2> floor = makeStaticBody<2>();
  const Vec2 n(0.0, 1.0);
  double smallest = std::numeric_limits<double>::infinity();
  double argmin = 0.0;
  for (int step = 1; step < 9000; ++step) {
    const double theta = step * M_PI / 18000.0;
    const double c = std::cos(theta), s = std::sin(theta);
    const ContactFrameK k = contactFrameK(rod, -0.5 * Vec2(c, s), floor, Vec2::Zero(), n);
    // Sliding with the lower end leading (T = t = -x): mu_P = (1 + 3 cos^2)/(3 sin cos).
    const double muP = painleveFriction(k, +1.0);
    CHECK(muP == doctest::Approx((1.0 + 3.0 * c * c) / (3.0 * s * c)).epsilon(1e-12));
    // Sliding the other way the denominator only grows: no finite mu breaks it.
    CHECK(std::isinf(painleveFriction(k, -1.0)));
    if (muP < smallest) {
      smallest = muP;
      argmin = theta;
    }
  }
  CHECK(smallest == doctest::Approx(4.0 / 3.0).epsilon(1e-6));
  CHECK(argmin == doctest::Approx(std::atan(2.0)).epsilon(1e-3));
}

// ---------------------------------------------------------------------------------------
// Exercise 4.2: four dimensions.

TEST_CASE("Exercise 4.2: the 4D r* is the wedge product and on xyz space the 3D cross product") {
  RandomSource random(422);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    Vec4 r, b;
    for (int i = 0; i < 4; ++i) {
      r[i] = random.uniform(-3.0, 3.0);
      b[i] = random.uniform(-3.0, 3.0);
    }
    const Bivec4 wedge = crossMatrix4(r) * b;
    int row = 0;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j, ++row) {
        CHECK(wedge[row] == doctest::Approx(r[i] * b[j] - r[j] * b[i]).epsilon(1e-12));
      }
    }
    // r ^ r = 0.
    CHECK((crossMatrix4(r) * r).cwiseAbs().maxCoeff() <= 1e-12 * r.squaredNorm());
    // With w = 0 the planes (xy, xz, yz) carry (c_z, -c_y, c_x) of c = r x b, and the
    // planes that contain w carry nothing.
    r[3] = 0.0;
    b[3] = 0.0;
    const Vec3 c = cross<3>(Vec3(r.head<3>()), Vec3(b.head<3>()));
    Bivec4 expected;
    expected << c.z(), -c.y(), 0.0, c.x(), 0.0, 0.0;
    CHECK_EIGEN_NEAR(Bivec4(crossMatrix4(r) * b), expected, 1e-12);
  }
}

TEST_CASE("Exercise 4.2: with one moment for every plane the 4D K is delta/m + (r.r delta - r r^T)/I") {
  RandomSource random(423);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    Vec4 r;
    for (int i = 0; i < 4; ++i) r[i] = random.uniform(-3.0, 3.0);
    const double invM = random.logUniform(0.1, 10.0), invI = random.logUniform(0.1, 10.0);
    const Mat4 K = collisionMatrix4(invM, Bivec4::Constant(invI), r);
    const Mat4 expected =
        invM * Mat4::Identity() + invI * (r.squaredNorm() * Mat4::Identity() - r * r.transpose());
    CHECK_EIGEN_NEAR(K, expected, 1e-12);
  }
}

TEST_CASE("Exercise 4.2: K j equals the change in 4D point velocity from the impulse") {
  RandomSource random(424);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    RigidBody4 body;
    body.inverseMass = random.logUniform(0.1, 10.0);
    Vec4 r, j;
    for (int i = 0; i < 4; ++i) {
      body.velocity[i] = random.uniform(-2.0, 2.0);
      r[i] = random.uniform(-2.0, 2.0);
      j[i] = random.uniform(-5.0, 5.0);
    }
    for (int p = 0; p < 6; ++p) {
      body.inverseInertia[p] = random.logUniform(0.1, 10.0);
      body.angularVelocity[p] = random.uniform(-3.0, 3.0);
    }
    const Mat4 K = collisionMatrix4(body.inverseMass, body.inverseInertia, r);
    const Vec4 before = body.pointVelocity(r);
    body.applyImpulse(r, j);
    const Vec4 after = body.pointVelocity(r);
    CHECK_EIGEN_NEAR(Vec4(after - before), Vec4(K * j), 1e-12);
    // K is symmetric with every eigenvalue at least 1/m; along r it is exactly 1/m.
    CHECK_EIGEN_NEAR(K, Mat4(K.transpose()), 1e-12);
    const Eigen::SelfAdjointEigenSolver<Mat4> eigen(K, Eigen::EigenvaluesOnly);
    CHECK(eigen.eigenvalues()[0] >= body.inverseMass * (1.0 - 1e-12));
    CHECK_EIGEN_NEAR(Vec4(K * r), Vec4(body.inverseMass * r), 1e-12);
  }
}

// ---------------------------------------------------------------------------------------
// Exercise 4.3: Cramer's rule as a 2D fast path.

TEST_CASE("Exercise 4.3: Cramer's rule agrees with the LDL^T solve for boxes touched within their extent") {
  RandomSource random(425);
  const FrictionSettings settings;
  int sticking = 0;
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const Vec2 p = random.vector<2>(-3.0, 3.0);
    const RigidBody<2> a = boxAroundPoint(random, p);
    const RigidBody<2> b = trial % 4 == 0 ? makeStaticBody<2>() : boxAroundPoint(random, p);
    const Vec2 ra = p - a.position, rb = p - b.position;
    const Mat2 K = pairCollisionMatrix<2>(a, ra, b, rb);
    const Vec2 rhs = random.vector<2>(-5.0, 5.0);
    Vec2 jCramer = Vec2::Zero(), jLdlt = Vec2::Zero(), jFast = Vec2::Zero();
    REQUIRE(solveCramer2(K, rhs, jCramer));
    REQUIRE(solveCollisionMatrix<2>(K, rhs, settings, jLdlt));
    CHECK_EIGEN_NEAR(jCramer, jLdlt, 1e-12);
    // Physical pairs are well conditioned, so the fast path is Cramer's rule, bit for bit.
    REQUIRE(solveCollisionMatrix2D(K, rhs, settings, jFast));
    CHECK(jFast == jCramer);
    // The fast path gives the sticking impulse of chapter 3 (Eq. (3.2)).
    Vec2 n = random.unitVector<2>();
    const Vec2 u = relativeVelocity<2>(a, ra, b, rb);
    if (u.dot(n) > 0.0) n = -n;
    const ContactImpulse<2> impulse = frictionalImpulse<2>(K, u, n, 0.0, 10.0);
    if (impulse.branch == ImpulseBranch::Sticking) {
      ++sticking;
      Vec2 jStick = Vec2::Zero();
      REQUIRE(solveCollisionMatrix2D(K, Vec2(-u), settings, jStick));
      CHECK_EIGEN_NEAR(jStick, impulse.j, 1e-12);
    }
  }
  CHECK(sticking > 100);
}

// [exercise_cramer_residual]
TEST_CASE("Exercise 4.3: Cramer's velocity residual grows with the condition number and LDL^T's does not") {
  const FrictionSettings settings;
  for (const double kappa : {1e2, 1e4, 1e6, 1e8}) {
    CAPTURE(kappa);
    double worstCramer = 0.0, worstLdlt = 0.0;
    for (int step = 0; step < 100; ++step) {
      const double phi = 2.0 * M_PI * step / 100.0 + 0.1;
      const Mat2 K = conditionedK(kappa, phi);
      const Vec2 rhs = stiffDirection(phi);  // |rhs| = 1
      Vec2 jCramer = Vec2::Zero(), jLdlt = Vec2::Zero();
      REQUIRE(solveCramer2(K, rhs, jCramer));
      REQUIRE(solveCollisionMatrix<2>(K, rhs, settings, jLdlt));
      // The residual K j - rhs is the velocity error the sticking impulse leaves behind.
      worstCramer = std::max(worstCramer, (K * jCramer - rhs).norm());
      worstLdlt = std::max(worstLdlt, (K * jLdlt - rhs).norm());
    }
    CAPTURE(worstCramer);
    CAPTURE(worstLdlt);
    CHECK(worstLdlt <= 8.0 * kEps);             // backward stable: rounding level
    CHECK(worstCramer <= 2.0 * kappa * kEps);   // Cramer: bounded by kappa eps ...
    if (kappa >= 1e4) CHECK(worstCramer >= 0.01 * kappa * kEps);  // ... and it gets there
  }
}
// [exercise_cramer_residual]

TEST_CASE("Exercise 4.3: the fast path keeps the velocity residual in tier T1 at any condition number") {
  const FrictionSettings settings;
  for (const double kappa : {1e1, 1e3, 1e5, 1e7, 1e9, 1e11}) {
    CAPTURE(kappa);
    for (int step = 0; step < 100; ++step) {
      const double phi = 2.0 * M_PI * step / 100.0 + 0.1;
      const Mat2 K = conditionedK(kappa, phi);
      const Vec2 rhs = stiffDirection(phi);
      Vec2 jFast = Vec2::Zero(), jCramer = Vec2::Zero(), jLdlt = Vec2::Zero();
      REQUIRE(solveCollisionMatrix2D(K, rhs, settings, jFast));
      CHECK((K * jFast - rhs).norm() <= 1e-12);
      // Below the bound it is Cramer's rule, above it the LDL^T solve, bit for bit.
      const double bound = K.trace() * K.trace() / (K(0, 0) * K(1, 1) - K(0, 1) * K(1, 0));
      if (bound <= 1e4) {
        REQUIRE(solveCramer2(K, rhs, jCramer));
        CHECK(jFast == jCramer);
      } else {
        REQUIRE(solveCollisionMatrix<2>(K, rhs, settings, jLdlt));
        CHECK(jFast == jLdlt);
      }
    }
  }
  // A body that can turn but not translate (1/m = 0) has the singular K = r*^T r* / I:
  // no solve may pretend otherwise, whatever the rounding of det(K).
  RandomSource random(426);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const Vec2 r = random.vector<2>(-2.0, 2.0);
    const Mat2 K = collisionMatrix<2>(0.0, AngMat<2>::Constant(random.logUniform(0.1, 10.0)), r);
    Vec2 j = Vec2::Zero();
    CHECK_FALSE(solveCollisionMatrix2D(K, Vec2(1.0, 0.0), settings, j));
  }
  Vec2 j = Vec2::Zero();
  CHECK_FALSE(solveCollisionMatrix2D(Mat2::Zero(), Vec2(1.0, 0.0), settings, j));
  CHECK_FALSE(solveCramer2(Mat2::Zero(), Vec2(1.0, 0.0), j));
}

}  // TEST_SUITE
