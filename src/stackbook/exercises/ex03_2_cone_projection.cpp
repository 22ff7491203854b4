// Exercise 3.2 (stub): the sticking trial projected onto the friction cone.
// Implement: projectedFrictionalImpulse. Delete every TODO(reader) comment once your code is in:
// while one is left, the exercise counts as not solved and its tests do not run.
// The reference solution is chapters/solutions/ex03_2_cone_projection.cpp.
#include "stackbook/exercises/ex03_2_cone_projection.hpp"

namespace stackbook::exercises {

template <int D>
ContactImpulse<D> projectedFrictionalImpulse([[maybe_unused]] const Mat<D>& K,
                                             [[maybe_unused]] const Vec<D>& u,
                                             [[maybe_unused]] const Vec<D>& n,
                                             [[maybe_unused]] double e, [[maybe_unused]] double mu) {
  // TODO(reader): solve for the sticking trial j* (Eq. (3.2)); keep it inside the cone,
  // otherwise keep j*_n and scale j*_t to length mu j*_n.
  return ContactImpulse<D>{};  // no impulse
}

template ContactImpulse<2> projectedFrictionalImpulse<2>(const Mat<2>&, const Vec<2>&, const Vec<2>&,
                                                         double, double);
template ContactImpulse<3> projectedFrictionalImpulse<3>(const Mat<3>&, const Vec<3>&, const Vec<3>&,
                                                         double, double);

}  // namespace stackbook::exercises
