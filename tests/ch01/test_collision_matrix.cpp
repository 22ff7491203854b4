// Chapter 1: notation and the collision matrix K.
#include <doctest/doctest.h>

#include "stackbook/impulse/collision_matrix.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;

TEST_SUITE(STACKBOOK_CHAPTER) {

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
    CHECK_EIGEN_NEAR(Vec<D>(after - before), Vec<D>(K * j), 1e-12);
  }
}

}  // TEST_SUITE
