#pragma once
// A rotation that turns axis 0 towards the up axis D-1, the same in 2D and 3D: the tilted
// boxes of chapter 7's narrow-phase tests and the inclines of chapter 8's scenes.
#include <Eigen/Geometry>

#include "stackbook/math/rotation.hpp"
#include "stackbook/math/types.hpp"

namespace stackbook::testing {

/// A rotation by `angle` in the plane of axis 0 and the up axis (2D: about z; 3D: about -y).
template <int D>
Orientation<D> tilt(double angle) {
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(angle);
  } else {
    return Eigen::Quaterniond(Eigen::AngleAxisd(-angle, Vec3::UnitY()));
  }
}

}  // namespace stackbook::testing
