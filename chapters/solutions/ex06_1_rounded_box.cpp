// Exercise 6.1, reference solution: the rounded box is the inner box grown by rho, so its
// signed distance is the inner box's minus rho (an offset surface of a convex set), and
// its gradient is the inner box's gradient.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stackbook/exercises/ex06_1_rounded_box.hpp"

namespace stackbook::exercises {

template <int D>
RoundedBoxSdf<D>::RoundedBoxSdf(const Vec<D>& h, double rho) : halfExtents(h), radius(rho) {
  for (int k = 0; k < D; ++k) {
    if (!std::isfinite(h[k]) || !(h[k] > 0.0)) {
      std::ostringstream msg;
      msg << "RoundedBoxSdf: half extent " << k << " must be finite and positive, got " << h[k];
      throw std::invalid_argument(msg.str());
    }
  }
  if (!(rho >= 0.0 && rho <= h.minCoeff())) {
    std::ostringstream msg;
    msg << "RoundedBoxSdf: radius must be in [0, " << h.minCoeff() << "] (the smallest half "
        << "extent), got " << rho;
    throw std::invalid_argument(msg.str());
  }
}

template <int D>
double RoundedBoxSdf<D>::distance(const Vec<D>& x) const {
  const Vec<D> q = x.cwiseAbs() - (halfExtents.array() - radius).matrix();
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0) - radius;
}

template <int D>
Vec<D> RoundedBoxSdf<D>::normal(const Vec<D>& x) const {
  const Vec<D> q = x.cwiseAbs() - (halfExtents.array() - radius).matrix();
  Eigen::Index k = 0;
  const double qmax = q.maxCoeff(&k);
  if (qmax > 0.0) {
    Vec<D> n = q.cwiseMax(0.0);
    for (int i = 0; i < D; ++i) n[i] *= x[i] >= 0.0 ? 1.0 : -1.0;
    return n.normalized();
  }
  Vec<D> n = Vec<D>::Zero();
  n[k] = x[k] >= 0.0 ? 1.0 : -1.0;
  return n;
}

template struct RoundedBoxSdf<2>;
template struct RoundedBoxSdf<3>;

}  // namespace stackbook::exercises
