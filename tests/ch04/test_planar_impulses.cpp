// Chapter 4: the impulses of chapters 2 and 3 with D = 2 are the 3D impulses of the same
// contact lifted into space (Eq. (4.6)), and the scalar normal response (Eqs. (4.7), (4.8)).
#include <doctest/doctest.h>

#include <cmath>

#include "ch04/planar_twins.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"
#include "stackbook/impulse/planar_reduction.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::PlanarTwin;
using stackbook::testing::RandomSource;

namespace {

/// One random planar contact and its 3D twin: two bodies (b static one time in four), a
/// contact point, a unit normal chosen so that the contact approaches (u_n < 0). One time
/// in ten the approach is head-on (n = -u/|u|, so u_t = 0): a sliding impulse must then
/// take its slip direction from the impact (Eq. (3.4)).
struct TwinContact {
  PlanarTwin a, b;
  Vec2 ra, rb, n;
};

TwinContact randomTwinContact(RandomSource& random, int trial) {
  TwinContact c;
  c.a = testing::randomPlanarTwin(random);
  c.b = trial % 4 == 3 ? testing::staticPlanarTwin(random) : testing::randomPlanarTwin(random);
  const Vec2 p = random.vector<2>(-3.0, 3.0);
  c.ra = p - c.a.plane.position;
  c.rb = p - c.b.plane.position;
  c.n = random.unitVector<2>();
  const Vec2 u = relativeVelocity<2>(c.a.plane, c.ra, c.b.plane, c.rb);
  if (u.dot(c.n) > 0.0) c.n = -c.n;
  if (trial % 10 == 9) c.n = -u.normalized();
  return c;
}

/// The 3D impulse has no z component (relative to its size).
bool staysInPlane(const Vec3& j) { return std::abs(j.z()) <= 1e-12 * j.norm(); }

// With e = 1 the energy guards of chapter 3 meet exact ties. An elastic head-on sticking
// impulse is exactly energy-neutral (K j = -2u, so Delta KE = 0 in Eq. (3.8)), and so is
// the frictionless impulse that a sliding impulse tends to as mu -> 0. Whether a guard
// fires there is decided by the last bit of Delta KE, and may differ between a planar
// contact and its 3D twin while the impulses agree to 1e-15 (see Pitfalls). These two
// helpers compare the decisions up to such ties.

/// A safeguard lowered a coefficient by more than rounding.
bool materiallyLowered(bool lowered, double used, double asked) {
  return lowered && std::abs(used) < std::abs(asked) * (1.0 - 1e-9);
}

/// The branch, with a slide whose friction the energy guard lowered to rounding level
/// counted as the frictionless impulse it equals.
template <int D>
ImpulseBranch decidedBranch(const ContactImpulse<D>& impulse, double mu) {
  if (impulse.branch == ImpulseBranch::Sliding && impulse.friction <= 1e-9 * mu) {
    return ImpulseBranch::Frictionless;
  }
  return impulse.branch;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_frictionless_twins]
TEST_CASE("2D frictionless impulses equal the in-plane 3D impulses") {
  RandomSource random(411);
  for (int trial = 0; trial < 600; ++trial) {
    CAPTURE(trial);
    const TwinContact c = randomTwinContact(random, trial);
    const double e = trial % 3 == 0 ? 0.0 : (trial % 3 == 1 ? 0.4 : 1.0);
    const Vec3 ra3 = liftToSpace(c.ra), rb3 = liftToSpace(c.rb), n3 = liftToSpace(c.n);
    const Mat2 K2 = pairCollisionMatrix<2>(c.a.plane, c.ra, c.b.plane, c.rb);
    const Mat3 K3 = pairCollisionMatrix<3>(c.a.space, ra3, c.b.space, rb3);
    const Vec2 u2 = relativeVelocity<2>(c.a.plane, c.ra, c.b.plane, c.rb);
    const Vec3 u3 = relativeVelocity<3>(c.a.space, ra3, c.b.space, rb3);
    CHECK_EIGEN_NEAR(u3, liftToSpace(u2), 1e-12);
    const ContactImpulse<2> j2 = frictionlessImpulse<2>(K2, u2, c.n, e);
    const ContactImpulse<3> j3 = frictionlessImpulse<3>(K3, u3, n3, e);
    REQUIRE(j2.branch == ImpulseBranch::Frictionless);
    CHECK(j3.branch == j2.branch);
    CHECK_EIGEN_NEAR(j3.j, liftToSpace(j2.j), 1e-12);
    CHECK(staysInPlane(j3.j));
  }
}
// [test_frictionless_twins]

// [test_frictional_twins]
TEST_CASE("2D frictional impulses equal the in-plane 3D impulses on both branches") {
  RandomSource random(412);
  const double frictions[] = {0.1, 0.3, 0.6, 1.0, 2.0};
  const double restitutions[] = {0.0, 0.5, 1.0};
  int sticking = 0, sliding = 0, guarded = 0, headOn = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    CAPTURE(trial);
    const TwinContact c = randomTwinContact(random, trial);
    const double mu = frictions[trial % 5];
    const double e = restitutions[(trial / 5) % 3];
    CAPTURE(mu);
    CAPTURE(e);
    const Vec3 ra3 = liftToSpace(c.ra), rb3 = liftToSpace(c.rb), n3 = liftToSpace(c.n);
    const Mat2 K2 = pairCollisionMatrix<2>(c.a.plane, c.ra, c.b.plane, c.rb);
    const Mat3 K3 = pairCollisionMatrix<3>(c.a.space, ra3, c.b.space, rb3);
    const Vec2 u2 = relativeVelocity<2>(c.a.plane, c.ra, c.b.plane, c.rb);
    const Vec3 u3 = relativeVelocity<3>(c.a.space, ra3, c.b.space, rb3);
    const ContactImpulse<2> j2 = frictionalImpulse<2>(K2, u2, c.n, e, mu);
    const ContactImpulse<3> j3 = frictionalImpulse<3>(K3, u3, n3, e, mu);
    CHECK(decidedBranch(j3, mu) == decidedBranch(j2, mu));
    CHECK_EIGEN_NEAR(j3.j, liftToSpace(j2.j), 1e-12);
    CHECK(staysInPlane(j3.j));
    // The safeguards of chapter 3 take the same decisions with the same coefficients.
    CHECK(j3.restitution == doctest::Approx(j2.restitution).epsilon(1e-12));
    CHECK(j3.friction == doctest::Approx(j2.friction).epsilon(1e-12));
    const bool eLowered = materiallyLowered(j2.restitutionLowered, j2.restitution, e);
    const bool muLowered = materiallyLowered(j2.frictionLowered, j2.friction, mu);
    CHECK(materiallyLowered(j3.restitutionLowered, j3.restitution, e) == eLowered);
    CHECK(materiallyLowered(j3.frictionLowered, j3.friction, mu) == muLowered);
    CHECK(j3.slipFromImpulse == j2.slipFromImpulse);
    sticking += j2.branch == ImpulseBranch::Sticking;
    sliding += j2.branch == ImpulseBranch::Sliding;
    guarded += eLowered || muLowered;
    headOn += trial % 10 == 9 && j2.branch == ImpulseBranch::Sliding;
  }
  // The loop must exercise both branches, the safeguards and head-on sliding.
  CHECK(sticking > 300);
  CHECK(sliding > 300);
  CHECK(guarded > 50);
  CHECK(headOn > 10);
}
// [test_frictional_twins]

// [test_stays_planar]
TEST_CASE("after an in-plane impulse the 3D bodies move as their planar twins") {
  RandomSource random(413);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    TwinContact c = randomTwinContact(random, trial);
    const Vec3 ra3 = liftToSpace(c.ra), rb3 = liftToSpace(c.rb), n3 = liftToSpace(c.n);
    const ContactImpulse<2> j2 = frictionalImpulse<2>(
        pairCollisionMatrix<2>(c.a.plane, c.ra, c.b.plane, c.rb),
        relativeVelocity<2>(c.a.plane, c.ra, c.b.plane, c.rb), c.n, 0.5, 0.5);
    const ContactImpulse<3> j3 = frictionalImpulse<3>(
        pairCollisionMatrix<3>(c.a.space, ra3, c.b.space, rb3),
        relativeVelocity<3>(c.a.space, ra3, c.b.space, rb3), n3, 0.5, 0.5);
    applyPairImpulse<2>(c.a.plane, c.ra, c.b.plane, c.rb, j2.j);
    applyPairImpulse<3>(c.a.space, ra3, c.b.space, rb3, j3.j);
    for (const PlanarTwin* twin : {&c.a, &c.b}) {
      const double spin = std::abs(twin->plane.angularVelocity[0]) + 1.0;
      // The angular velocity stays along z, and the velocity in the plane.
      CHECK(std::abs(twin->space.angularVelocity.x()) <= 1e-12 * spin);
      CHECK(std::abs(twin->space.angularVelocity.y()) <= 1e-12 * spin);
      CHECK(std::abs(twin->space.velocity.z()) <= 1e-12 * (twin->plane.velocity.norm() + 1.0));
      // What is left is the planar motion.
      CHECK_EIGEN_NEAR(dropToPlane(twin->space.velocity), twin->plane.velocity, 1e-12);
      CHECK(twin->space.angularVelocity.z() ==
            doctest::Approx(twin->plane.angularVelocity[0]).epsilon(1e-12));
    }
  }
}
// [test_stays_planar]

// [test_normal_response]
TEST_CASE("n^T K n equals the textbook 2D expression in both of its forms") {
  RandomSource random(414);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const TwinContact c = randomTwinContact(random, trial);
    const RigidBody<2>& a = c.a.plane;
    const RigidBody<2>& b = c.b.plane;
    const Vec2& n = c.n;
    const double knn = n.dot(pairCollisionMatrix<2>(a, c.ra, b, c.rb) * n);
    // Eq. (4.7): 1/m_a + 1/m_b + (r_a x n)^2 / I_a + (r_b x n)^2 / I_b.
    const double crossA = c.ra.x() * n.y() - c.ra.y() * n.x();
    const double crossB = c.rb.x() * n.y() - c.rb.y() * n.x();
    const double textbook = a.inverseMass + b.inverseMass +
                            crossA * crossA * a.inverseInertia[0] +
                            crossB * crossB * b.inverseInertia[0];
    CHECK(knn == doctest::Approx(textbook).epsilon(1e-12));
    // Eq. (4.8), box2d-lite's kNormal: 1/m + (r.r - (r.n)^2)/I per body.
    CHECK(planarNormalResponse(a, c.ra, b, c.rb, n) == doctest::Approx(textbook).epsilon(1e-12));
  }
}
// [test_normal_response]

// [test_worked_example]
TEST_CASE("a unit square landing on a corner gets the same impulse in the plane and as any prism") {
  // Square of side 1 and mass 1 (I = 1/6) falling without spin at v = (1, -2) onto a static
  // floor (n = +y), touching it with its corner r = (1/2, -1/2). Eq. (4.3):
  // K = delta + 6 [[1/4, 1/4], [1/4, 1/4]] = [[5/2, 3/2], [3/2, 5/2]], with e = 0:
  //   mu = 1:   sticking, j = -K^{-1} u = (-11/8, 13/8), inside the cone (11/13 < 1);
  //   mu = 1/2: sliding along T = +x, j_n = 2 / (n^T K (n - T/2)) = 2 / (7/4) = 8/7,
  //             j = (8/7)(-1/2, 1) = (-4/7, 8/7), leaving u' = u + K j = (9/7, 0).
  RigidBody<2> square = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 6.0));
  square.velocity = Vec2(1.0, -2.0);
  const RigidBody<2> floor = makeStaticBody<2>();
  const Vec2 r(0.5, -0.5), n(0.0, 1.0);
  Mat2 expectedK;
  expectedK << 2.5, 1.5,
               1.5, 2.5;
  const Mat2 K2 = pairCollisionMatrix<2>(square, r, floor, r);
  const Vec2 u2 = relativeVelocity<2>(square, r, floor, r);
  CHECK_EIGEN_NEAR(K2, expectedK, 1e-12);

  const ContactImpulse<2> stick2 = frictionalImpulse<2>(K2, u2, n, 0.0, 1.0);
  const ContactImpulse<2> slide2 = frictionalImpulse<2>(K2, u2, n, 0.0, 0.5);
  CHECK(stick2.branch == ImpulseBranch::Sticking);
  CHECK_EIGEN_NEAR(stick2.j, Vec2(-11.0 / 8.0, 13.0 / 8.0), 1e-12);
  CHECK(slide2.branch == ImpulseBranch::Sliding);
  CHECK_EIGEN_NEAR(slide2.j, Vec2(-4.0 / 7.0, 8.0 / 7.0), 1e-12);
  // Friction opposes the slip, yet the corner slides faster afterwards: the normal impulse
  // at the corner turns the square, and the turning carries the corner forward.
  CHECK_EIGEN_NEAR(Vec2(u2 + K2 * slide2.j), Vec2(9.0 / 7.0, 0.0), 1e-12, 1e-15);

  // The same square as a box of height h in space (a lamina at h = 0): I_x = I_y =
  // (1 + h^2)/12 and I_z = 1/6. Only K_zz = 1 + 6/(1 + h^2) depends on h (Eq. (4.5)).
  for (const double h : {0.0, 0.5, 1.0, 4.0}) {
    CAPTURE(h);
    const double Ixy = (1.0 + h * h) / 12.0;
    const RigidBody<3> prism = liftToSpace(square, Ixy, Ixy);
    const RigidBody<3> floor3 = liftToSpace(floor);
    const Vec3 r3 = liftToSpace(r), n3 = liftToSpace(n);
    const Mat3 K3 = pairCollisionMatrix<3>(prism, r3, floor3, r3);
    Mat3 expectedK3 = Mat3::Zero();
    expectedK3.topLeftCorner<2, 2>() = expectedK;
    expectedK3(2, 2) = 1.0 + 6.0 / (1.0 + h * h);
    CHECK_EIGEN_NEAR(K3, expectedK3, 1e-12);
    const Vec3 u3 = relativeVelocity<3>(prism, r3, floor3, r3);
    CHECK_EIGEN_NEAR(frictionalImpulse<3>(K3, u3, n3, 0.0, 1.0).j,
                     Vec3(-11.0 / 8.0, 13.0 / 8.0, 0.0), 1e-12);
    CHECK_EIGEN_NEAR(frictionalImpulse<3>(K3, u3, n3, 0.0, 0.5).j,
                     Vec3(-4.0 / 7.0, 8.0 / 7.0, 0.0), 1e-12);
  }
}
// [test_worked_example]

}  // TEST_SUITE
