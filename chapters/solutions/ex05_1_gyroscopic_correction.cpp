// Exercise 5.1 (reference solution): the gyroscopic correction of the orientation update.
#include "stackbook/exercises/ex05_1_gyroscopic_correction.hpp"

namespace stackbook::exercises {

template <int D>
void advancePositionGyroscopic(RigidBody<D>& body, double dt) {
  if (body.isStatic()) {
    advancePosition<D>(body, dt);  // prescribed motion: nothing to correct
    return;
  }
  body.position += dt * body.velocity;  // Eq. (5.8)
  body.orientation = normalizedOrientation<D>(body.orientation);
  AngVec<D> w = body.angularVelocity;
  if constexpr (D == 3) {
    // Midpoint estimate: omega(t + dt/2) = omega - (dt/2) I^{-1} (omega x L), Eq. (5.6).
    const Vec3 gyroscopic = body.angularVelocity.cross(body.angularMomentum);
    w -= 0.5 * dt * (body.inverseInertiaWorld() * gyroscopic);
  }
  body.orientation = rotateByAngularVelocity<D>(body.orientation, w, dt);  // Eqs. (5.9)-(5.11)
  body.syncAngularVelocity();                                              // Eq. (5.12)
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
