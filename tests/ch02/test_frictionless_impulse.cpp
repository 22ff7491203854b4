// Chapter 2: the frictionless impulse. Which contacts get one (Eq. (2.1)), that it reaches
// Newton's restitution exactly (Eqs. (2.2), (2.3)), static and immovable partners, and what
// it does to the tangential velocity.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <doctest/doctest.h>

#include "pair_fixture.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::kTierImpulseAlgebra;
using stackbook::testing::PairContact;
using stackbook::testing::RandomSource;

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_restitution_reached]
TEST_CASE_TEMPLATE("the impulse leaves the contact with normal velocity -e u_n", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(200 + D);
  for (const double e : {0.0, 0.3, 1.0}) {
    for (int trial = 0; trial < 300; ++trial) {
      CAPTURE(e);
      CAPTURE(trial);
      PairContact<D> c = testing::randomApproachingContact<D>(random);
      const Vec<D> u = c.relative();
      const double un = u.dot(c.n);
      const ContactImpulse<D> impulse = frictionlessImpulse<D>(c.K(), u, c.n, e);
      REQUIRE(impulse.branch == ImpulseBranch::Frictionless);
      const double jn = impulse.normal(c.n);
      CHECK(jn > 0.0);                                                  // it pushes
      CHECK_EIGEN_NEAR(impulse.j, Vec<D>(jn * c.n), kTierImpulseAlgebra);  // along n only

      const double scaleBefore = testing::pointVelocityScale<D>(c);
      applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, impulse.j);
      const double scale = std::max(scaleBefore, testing::pointVelocityScale<D>(c));
      CHECK(std::abs(c.un() - (-e * un)) <= kTierImpulseAlgebra * scale);  // Eq. (2.3)
    }
  }
}
// [test_restitution_reached]

TEST_CASE_TEMPLATE("separating and resting contacts get no impulse", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(210 + D);
  for (const double e : {0.0, 0.3, 1.0}) {
    CAPTURE(e);
    // Separating: an approaching contact with every motion reversed, so u_n > 0.
    for (int trial = 0; trial < 100; ++trial) {
      PairContact<D> c = testing::randomApproachingContact<D>(random);
      testing::reverseMotion<D>(c.a);
      testing::reverseMotion<D>(c.b);
      REQUIRE(c.un() > 0.0);
      const ContactImpulse<D> impulse = frictionlessImpulse<D>(c.K(), c.relative(), c.n, e);
      CHECK(impulse.branch == ImpulseBranch::Separating);
      CHECK(impulse.j == Vec<D>::Zero());
      CHECK(impulse.restitution == e);
    }
    // Resting: u_n = 0 exactly (sliding along the surface, or no motion at all).
    const Mat<D> K = testing::randomApproachingContact<D>(random).K();
    Vec<D> n = Vec<D>::Zero(), sliding = Vec<D>::Zero();
    n[0] = 0.6, n[1] = 0.8;
    sliding[0] = 0.8, sliding[1] = -0.6;  // 0.8 * 0.6 - 0.6 * 0.8 is exactly 0
    if constexpr (D == 3) sliding[2] = 1.7;
    REQUIRE(sliding.dot(n) == 0.0);
    for (const Vec<D>& u : {sliding, Vec<D>(Vec<D>::Zero())}) {
      const ContactImpulse<D> impulse = frictionlessImpulse<D>(K, u, n, e);
      CHECK(impulse.branch == ImpulseBranch::Separating);
      CHECK(impulse.j == Vec<D>::Zero());
    }
  }
}

TEST_CASE_TEMPLATE("negative restitution slows an approach without reversing it", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(220 + D);
  for (const double e : {-1.0, -0.9, -0.5, -0.1}) {
    for (int trial = 0; trial < 100; ++trial) {
      CAPTURE(e);
      CAPTURE(trial);
      PairContact<D> c = testing::randomApproachingContact<D>(random);
      const double un = c.un();
      const ContactImpulse<D> impulse = frictionlessImpulse<D>(c.K(), c.relative(), c.n, e);
      const double jn = impulse.normal(c.n);
      CHECK(jn >= 0.0);  // still a push, never a pull
      if (e == -1.0) CHECK(impulse.j.isZero(0.0));  // -(1 + e) = 0: nothing happens
      const double scaleBefore = testing::pointVelocityScale<D>(c);
      applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, impulse.j);
      const double scale = std::max(scaleBefore, testing::pointVelocityScale<D>(c));
      CHECK(std::abs(c.un() - (-e * un)) <= kTierImpulseAlgebra * scale);
      CHECK(c.un() < 0.0);  // still approaching, at |e| times the speed
    }
  }
}

TEST_CASE_TEMPLATE("a restitution outside the interval from -1 to 1 is rejected", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  RandomSource random(230 + D);
  const PairContact<D> c = testing::randomApproachingContact<D>(random);
  const Mat<D> K = c.K();
  const Vec<D> u = c.relative();
  for (const double bad : {1.0 + 1e-9, -1.0 - 1e-9, 2.0, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
    CAPTURE(bad);
    // Rejected whether or not the contact approaches: the check does not depend on state.
    CHECK_THROWS_AS(frictionlessImpulse<D>(K, u, c.n, bad), std::invalid_argument);
    CHECK_THROWS_AS(frictionlessImpulse<D>(K, Vec<D>(-u), c.n, bad), std::invalid_argument);
    try {
      frictionlessImpulse<D>(K, u, c.n, bad);
    } catch (const std::invalid_argument& error) {
      CHECK(std::string(error.what()).find("restitution e must be in [-1, 1]") !=
            std::string::npos);
    }
  }
  CHECK_NOTHROW(frictionlessImpulse<D>(K, u, c.n, 1.0));
  CHECK_NOTHROW(frictionlessImpulse<D>(K, u, c.n, -1.0));
}

// [test_static_partner]
TEST_CASE_TEMPLATE("a static partner is untouched and the dynamic body reaches -e u_n", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  RandomSource random(240 + D);
  for (const bool staticIsA : {false, true}) {
    for (const double e : {0.0, 0.3, 1.0}) {
      for (int trial = 0; trial < 100; ++trial) {
        CAPTURE(staticIsA);
        CAPTURE(e);
        CAPTURE(trial);
        PairContact<D> c = testing::randomApproachingContact<D>(random);
        RigidBody<D>& fixed = staticIsA ? c.a : c.b;
        RigidBody<D>& moving = staticIsA ? c.b : c.a;
        const Vec<D> rMoving = staticIsA ? c.rb : c.ra;
        fixed = makeStaticBody<D>(fixed.position, fixed.orientation);
        fixed.velocity = random.vector<D>(-1.0, 1.0);  // a moving (kinematic) wall is allowed
        if (c.un() > 0.0) {
          testing::reverseMotion<D>(moving);
          fixed.velocity = -fixed.velocity;
        }
        if (c.un() == 0.0) continue;
        const RigidBody<D> fixedBefore = fixed;
        const double un = c.un();
        const Mat<D> K = c.K();
        CHECK_EIGEN_NEAR(K, collisionMatrix<D>(moving, rMoving), kTierImpulseAlgebra);  // K_static = 0
        const double keBefore = moving.kineticEnergy();

        const ContactImpulse<D> impulse = frictionlessImpulse<D>(K, c.relative(), c.n, e);
        REQUIRE(impulse.branch == ImpulseBranch::Frictionless);
        applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, impulse.j);

        CHECK(fixed.velocity == fixedBefore.velocity);  // bit for bit
        CHECK(fixed.angularMomentum == fixedBefore.angularMomentum);
        CHECK(fixed.angularVelocity == fixedBefore.angularVelocity);
        const double scale = testing::pointVelocityScale<D>(c) + std::abs(un);
        CHECK(std::abs(c.un() - (-e * un)) <= kTierImpulseAlgebra * scale);
        // Eq. (2.7) is the energy change seen from the wall. A moving wall also does the work
        // (impulse on the moving body) . (wall velocity), which here is j . u_b or -j . u_a.
        const double closedForm = -(1.0 - e * e) * un * un / (2.0 * c.n.dot(K * c.n));
        const Vec<D> onMoving = staticIsA ? Vec<D>(-impulse.j) : impulse.j;
        const double wallWork = onMoving.dot(fixed.velocity);
        const double energyScale = keBefore + std::abs(wallWork) + std::abs(closedForm);
        CHECK(std::abs(moving.kineticEnergy() - keBefore - (closedForm + wallWork)) <=
              kTierImpulseAlgebra * energyScale);
      }
    }
  }
}
// [test_static_partner]

// [test_two_static_bodies]
TEST_CASE_TEMPLATE("two static bodies get no impulse and no NaN", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(250 + D);
  RigidBody<D> a = makeStaticBody<D>(random.vector<D>(-1.0, 1.0), random.orientation<D>());
  RigidBody<D> b = makeStaticBody<D>(random.vector<D>(-1.0, 1.0), random.orientation<D>());
  const Vec<D> n = random.unitVector<D>();
  a.velocity = -2.0 * n;  // two kinematic bodies driven into each other
  b.velocity = 3.0 * n;
  const Vec<D> p = random.vector<D>(-1.0, 1.0);
  const Vec<D> ra = p - a.position, rb = p - b.position;
  const Mat<D> K = pairCollisionMatrix<D>(a, ra, b, rb);
  CHECK(K == Mat<D>::Zero());
  const Vec<D> u = relativeVelocity<D>(a, ra, b, rb);
  REQUIRE(u.dot(n) < 0.0);  // approaching: the formula would divide 0 by 0
  for (const double e : {0.0, 0.3, 1.0}) {
    const ContactImpulse<D> impulse = frictionlessImpulse<D>(K, u, n, e);
    CHECK(impulse.branch == ImpulseBranch::Immovable);
    CHECK(impulse.j == Vec<D>::Zero());
    CHECK(impulse.j.allFinite());
  }
}
// [test_two_static_bodies]

TEST_CASE_TEMPLATE("a pinned body struck through its pin is immovable and struck off it turns", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(260 + D);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    // A wheel on a fixed axle: no translation (1/m = 0) but free rotation.
    RigidBody<D> wheel = random.dynamicBody<D>();
    wheel.inverseMass = 0.0;
    wheel.velocity.setZero();
    wheel.setAngularVelocity(AngVec<D>::Zero());
    RigidBody<D> wall = makeStaticBody<D>();
    const Vec<D> n = random.unitVector<D>();
    wall.velocity = n;  // the wall moves toward the wheel: u_n = -1
    // Through the pin: r parallel to n, so r x n = 0 and n^T K n = 0 although K != 0.
    const Vec<D> rThrough = 0.7 * n;
    const Mat<D> K = pairCollisionMatrix<D>(wheel, rThrough, wall, Vec<D>(Vec<D>::Zero()));
    CHECK(K.trace() > 0.0);
    const Vec<D> u = relativeVelocity<D>(wheel, rThrough, wall, Vec<D>(Vec<D>::Zero()));
    const ContactImpulse<D> through = frictionlessImpulse<D>(K, u, n, 0.5);
    CHECK(through.branch == ImpulseBranch::Immovable);
    CHECK(through.j == Vec<D>::Zero());
    // Off the pin the same wheel turns away and the contact leaves at -e u_n.
    const Vec<D> rOff = rThrough + 0.4 * random.unitVector<D>();
    const Mat<D> Koff = pairCollisionMatrix<D>(wheel, rOff, wall, Vec<D>(Vec<D>::Zero()));
    const Vec<D> uOff = relativeVelocity<D>(wheel, rOff, wall, Vec<D>(Vec<D>::Zero()));
    if (cross<D>(rOff, n).norm() < 0.05) continue;  // too close to the pin line
    const ContactImpulse<D> off = frictionlessImpulse<D>(Koff, uOff, n, 0.5);
    REQUIRE(off.branch == ImpulseBranch::Frictionless);
    applyPairImpulse<D>(wheel, rOff, wall, Vec<D>(Vec<D>::Zero()), off.j);
    const double unAfter = relativeVelocity<D>(wheel, rOff, wall, Vec<D>(Vec<D>::Zero())).dot(n);
    CHECK(unAfter == testing::tierOne(0.5));
    CHECK(wheel.velocity == Vec<D>::Zero());  // the axle holds
  }
}

// [test_tangential_unchanged]
TEST_CASE_TEMPLATE("tangential velocity is unchanged when the contact line joins both centres",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(270 + D);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    PairContact<D> c = testing::randomApproachingContact<D>(random);
    // Put the contact on the segment between the centres, with n along it (b toward a).
    const Vec<D> ab = c.a.position - c.b.position;
    c.n = ab.normalized();
    c.p = c.b.position + random.uniform(0.2, 0.8) * ab;
    c.ra = c.p - c.a.position;
    c.rb = c.p - c.b.position;
    if (c.un() > 0.0) {
      testing::reverseMotion<D>(c.a);
      testing::reverseMotion<D>(c.b);
    }
    const Mat<D> K = c.K();
    // r x n = 0 for both bodies, so n is an eigenvector of K: K n = (1/m_a + 1/m_b) n.
    const double reduced = c.a.inverseMass + c.b.inverseMass;
    CHECK_EIGEN_NEAR(Vec<D>(K * c.n), Vec<D>(reduced * c.n), 1e-12);
    const Vec<D> u = c.relative();
    const Vec<D> ut = u - u.dot(c.n) * c.n;
    const double scaleBefore = testing::pointVelocityScale<D>(c);
    applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, frictionlessImpulse<D>(K, u, c.n, 0.3).j);
    const Vec<D> uAfter = c.relative();
    const Vec<D> utAfter = uAfter - uAfter.dot(c.n) * c.n;
    const double scale = std::max(scaleBefore, testing::pointVelocityScale<D>(c));
    CHECK((utAfter - ut).norm() <= kTierImpulseAlgebra * scale);
  }
}
// [test_tangential_unchanged]

}  // TEST_SUITE
