// Exercise 2.1 (stub): the impulse that makes a contact separate at a target speed.
// Implement: separationSpeedImpulse. Delete every TODO(reader) comment once your code is in:
// while one is left, the exercise counts as not solved and its tests do not run.
// The reference solution is chapters/solutions/ex02_1_separation_speed.cpp.
#include "stackbook/exercises/ex02_1_separation_speed.hpp"

namespace stackbook::exercises {

template <int D>
ContactImpulse<D> separationSpeedImpulse([[maybe_unused]] const Mat<D>& K,
                                         [[maybe_unused]] const Vec<D>& u,
                                         [[maybe_unused]] const Vec<D>& n,
                                         [[maybe_unused]] double s,
                                         [[maybe_unused]] double immovableTolerance) {
  // TODO(reader): solve Eq. (2.2) for the j_n that gives u_n' = s, with the same
  // Separating and Immovable branches as frictionlessImpulse (Eqs. (2.1), (2.3)).
  return ContactImpulse<D>{};  // no impulse
}

template ContactImpulse<2> separationSpeedImpulse<2>(const Mat<2>&, const Vec<2>&, const Vec<2>&,
                                                     double, double);
template ContactImpulse<3> separationSpeedImpulse<3>(const Mat<3>&, const Vec<3>&, const Vec<3>&,
                                                     double, double);

}  // namespace stackbook::exercises
