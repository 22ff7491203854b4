// Exercise 2.4 (stub): two contacts resolved at once.
// Implement: twoContactMatrix and simultaneousNormalImpulses. Delete every TODO(reader) comment
// once your code is in: while one is left, the exercise counts as not solved and its tests do
// not run.
// The reference solution is chapters/solutions/ex02_4_two_contacts.cpp.
#include "stackbook/exercises/ex02_4_two_contacts.hpp"

namespace stackbook::exercises {

template <int D>
Eigen::Matrix2d twoContactMatrix([[maybe_unused]] const RigidBody<D>& a,
                                 [[maybe_unused]] const RigidBody<D>& b,
                                 [[maybe_unused]] const std::array<ContactPoint<D>, 2>& contacts) {
  // TODO(reader): A(c, k) = n_c^T K^{ck} n_k, from the offsets of both contacts.
  return Eigen::Matrix2d::Zero();
}

template <int D>
Eigen::Vector2d simultaneousNormalImpulses(
    [[maybe_unused]] const RigidBody<D>& a, [[maybe_unused]] const RigidBody<D>& b,
    [[maybe_unused]] const std::array<ContactPoint<D>, 2>& contacts, [[maybe_unused]] double e) {
  // TODO(reader): try the active sets {1, 2}, {1}, {2}, {} and keep the first whose
  // impulses are non-negative and leave no contact approaching faster than allowed.
  return Eigen::Vector2d::Zero();  // no impulse
}

template Eigen::Matrix2d twoContactMatrix<2>(const RigidBody<2>&, const RigidBody<2>&,
                                             const std::array<ContactPoint<2>, 2>&);
template Eigen::Matrix2d twoContactMatrix<3>(const RigidBody<3>&, const RigidBody<3>&,
                                             const std::array<ContactPoint<3>, 2>&);
template Eigen::Vector2d simultaneousNormalImpulses<2>(const RigidBody<2>&, const RigidBody<2>&,
                                                       const std::array<ContactPoint<2>, 2>&,
                                                       double);
template Eigen::Vector2d simultaneousNormalImpulses<3>(const RigidBody<3>&, const RigidBody<3>&,
                                                       const std::array<ContactPoint<3>, 2>&,
                                                       double);

}  // namespace stackbook::exercises
