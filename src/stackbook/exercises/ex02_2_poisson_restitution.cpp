// Exercise 2.2 (stub): Poisson restitution.
// Implement: poissonImpulse. Delete every TODO(reader) comment once your code is in: while one
// is left, the exercise counts as not solved and its tests do not run.
// The reference solution is chapters/solutions/ex02_2_poisson_restitution.cpp.
#include "stackbook/exercises/ex02_2_poisson_restitution.hpp"

namespace stackbook::exercises {

template <int D>
PoissonImpulse<D> poissonImpulse([[maybe_unused]] const Mat<D>& K,
                                 [[maybe_unused]] const Vec<D>& u,
                                 [[maybe_unused]] const Vec<D>& n, [[maybe_unused]] double eP,
                                 [[maybe_unused]] double immovableTolerance) {
  // TODO(reader): find the compression impulse that ends the approach (u_n' = 0),
  // scale it by e_P for the restitution phase, and return both and their sum along n.
  return PoissonImpulse<D>{};  // no impulse
}

template PoissonImpulse<2> poissonImpulse<2>(const Mat<2>&, const Vec<2>&, const Vec<2>&, double,
                                             double);
template PoissonImpulse<3> poissonImpulse<3>(const Mat<3>&, const Vec<3>&, const Vec<3>&, double,
                                             double);

}  // namespace stackbook::exercises
