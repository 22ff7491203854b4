// Exercise 3.2 (chapter 3): the sticking trial projected onto the friction cone, the
// reference solution.
#include "stackbook/exercises/ex03_2_cone_projection.hpp"

#include "stackbook/impulse/frictional_impulse.hpp"

namespace stackbook::exercises {

template <int D>
ContactImpulse<D> projectedFrictionalImpulse(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n,
                                             double e, double mu) {
  const ContactImpulse<D> frictionless = frictionlessImpulse<D>(K, u, n, e);
  if (mu == 0.0 || frictionless.branch != ImpulseBranch::Frictionless) return frictionless;
  Vec<D> jStick = Vec<D>::Zero();
  const double un = u.dot(n);
  if (!solveCollisionMatrix<D>(K, Vec<D>(-e * un * n - u), FrictionSettings{}, jStick)) {
    return frictionless;
  }
  const double jn = jStick.dot(n);
  if (!(jn > 0.0)) return frictionless;  // sticking would pull: nothing to project
  const Vec<D> jt = jStick - jn * n;
  ContactImpulse<D> result = frictionless;
  result.friction = mu;
  if (jt.norm() <= mu * jn) {
    result.j = jStick;
    result.branch = ImpulseBranch::Sticking;
  } else {
    result.j = jn * n + (mu * jn / jt.norm()) * jt;
    result.branch = ImpulseBranch::Sliding;
  }
  return result;
}

template ContactImpulse<2> projectedFrictionalImpulse<2>(const Mat<2>&, const Vec<2>&, const Vec<2>&,
                                                         double, double);
template ContactImpulse<3> projectedFrictionalImpulse<3>(const Mat<3>&, const Vec<3>&, const Vec<3>&,
                                                         double, double);

}  // namespace stackbook::exercises
