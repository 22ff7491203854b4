// Chapter 1: the collision matrix K (Eqs. (1.8)-(1.10)) and what follows from its form.
#include <cmath>
#include <limits>

#include <doctest/doctest.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "stackbook/impulse/collision_matrix.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::kEps;
using stackbook::testing::kTierImpulseAlgebra;
using stackbook::testing::RandomSource;

namespace {

/// Eigenvalues of a symmetric matrix, ascending.
template <int D>
Vec<D> eigenvalues(const Mat<D>& K) {
  return Eigen::SelfAdjointEigenSolver<Mat<D>>(K, Eigen::EigenvaluesOnly).eigenvalues();
}

/// A random contact: two bodies (b static when asked) and a common world point p.
template <int D>
struct RandomContact {
  RigidBody<D> a, b;
  Vec<D> ra, rb;
};

template <int D>
RandomContact<D> randomContact(RandomSource& random, bool staticB) {
  RandomContact<D> c;
  c.a = random.dynamicBody<D>();
  c.b = staticB ? makeStaticBody<D>(random.vector<D>(-3.0, 3.0), random.orientation<D>())
                : random.dynamicBody<D>();
  const Vec<D> p = random.vector<D>(-3.0, 3.0);
  c.ra = p - c.a.position;
  c.rb = p - c.b.position;
  return c;
}

/// Every field of the state, compared bit for bit.
template <int D>
bool sameState(const RigidBody<D>& x, const RigidBody<D>& y) {
  bool sameOrientation;
  if constexpr (D == 2) {
    sameOrientation = x.orientation.angle() == y.orientation.angle();
  } else {
    sameOrientation = x.orientation.coeffs() == y.orientation.coeffs();
  }
  return sameOrientation && x.position == y.position && x.velocity == y.velocity && x.angularMomentum == y.angularMomentum &&
         x.angularVelocity == y.angularVelocity;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_k_matches_impulse]
TEST_CASE_TEMPLATE("K j equals the change in relative point velocity from applying +j and -j",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(101 + D);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    RigidBody<D> a = random.dynamicBody<D>();
    RigidBody<D> b = random.dynamicBody<D>();
    const Vec<D> p = random.vector<D>(-3.0, 3.0);
    const Vec<D> ra = p - a.position, rb = p - b.position;
    const Vec<D> j = random.vector<D>(-5.0, 5.0);
    const Vec<D> before = relativeVelocity<D>(a, ra, b, rb);
    const Mat<D> K = pairCollisionMatrix<D>(a, ra, b, rb);
    applyPairImpulse<D>(a, ra, b, rb, j);
    const Vec<D> after = relativeVelocity<D>(a, ra, b, rb);
    CHECK_EIGEN_NEAR(Vec<D>(after - before), Vec<D>(K * j), 1e-12);  // Eq. (1.10)
  }
}
// [test_k_matches_impulse]

// [test_k_closed_form]
TEST_CASE_TEMPLATE("K has the closed form of a diagonal inertia in the principal frame",
                   Dim, In2D, In3D) {
  // Written out without crossMatrix: with r_b = R^T r = (x, y, z) and the inverse
  // moments (a, b, c), r_b*^T diag(a, b, c) r_b* is the matrix S below, and
  // K = R (delta/m + S) R^T. In 2D this is the notes' formula
  // K = delta/m + (1/I) [r_y^2, -r_x r_y; -r_x r_y, r_x^2], whatever the rotation.
  constexpr int D = Dim::value;
  RandomSource random(41 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const RigidBody<D> body = random.dynamicBody<D>();
    const Vec<D> r = random.vector<D>(-2.0, 2.0);
    Mat<D> expected;
    if constexpr (D == 2) {
      const double x = r.x(), y = r.y(), c = body.inverseInertia[0];
      expected << y * y, -x * y, -x * y, x * x;
      expected = body.inverseMass * Mat2::Identity() + c * expected;
    } else {
      const Mat3 R = body.orientation.toRotationMatrix();
      const Vec3 rb = R.transpose() * r;
      const double x = rb.x(), y = rb.y(), z = rb.z();
      const double a = body.inverseInertia[0], b = body.inverseInertia[1],
                   c = body.inverseInertia[2];
      Mat3 S;
      S << b * z * z + c * y * y, -c * x * y, -b * x * z,
           -c * x * y, a * z * z + c * x * x, -a * y * z,
           -b * x * z, -a * y * z, a * y * y + b * x * x;
      expected = R * (body.inverseMass * Mat3::Identity() + S) * R.transpose();
    }
    CHECK_EIGEN_NEAR(collisionMatrix<D>(body, r), expected, kTierImpulseAlgebra);  // Eq. (1.8)
  }
}
// [test_k_closed_form]

TEST_CASE_TEMPLATE("K is symmetric to rounding and K_T exactly", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(43 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const RandomContact<D> c = randomContact<D>(random, trial % 4 == 0);
    const Mat<D> Ka = collisionMatrix<D>(c.a, c.ra);
    // Assembled in floating point, r*^T I^{-1} r* is symmetric only to rounding ...
    CHECK_EIGEN_NEAR(Ka, Mat<D>(Ka.transpose()), 16 * kEps);
    // ... so the pair matrix is symmetrised, bit for bit, as LDL^T factorisations assume.
    const Mat<D> K = pairCollisionMatrix<D>(c.a, c.ra, c.b, c.rb);
    CHECK(K == K.transpose());
  }
}

// [test_k_eigenvalues]
TEST_CASE_TEMPLATE("every eigenvalue of K_T is at least the sum of the inverse masses",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(47 + D);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const RandomContact<D> c = randomContact<D>(random, trial % 4 == 0);
    const Mat<D> K = pairCollisionMatrix<D>(c.a, c.ra, c.b, c.rb);
    const Vec<D> lambda = eigenvalues<D>(K);
    const double sumInverseMass = c.a.inverseMass + c.b.inverseMass;
    CAPTURE(lambda.transpose());
    // A symmetric eigensolver is accurate to a few eps times the largest eigenvalue.
    CHECK(lambda[0] >= sumInverseMass - 16 * kEps * lambda[D - 1]);
  }
}
// [test_k_eigenvalues]

TEST_CASE_TEMPLATE("an impulse along r through the centre of mass meets the full mass: K r = r/m",
                   Dim, In2D, In3D) {
  // The bound of the previous test is attained: r is an eigenvector with eigenvalue 1/m.
  constexpr int D = Dim::value;
  RandomSource random(53 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const RigidBody<D> body = random.dynamicBody<D>();
    const Vec<D> r = random.vector<D>(-2.0, 2.0);
    const Mat<D> K = collisionMatrix<D>(body, r);
    // Rounding in the entries of K is a few eps |K|, so in K r a few eps |K| |r|.
    CHECK_EIGEN_NEAR(Vec<D>(K * r), Vec<D>(body.inverseMass * r), 0.0,
                     16 * kEps * K.norm() * r.norm());
    CHECK(eigenvalues<D>(K)[0] <= body.inverseMass + 16 * kEps * K.norm());
  }
}

// [test_k_inverse_bound]
TEST_CASE_TEMPLATE("the inverse of K_T is bounded by the reduced mass", Dim, In2D, In3D) {
  // |K_T^{-1} du| <= m_red |du| with 1/m_red = 1/m_a + 1/m_b: no velocity change needs an
  // impulse larger than the reduced mass times it. Solved with LDL^T, never an inverse.
  constexpr int D = Dim::value;
  RandomSource random(59 + D);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const RandomContact<D> c = randomContact<D>(random, trial % 4 == 0);
    const Mat<D> K = pairCollisionMatrix<D>(c.a, c.ra, c.b, c.rb);
    const double reducedMass = 1.0 / (c.a.inverseMass + c.b.inverseMass);
    const Eigen::LDLT<Mat<D>> ldlt(K);
    REQUIRE(ldlt.info() == Eigen::Success);
    REQUIRE(ldlt.isPositive());
    const Vec<D> lambda = eigenvalues<D>(K);
    const double kappa = lambda[D - 1] / lambda[0];
    const Vec<D> du = random.vector<D>(-3.0, 3.0);
    const Vec<D> j = ldlt.solve(du);
    // The solve is backward stable: its relative error is a few kappa eps.
    CHECK(j.norm() <= reducedMass * du.norm() * (1.0 + 16 * kappa * kEps));
  }
}
// [test_k_inverse_bound]

// [test_static_body]
TEST_CASE_TEMPLATE("a static body contributes nothing to K_T and impulses leave it untouched",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(61 + D);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    RandomContact<D> c = randomContact<D>(random, true);
    REQUIRE(c.b.isStatic());
    CHECK(collisionMatrix<D>(c.b, c.rb).isZero(0.0));  // Eq. (1.9), exactly
    const Mat<D> Ka = collisionMatrix<D>(c.a, c.ra);
    CHECK_EIGEN_NEAR(pairCollisionMatrix<D>(c.a, c.ra, c.b, c.rb), Ka, 8 * kEps);
    CHECK_EIGEN_NEAR(pairCollisionMatrix<D>(c.b, c.rb, c.a, c.ra), Ka, 8 * kEps);
    // Two static bodies: K_T = 0, nothing can change their relative velocity.
    CHECK(pairCollisionMatrix<D>(c.b, c.rb, c.b, c.rb).isZero(0.0));

    const RigidBody<D> staticBefore = c.b;
    RigidBody<D> alone = c.a;  // body a receiving +j with no partner at all
    const Vec<D> j = random.vector<D>(-5.0, 5.0);
    applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, j);
    alone.applyImpulse(c.ra, j);
    CHECK(sameState<D>(c.b, staticBefore));
    CHECK(sameState<D>(c.a, alone));
  }
}
// [test_static_body]

TEST_CASE_TEMPLATE("a contact at the centre of mass gives K = delta/m", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(67 + D);
  for (int trial = 0; trial < 50; ++trial) {
    CAPTURE(trial);
    const double m = random.logUniform(0.01, 100.0);
    RigidBody<D> body = makeDynamicBody<D>(m, random.principalInertia<D>(m));
    body.orientation = random.orientation<D>();
    const Mat<D> K = collisionMatrix<D>(body, Vec<D>::Zero());
    CHECK(K == Mat<D>((1.0 / m) * Mat<D>::Identity()));  // r* = 0: exactly, bit for bit
    // And an impulse there changes no angular momentum.
    body.applyImpulse(Vec<D>::Zero(), random.vector<D>(-5.0, 5.0));
    CHECK(body.angularMomentum.isZero(0.0));
  }
}

// [test_pinned_body]
TEST_CASE_TEMPLATE("a body pinned at its centre of mass has a singular K with null direction r",
                   Dim, In2D, In3D) {
  // Translation locked (1/m = 0), rotation free: K = r*^T I^{-1} r* has rank D - 1.
  // With a static partner this is K_T, and K_T^{-1} does not exist (chapter 3).
  constexpr int D = Dim::value;
  RandomSource random(79 + D);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    const RigidBody<D> body = random.dynamicBody<D>();
    const Vec<D> r = random.vector<D>(-2.0, 2.0);
    const Mat<D> K = collisionMatrix<D>(0.0, body.inverseInertiaWorld(), r);
    const Vec<D> lambda = eigenvalues<D>(K);
    CAPTURE(lambda.transpose());
    CHECK((K * r).norm() <= 16 * kEps * K.norm() * r.norm());  // no response along r
    CHECK(std::abs(lambda[0]) <= 16 * kEps * lambda[D - 1]);   // singular ...
    CHECK(lambda[1] > 1e-6 * lambda[D - 1]);                   // ... of rank D - 1 exactly
    if constexpr (D == 2) {
      // The one nonzero eigenvalue: a push across r turns the body, |r|^2 / I.
      CHECK(lambda[1] == doctest::Approx(r.squaredNorm() * body.inverseInertia[0]).epsilon(1e-12));
    }
  }
}
// [test_pinned_body]

// [test_kinetic_energy]
TEST_CASE_TEMPLATE("an impulse on a body at rest gives it the kinetic energy j^T K j / 2",
                   Dim, In2D, In3D) {
  // KE = |j|^2/(2m) + (r x j)^T I^{-1} (r x j)/2 = j^T K j / 2: K is positive
  // semidefinite because an impulse cannot take energy from a body at rest.
  constexpr int D = Dim::value;
  RandomSource random(71 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    RigidBody<D> body = random.dynamicBody<D>();
    body.velocity.setZero();
    body.setAngularVelocity(AngVec<D>::Zero());
    const Vec<D> r = random.vector<D>(-2.0, 2.0);
    const Vec<D> j = random.vector<D>(-5.0, 5.0);
    const double expected = 0.5 * j.dot(collisionMatrix<D>(body, r) * j);
    body.applyImpulse(r, j);
    CHECK(body.kineticEnergy() == doctest::Approx(expected).epsilon(kTierImpulseAlgebra));
  }
}
// [test_kinetic_energy]

TEST_CASE_TEMPLATE("K turns with the configuration: rotating body and r by Q gives Q K Q^T",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(73 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const RigidBody<D> body = random.dynamicBody<D>();
    const Vec<D> r = random.vector<D>(-2.0, 2.0);
    const Orientation<D> q = random.orientation<D>();
    const Mat<D> Q = rotationMatrix<D>(q);
    RigidBody<D> turned = body;
    turned.orientation = q * body.orientation;
    const Mat<D> K = collisionMatrix<D>(body, r);
    CHECK_EIGEN_NEAR(collisionMatrix<D>(turned, Vec<D>(Q * r)), Mat<D>(Q * K * Q.transpose()),
                     kTierImpulseAlgebra);
  }
}

}  // TEST_SUITE
