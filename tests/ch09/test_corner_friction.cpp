// Chapter 9: why a pile of boxes creeps under per-point impulses (Eqs. (9.6)-(9.7)). A
// box held still at one corner needs a friction coefficient of at least 3/5 (a square)
// or 3 sqrt(2) / 5 (a cube): below it, every corner impulse of a resting box slides.
#include <doctest/doctest.h>

#include <cmath>

#include "stack_scenes.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// The corner (+1/2, ..., -1/2) of a unit box of mass 1 resting on a static body.
template <int D>
Vec<D> corner() {
  Vec<D> r = Vec<D>::Constant(0.5);
  r[D - 1] = -0.5;
  return r;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [corner_friction_test]
TEST_CASE_TEMPLATE("A box stopped at one corner needs friction 3/5 of the normal impulse in 2D and 3 sqrt 2/5 in 3D",
                   Dim, In2D, In3D) {
  // Eq. (9.7): K = (1/m) 1 + (1/I) [r]x^T [r]x with I = m/6 for the unit box; the sticking
  // trial that stops a purely normal approach is j* = K^{-1} (-u_n n).
  constexpr int D = Dim::value;
  const RigidBody<D> box = stacks::uniformBox<D>(Vec<D>::Constant(1.0), 1.0);
  const RigidBody<D> ground = makeStaticBody<D>();
  const Mat<D> K = pairCollisionMatrix<D>(box, corner<D>(), ground, Vec<D>::Zero());
  const Vec<D> n = stacks::up<D>();
  Vec<D> jStick;
  REQUIRE(solveCollisionMatrix<D>(K, Vec<D>(0.01 * n), FrictionSettings{}, jStick));
  const double jn = jStick.dot(n);
  const double ratio = (jStick - jn * n).norm() / jn;
  const double expected = D == 2 ? 0.6 : 0.6 * std::sqrt(2.0);
  CHECK(ratio == doctest::Approx(expected).epsilon(1e-12));
  // Just above the ratio the corner sticks; just below it slides.
  const Vec<D> u = -0.01 * n;
  CHECK(frictionalImpulse<D>(K, u, n, 0.0, 1.01 * expected).branch == ImpulseBranch::Sticking);
  CHECK(frictionalImpulse<D>(K, u, n, 0.0, 0.99 * expected).branch == ImpulseBranch::Sliding);
}
// [corner_friction_test]

}  // TEST_SUITE
