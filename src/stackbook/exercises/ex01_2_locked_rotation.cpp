// Exercise 1.2 (your answer goes here): see ex01_2_locked_rotation.hpp and chapter 1.
// Implement: inverseInertiaLockedAbout and inverseInertiaHingedAbout. Delete every TODO(reader)
// comment once your code is in: while one is left, the exercise counts as not solved and its
// tests do not run.
#include "stackbook/exercises/ex01_2_locked_rotation.hpp"

namespace stackbook {

AngMat<3> inverseInertiaLockedAbout(const RigidBody<3>& body, const Vec3& a) {
  // TODO(reader): solve I dw = tau + lambda a, a . dw = 0 for dw = W tau.
  (void)body;
  (void)a;
  return AngMat<3>::Zero();
}

AngMat<3> inverseInertiaHingedAbout(const RigidBody<3>& body, const Vec3& a) {
  // TODO(reader): dw = s a; find s from the component of I dw = tau + reaction along a.
  (void)body;
  (void)a;
  return AngMat<3>::Zero();
}

}  // namespace stackbook
