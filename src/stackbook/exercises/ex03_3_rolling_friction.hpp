#pragma once
/// \file
/// \brief Exercise 3.3 (\ref ch03): rolling and spinning friction, the last part of
/// GBF's friction model.
///
/// A ball that sticks at its contact still rolls, and a top still spins, for ever: the
/// impulse of chapter 3 acts at one point and cannot brake a rotation about that point.
/// GBF adds rolling and spinning friction after a sticking impulse with normal part j_n.
/// Split the relative angular velocity w = w_a - w_b into spin w_s = (w . n) n and roll
/// w_r = w - w_s. Shrink the length of each by mu_r j_n, stopping at zero (never
/// reversing), which gives the target w'. Then find a linear impulse j at the contact
/// (+j on a at ra, -j on b at rb) and an angular impulse tau (+tau on a, -tau on b) that
/// change w to w' while leaving the contact point velocity u unchanged:
///
///     [ K    C      ] [ j   ]   [ 0        ]
///     [ C^T  Ia^-1 + Ib^-1 ] [ tau ] = [ w' - w ],   C = ra*^T Ia^-1 + rb*^T Ib^-1,
///
/// with K the pair's collision matrix of Eq. (1.10) and Ia^-1, Ib^-1 the world inverse
/// inertias. Derive the blocks first (the first row is the change of u, the second the
/// change of w). The 6 x 6 matrix is symmetric positive definite when a body can rotate
/// freely; solve it with a factorisation. If it is singular, return zero impulses.

#include "stackbook/body/rigid_body.hpp"

namespace stackbook::exercises {

/// The impulses of rolling and spinning friction: apply +j at ra and +tau to body a,
/// -j at rb and -tau to body b.
struct RollingFrictionImpulse {
  Vec3 j = Vec3::Zero();
  Vec3 tau = Vec3::Zero();
};

/// Rolling and spinning friction with coefficient muRolling after a sticking impulse whose
/// normal component is jn (Exercise 3.3). n is the unit normal from b toward a.
RollingFrictionImpulse rollingFrictionImpulse(const RigidBody<3>& a, const Vec3& ra,
                                              const RigidBody<3>& b, const Vec3& rb,
                                              const Vec3& n, double jn, double muRolling);

/// Applies the impulses of rollingFrictionImpulse to the two bodies.
void applyRollingFriction(RigidBody<3>& a, const Vec3& ra, RigidBody<3>& b, const Vec3& rb,
                          const RollingFrictionImpulse& impulse);

}  // namespace stackbook::exercises
