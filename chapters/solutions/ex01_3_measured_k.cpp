// Exercise 1.3, reference solution. The velocity change is exactly linear in the impulse,
// so one experiment per axis measures K_T with no truncation error: only the rounding in
// u' - u remains, about eps |u| / s.
#include "stackbook/exercises/ex01_3_measured_k.hpp"

namespace stackbook {

template <int D>
Mat<D> measuredCollisionMatrix(const RigidBody<D>& a, const Vec<D>& ra, const RigidBody<D>& b,
                               const Vec<D>& rb, double s) {
  const Vec<D> before = a.pointVelocity(ra) - b.pointVelocity(rb);
  Mat<D> K;
  for (int i = 0; i < D; ++i) {
    RigidBody<D> aCopy = a, bCopy = b;
    const Vec<D> j = s * Vec<D>::Unit(i);
    aCopy.applyImpulse(ra, j);
    bCopy.applyImpulse(rb, -j);
    const Vec<D> after = aCopy.pointVelocity(ra) - bCopy.pointVelocity(rb);
    K.col(i) = (after - before) / s;
  }
  return K;
}

template Mat<2> measuredCollisionMatrix<2>(const RigidBody<2>&, const Vec<2>&,
                                           const RigidBody<2>&, const Vec<2>&, double);
template Mat<3> measuredCollisionMatrix<3>(const RigidBody<3>&, const Vec<3>&,
                                           const RigidBody<3>&, const Vec<3>&, double);

}  // namespace stackbook
