#pragma once
/// \file
/// \brief A rigid placement (position of the centre of mass and orientation) and the maps
/// between body and world frames. Collision detection (chapter 7) works with predicted
/// poses that are not the body's current one, so a pose is a value of its own.

#include "stackbook/math/rotation.hpp"

namespace stackbook {

// [pose]
template <int D>
struct Pose {
  Vec<D> position = Vec<D>::Zero();
  Orientation<D> orientation = identityOrientation<D>();

  /// Body-frame point to world frame: x + R p.
  Vec<D> toWorld(const Vec<D>& pBody) const { return position + orientation * pBody; }
  /// World-frame point to body frame: R^T (p - x).
  Vec<D> toBody(const Vec<D>& pWorld) const {
    return orientation.inverse() * Vec<D>(pWorld - position);
  }
  /// Body-frame direction to world frame: R d.
  Vec<D> directionToWorld(const Vec<D>& dBody) const { return orientation * dBody; }
  /// World-frame direction to body frame: R^T d.
  Vec<D> directionToBody(const Vec<D>& dWorld) const { return orientation.inverse() * dWorld; }
};
// [pose]

}  // namespace stackbook
