// Exercise 2.2 (reference solution): Poisson restitution. The compression phase ends the
// approach; the restitution phase returns e_P times the compression impulse.
#include <sstream>
#include <stdexcept>

#include "stackbook/exercises/ex02_2_poisson_restitution.hpp"

namespace stackbook::exercises {

template <int D>
PoissonImpulse<D> poissonImpulse(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n, double eP,
                                 double immovableTolerance) {
  if (!(eP >= 0.0 && eP <= 1.0)) {
    std::ostringstream msg;
    msg << "poissonImpulse: Poisson restitution e_P must be in [0, 1], got " << eP;
    throw std::invalid_argument(msg.str());
  }
  PoissonImpulse<D> result;
  const double un = u.dot(n);
  if (!(un < 0.0)) return result;  // Eq. (2.1)
  const double knn = n.dot(K * n);
  if (!(knn > immovableTolerance * K.trace())) return result;
  result.compression = -un / knn;  // Eq. (2.2) with u_n' = 0
  result.restitution = eP * result.compression;
  result.j = (result.compression + result.restitution) * n;
  return result;
}

template PoissonImpulse<2> poissonImpulse<2>(const Mat<2>&, const Vec<2>&, const Vec<2>&, double,
                                             double);
template PoissonImpulse<3> poissonImpulse<3>(const Mat<3>&, const Vec<3>&, const Vec<3>&, double,
                                             double);

}  // namespace stackbook::exercises
