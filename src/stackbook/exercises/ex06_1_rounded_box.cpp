// Exercise 6.1 (your answer goes here): see ex06_1_rounded_box.hpp and chapter 6.
// Implement: RoundedBoxSdf (distance and normal). Delete every TODO(reader) comment once your
// code is in: while one is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex06_1_rounded_box.hpp"

namespace stackbook::exercises {

template <int D>
RoundedBoxSdf<D>::RoundedBoxSdf(const Vec<D>& h, double rho) : halfExtents(h), radius(rho) {
  // TODO(reader): reject non-finite or non-positive half extents and a radius outside
  // [0, smallest half extent], naming the argument.
}

template <int D>
double RoundedBoxSdf<D>::distance(const Vec<D>& x) const {
  // TODO(reader): the distance to the inner box (half extents h - rho), minus rho.
  (void)x;
  return 0.0;
}

template <int D>
Vec<D> RoundedBoxSdf<D>::normal(const Vec<D>& x) const {
  // TODO(reader): the gradient of distance(x).
  (void)x;
  return Vec<D>::Zero();
}

template struct RoundedBoxSdf<2>;
template struct RoundedBoxSdf<3>;

}  // namespace stackbook::exercises
