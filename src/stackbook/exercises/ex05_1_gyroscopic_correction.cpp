// Exercise 5.1 (stub): the gyroscopic correction of the orientation update.
// Implement: advancePositionGyroscopic and advanceFreeBodyGyroscopic. Delete every TODO(reader)
// comment once your code is in: while one is left, the exercise counts as not solved and its
// tests do not run.
// The reference solution is chapters/solutions/ex05_1_gyroscopic_correction.cpp.
#include "stackbook/exercises/ex05_1_gyroscopic_correction.hpp"

namespace stackbook::exercises {

template <int D>
void advancePositionGyroscopic(RigidBody<D>& body, double dt) {
  // TODO(reader): turn the body with w = omega - (dt/2) I_world^{-1} (omega x L) instead of
  // omega. Until then this is the uncorrected update of the chapter.
  advancePosition<D>(body, dt);
}

template <int D>
void advanceFreeBodyGyroscopic(RigidBody<D>& body, double dt, const ExternalLoads<D>& loads) {
  advanceVelocity<D>(body, dt, loads);
  advancePositionGyroscopic<D>(body, dt);
}

template void advancePositionGyroscopic<2>(RigidBody<2>&, double);
template void advancePositionGyroscopic<3>(RigidBody<3>&, double);
template void advanceFreeBodyGyroscopic<2>(RigidBody<2>&, double, const ExternalLoads<2>&);
template void advanceFreeBodyGyroscopic<3>(RigidBody<3>&, double, const ExternalLoads<3>&);

}  // namespace stackbook::exercises
