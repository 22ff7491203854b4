#pragma once
/// \file
/// \brief Exercise 1.3: the collision matrix measured by experiment, one column per unit
/// impulse, with no formula for K at all (\ref ch01).

#include "stackbook/body/rigid_body.hpp"

namespace stackbook {

/// K_T of the contact where body a (offset ra) receives +j and body b (offset rb)
/// receives -j, measured: for each axis e_i, apply the impulse s e_i to copies of the two
/// bodies (applyImpulse) and record the change of the relative point velocity
/// u_a - u_b (pointVelocity). Column i of K_T is that change divided by s.
/// The bodies passed in are not changed. s is the impulse size, s > 0.
template <int D>
Mat<D> measuredCollisionMatrix(const RigidBody<D>& a, const Vec<D>& ra, const RigidBody<D>& b,
                               const Vec<D>& rb, double s = 1.0);

}  // namespace stackbook
