#pragma once
/// \file
/// \brief Exercise 3.2 (\ref ch03): the OpenTissue alternative to the kinetic impulse,
/// projecting the sticking trial onto the friction cone.
///
/// When the sticking trial j* of Eq. (3.2) leaves the cone, chapter 3 builds a new impulse
/// along n - mu T (Eq. (3.5)) that meets the normal target u_n' = -e u_n. OpenTissue (and
/// Jolt, for its tangential impulse) instead keep the sticking trial's normal component and
/// scale its tangential part back onto the cone:
///
///     j = j*_n n + (mu j*_n / |j*_t|) j*_t .
///
/// Implement projectedFrictionalImpulse:
/// 1. not approaching, immovable, or mu = 0: the frictionless impulse of chapter 2;
/// 2. j* with j*_n > 0 inside the cone (Eq. (3.3)): j*, branch Sticking;
/// 3. j*_n > 0 outside the cone: the projection above, branch Sliding;
/// 4. j*_n <= 0 (sticking would pull; there is nothing to project): the frictionless impulse.
/// Set restitution = e and friction = mu. No energy rule: e is used as given.
/// The tests compare it with the chapter's impulse: where they agree, and where the
/// projection misses the normal target.

#include "stackbook/impulse/contact_impulse.hpp"

namespace stackbook::exercises {

/// The sticking trial projected onto the friction cone (Exercise 3.2).
template <int D>
ContactImpulse<D> projectedFrictionalImpulse(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n,
                                             double e, double mu);

}  // namespace stackbook::exercises
