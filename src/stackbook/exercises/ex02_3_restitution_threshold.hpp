#pragma once
/// \file
/// \brief Exercise 2.3: a restitution that vanishes below a threshold speed, and what it
/// does to the infinite (Zeno) sequence of bounces of a ball (chapter 2, "Exercises").

#include <vector>

namespace stackbook::exercises {

/// Velocity-dependent restitution: e when the approach speed -u_n is at least `threshold`,
/// and 0 (a plastic impact) when the contact approaches more slowly.
double thresholdRestitution(double un, double e, double threshold);

/// What happened to a dropped ball, impact by impact.
struct BounceHistory {
  std::vector<double> impactTimes;   ///< time of each impact, from the release
  std::vector<double> impactSpeeds;  ///< approach speed -u_n at each impact
  bool cameToRest = false;           ///< the last impact left no upward velocity
};

/// A ball of radius 0.5 and mass 1 (a 3D RigidBody) released from rest with its lowest point
/// `height` above a static floor, under gravity `gravity`, with no air and no spin. The
/// flights between impacts are exact (ballistic, in closed form); each impact applies the
/// frictionless impulse of chapter 2 with e = thresholdRestitution(u_n, e, threshold).
/// Simulates until an impact leaves the ball with no upward velocity (cameToRest) or
/// maxImpacts impacts have happened.
BounceHistory dropBall(double height, double gravity, double e, double threshold, int maxImpacts);

}  // namespace stackbook::exercises
