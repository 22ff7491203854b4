#pragma once
/// \file
/// \brief Exercise 2.1: the frictionless impulse that makes a contact separate at a
/// prescribed normal speed (chapter 2, "Exercises").

#include "stackbook/impulse/frictionless_impulse.hpp"

namespace stackbook::exercises {

/// The frictionless impulse j = j_n n after which the contact separates at the target
/// normal speed s: u_n' = s. From Eq. (2.2), j_n = (s - u_n) / (n^T K n).
///
/// - A contact that already separates at least as fast as s (u_n >= s) gets no impulse
///   (branch Separating): an impulse never pulls.
/// - n^T K n <= immovableTolerance * trace(K): no impulse (branch Immovable), as in
///   frictionlessImpulse.
/// - Otherwise the branch is Frictionless. The restitution field is left at 0.
///
/// Unlike Newton restitution, the target does not scale with the approach speed, and a
/// contact that separates slowly (0 <= u_n < s) is pushed too.
/// Throws std::invalid_argument when s is not finite.
template <int D>
ContactImpulse<D> separationSpeedImpulse(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n,
                                         double s,
                                         double immovableTolerance = kDefaultImmovableTolerance);

}  // namespace stackbook::exercises
