// Chapter 3: the sticking trial, the cone test, the solve of K j = b, and the energy rule
// for a sticking impulse (Eqs. (3.1)-(3.3), (3.8), (3.9)).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "ch03/friction_fixtures.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::Partner;
using stackbook::testing::RandomSource;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
using LongVec3 = Eigen::Matrix<long double, 3, 1>;
using LongMat3 = Eigen::Matrix<long double, 3, 3>;

/// A body with principal moments (1, 1, 1e-8), mass 1, turned at random, touched at a
/// lever arm of 1 in a random direction (hard case B12): cond(K) is about 1e8.
testing::PairContact<3> illConditionedContact(RandomSource& random) {
  testing::PairContact<3> c;
  c.a = makeDynamicBody<3>(1.0, Vec3(1.0, 1.0, 1e-8));
  c.a.orientation = random.orientation<3>();
  c.a.syncAngularVelocity();
  c.b = makeStaticBody<3>();
  c.ra = random.unitVector<3>();
  c.rb = c.a.position + c.ra;
  c.n = random.unitVector<3>();
  c.setRelativeVelocity(Vec3(-random.uniform(0.1, 1.0) * c.n +
                             random.uniform(0.0, 1.0) * testing::randomTangent<3>(random, c.n)));
  return c;
}

/// K^{-1} b in long double (64-bit mantissa), refined once: the reference solution.
LongVec3 extendedSolve(const Mat3& K, const Vec3& b) {
  const LongMat3 KL = K.cast<long double>();
  const LongVec3 bL = b.cast<long double>();
  const Eigen::LDLT<LongMat3> ldlt(KL);
  LongVec3 x = ldlt.solve(bL);
  x += ldlt.solve(LongVec3(bL - KL * x));
  return x;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_sticking_target]
TEST_CASE_TEMPLATE("a sticking impulse leaves the contact moving at exactly -e u_n n", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  RandomSource random(301 + D);
  int sticking = 0;
  for (int trial = 0; trial < 600; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 3), random.uniform(0.0, 2.0));
    const double e = (trial % 3) * 0.5;
    const Vec<D> u = c.u();
    const ContactImpulse<D> r = frictionalImpulse<D>(c.K(), u, c.n, e, 1e6);
    if (r.branch != ImpulseBranch::Sticking) continue;  // sticking would need a pull
    ++sticking;
    // Measured on the bodies, not through K: the contact velocity after the impulse.
    const Vec<D> target = -r.restitution * u.dot(c.n) * c.n;  // Eq. (3.1)
    CHECK_EIGEN_NEAR(c.after(r.j).u(), target, 0.0, 1e-12 * (u.norm() + target.norm()));
    // The same impulse as an explicit inverse gives (Eq. (3.2)).
    CHECK_EIGEN_NEAR(r.j, testing::stickingReference<D>(c.K(), u, c.n, r.restitution), 1e-10);
  }
  CHECK(sticking > 400);
}
// [test_sticking_target]

TEST_CASE_TEMPLATE("the sticking trial is accepted exactly when it lies inside the cone", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  RandomSource random(311 + D);
  int inside = 0, outside = 0;
  for (int trial = 0; trial < 800; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 3), random.logUniform(1e-3, 3.0));
    const double mu = random.uniform(0.05, 1.5);
    const Vec<D> u = c.u();
    const ContactImpulse<D> r = frictionalImpulse<D>(c.K(), u, c.n, 0.3, mu);
    // The trial uses min(e, e_max) (Eq. (3.9)); computed here from the closed form.
    const double eTrial = std::min(0.3, testing::eMaxReference<D>(c.K(), u, c.n));
    const Vec<D> jStar = testing::stickingReference<D>(c.K(), u, c.n, eTrial);
    const double jn = jStar.dot(c.n);
    const double jt = testing::tangentialPart<D>(jStar, c.n).norm();
    if (std::abs(jt - mu * jn) <= 1e-9 * jStar.norm()) continue;  // on the cone: either is right
    const bool inCone = jn > 0.0 && jt <= mu * jn;  // Eq. (3.3)
    CHECK((r.branch == ImpulseBranch::Sticking) == inCone);
    inside += inCone;
    outside += !inCone;
  }
  CHECK(inside > 100);
  CHECK(outside > 100);
}

// [test_cone_norm]
TEST_CASE("the cone test compares the norm of the tangential impulse and not its components") {
  // A point mass (K = identity) hitting the floor with u = (0.8, 0.8, -1), e = 0:
  // j* = (-0.8, -0.8, 1). Each tangential component 0.8 is below mu j_n = 1, but
  // |j*_t| = 0.8 sqrt(2) = 1.13 is not: the contact must slide (erratum 2 of the notes).
  const Mat3 K = Mat3::Identity();
  const Vec3 u(0.8, 0.8, -1.0), n = Vec3::UnitZ();
  const ContactImpulse<3> r = frictionalImpulse<3>(K, u, n, 0.0, 1.0);
  CHECK(r.branch == ImpulseBranch::Sliding);
  // Sliding along -u_t/|u_t| with |j_t| = mu j_n = 1: j = (-1/sqrt 2, -1/sqrt 2, 1).
  CHECK_EIGEN_NEAR(r.j, Vec3(-std::sqrt(0.5), -std::sqrt(0.5), 1.0), 1e-15);
  // With mu = 1.2 > 0.8 sqrt(2) it sticks and stops the contact.
  const ContactImpulse<3> s = frictionalImpulse<3>(K, u, n, 0.0, 1.2);
  CHECK(s.branch == ImpulseBranch::Sticking);
  CHECK_EIGEN_NEAR(s.j, Vec3(-0.8, -0.8, 1.0), 1e-15);
}
// [test_cone_norm]

// [test_ill_conditioned]
TEST_CASE("an ill-conditioned K is solved to one rounding of its data (B12)") {
  RandomSource random(321);
  double worstBackward = 0.0, worstResidual = 0.0, worstForward = 0.0;
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const auto c = illConditionedContact(random);
    const Mat3 K = c.K();
    const Vec3 b = random.vector<3>(-1.0, 1.0);
    Vec3 j = Vec3::Zero();
    REQUIRE(solveCollisionMatrix<3>(K, b, FrictionSettings{}, j));
    REQUIRE(j.allFinite());
    // Residual and reference in long double, so that they measure j and not themselves.
    const LongMat3 KL = K.cast<long double>();
    const LongVec3 jL = j.cast<long double>(), bL = b.cast<long double>();
    const LongVec3 residual = bL - KL * jL;
    // Normwise backward error (Rigal-Gaches): j solves exactly a system whose K and b
    // differ from the given ones by this fraction of their norms.
    const double backward = double(residual.norm() / (KL.norm() * jL.norm() + bL.norm()));
    worstBackward = std::max(worstBackward, backward);
    worstResidual = std::max(worstResidual, double(residual.norm() / bL.norm()));
    const LongVec3 exact = extendedSolve(K, b);
    worstForward = std::max(worstForward, double((jL - exact).norm() / exact.norm()));
  }
  MESSAGE("B12 worst: backward ", worstBackward, ", |Kj - b|/|b| ", worstResidual,
          ", forward ", worstForward);
  const double kappa = 1e8;  // cond(K) for moments (1, 1, 1e-8) at a lever arm of 1
  CHECK(worstBackward <= 2.0 * kEps);          // one rounding of the data
  CHECK(worstResidual <= 10.0 * kappa * kEps); // what a double j can achieve: ~kappa eps
  CHECK(worstForward <= 10.0 * kappa * kEps);  // the conditioning bound
}
// [test_ill_conditioned]

TEST_CASE("an ill-conditioned contact decides stick or slide as an extended-precision solve does") {
  RandomSource random(322);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const auto c = illConditionedContact(random);
    const Mat3 K = c.K();
    const Vec3 u = c.u(), n = c.n;
    const double un = u.dot(n);
    // The exact sticking trial for e = 0, and a mu 1 % away from its threshold.
    const LongVec3 jStar = extendedSolve(K, Vec3(-u));
    const double jn = double(jStar.dot(n.cast<long double>()));
    const double jt = double((jStar - jStar.dot(n.cast<long double>()) * n.cast<long double>()).norm());
    if (!(jn > 0.0)) continue;
    const double muThreshold = jt / jn;
    for (const double factor : {0.99, 1.01}) {
      const double mu = factor * muThreshold;
      const ContactImpulse<3> r = frictionalImpulse<3>(K, u, n, 0.0, mu);
      CHECK((r.branch == ImpulseBranch::Sticking) == (factor > 1.0));
      // A perturbation of u by 1e-12 of itself does not change the decision.
      const Vec3 du = 1e-12 * u.norm() * random.unitVector<3>();
      CHECK(frictionalImpulse<3>(K, Vec3(u + du), n, 0.0, mu).branch == r.branch);
      if (r.branch == ImpulseBranch::Sliding) CHECK(r.j.dot(n) > 0.0);
      CHECK(r.j.allFinite());
      ++checked;
    }
    CHECK(un < 0.0);
  }
  CHECK(checked > 200);
}

// [test_energy_rod]
TEST_CASE("a sticking impulse with e = 1 that would add energy gets e_max instead (B11)") {
  // Uniform rod at 45 degrees, lower end on the floor, u = (0.5, -1), e = 1, mu = 1.
  // K = [5/2 -3/2; -3/2 5/2], K^{-1} = [5/8 3/8; 3/8 5/8]. Eq. (3.9):
  // u^T K^{-1} u = 13/32 and u_n^2 n^T K^{-1} n = 5/8, so e_max^2 = 13/20.
  const auto c = testing::rodOnFloor(0.25 * M_PI, Vec2(0.5, -1.0));
  const Mat2 K = c.K();
  Mat2 expectedK;
  expectedK << 2.5, -1.5, -1.5, 2.5;
  CHECK_EIGEN_NEAR(K, expectedK, 1e-15);
  const Vec2 u = c.u();
  const double kineticEnergy = c.kineticEnergy();  // 0.625 J: omega = 0, |v| = |u|
  CHECK(kineticEnergy == doctest::Approx(0.625).epsilon(1e-15));

  // The impulse Eq. (3.2) asks for with e = 1 would create (5/8 - 13/32)/2 = 7/64 J (Eq. (3.8)).
  const Vec2 greedy = testing::stickingReference<2>(K, u, c.n, 1.0);
  CHECK(impulseEnergyChange<2>(K, u, greedy) == doctest::Approx(7.0 / 64.0).epsilon(1e-13));

  const ContactImpulse<2> r = frictionalImpulse<2>(K, u, c.n, 1.0, 1.0);
  CHECK(r.branch == ImpulseBranch::Sticking);
  CHECK(r.restitutionLowered);
  CHECK(r.restitution == doctest::Approx(std::sqrt(13.0 / 20.0)).epsilon(1e-14));
  // On the bodies: the contact leaves at e_max |u_n| with no slip, and the energy is kept.
  const auto after = c.after(r.j);
  CHECK_EIGEN_NEAR(after.u(), Vec2(0.0, std::sqrt(13.0 / 20.0)), 0.0, 1e-14);
  CHECK(std::abs(after.kineticEnergy() - kineticEnergy) <= 1e-12 * kineticEnergy);
}
// [test_energy_rod]

TEST_CASE_TEMPLATE("the restitution a sticking impulse uses is min(e e_max) of Eq. (3.9)", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(331 + D);
  int lowered = 0, kept = 0;
  for (int trial = 0; trial < 800; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 3), random.logUniform(1e-3, 3.0));
    const double e = trial % 4 == 0 ? -0.9 : random.uniform(0.7, 1.0);  // also the e < 0 of chapter 8
    CAPTURE(e);
    const Vec<D> u = c.u();
    const ContactImpulse<D> r = frictionalImpulse<D>(c.K(), u, c.n, e, 1e6);
    if (r.branch != ImpulseBranch::Sticking) continue;
    const double eMax = testing::eMaxReference<D>(c.K(), u, c.n);
    if (std::abs(std::abs(e) - eMax) <= 1e-9) continue;  // at the boundary either is right
    if (r.restitutionLowered) {
      ++lowered;
      CHECK(eMax < std::abs(e));
      CHECK(r.restitution == doctest::Approx(std::copysign(eMax, e)).epsilon(1e-10));
      // Eq. (3.9) makes Delta KE exactly zero.
      CHECK(std::abs(impulseEnergyChange<D>(c.K(), u, r.j)) <= 1e-12 * c.kineticEnergy() + 1e-15);
    } else {
      ++kept;
      CHECK(eMax > std::abs(e));
      CHECK(r.restitution == e);
    }
    CHECK(impulseEnergyChange<D>(c.K(), u, r.j) <= 1e-12 * c.kineticEnergy() + 1e-15);
  }
  CHECK(lowered > 20);
  CHECK(kept > 20);
}

TEST_CASE_TEMPLATE("a contact with no tangential velocity and enough friction stops dead", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  RandomSource random(341 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 3), 0.0);
    const Vec<D> u = c.u();
    REQUIRE(testing::tangentialPart<D>(u, c.n).norm() <= 1e-14 * u.norm());
    const Vec<D> jStar = testing::stickingReference<D>(c.K(), u, c.n, 0.5);
    const double ratio = testing::tangentialPart<D>(jStar, c.n).norm() / jStar.dot(c.n);
    if (!(jStar.dot(c.n) > 0.0)) continue;
    const ContactImpulse<D> r = frictionalImpulse<D>(c.K(), u, c.n, 0.5, 1.01 * ratio);
    CHECK(r.branch == ImpulseBranch::Sticking);
    CHECK(!r.restitutionLowered);  // with u_t = 0, e_max = 1 (Eq. (3.9))
    CHECK_EIGEN_NEAR(c.after(r.j).u(), Vec<D>(-0.5 * u.dot(c.n) * c.n), 0.0, 1e-12 * u.norm());
  }
}

}  // TEST_SUITE
