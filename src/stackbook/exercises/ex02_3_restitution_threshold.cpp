// Exercise 2.3 (stub): restitution with a threshold speed, and a bouncing ball.
// Implement: thresholdRestitution and dropBall. Delete every TODO(reader) comment once your code
// is in: while one is left, the exercise counts as not solved and its tests do not run.
// The reference solution is chapters/solutions/ex02_3_restitution_threshold.cpp.
#include "stackbook/exercises/ex02_3_restitution_threshold.hpp"

namespace stackbook::exercises {

double thresholdRestitution([[maybe_unused]] double un, double e,
                            [[maybe_unused]] double threshold) {
  // TODO(reader): return 0 when the approach speed -u_n is below the threshold.
  return e;  // no threshold yet
}

BounceHistory dropBall([[maybe_unused]] double height, [[maybe_unused]] double gravity,
                       [[maybe_unused]] double e, [[maybe_unused]] double threshold,
                       [[maybe_unused]] int maxImpacts) {
  // TODO(reader): fall to the floor, apply frictionlessImpulse with the threshold law,
  // fly back up and down in closed form, and repeat.
  return BounceHistory{};  // no impacts recorded
}

}  // namespace stackbook::exercises
