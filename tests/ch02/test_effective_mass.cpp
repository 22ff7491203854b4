// Chapter 2: the normal compliance n^T K n and the effective mass 1/(n^T K n) (Eq. (2.4)),
// the reduction to the textbook two-body collision (Eq. (2.8)), and the validation cases
// A6 (1D collisions) and A7 (an off-centre 2D impact), with exact fractions derived by hand.
#include <cmath>

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

namespace {

// Two bodies on a line along the unit vector d: body a (mass m1) behind, body b (mass m2)
// ahead, touching at a point on the segment between their centres. Body a moves at v1
// along d, body b at v2. Orientations and inertias are random; so are the spins and the
// sideways velocities when `dressed` is true. The normal n = -d points from b toward a.
template <int D>
PairContact<D> headOnPair(RandomSource& random, double m1, double m2, double v1, double v2,
                          bool dressed) {
  const Vec<D> d = random.unitVector<D>();
  RigidBody<D> a = makeDynamicBody<D>(m1, random.principalInertia<D>(m1));
  RigidBody<D> b = makeDynamicBody<D>(m2, random.principalInertia<D>(m2));
  a.orientation = random.orientation<D>();
  b.orientation = random.orientation<D>();
  b.position = random.vector<D>(-2.0, 2.0);
  a.position = b.position - random.uniform(1.0, 3.0) * d;
  const Vec<D> p = b.position - random.uniform(0.2, 0.9) * d;
  a.velocity = v1 * d;
  b.velocity = v2 * d;
  if (dressed) {
    for (RigidBody<D>* body : {&a, &b}) {
      const Vec<D> w = random.vector<D>(-2.0, 2.0);
      body->velocity += w - w.dot(d) * d;  // sideways motion, normal to d
      body->setAngularVelocity(random.angularVector<D>(-3.0, 3.0));
    }
  } else {
    a.syncAngularVelocity();
    b.syncAngularVelocity();
  }
  return PairContact<D>{a, b, p, Vec<D>(-d), Vec<D>(p - a.position), Vec<D>(p - b.position)};
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("n^T K n is the inverse masses plus (r x n)^T I^-1 (r x n) of each body", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(400 + D);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const PairContact<D> c = testing::randomApproachingContact<D>(random);
    double expected = c.a.inverseMass + c.b.inverseMass;  // Eq. (2.4)
    for (const auto& [body, r] : {std::pair{&c.a, c.ra}, std::pair{&c.b, c.rb}}) {
      const AngVec<D> rxn = cross<D>(r, c.n);
      expected += rxn.dot(body->inverseInertiaWorld() * rxn);
    }
    CHECK(c.n.dot(c.K() * c.n) == testing::tierOne(expected));
  }
}

// [test_textbook_collision]
TEST_CASE_TEMPLATE("a contact through both centres reproduces the textbook two-body collision",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(410 + D);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const double m1 = random.logUniform(0.01, 100.0), m2 = random.logUniform(0.01, 100.0);
    const double v2 = random.uniform(-2.0, 2.0), v1 = v2 + random.uniform(0.1, 4.0);
    const double e = random.uniform(0.0, 1.0);
    PairContact<D> c = headOnPair<D>(random, m1, m2, v1, v2, /*dressed=*/true);
    const Vec<D> d = -c.n;
    const RigidBody<D> a0 = c.a, b0 = c.b;
    // The effective mass of a central contact is the reduced mass m1 m2 / (m1 + m2).
    CHECK(1.0 / c.n.dot(c.K() * c.n) ==
          testing::tierOne(m1 * m2 / (m1 + m2)));
    applyPairImpulse<D>(c.a, c.ra, c.b, c.rb,
                        frictionlessImpulse<D>(c.K(), c.relative(), c.n, e).j);
    // Eq. (2.8), written independently of K.
    const double v1After = (m1 * v1 + m2 * v2 - m2 * e * (v1 - v2)) / (m1 + m2);
    const double v2After = (m1 * v1 + m2 * v2 + m1 * e * (v1 - v2)) / (m1 + m2);
    CHECK_EIGEN_NEAR(c.a.velocity, Vec<D>(a0.velocity + (v1After - v1) * d), kTierImpulseAlgebra);
    CHECK_EIGEN_NEAR(c.b.velocity, Vec<D>(b0.velocity + (v2After - v2) * d), kTierImpulseAlgebra);
    // The impulse passes through both centres: no torque, spins unchanged.
    CHECK_EIGEN_NEAR(c.a.angularMomentum, a0.angularMomentum, kTierImpulseAlgebra);
    CHECK_EIGEN_NEAR(c.b.angularMomentum, b0.angularMomentum, kTierImpulseAlgebra);
  }
}
// [test_textbook_collision]

// [test_validation_a6]
TEST_CASE_TEMPLATE("A6 masses 1 and 3 meeting at 4 and 0 with e = 0.5 leave at -1/2 and 3/2", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(420 + D);
  PairContact<D> c = headOnPair<D>(random, 1.0, 3.0, 4.0, 0.0, /*dressed=*/false);
  const Vec<D> d = -c.n;
  CHECK(c.a.kineticEnergy() + c.b.kineticEnergy() == testing::tierOne(8.0));
  applyPairImpulse<D>(c.a, c.ra, c.b, c.rb,
                      frictionlessImpulse<D>(c.K(), c.relative(), c.n, 0.5).j);
  // By hand: reduced mass 3/4, j_n = (1 + 1/2)(3/4) 4 = 9/2; v1' = 4 - 9/2, v2' = (9/2)/3.
  CHECK_EIGEN_NEAR(c.a.velocity, Vec<D>(-0.5 * d), kTierImpulseAlgebra);
  CHECK_EIGEN_NEAR(c.b.velocity, Vec<D>(1.5 * d), kTierImpulseAlgebra);
  // KE 8 -> 1/8 + 27/8 = 7/2: the loss 9/2 is (1 - e^2) (3/4) 4^2 / 2 of Eq. (2.7).
  CHECK(c.a.kineticEnergy() + c.b.kineticEnergy() == testing::tierOne(3.5));
}

TEST_CASE_TEMPLATE("A6 an elastic 1 to 1000 collision leaves at -999/1001 and 2/1001", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  RandomSource random(430 + D);
  PairContact<D> c = headOnPair<D>(random, 1.0, 1000.0, 1.0, 0.0, /*dressed=*/false);
  const Vec<D> d = -c.n;
  applyPairImpulse<D>(c.a, c.ra, c.b, c.rb,
                      frictionlessImpulse<D>(c.K(), c.relative(), c.n, 1.0).j);
  CHECK_EIGEN_NEAR(c.a.velocity, Vec<D>((-999.0 / 1001.0) * d), kTierImpulseAlgebra);
  CHECK_EIGEN_NEAR(c.b.velocity, Vec<D>((2.0 / 1001.0) * d), kTierImpulseAlgebra);
  CHECK(c.a.kineticEnergy() + c.b.kineticEnergy() == testing::tierOne(0.5));
}
// [test_validation_a6]

// [test_validation_a7]
TEST_CASE_TEMPLATE("A7 an off-centre elastic hit on a box keeps momentum and energy exactly", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  // Box (body a): 1 x 1 (x 1), m = 2, I = m (1 + 1) / 12 = 1/3 about z, at rest at the origin.
  // Disk or ball (body b): m = 1 at (-1, 0.3) moving at (2, 0); it is hit through its centre,
  // so its moment of inertia never enters. n = +x points from b into a.
  AngVec<D> boxInertia, ballInertia;
  boxInertia.setConstant(1.0 / 3.0);
  ballInertia.setConstant(D == 2 ? 0.125 : 0.1);  // disk m r^2 / 2, ball 2 m r^2 / 5, r = 0.5
  RigidBody<D> box = makeDynamicBody<D>(2.0, boxInertia);
  RigidBody<D> ball = makeDynamicBody<D>(1.0, ballInertia);
  ball.position.setZero();
  ball.position.template head<2>() << -1.0, 0.3;
  ball.velocity.setZero();
  ball.velocity[0] = 2.0;
  Vec<D> p = Vec<D>::Zero(), n = Vec<D>::Zero(), x = Vec<D>::Zero(), y = Vec<D>::Zero();
  p.template head<2>() << -0.5, 0.3;
  n[0] = 1.0;
  x[0] = 1.0;
  y[1] = 1.0;
  PairContact<D> c{box, ball, p, n, p - box.position, p - ball.position};
  const Vec<D> origin = Vec<D>::Zero();
  auto zOf = [](const AngVec<D>& w) { return w[kAngularDim<D> - 1]; };  // the z component

  const Vec<D> momentumBefore = testing::linearMomentum<D>(c.a, c.b);
  const double lzBefore = zOf(testing::angularMomentumAbout<D>(c.a, origin) +
                              testing::angularMomentumAbout<D>(c.b, origin));
  const double keBefore = c.a.kineticEnergy() + c.b.kineticEnergy();
  CHECK_EIGEN_NEAR(momentumBefore, Vec<D>(2.0 * x), kTierImpulseAlgebra);
  CHECK(lzBefore == testing::tierOne(-0.6));  // (x - o) x m v = -0.3 * 2
  CHECK(keBefore == testing::tierOne(2.0));

  // By hand: r_a x n = -r_y = -0.3, so n^T K n = 1/2 + 1 + 0.09 * 3 = 177/100 (Eq. (2.4)),
  // and j_n = (1 + 1) * 2 / (177/100) = 400/177 (Eq. (2.3)).
  const Mat<D> K = c.K();
  CHECK(n.dot(K * n) == testing::tierOne(177.0 / 100.0));
  const ContactImpulse<D> impulse = frictionlessImpulse<D>(K, c.relative(), n, 1.0);
  REQUIRE(impulse.branch == ImpulseBranch::Frictionless);
  CHECK(impulse.normal(n) == testing::tierOne(400.0 / 177.0));
  applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, impulse.j);

  // v_box = j/2 = 200/177, w_box = 3 (-0.3) j = -120/59, v_ball = 2 - j = -46/177, w_ball = 0.
  CHECK_EIGEN_NEAR(c.a.velocity, Vec<D>((200.0 / 177.0) * x), kTierImpulseAlgebra);
  CHECK(zOf(c.a.angularVelocity) == testing::tierOne(-120.0 / 59.0));
  CHECK(c.a.angularVelocity.norm() == testing::tierOne(120.0 / 59.0));
  CHECK_EIGEN_NEAR(c.b.velocity, Vec<D>((-46.0 / 177.0) * x), kTierImpulseAlgebra);
  CHECK(c.b.angularVelocity.norm() == 0.0);

  // P, L_z about the origin and KE are what they were.
  CHECK_EIGEN_NEAR(testing::linearMomentum<D>(c.a, c.b), momentumBefore, kTierImpulseAlgebra);
  const double lzAfter = zOf(testing::angularMomentumAbout<D>(c.a, origin) +
                             testing::angularMomentumAbout<D>(c.b, origin));
  CHECK(lzAfter == testing::tierOne(-0.6));
  CHECK(c.a.kineticEnergy() + c.b.kineticEnergy() == testing::tierOne(2.0));

  // The normal velocity is reversed, and the box's spin gives the contact a tangential
  // velocity it did not have: u' = (2, 180/177). Frictionless is not "tangent-preserving".
  CHECK_EIGEN_NEAR(c.relative(), Vec<D>(2.0 * x + (180.0 / 177.0) * y), kTierImpulseAlgebra);
}
// [test_validation_a7]

}  // TEST_SUITE
