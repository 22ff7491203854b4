// Exercise 8.3 (your answer goes here): see ex08_3_rolling_rest_angle.hpp and chapter 8.
// Implement: rollingRestAngle. Delete every TODO(reader) comment once your code is in: while one
// is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex08_3_rolling_rest_angle.hpp"

namespace stackbook::exercises {

double rollingRestAngle(double rollingFriction, double radius) {
  // TODO(reader): balance the moment of gravity about the contact against the largest
  // rolling-friction couple.
  (void)rollingFriction;
  (void)radius;
  return 0.0;
}

}  // namespace stackbook::exercises
