// Exercise 2.3 (reference solution): restitution with a threshold speed, and a ball that
// bounces on a static floor with exact flights between the impacts.
#include <cmath>

#include "stackbook/exercises/ex02_3_restitution_threshold.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"

namespace stackbook::exercises {

double thresholdRestitution(double un, double e, double threshold) {
  return -un >= threshold ? e : 0.0;
}

BounceHistory dropBall(double height, double gravity, double e, double threshold,
                       int maxImpacts) {
  BounceHistory history;
  const double radius = 0.5;
  RigidBody<3> ball = makeDynamicBody<3>(1.0, Vec3::Constant(0.4 * radius * radius));
  RigidBody<3> ground = makeStaticBody<3>();
  const Vec3 n = Vec3::UnitZ();  // from the ground (b) toward the ball (a)

  // Free fall from rest through `height`: t = sqrt(2 h / g), speed g t.
  double t = std::sqrt(2.0 * height / gravity);
  ball.position = Vec3(0.0, 0.0, radius);  // touching the floor at the origin
  ball.velocity = Vec3(0.0, 0.0, -gravity * t);
  const Vec3 ra = -radius * n;
  const Vec3 rb = ball.position + ra - ground.position;
  for (int impact = 0; impact < maxImpacts; ++impact) {
    const Vec3 u = relativeVelocity<3>(ball, ra, ground, rb);
    const double un = u.dot(n);
    history.impactTimes.push_back(t);
    history.impactSpeeds.push_back(-un);
    const double eUsed = thresholdRestitution(un, e, threshold);
    const Mat3 K = pairCollisionMatrix<3>(ball, ra, ground, rb);
    applyPairImpulse<3>(ball, ra, ground, rb, frictionlessImpulse<3>(K, u, n, eUsed).j);
    const double up = ball.velocity.dot(n);
    if (!(up > 0.0)) {  // a plastic impact: the ball stays on the floor
      history.cameToRest = true;
      break;
    }
    // Up and down again in closed form: back at the floor after 2 up / g, at speed up.
    t += 2.0 * up / gravity;
    ball.velocity = -up * n;
  }
  return history;
}

}  // namespace stackbook::exercises
