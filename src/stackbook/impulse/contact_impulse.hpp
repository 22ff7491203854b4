#pragma once
/// \file
/// \brief The result of an impulse computation: the impulse and which branch produced it
/// (\ref ch02, \ref ch03).

#include <cstdint>

#include "stackbook/math/types.hpp"

namespace stackbook {

/// Which formula produced an impulse. Stages count these (chapter 8).
enum class ImpulseBranch : std::uint8_t {
  Separating,    ///< u_n >= 0: the contact is not approaching, no impulse (Eq. (2.1))
  Immovable,     ///< K gives no normal response (both bodies static, or n^T K n ~ 0)
  Frictionless,  ///< normal impulse only (Eq. (2.3)); also mu = 0
  Sticking,      ///< static friction: the tangential velocity is stopped (Eq. (3.2))
  Sliding,       ///< kinetic friction on the cone boundary (Eq. (3.5))
};

/// Human-readable name of a branch ("sticking", ...).
constexpr const char* branchName(ImpulseBranch b) {
  switch (b) {
    case ImpulseBranch::Separating: return "separating";
    case ImpulseBranch::Immovable: return "immovable";
    case ImpulseBranch::Frictionless: return "frictionless";
    case ImpulseBranch::Sticking: return "sticking";
    case ImpulseBranch::Sliding: return "sliding";
  }
  return "unknown";
}

// [contact_impulse]
/// An impulse j for a contact (apply +j to the first body, -j to the second), the branch
/// that produced it, and the coefficients that were actually used. The safeguards of
/// \ref ch03 may lower restitution or friction for one impulse; when they do, the
/// corresponding flag says so.
template <int D>
struct ContactImpulse {
  Vec<D> j = Vec<D>::Zero();
  ImpulseBranch branch = ImpulseBranch::Separating;
  double restitution = 0.0;  ///< e used (may be lowered so the impulse adds no energy)
  double friction = 0.0;     ///< mu used (may be lowered: Painleve guard or energy)
  bool restitutionLowered = false;   ///< sticking target lowered to stop an energy gain
  bool frictionLowered = false;      ///< kinetic mu lowered (Painleve or energy guard)
  bool slipFromImpulse = false;      ///< slip direction T* = -j*_t/|j*_t| from the sticking trial (u_t ~ 0, a reversed slip, the StickingImpulse rule, or the Painleve switch of Eq. (3.7))
  bool singularK = false;            ///< K singular: no sticking trial; slid along u_t (mu kept to the Painleve margin) or applied the normal impulse

  /// Normal component j . n of the impulse.
  double normal(const Vec<D>& n) const { return j.dot(n); }
};
// [contact_impulse]

}  // namespace stackbook
