#pragma once
// Chapter 4 test support: a planar body and the 3D body that performs the same motion.
//
// The 3D twin has one principal axis along the world z axis, so planar motion stays planar
// (Eq. (4.5)). Which principal axis that is varies: body x, y or z is turned onto world z
// before the in-plane rotation, so the tests do not depend on one particular embedding.

#include <cmath>

#include "stackbook/body/rigid_body.hpp"
#include "stackbook/impulse/planar_reduction.hpp"
#include "support/random_bodies.hpp"

namespace stackbook::testing {

struct PlanarTwin {
  RigidBody<2> plane;
  RigidBody<3> space;
};

/// The rotation that carries the body's principal axis `axis` (0, 1 or 2) onto world z.
inline Eigen::Quaterniond principalAxisOntoZ(int axis) {
  switch (axis) {
    case 0: return Eigen::Quaterniond(Eigen::AngleAxisd(-0.5 * M_PI, Vec3::UnitY()));
    case 1: return Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * M_PI, Vec3::UnitX()));
    default: return Eigen::Quaterniond::Identity();
  }
}

/// A random dynamic planar body (mass, position, velocity, spin) and its 3D twin: a body
/// with random physical principal moments, one of which (chosen at random) is the planar
/// moment I, with that principal axis along world z.
inline PlanarTwin randomPlanarTwin(RandomSource& random) {
  const double m = random.logUniform(0.1, 10.0);
  const AngVec<3> moments = random.principalInertia<3>(m);
  const int axis = static_cast<int>(std::floor(random.uniform(0.0, 3.0))) % 3;
  const double theta = random.uniform(-M_PI, M_PI);

  PlanarTwin twin;
  AngVec<2> planarMoment;
  planarMoment << moments[axis];
  twin.plane = makeDynamicBody<2>(m, planarMoment);
  twin.plane.position = random.vector<2>(-3.0, 3.0);
  twin.plane.orientation = Eigen::Rotation2Dd(theta);
  twin.plane.velocity = random.vector<2>(-2.0, 2.0);
  twin.plane.setAngularVelocity(random.angularVector<2>(-3.0, 3.0));

  twin.space = makeDynamicBody<3>(m, moments);
  twin.space.position = liftToSpace(twin.plane.position);
  twin.space.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(theta, Vec3::UnitZ())) * principalAxisOntoZ(axis);
  twin.space.velocity = liftToSpace(twin.plane.velocity);
  twin.space.setAngularVelocity(Vec3(0.0, 0.0, twin.plane.angularVelocity[0]));
  return twin;
}

/// A static planar body and its 3D twin.
inline PlanarTwin staticPlanarTwin(RandomSource& random) {
  PlanarTwin twin;
  twin.plane = makeStaticBody<2>(random.vector<2>(-3.0, 3.0));
  twin.space = liftToSpace(twin.plane);
  return twin;
}

}  // namespace stackbook::testing
