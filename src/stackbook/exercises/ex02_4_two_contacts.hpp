#pragma once
/// \file
/// \brief Exercise 2.4: two contacts between the same pair of bodies, resolved at once as a
/// 2 x 2 complementarity problem instead of one after the other (chapter 2, "Exercises").

#include <array>

#include <Eigen/Core>

#include "stackbook/body/rigid_body.hpp"

namespace stackbook::exercises {

/// One contact between bodies a and b: the offsets of the contact point from each centre
/// of mass and the unit normal, pointing from b toward a (chapter 2 conventions).
template <int D>
struct ContactPoint {
  Vec<D> ra;
  Vec<D> rb;
  Vec<D> n;
};

/// The 2 x 2 matrix A of the pair: A(c, k) is the change of the normal relative velocity
/// u_n at contact c per unit normal impulse (+n_k on a, -n_k on b) at contact k,
///   A(c, k) = n_c^T K^{ck} n_k,
///   K^{ck} = delta/m_a + ra_c*^T I_a^{-1} ra_k* + delta/m_b + rb_c*^T I_b^{-1} rb_k*,
/// the two-point generalisation of the collision matrix of Eq. (1.8). A is symmetric
/// positive semidefinite, and its diagonal holds the n^T K n of each contact (Eq. (2.4)).
template <int D>
Eigen::Matrix2d twoContactMatrix(const RigidBody<D>& a, const RigidBody<D>& b,
                                 const std::array<ContactPoint<D>, 2>& contacts);

/// Normal impulse magnitudes (j_1, j_2), applied at the same time (+j_c n_c on a, -j_c n_c on
/// b), that satisfy Newton restitution at both contacts in the complementarity sense:
/// with u_c the normal relative velocity before and w_c = u_c' + e min(u_c, 0) after,
///   j_c >= 0,  w_c >= 0,  j_c w_c = 0   for c = 1, 2.
/// An active contact (j_c > 0) leaves at exactly -e u_c; an inactive one is not made to
/// approach. Find it by trying the active sets {1, 2}, {1}, {2}, {} in that order and
/// returning the first that meets all the conditions, to a relative tolerance of 1e-12.
/// No approaching contact returns (0, 0); so does a pair for which no active set works
/// (an immovable pair, A = 0, with an approaching contact). Throws std::invalid_argument
/// when e is not in [0, 1].
template <int D>
Eigen::Vector2d simultaneousNormalImpulses(const RigidBody<D>& a, const RigidBody<D>& b,
                                           const std::array<ContactPoint<D>, 2>& contacts,
                                           double e);

}  // namespace stackbook::exercises
