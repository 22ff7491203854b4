#pragma once
/// \file
/// \brief Exercise 4.2 (chapter 4): the collision matrix of a rigid body in four
/// dimensions, where an angular quantity has D(D-1)/2 = 6 components, one per plane.

#include <Eigen/Core>

namespace stackbook::exercises {

/// A linear vector of 4D space (x, y, z, w).
using Vec4 = Eigen::Matrix<double, 4, 1>;
/// A linear 4 x 4 matrix, e.g. the collision matrix K.
using Mat4 = Eigen::Matrix<double, 4, 4>;
/// An angular quantity of 4D space (a bivector): one component per coordinate plane, in
/// the order (xy, xz, xw, yz, yw, zw). A positive component (i, j) turns axis i toward
/// axis j, as omega_z > 0 turns x toward y in 3D.
using Bivec4 = Eigen::Matrix<double, 6, 1>;
/// The 4D cross-product matrix r*, 6 x 4: r ^ b = r* b.
using CrossMat4 = Eigen::Matrix<double, 6, 4>;

/// The 4D r*: the matrix of the wedge product b -> r ^ b, whose (i, j) component is
/// r_i b_j - r_j b_i (Eq. (4.9) of chapter 4), rows in the order of Bivec4.
CrossMat4 crossMatrix4(const Vec4& r);

/// K = delta/m + r*^T I^{-1} r* (Eq. (1.8) with D = 4) for a body whose inverse inertia
/// is diagonal in the plane basis: one inverse moment per plane, in the order of Bivec4.
Mat4 collisionMatrix4(double inverseMass, const Bivec4& inversePlaneInertia, const Vec4& r);

/// A rigid body of 4D space at the instant of an impulse, in a frame whose planes are its
/// principal planes (so its inverse inertia is diagonal). Uses crossMatrix4.
struct RigidBody4 {
  double inverseMass = 0.0;                       ///< 1/m
  Bivec4 inverseInertia = Bivec4::Zero();         ///< 1/I per plane
  Vec4 velocity = Vec4::Zero();                   ///< v
  Bivec4 angularVelocity = Bivec4::Zero();        ///< omega, one rate per plane

  /// u = v + omega x r = v + r*^T omega (Eqs. (1.4), (1.6) with D = 4).
  Vec4 pointVelocity(const Vec4& r) const {
    return velocity + crossMatrix4(r).transpose() * angularVelocity;
  }

  /// v += j/m and omega += I^{-1} r* j (Eqs. (1.1), (1.5) with D = 4).
  void applyImpulse(const Vec4& r, const Vec4& j) {
    velocity += inverseMass * j;
    angularVelocity += inverseInertia.cwiseProduct(crossMatrix4(r) * j);
  }
};

}  // namespace stackbook::exercises
