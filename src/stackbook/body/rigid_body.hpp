#pragma once
/// \file
/// \brief The rigid-body state that impulses act on (\ref ch01; motion in time is chapter 5).

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "stackbook/math/cross.hpp"
#include "stackbook/math/rotation.hpp"

namespace stackbook {

/// A rigid body in D dimensions. The body frame has its origin at the centre of mass
/// and its axes along the principal axes of inertia, so the body-frame inertia is
/// diagonal and is stored as its principal moments.
///
/// Angular momentum L is the primary angular state, as in GBF-style codes; the angular
/// velocity omega = I_world^{-1} L is kept in sync by every function that changes L or
/// the orientation (chapter 5 explains why L and not omega).
///
/// A static body (infinite mass) has inverseMass = 0 and inverseInertia = 0: it
/// contributes nothing to K (Eq. (1.9)) and impulses leave it unchanged.
/// A zero inverse moment about one principal axis locks rotation about that axis.
// [rigid_body]
template <int D>
struct RigidBody {
  // Mass properties (body frame, principal axes).
  double inverseMass = 0.0;                           ///< 1/m; 0 for a static body
  AngVec<D> inertia = AngVec<D>::Zero();              ///< principal moments I_body
  AngVec<D> inverseInertia = AngVec<D>::Zero();       ///< 1/I_body per axis; 0 = infinite

  // State (world frame).
  Vec<D> position = Vec<D>::Zero();                   ///< centre of mass x
  Orientation<D> orientation = identityOrientation<D>();  ///< body-to-world rotation
  Vec<D> velocity = Vec<D>::Zero();                   ///< v
  AngVec<D> angularMomentum = AngVec<D>::Zero();      ///< L (primary angular state)
  AngVec<D> angularVelocity = AngVec<D>::Zero();      ///< omega = I_world^{-1} L (cached)
  // [rigid_body]

  /// Mass m (infinity for a body with inverseMass = 0).
  double mass() const {
    return inverseMass > 0.0 ? 1.0 / inverseMass : std::numeric_limits<double>::infinity();
  }

  /// True when neither translation nor rotation can be changed by an impulse.
  bool isStatic() const { return inverseMass == 0.0 && inverseInertia.isZero(0.0); }

  // [world_inverse_inertia]
  /// World-frame inverse inertia I^{-1} = R I_body^{-1} R^T (Eq. (1.7)).
  /// Built from the body-frame principal moments: a world-frame tensor is never inverted.
  AngMat<D> inverseInertiaWorld() const {
    const AngMat<D> R = angularRotationMatrix<D>(orientation);
    return R * inverseInertia.asDiagonal() * R.transpose();
  }

  /// World-frame inertia I = R I_body R^T.
  AngMat<D> inertiaWorld() const {
    const AngMat<D> R = angularRotationMatrix<D>(orientation);
    return R * inertia.asDiagonal() * R.transpose();
  }
  // [world_inverse_inertia]

  // [point_velocity]
  /// Velocity of the material point at offset r from the centre of mass (world frame):
  /// u = v + omega x r = v + r*^T omega (Eqs. (1.6), (1.4)). The implementation notes
  /// print omega x v: an erratum (\ref ch01_point_velocity).
  Vec<D> pointVelocity(const Vec<D>& r) const {
    return velocity + crossAngular<D>(angularVelocity, r);
  }
  // [point_velocity]

  // [apply_impulse]
  /// Apply the impulse j at offset r from the centre of mass (Eqs. (1.1), (1.2)):
  /// v += j/m, L += r x j, then omega = I_world^{-1} L. A static body is left untouched.
  void applyImpulse(const Vec<D>& r, const Vec<D>& j) {
    if (isStatic()) return;
    velocity += inverseMass * j;        // Eq. (1.1)
    angularMomentum += cross<D>(r, j);  // Delta L = r x j = r* j, Eq. (1.3)
    syncAngularVelocity();              // omega' = I^{-1} L' = omega + I^{-1} r* j, Eq. (1.5)
  }
  // [apply_impulse]

  /// Apply a pure angular impulse (a torque impulse) tau: L += tau.
  void applyAngularImpulse(const AngVec<D>& tau) {
    if (isStatic()) return;
    angularMomentum += tau;
    syncAngularVelocity();
  }

  /// Set the angular velocity, and the angular momentum L = I_world omega to match.
  /// About a locked axis (infinite moment) the angular velocity is forced to zero.
  void setAngularVelocity(const AngVec<D>& omega) {
    angularMomentum = inertiaWorld() * omega;
    syncAngularVelocity();
  }

  /// Recompute the cached omega from L and the current orientation.
  void syncAngularVelocity() { angularVelocity = inverseInertiaWorld() * angularMomentum; }

  /// Linear kinetic energy plus rotational kinetic energy, (m v.v + omega.L)/2.
  /// A static body has zero kinetic energy.
  double kineticEnergy() const {
    const double linear = inverseMass > 0.0 ? velocity.squaredNorm() / inverseMass : 0.0;
    return 0.5 * (linear + angularVelocity.dot(angularMomentum));
  }
};

/// A dynamic body with mass m and body-frame principal moments of inertia, at rest
/// at the origin. Throws std::invalid_argument naming the bad value when the mass or a
/// moment is not finite and positive, or the moments violate the triangle inequality
/// (A + B >= C for every ordering; only in 3D).
template <int D>
RigidBody<D> makeDynamicBody(double mass, const AngVec<D>& principalInertia);

/// The checks of makeDynamicBody, for any code that accepts mass properties (\ref ch05):
/// throws std::invalid_argument whose message starts with `context` unless the mass is
/// finite and positive, every principal moment is finite and positive, and (in 3D) each
/// moment is at most the sum of the other two (A + B >= C, up to 1e-12 of the trace).
template <int D>
void validateMassProperties(const char* context, double mass, const AngVec<D>& principalInertia);

/// A static (immovable, infinite-mass) body at the given pose.
template <int D>
RigidBody<D> makeStaticBody(const Vec<D>& position = Vec<D>::Zero(),
                            const Orientation<D>& orientation = identityOrientation<D>()) {
  RigidBody<D> body;
  body.position = position;
  body.orientation = orientation;
  return body;
}

}  // namespace stackbook

#include "stackbook/body/rigid_body_impl.hpp"
