// Exercise 1.2, reference solution.
//
// Locked about a: I dw = tau + lambda a and a . dw = 0. With W0 = I^{-1} (world frame),
// dw = W0 tau + lambda W0 a; the constraint gives lambda = -(a . W0 tau)/(a . W0 a), so
//   W = W0 - (W0 a)(W0 a)^T / (a^T W0 a),
// a rank-one downdate of W0 (W0 is symmetric). If a^T W0 a = 0 the body cannot turn
// about a anyway and W = W0.
//
// Hinged about a: dw = s a, and the reaction torque is perpendicular to a, so the
// component along a of I dw = tau + reaction reads s (a^T I a) = a . tau:
//   W = a a^T / (a^T I a),  with a^T I a = sum_k I_k (R^T a)_k^2 from the body-frame moments.
#include "stackbook/exercises/ex01_2_locked_rotation.hpp"

namespace stackbook {

AngMat<3> inverseInertiaLockedAbout(const RigidBody<3>& body, const Vec3& a) {
  const AngMat<3> W0 = body.inverseInertiaWorld();
  const Vec3 W0a = W0 * a;
  const double aW0a = a.dot(W0a);
  if (!(aW0a > 0.0)) return W0;
  return W0 - W0a * W0a.transpose() / aW0a;
}

AngMat<3> inverseInertiaHingedAbout(const RigidBody<3>& body, const Vec3& a) {
  const Vec3 aBody = body.orientation.inverse() * a;
  const double aIa = aBody.cwiseAbs2().dot(body.inertia);  // a^T I_world a
  return a * a.transpose() / aIa;
}

}  // namespace stackbook
