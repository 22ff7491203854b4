#pragma once
/// \file
/// \brief Orientations in 2D (an angle) and 3D (a unit quaternion), and how each
/// rotates linear and angular quantities (\ref ch01, Eq. (1.7); chapter 5).

#include <cmath>

#include "stackbook/math/types.hpp"

namespace stackbook {

// [orientation_types]
/// The orientation of a body: a rotation angle in 2D, a unit quaternion in 3D.
template <int D>
struct OrientationOf;
template <>
struct OrientationOf<2> {
  using type = Eigen::Rotation2Dd;
};
template <>
struct OrientationOf<3> {
  using type = Eigen::Quaterniond;
};
template <int D>
using Orientation = typename OrientationOf<D>::type;
// [orientation_types]

/// The identity orientation.
template <int D>
Orientation<D> identityOrientation() {
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(0.0);
  } else {
    return Eigen::Quaterniond::Identity();
  }
}

/// Rotation matrix R acting on linear vectors (body frame to world frame).
template <int D>
Mat<D> rotationMatrix(const Orientation<D>& q) {
  return q.toRotationMatrix();
}

// [angular_rotation]
/// The matrix that carries an angular quantity from the body frame to the world frame.
/// In 3D angular vectors rotate like linear ones (R). In 2D the single angular
/// component is the z axis, which an in-plane rotation leaves alone, so it is [1].
template <int D>
AngMat<D> angularRotationMatrix(const Orientation<D>& q) {
  if constexpr (D == 2) {
    (void)q;
    return AngMat<2>::Identity();
  } else {
    return q.toRotationMatrix();
  }
}
// [angular_rotation]

/// Angle of the rotation in radians (2D: the angle; 3D: the rotation angle about its axis).
template <int D>
double rotationAngle(const Orientation<D>& q) {
  if constexpr (D == 2) {
    return q.angle();
  } else {
    return Eigen::AngleAxisd(q).angle();
  }
}

}  // namespace stackbook
