// Exercise 2.1 (reference solution): the impulse that makes a contact separate at a
// target normal speed s.
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "stackbook/exercises/ex02_1_separation_speed.hpp"

namespace stackbook::exercises {

template <int D>
ContactImpulse<D> separationSpeedImpulse(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n,
                                         double s, double immovableTolerance) {
  if (!std::isfinite(s)) {
    std::ostringstream msg;
    msg << "separationSpeedImpulse: target separation speed s must be finite, got " << s;
    throw std::invalid_argument(msg.str());
  }
  ContactImpulse<D> result;
  const double un = u.dot(n);
  if (!(un < s)) return result;  // already separating at least as fast: never pull
  const double knn = n.dot(K * n);
  if (!(knn > immovableTolerance * K.trace())) {
    result.branch = ImpulseBranch::Immovable;
    return result;
  }
  result.j = ((s - un) / knn) * n;  // Eq. (2.2) with u_n' = s
  result.branch = ImpulseBranch::Frictionless;
  return result;
}

template ContactImpulse<2> separationSpeedImpulse<2>(const Mat<2>&, const Vec<2>&, const Vec<2>&,
                                                     double, double);
template ContactImpulse<3> separationSpeedImpulse<3>(const Mat<3>&, const Vec<3>&, const Vec<3>&,
                                                     double, double);

}  // namespace stackbook::exercises
