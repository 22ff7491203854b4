// Exercise 4.2 stub: your starting point. The tests are in tests/ch04/exercises.cpp:
// Implement: crossMatrix4 and collisionMatrix4. Delete every TODO(reader) comment once your code
// is in: while one is left, the exercise counts as not solved and its tests do not run.
//   build/exercises/tests/ch04/test_ch04_exercises --no-skip -ts=ch04_exercises -tc="Exercise 4.2*"
#include "stackbook/exercises/ex04_2_four_dimensions.hpp"

namespace stackbook::exercises {

CrossMat4 crossMatrix4(const Vec4& r) {
  // TODO(reader): one row per plane (i, j), i < j, in the order (xy, xz, xw, yz, yw, zw);
  // row (i, j) holds r_i in column j and -r_j in column i.
  (void)r;
  return CrossMat4::Zero();
}

Mat4 collisionMatrix4(double inverseMass, const Bivec4& inversePlaneInertia, const Vec4& r) {
  // TODO(reader): Eq. (1.8) with D = 4.
  (void)inverseMass;
  (void)inversePlaneInertia;
  (void)r;
  return Mat4::Zero();
}

}  // namespace stackbook::exercises
