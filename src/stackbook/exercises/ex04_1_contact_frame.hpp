#pragma once
/// \file
/// \brief Exercise 4.1 (chapter 4): the 2D pair collision matrix in the contact frame, in
/// closed form, and the friction coefficient at which the sliding impulse breaks down.

#include "stackbook/body/rigid_body.hpp"

namespace stackbook::exercises {

/// The entries of the 2D pair collision matrix K_T = K_a + K_b in the contact frame
/// (n, t), where t = (-n_y, n_x) is the unit normal turned by +90 degrees.
struct ContactFrameK {
  double nn = 0.0;  ///< n^T K_T n
  double nt = 0.0;  ///< n^T K_T t (= t^T K_T n)
  double tt = 0.0;  ///< t^T K_T t
};

/// The three entries of K_T in the contact frame, computed in closed form from the inverse
/// masses, the scalar inverse moments 1/I and the lever arms, without forming K_T.
/// Body a receives +j at ra, body b receives -j at rb; n is a unit vector.
ContactFrameK contactFrameK(const RigidBody<2>& a, const Vec2& ra, const RigidBody<2>& b,
                            const Vec2& rb, const Vec2& n);

/// The smallest friction coefficient mu >= 0 at which the kinetic denominator
/// n^T K_T (n - mu T) of Eq. (3.5) reaches zero, for sliding along T = slipSign * t
/// (slipSign = +1 or -1). Returns +infinity when no such mu exists.
double painleveFriction(const ContactFrameK& k, double slipSign);

}  // namespace stackbook::exercises
