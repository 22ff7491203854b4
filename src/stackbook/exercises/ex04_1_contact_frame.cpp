// Exercise 4.1 stub: your starting point. The tests are in tests/ch04/exercises.cpp:
// Implement: contactFrameK and painleveFriction. Delete every TODO(reader) comment once your
// code is in: while one is left, the exercise counts as not solved and its tests do not run.
//   build/exercises/tests/ch04/test_ch04_exercises --no-skip -ts=ch04_exercises -tc="Exercise 4.1*"
#include "stackbook/exercises/ex04_1_contact_frame.hpp"

#include <limits>

namespace stackbook::exercises {

ContactFrameK contactFrameK(const RigidBody<2>& a, const Vec2& ra, const RigidBody<2>& b,
                            const Vec2& rb, const Vec2& n) {
  // TODO(reader): per body, write n^T K n, n^T K t and t^T K t with Eq. (4.4) and
  // t = (-n_y, n_x); the pair entries are the sums over the two bodies.
  (void)a;
  (void)ra;
  (void)b;
  (void)rb;
  (void)n;
  return ContactFrameK{};
}

double painleveFriction(const ContactFrameK& k, double slipSign) {
  // TODO(reader): expand n^T K_T (n - mu T) with T = slipSign * t and solve for mu.
  (void)k;
  (void)slipSign;
  return std::numeric_limits<double>::infinity();
}

}  // namespace stackbook::exercises
