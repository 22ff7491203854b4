// Exercise 1.3 (your answer goes here): see ex01_3_measured_k.hpp and chapter 1.
// Implement: measuredCollisionMatrix. Delete every TODO(reader) comment once your code is in:
// while one is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex01_3_measured_k.hpp"

namespace stackbook {

template <int D>
Mat<D> measuredCollisionMatrix(const RigidBody<D>& a, const Vec<D>& ra, const RigidBody<D>& b,
                               const Vec<D>& rb, double s) {
  // TODO(reader): one experiment per column: copy the bodies, apply +s e_i and -s e_i,
  // and divide the change in relative point velocity by s.
  (void)a;
  (void)ra;
  (void)b;
  (void)rb;
  (void)s;
  return Mat<D>::Zero();
}

template Mat<2> measuredCollisionMatrix<2>(const RigidBody<2>&, const Vec<2>&,
                                           const RigidBody<2>&, const Vec<2>&, double);
template Mat<3> measuredCollisionMatrix<3>(const RigidBody<3>&, const Vec<3>&,
                                           const RigidBody<3>&, const Vec<3>&, double);

}  // namespace stackbook
