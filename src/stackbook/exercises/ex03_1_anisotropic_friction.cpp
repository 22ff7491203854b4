// Exercise 3.1 (stub): anisotropic friction, the elliptic cone.
// Implement: anisotropicFrictionalImpulse. Delete every TODO(reader) comment once your code is
// in: while one is left, the exercise counts as not solved and its tests do not run.
// The reference solution is chapters/solutions/ex03_1_anisotropic_friction.cpp.
#include "stackbook/exercises/ex03_1_anisotropic_friction.hpp"

namespace stackbook::exercises {

ContactImpulse<3> anisotropicFrictionalImpulse([[maybe_unused]] const Mat3& K,
                                               [[maybe_unused]] const Vec3& u,
                                               [[maybe_unused]] const Vec3& n,
                                               [[maybe_unused]] double e,
                                               [[maybe_unused]] const AnisotropicFriction& friction) {
  // TODO(reader): try sticking inside the elliptic cone, else slide with the friction
  // f = -M^2 s / |M s| that dissipates most (see the header and chapter 3).
  return ContactImpulse<3>{};  // no impulse
}

}  // namespace stackbook::exercises
