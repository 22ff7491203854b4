// Exercise 3.3 (stub): rolling and spinning friction.
// Implement: rollingFrictionImpulse and applyRollingFriction. Delete every TODO(reader) comment
// once your code is in: while one is left, the exercise counts as not solved and its tests do
// not run.
// The reference solution is chapters/solutions/ex03_3_rolling_friction.cpp.
#include "stackbook/exercises/ex03_3_rolling_friction.hpp"

namespace stackbook::exercises {

RollingFrictionImpulse rollingFrictionImpulse([[maybe_unused]] const RigidBody<3>& a,
                                              [[maybe_unused]] const Vec3& ra,
                                              [[maybe_unused]] const RigidBody<3>& b,
                                              [[maybe_unused]] const Vec3& rb,
                                              [[maybe_unused]] const Vec3& n,
                                              [[maybe_unused]] double jn,
                                              [[maybe_unused]] double muRolling) {
  // TODO(reader): shrink spin and roll by muRolling * jn, then solve the 6 x 6 system
  // of the header for (j, tau).
  return RollingFrictionImpulse{};  // no impulse
}

void applyRollingFriction(RigidBody<3>& a, const Vec3& ra, RigidBody<3>& b, const Vec3& rb,
                          const RollingFrictionImpulse& impulse) {
  a.applyImpulse(ra, impulse.j);
  a.applyAngularImpulse(impulse.tau);
  b.applyImpulse(rb, Vec3(-impulse.j));
  b.applyAngularImpulse(Vec3(-impulse.tau));
}

}  // namespace stackbook::exercises
