// Chapter 4: the 2D cross-product matrix, the 2D collision matrix and its place inside
// the 3D one (Eqs. (4.1)-(4.5), (4.10), (4.11)).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "ch04/planar_twins.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/planar_reduction.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::PlanarTwin;
using stackbook::testing::RandomSource;

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_cross_identities]
TEST_CASE("the 2D cross products are the z components of the 3D ones") {
  RandomSource random(401);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const Vec2 r = random.vector<2>(-3.0, 3.0), b = random.vector<2>(-3.0, 3.0);
    AngVec<2> w;
    w << random.uniform(-5.0, 5.0);
    // Eq. (4.1): r* is the row [-r_y, r_x], so r x b = r_x b_y - r_y b_x.
    CHECK(crossMatrix<2>(r)(0, 0) == -r.y());
    CHECK(crossMatrix<2>(r)(0, 1) == r.x());
    CHECK(cross<2>(r, b)[0] == doctest::Approx(r.x() * b.y() - r.y() * b.x()).epsilon(1e-12));
    // Eq. (4.2): w x r = r*^T w = w (-r_y, r_x).
    CHECK_EIGEN_NEAR(crossAngular<2>(w, r), Vec2(w[0] * Vec2(-r.y(), r.x())), 1e-12);
    // The same numbers from the 3D products of the lifted vectors.
    const Vec3 r3 = liftToSpace(r), b3 = liftToSpace(b), w3(0.0, 0.0, w[0]);
    CHECK_EIGEN_NEAR(cross<3>(r3, b3), Vec3(0.0, 0.0, cross<2>(r, b)[0]), 1e-12);
    CHECK_EIGEN_NEAR(crossAngular<3>(w3, r3), liftToSpace(crossAngular<2>(w, r)), 1e-12);
  }
}
// [test_cross_identities]

TEST_CASE("the 2D r* is the z row of the 3D r* of an in-plane offset") {
  RandomSource random(402);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const Vec2 r = random.vector<2>(-3.0, 3.0);
    const CrossMat<3> rs3 = crossMatrix<3>(liftToSpace(r));
    // Eq. (4.1): the z row restricted to the plane columns is the 2D r*.
    CHECK(rs3.block<1, 2>(2, 0) == crossMatrix<2>(r));
    // The x and y rows see the plane columns not at all: an in-plane impulse has no
    // angular component about x or y.
    CHECK(rs3.block<2, 2>(0, 0).isZero(0.0));
  }
}

TEST_CASE_TEMPLATE("r*^T r* equals r.r delta minus r r^T", Dim, In2D, In3D) {
  // The identity behind Eq. (4.4); it holds in every dimension (Eq. (4.10)).
  constexpr int D = Dim::value;
  RandomSource random(403 + D);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const Vec<D> r = random.vector<D>(-3.0, 3.0);
    const CrossMat<D> rs = crossMatrix<D>(r);
    const Mat<D> expected = r.squaredNorm() * Mat<D>::Identity() - r * r.transpose();
    CHECK_EIGEN_NEAR(Mat<D>(rs.transpose() * rs), expected, 1e-12);
    // r x r = 0: the lever arm itself is in the null space of r*.
    CHECK_EIGEN_NEAR(AngVec<D>(rs * r), AngVec<D>::Zero(), 0.0, 1e-12 * r.squaredNorm());
  }
}

// [test_closed_form_k]
TEST_CASE("the 2D K equals the notes' closed form") {
  RandomSource random(404);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const RigidBody<2> body = random.dynamicBody<2>();
    const Vec2 r = random.vector<2>(-3.0, 3.0);
    const double invM = body.inverseMass, invI = body.inverseInertia[0];
    // Eq. (4.3), written out from the notes.
    Mat2 notes;
    notes << invM + invI * r.y() * r.y(), -invI * r.x() * r.y(),
             -invI * r.x() * r.y(), invM + invI * r.x() * r.x();
    const Mat2 K = collisionMatrix<2>(body, r);
    CHECK_EIGEN_NEAR(K, notes, 1e-12);
    CHECK_EIGEN_NEAR(planarCollisionMatrix(invM, invI, r), notes, 1e-12);
    // Eq. (4.4): the same matrix as delta/m + (|r|^2 delta - r r^T)/I.
    CHECK_EIGEN_NEAR(K, Mat2(invM * Mat2::Identity() +
                             invI * (r.squaredNorm() * Mat2::Identity() - r * r.transpose())),
                     1e-12);
  }
}
// [test_closed_form_k]

TEST_CASE("the 2D K has eigenvectors r and r-perp with eigenvalues 1/m and 1/m + r.r/I") {
  RandomSource random(405);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const RigidBody<2> body = random.dynamicBody<2>();
    const Vec2 r = random.vector<2>(-3.0, 3.0);
    const Vec2 rPerp(-r.y(), r.x());
    const double invM = body.inverseMass, invI = body.inverseInertia[0];
    const Mat2 K = collisionMatrix<2>(body, r);
    CHECK_EIGEN_NEAR(Vec2(K * r), Vec2(invM * r), 1e-12);                    // Eq. (4.4)
    CHECK_EIGEN_NEAR(Vec2(K * rPerp), Vec2((invM + invI * r.squaredNorm()) * rPerp), 1e-12);
  }
}

// [test_pair_spectrum]
TEST_CASE("the 2D pair K is symmetric with eigenvalues at least the sum of inverse masses") {
  RandomSource random(406);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const RigidBody<2> a = random.dynamicBody<2>();
    const RigidBody<2> b = trial % 4 == 0 ? makeStaticBody<2>() : random.dynamicBody<2>();
    const Vec2 p = random.vector<2>(-3.0, 3.0);
    const Vec2 ra = p - a.position, rb = p - b.position;
    const Mat2 K = pairCollisionMatrix<2>(a, ra, b, rb);
    CHECK(K(0, 1) == K(1, 0));
    const Eigen::SelfAdjointEigenSolver<Mat2> eigen(K, Eigen::EigenvaluesOnly);
    const double lowerBound = a.inverseMass + b.inverseMass;
    CHECK(eigen.eigenvalues()[0] >= lowerBound * (1.0 - 1e-12));
    // The largest eigenvalue is at most sum(1/m) + sum(|r|^2/I) (Eq. (4.4), Weyl).
    const double upperBound = lowerBound + a.inverseInertia[0] * ra.squaredNorm() +
                              b.inverseInertia[0] * rb.squaredNorm();
    CHECK(eigen.eigenvalues()[1] <= upperBound * (1.0 + 1e-12));
  }
}
// [test_pair_spectrum]

TEST_CASE("the 2D world inverse inertia does not depend on the orientation") {
  RandomSource random(407);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    RigidBody<2> body = random.dynamicBody<2>();
    const double invI = body.inverseInertia[0];
    for (int turn = 0; turn < 5; ++turn) {
      body.orientation = random.orientation<2>();
      // Eq. (4.11): the angular rotation of the plane is [1], exactly.
      CHECK(angularRotationMatrix<2>(body.orientation) == AngMat<2>::Identity());
      CHECK(body.inverseInertiaWorld()(0, 0) == invI);
    }
  }
}

// [test_block_diagonal]
TEST_CASE("the 3D K of an in-plane contact is block diagonal with the 2D K as its plane block") {
  RandomSource random(408);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const PlanarTwin twin = testing::randomPlanarTwin(random);
    const Vec2 r = random.vector<2>(-3.0, 3.0);
    const Mat3 K3 = collisionMatrix<3>(twin.space, liftToSpace(r));
    const Mat2 K2 = collisionMatrix<2>(twin.plane, r);
    const double scale = K3.cwiseAbs().maxCoeff();
    // Eq. (4.5): the plane block is the 2D K ...
    CHECK_EIGEN_NEAR(Mat2(K3.topLeftCorner<2, 2>()), K2, 1e-12);
    // ... and the z row and column decouple.
    CHECK(std::abs(K3(0, 2)) <= 1e-12 * scale);
    CHECK(std::abs(K3(1, 2)) <= 1e-12 * scale);
    CHECK(std::abs(K3(2, 0)) <= 1e-12 * scale);
    CHECK(std::abs(K3(2, 1)) <= 1e-12 * scale);
    // K_zz = 1/m + (r_y, -r_x, 0) I^{-1} (r_y, -r_x, 0)^T: a push along z turns the body
    // about in-plane axes, so K_zz sees the in-plane moments and not I_z.
    const Vec3 c(r.y(), -r.x(), 0.0);
    const double kzz = twin.space.inverseMass + c.dot(twin.space.inverseInertiaWorld() * c);
    CHECK(K3(2, 2) == doctest::Approx(kzz).epsilon(1e-12));
  }
}
// [test_block_diagonal]

// [test_tilted_body_couples]
TEST_CASE("a body whose z axis is not principal couples an in-plane contact to z") {
  // Principal moments (1, 2, 3), turned 45 degrees about x: the world inverse inertia gets
  // the product term (I^{-1})_yz = sin 45 cos 45 (1/2 - 1/3) = 1/12.
  RigidBody<3> body = makeDynamicBody<3>(1.0, Vec3(1.0, 2.0, 3.0));
  body.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.25 * M_PI, Vec3::UnitX()));
  CHECK(body.inverseInertiaWorld()(1, 2) == doctest::Approx(1.0 / 12.0).epsilon(1e-12));
  const Vec3 r(1.0, 2.0, 0.0);
  const Mat3 K = collisionMatrix<3>(body, r);
  // K_xz = r_x r_y / 12 and K_yz = -r_x^2 / 12 (worked in the Pitfalls section).
  CHECK(K(0, 2) == doctest::Approx(r.x() * r.y() / 12.0).epsilon(1e-12));
  CHECK(K(1, 2) == doctest::Approx(-r.x() * r.x() / 12.0).epsilon(1e-12));
  // An in-plane impulse now spins the body about y: the motion leaves the plane.
  const Vec3 j(0.0, 1.0, 0.0);
  body.applyImpulse(r, j);
  CHECK(body.angularVelocity.y() == doctest::Approx(r.x() * j.y() / 12.0).epsilon(1e-12));
}
// [test_tilted_body_couples]

TEST_CASE("lifting a planar body into space checks that its moments make a physical body") {
  const RigidBody<2> body = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0));
  // I_x + I_y < I_z: no mass distribution has these moments.
  CHECK_THROWS_WITH_AS(liftToSpace(body, 0.2, 0.3),
                       doctest::Contains("in-plane moments (Ix, Iy) = (0.2, 0.3)"),
                       std::invalid_argument);
  CHECK_THROWS_AS(liftToSpace(body, 3.0, 1.0), std::invalid_argument);  // I_y + I_z < I_x
  CHECK_THROWS_AS(liftToSpace(body, -1.0, 2.0), std::invalid_argument);
  CHECK_THROWS_AS(liftToSpace(body, std::nan(""), 1.0), std::invalid_argument);
  CHECK_THROWS_AS(liftToSpace(body, 1.0, std::numeric_limits<double>::infinity()),
                  std::invalid_argument);
  // The lamina sits on the boundary I_x + I_y = I_z and is accepted.
  const RigidBody<3> lamina = liftToSpace(body);
  CHECK(lamina.inertia == Vec3(0.5, 0.5, 1.0));
  // A static body stays static, whatever in-plane moments are asked for.
  CHECK(liftToSpace(makeStaticBody<2>(Vec2(1.0, 2.0))).isStatic());
  CHECK(liftToSpace(makeStaticBody<2>(), 0.2, 0.3).isStatic());
}

}  // TEST_SUITE
