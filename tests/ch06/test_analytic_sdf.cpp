// Chapter 6: exact signed distances of primitives, and shapes built on them.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;

namespace {

// Central-difference gradient with step s: error O(s^2) where phi is smooth.
template <int D, class Sdf>
Vec<D> finiteDifferenceGradient(const Sdf& sdf, const Vec<D>& x, double s = 1e-6) {
  Vec<D> g;
  for (int k = 0; k < D; ++k) {
    Vec<D> e = Vec<D>::Zero();
    e[k] = s;
    g[k] = (sdf.distance(x + e) - sdf.distance(x - e)) / (2.0 * s);
  }
  return g;
}

// For random points in (a margin around) the shape's box: |grad phi| = 1 (Eq. (6.2)) and
// normal() is that gradient. Finite differences see a kink only if the 2e-6 wide stencil
// straddles the medial axis, which the fixed seeds below do not hit.
template <int D, class Sdf>
void checkEikonalAndNormal(const Sdf& sdf, std::uint64_t seed) {
  RandomSource random(seed);
  const Aabb<D> box = sdf.bounds().inflated(0.3);
  for (int trial = 0; trial < 400; ++trial) {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = random.uniform(box.lower[k], box.upper[k]);
    CAPTURE(x.transpose());
    const Vec<D> g = finiteDifferenceGradient<D>(sdf, x);
    CHECK(g.norm() == doctest::Approx(1.0).epsilon(1e-6));
    CHECK_EIGEN_NEAR(sdf.normal(x), g, 0.0, 1e-6);
  }
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_analytic_values]
TEST_CASE("analytic signed distances match hand-computed values") {
  const SphereSdf<3> sphere(0.5);
  CHECK(sphere.distance(Vec3(0, 0, 2)) == doctest::Approx(1.5));
  CHECK(sphere.distance(Vec3(0.1, 0, 0)) == doctest::Approx(-0.4));

  const BoxSdf<3> box(Vec3(0.5, 0.3, 0.2));
  CHECK(box.distance(Vec3(1.0, 0.0, 0.0)) == doctest::Approx(0.5));             // face region
  CHECK(box.distance(Vec3(0.8, 0.6, 0.0)) == doctest::Approx(std::sqrt(0.18))); // edge region
  CHECK(box.distance(Vec3(0.6, 0.4, 0.3)) == doctest::Approx(std::sqrt(0.03))); // corner
  CHECK(box.distance(Vec3(0.1, 0.0, 0.05)) == doctest::Approx(-0.15));          // nearest: z faces

  const TorusSdf<3> torus(0.5, 0.2);
  CHECK(torus.distance(Vec3::Zero()) == doctest::Approx(0.3));         // centre of the hole
  CHECK(torus.distance(Vec3(0, 0.5, 0)) == doctest::Approx(-0.2));     // core circle
  CHECK(torus.distance(Vec3(0.5, 0, 0.5)) == doctest::Approx(0.3));    // above the core
  const TorusSdf<2> annulus(0.5, 0.2);
  CHECK(annulus.distance(Vec2::Zero()) == doctest::Approx(0.3));
  CHECK(annulus.distance(Vec2(0, -0.6)) == doctest::Approx(-0.1));

  const CapsuleSdf<3> capsule(0.5, 0.25);
  CHECK(capsule.distance(Vec3(0, 0, 1.0)) == doctest::Approx(0.25));   // beyond the cap
  CHECK(capsule.distance(Vec3(0.3, 0.4, 0.1)) == doctest::Approx(0.25)); // beside the core
  CHECK(capsule.distance(Vec3::Zero()) == doctest::Approx(-0.25));

  const CylinderSdf<3> cylinder(0.5, 0.5);
  CHECK(cylinder.distance(Vec3::Zero()) == doctest::Approx(-0.5));
  CHECK(cylinder.distance(Vec3(0.3, 0.4, 0.2)) == doctest::Approx(0.0)); // on the side wall
  CHECK(cylinder.distance(Vec3(1.0, 0.0, 1.0)) == doctest::Approx(std::sqrt(0.5)));  // rim
  CHECK(cylinder.distance(Vec3(0.1, 0.0, 0.45)) == doctest::Approx(-0.05));          // near a cap
  const CylinderSdf<2> section(0.5, 0.5);  // the 2D cylinder is a rectangle
  CHECK(section.distance(Vec2(0.7, 0.0)) == doctest::Approx(0.2));
}
// [test_analytic_values]

TEST_CASE_TEMPLATE("analytic signed distances satisfy the eikonal equation and normal is their gradient",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  Vec<D> half = Vec<D>::Constant(0.3);
  half[0] = 0.5;
  checkEikonalAndNormal<D>(SphereSdf<D>(0.5), 71);
  checkEikonalAndNormal<D>(BoxSdf<D>(half), 72);
  checkEikonalAndNormal<D>(TorusSdf<D>(0.5, 0.2), 73);
  checkEikonalAndNormal<D>(CapsuleSdf<D>(0.4, 0.25), 74);
  checkEikonalAndNormal<D>(CylinderSdf<D>(0.4, 0.3), 75);
}

TEST_CASE_TEMPLATE("normals on the medial axis are the documented unit vectors", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  Vec<D> last = Vec<D>::Zero(), first = Vec<D>::Zero();
  last[D - 1] = 1.0;
  first[0] = 1.0;
  CHECK_EIGEN_NEAR(SphereSdf<D>(1.0).normal(Vec<D>::Zero()), last, 0.0, 0.0);
  // A cube's centre is equidistant from all faces: the lowest axis, positive side.
  CHECK_EIGEN_NEAR(BoxSdf<D>(Vec<D>::Constant(1.0)).normal(Vec<D>::Zero()), first, 0.0, 0.0);
  CHECK_EIGEN_NEAR(CapsuleSdf<D>(0.5, 0.2).normal(Vec<D>::Zero()), first, 0.0, 0.0);
  // On the torus core circle, away from the axis.
  Vec<D> core = Vec<D>::Zero();
  core[1] = 0.5;
  Vec<D> outward = Vec<D>::Zero();
  outward[1] = 1.0;
  CHECK_EIGEN_NEAR(TorusSdf<D>(0.5, 0.2).normal(core), outward, 0.0, 1e-15);
}

TEST_CASE_TEMPLATE("analytic shapes take their samples from a mesh on their surface", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  Vec<D> size = Vec<D>::Constant(0.6);
  size[0] = 1.0;
  const SphereShape<D> sphere = makeSphereShape<D>(0.5);
  const BoxShape<D> box = makeBoxShape<D>(size);
  const TorusShape<D> torus = makeTorusShape<D>(0.5, 0.2);
  const CapsuleShape<D> capsule = makeCapsuleShape<D>(0.4, 0.25);
  const CylinderShape<D> cylinder = makeCylinderShape<D>(0.4, 0.3);
  const Shape<D>* shapes[] = {&sphere, &box, &torus, &capsule, &cylinder};
  for (const Shape<D>* shape : shapes) {
    CAPTURE(shape->describe());
    CHECK(shape->surfaceSamples().size() >= 16);
    for (const Vec<D>& p : shape->surfaceSamples()) {
      CHECK(std::abs(shape->signedDistance(p)) < 1e-12);
      CHECK(shape->bounds().inflated(1e-12).contains(p));
    }
  }
  // The torus' samples lie on both boundary loops in 2D: the hole has samples too.
  int inner = 0;
  for (const Vec<D>& p : torus.surfaceSamples()) inner += p.norm() < 0.5 ? 1 : 0;
  CHECK(inner > 0);
}

TEST_CASE("an analytic shape rejects a sample mesh that is not on its surface") {
  // A cube of side 1 is not a sphere of radius 0.5: its corners are at distance
  // sqrt(3)/2 - 1/2 = 0.366 from the sphere.
  try {
    const SphereShape<3> wrong(SphereSdf<3>(0.5), boxMesh(Vec3(1, 1, 1)));
    FAIL("no exception");
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    CHECK(message.find("sphere r = 0.5") != std::string::npos);
    CHECK(message.find("mesh vertex 0") != std::string::npos);
    CHECK(message.find("0.366") != std::string::npos);
  }
  CHECK_THROWS_AS(SphereSdf<3>(-1.0), std::invalid_argument);
  CHECK_THROWS_AS(TorusSdf<3>(0.2, 0.5), std::invalid_argument);  // r > R: not a ring
  CHECK_THROWS_AS(BoxSdf<2>(Vec2(1.0, std::nan(""))), std::invalid_argument);
}

}  // TEST_SUITE
