// Chapter 1: mass properties. The world-frame inverse inertia (Eq. (1.7)) and the
// validation of makeDynamicBody.
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <doctest/doctest.h>
#include <Eigen/LU>

#include "stackbook/body/rigid_body.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::kEps;
using stackbook::testing::RandomSource;

namespace {

/// The message makeDynamicBody throws for (mass, moments), or "" if it accepts them.
template <int D>
std::string rejection(double mass, const AngVec<D>& moments) {
  try {
    (void)makeDynamicBody<D>(mass, moments);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

/// True when the message contains the text.
bool mentions(const std::string& message, const std::string& text) {
  return message.find(text) != std::string::npos;
}

/// Principal moments that pass every check: the moments of a box.
template <int D>
AngVec<D> validMoments() {
  if constexpr (D == 2) {
    return AngVec<2>(0.5);
  } else {
    return AngVec<3>(0.5, 0.75, 1.0);
  }
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_world_inverse_inertia]
TEST_CASE_TEMPLATE("world inverse inertia is the inverse of R I_body R^T", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(31 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const RigidBody<D> body = random.dynamicBody<D>();
    // The world tensor and its inverse, computed here the slow way: inverting the
    // world-frame tensor (which the library never does).
    const AngMat<D> R = angularRotationMatrix<D>(body.orientation);
    const AngMat<D> worldInertia = R * body.inertia.asDiagonal() * R.transpose();
    const AngMat<D> inverted = worldInertia.inverse();
    // Inverting a matrix of condition number kappa loses about kappa eps.
    const double kappa = body.inertia.maxCoeff() / body.inertia.minCoeff();
    CAPTURE(kappa);
    CHECK_EIGEN_NEAR(body.inverseInertiaWorld(), inverted, 64 * kEps * kappa);  // Eq. (1.7)
    CHECK_EIGEN_NEAR(AngMat<D>(body.inverseInertiaWorld() * worldInertia),
                     AngMat<D>(AngMat<D>::Identity()), 64 * kEps * kappa);
    if constexpr (D == 2) {
      // In the plane the single angular axis is z, which a rotation leaves alone.
      CHECK(body.inverseInertiaWorld()(0, 0) == 1.0 / body.inertia[0]);
    }
  }
}
// [test_world_inverse_inertia]

// [test_locked_axis]
TEST_CASE("world inverse inertia of a body locked about a principal axis has that axis as null space") {
  // A zero inverse moment (an infinite moment) has no finite world tensor to invert:
  // the world inverse inertia exists only because it is built from body-frame moments.
  RandomSource random(37);
  for (int trial = 0; trial < 100; ++trial) {
    CAPTURE(trial);
    RigidBody<3> body = random.dynamicBody<3>();
    const int locked = trial % 3;
    body.inverseInertia[locked] = 0.0;
    const Mat3 W = body.inverseInertiaWorld();
    const Vec3 axis = body.orientation * Vec3(Vec3::Unit(locked));  // locked axis, world frame
    REQUIRE(W.allFinite());
    // W axis = 0: no angular impulse turns the body about the locked axis ...
    CHECK((W * axis).norm() <= 16 * kEps * W.norm());
    // ... while about the other principal axes it turns with 1/I_k.
    for (int k = 0; k < 3; ++k) {
      if (k == locked) continue;
      const Vec3 free = body.orientation * Vec3(Vec3::Unit(k));
      CHECK_EIGEN_NEAR(Vec3(W * free), Vec3(body.inverseInertia[k] * free), 16 * kEps);
    }
    // An angular impulse about the locked axis leaves the cached angular velocity zero.
    body.angularMomentum.setZero();
    body.applyAngularImpulse(3.0 * axis);
    CHECK(body.angularVelocity.norm() <= 16 * kEps * W.norm() * 3.0);
  }
}
// [test_locked_axis]

// [test_make_dynamic_body]
TEST_CASE_TEMPLATE("makeDynamicBody rejects bad mass and inertia with messages naming the value",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const AngVec<D> good = validMoments<D>();

  SUBCASE("a finite positive mass and positive moments are accepted") {
    CHECK(rejection<D>(2.0, good) == "");
    const RigidBody<D> body = makeDynamicBody<D>(4.0, good);
    CHECK(body.inverseMass == 0.25);
    CHECK(body.inverseInertia == good.cwiseInverse());
    CHECK(!body.isStatic());
  }
  SUBCASE("the mass must be finite and positive") {
    CHECK(mentions(rejection<D>(0.0, good), "mass must be finite and positive, got 0"));
    CHECK(mentions(rejection<D>(-1.5, good), "mass must be finite and positive, got -1.5"));
    CHECK(mentions(rejection<D>(nan, good), "mass must be finite and positive, got nan"));
    CHECK(mentions(rejection<D>(inf, good), "mass must be finite and positive, got inf"));
  }
  SUBCASE("every principal moment must be finite and positive") {
    for (int k = 0; k < kAngularDim<D>; ++k) {
      CAPTURE(k);
      const std::string which = "principal moment of inertia " + std::to_string(k);
      for (double bad : {0.0, -2.0, nan, inf}) {
        AngVec<D> moments = good;
        moments[k] = bad;
        const std::string message = rejection<D>(1.0, moments);
        CAPTURE(message);
        std::ostringstream value;
        value << "got " << bad;
        CHECK(mentions(message, which));
        CHECK(mentions(message, value.str()));
      }
    }
  }
  if constexpr (D == 3) {
    SUBCASE("3D moments must satisfy the triangle inequality") {
      // (1, 1, 3): no mass distribution has I_z > I_x + I_y.
      CHECK(mentions(rejection<3>(1.0, AngVec<3>(1.0, 1.0, 3.0)),
                     "principal moments (1, 1, 3) violate the triangle inequality"));
      CHECK(mentions(rejection<3>(1.0, AngVec<3>(1.0, 3.0, 1.0)), "(1, 3, 1)"));
      CHECK(mentions(rejection<3>(1.0, AngVec<3>(3.0, 1.0, 1.0)), "(3, 1, 1)"));
      // (1, 1, 2) is the boundary: a flat lamina in the z = 0 plane. Accepted.
      CHECK(rejection<3>(1.0, AngVec<3>(1.0, 1.0, 2.0)) == "");
    }
  }
}
// [test_make_dynamic_body]

}  // TEST_SUITE
