#pragma once
/// \file
/// \brief The collision matrix K, which maps an impulse to the change in point velocity
/// (\ref ch01, Eqs. (1.8)-(1.10)).

#include "stackbook/body/rigid_body.hpp"

namespace stackbook {

// [collision_matrix]
/// K for one body at the contact offset r (Eq. (1.8)):
/// K = delta/m + r*^T I^{-1} r*, with I^{-1} the world-frame inverse inertia.
/// A static body has 1/m = 0 and I^{-1} = 0, so its K is zero (Eq. (1.9)).
/// This overload takes the mass properties directly, so a constrained body (a locked
/// translation, a hinge; exercise 1.2 of \ref ch01) can pass its own 1/m and I^{-1}.
template <int D>
Mat<D> collisionMatrix(double inverseMass, const AngMat<D>& inverseInertiaWorld,
                       const Vec<D>& r) {
  const CrossMat<D> rs = crossMatrix<D>(r);  // Eq. (1.3)
  // Eq. (1.8): the translational part delta/m plus the rotational part r*^T I^{-1} r*.
  return inverseMass * Mat<D>::Identity() + rs.transpose() * inverseInertiaWorld * rs;
}

/// K of a body at the contact offset r (world frame, from the centre of mass), Eq. (1.8).
template <int D>
Mat<D> collisionMatrix(const RigidBody<D>& body, const Vec<D>& r) {
  return collisionMatrix<D>(body.inverseMass, body.inverseInertiaWorld(), r);
}
// [collision_matrix]

// [pair_collision_matrix]
/// K_T = K_a + K_b for a contact where body a receives +j at offset ra and body b
/// receives -j at offset rb (Eq. (1.10)): u_rel' = u_rel + K_T j with u_rel = u_a - u_b.
/// The result is symmetrised so that rounding cannot make it unsymmetric.
template <int D>
Mat<D> pairCollisionMatrix(const RigidBody<D>& a, const Vec<D>& ra,
                           const RigidBody<D>& b, const Vec<D>& rb) {
  const Mat<D> K = collisionMatrix<D>(a, ra) + collisionMatrix<D>(b, rb);
  return 0.5 * (K + K.transpose());
}
// [pair_collision_matrix]

// [relative_velocity]
/// Relative velocity of the contact point, u_rel = u_a - u_b (Eq. (1.10)).
template <int D>
Vec<D> relativeVelocity(const RigidBody<D>& a, const Vec<D>& ra,
                        const RigidBody<D>& b, const Vec<D>& rb) {
  return a.pointVelocity(ra) - b.pointVelocity(rb);
}

/// Apply +j to body a at ra and -j to body b at rb (the pair impulse of Eq. (1.10)).
template <int D>
void applyPairImpulse(RigidBody<D>& a, const Vec<D>& ra, RigidBody<D>& b, const Vec<D>& rb,
                      const Vec<D>& j) {
  a.applyImpulse(ra, j);
  b.applyImpulse(rb, -j);
}
// [relative_velocity]

}  // namespace stackbook
