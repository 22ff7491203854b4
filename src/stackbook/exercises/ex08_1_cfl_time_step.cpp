// Exercise 8.1 (your answer goes here): see ex08_1_cfl_time_step.hpp and chapter 8.
// Implement: cflTimeStep. Delete every TODO(reader) comment once your code is in: while one is
// left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex08_1_cfl_time_step.hpp"

namespace stackbook::exercises {

double cflTimeStep(double speed, double gravity, double thickness, double safety) {
  // TODO(reader): check the arguments, then return the positive root of
  // gravity dt^2 + speed dt - safety thickness / 2 = 0 (Eq. (8.9)).
  (void)speed;
  (void)gravity;
  (void)thickness;
  (void)safety;
  return 0.0;
}

}  // namespace stackbook::exercises
