#pragma once
/// \file
/// \brief The frictionless impulse with Newton restitution (\ref ch02, Eqs. (2.1)-(2.3)).

#include <sstream>
#include <stdexcept>

#include "stackbook/impulse/contact_impulse.hpp"

namespace stackbook {

/// Tolerance for "K gives no response along n": n^T K n <= tolerance * trace(K).
inline constexpr double kDefaultImmovableTolerance = 1e-12;

/// Throws std::invalid_argument unless the restitution e is a number in [-1, 1].
/// e in [0, 1] is a collision (0 plastic, 1 elastic); e in [-1, 0) only slows an
/// approach, as the contact stage of chapter 8 uses it. e > 1 would create energy
/// (Eq. (2.7)) and e < -1 would pull the bodies together (Eq. (2.3)).
inline void checkRestitution(double e, const char* caller) {
  if (e >= -1.0 && e <= 1.0) return;  // false for NaN as well
  std::ostringstream msg;
  msg << caller << ": restitution e must be in [-1, 1], got " << e;
  throw std::invalid_argument(msg.str());
}

// [frictionless_impulse]
/// Frictionless impulse along the unit normal n for the relative contact velocity u,
/// with restitution e (Eq. (2.3)): j = j_n n, j_n = -(1 + e) u_n / (n^T K n).
/// Only approaching contacts (u_n < 0) get an impulse (Eq. (2.1)). Restitution is
/// e in [0, 1] for collisions; the contact stage of chapter 8 also uses e in [-1, 0].
/// Throws std::invalid_argument when e is not in [-1, 1].
template <int D>
ContactImpulse<D> frictionlessImpulse(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n,
                                      double e,
                                      double immovableTolerance = kDefaultImmovableTolerance) {
  checkRestitution(e, "frictionlessImpulse");
  ContactImpulse<D> result;
  result.restitution = e;
  const double un = u.dot(n);
  if (!(un < 0.0)) return result;  // separating or resting: Eq. (2.1)
  const double knn = n.dot(K * n);  // n^T K n of Eq. (2.2)
  if (!(knn > immovableTolerance * K.trace())) {  // also catches K = 0
    result.branch = ImpulseBranch::Immovable;
    return result;
  }
  const double jn = -(1.0 + e) * un / knn;  // Eq. (2.3)
  result.j = jn * n;
  result.branch = ImpulseBranch::Frictionless;
  return result;
}
// [frictionless_impulse]

}  // namespace stackbook
