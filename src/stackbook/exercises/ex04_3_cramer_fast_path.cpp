// Exercise 4.3 stub: your starting point. The tests are in tests/ch04/exercises.cpp:
// Implement: solveCramer2 and solveCollisionMatrix2D. Delete every TODO(reader) comment once
// your code is in: while one is left, the exercise counts as not solved and its tests do not
// run.
//   build/exercises/tests/ch04/test_ch04_exercises --no-skip -ts=ch04_exercises -tc="Exercise 4.3*"
#include "stackbook/exercises/ex04_3_cramer_fast_path.hpp"

namespace stackbook::exercises {

bool solveCramer2(const Mat2& K, const Vec2& rhs, Vec2& j) {
  // TODO(reader): det(K), then the adjugate of K applied to rhs, divided by det(K).
  (void)K;
  (void)rhs;
  (void)j;
  return false;
}

bool solveCollisionMatrix2D(const Mat2& K, const Vec2& rhs, const FrictionSettings& settings,
                            Vec2& j, double maxCondition) {
  // TODO(reader): choose between solveCramer2 and solveCollisionMatrix<2>
  // (stackbook/impulse/frictional_impulse.hpp) with the bound trace(K)^2 / det(K).
  (void)K;
  (void)rhs;
  (void)settings;
  (void)j;
  (void)maxCondition;
  return false;
}

}  // namespace stackbook::exercises
