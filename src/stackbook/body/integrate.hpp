#pragma once
/// \file
/// \brief Rigid-body motion in time (\ref ch05): GBF's semi-implicit Euler step, split into
/// a velocity update (forces) and a position update (exponential map), plus pose
/// prediction for the collision and contact stages of chapters 7 and 8.
///
/// The order is GBF's: velocities first from the forces, Eq. (5.7); then positions from the
/// new velocities, Eqs. (5.8)-(5.12). The two halves are separate functions because the GBF
/// time step (chapter 8) processes collisions before the velocity update and contacts
/// between the two. Angular momentum L is the primary angular state; the angular velocity
/// omega = I_world^{-1} L is re-derived whenever L or the orientation changes.

#include <cmath>

#include "stackbook/body/rigid_body.hpp"
#include "stackbook/body/rotation_update.hpp"
#include "stackbook/math/pose.hpp"

namespace stackbook {

// [external_loads]
/// What acts on a body during one step, all in the world frame (\ref ch05): a uniform
/// acceleration field g (gravity: the same for every mass), a force F through the centre of
/// mass and a torque tau about it. The velocity update adds dt (g + F/m) to v and dt tau to L.
template <int D>
struct ExternalLoads {
  Vec<D> acceleration = Vec<D>::Zero();  ///< g, e.g. (0, -9.81) or (0, 0, -9.81)
  Vec<D> force = Vec<D>::Zero();         ///< F, applied at the centre of mass
  AngVec<D> torque = AngVec<D>::Zero();  ///< tau, about the centre of mass
};
// [external_loads]

/// Loads of a uniform gravity field g and nothing else.
template <int D>
ExternalLoads<D> gravityLoads(const Vec<D>& g) {
  ExternalLoads<D> loads;
  loads.acceleration = g;
  return loads;
}

/// The body's current placement (centre of mass and orientation) as a Pose.
template <int D>
Pose<D> poseOf(const RigidBody<D>& body) {
  return Pose<D>{body.position, body.orientation};
}

// [normalize_orientation]
/// The orientation as a proper rotation: the unit quaternion q/|q| in 3D (Eq. (5.10)), the
/// angle wrapped into [-pi, pi] in 2D. A quaternion of norm zero or a non-finite one has no
/// rotation to recover and throws std::invalid_argument.
template <int D>
Orientation<D> normalizedOrientation(const Orientation<D>& q) {
  if constexpr (D == 2) {
    // In the plane the angle is the whole orientation; wrapping keeps it small, so that
    // its rounding error stays at the 1e-16 level however long the body spins. An angle
    // already in [-pi, pi] is its own remainder (the nearest multiple of 2 pi is 0, and
    // 2.0 * M_PI / 2 is M_PI exactly), so the call is skipped there: same bits, and most
    // calls (every predicted pose of a resting body) take the shortcut.
    const double angle = q.angle();
    if (std::abs(angle) <= M_PI) return Eigen::Rotation2Dd(angle);
    return Eigen::Rotation2Dd(std::remainder(angle, 2.0 * M_PI));
  } else {
    const double norm = q.norm();
    if (!std::isfinite(norm) || !(norm > 0.0)) {
      throw std::invalid_argument(
          "normalizedOrientation: the quaternion has zero or non-finite norm and "
          "represents no rotation");
    }
    return Eigen::Quaterniond(q.coeffs() / norm);
  }
}
// [normalize_orientation]

// [exponential_map]
/// The exponential map: the orientation reached from q by turning at the constant world
/// angular velocity omega for the time dt (Eqs. (5.9), (5.11)). In 3D this is
/// q' = exp(dt omega / 2) (x) q with the exact axis-angle quaternion
/// (cos(|theta|/2), sin(|theta|/2) theta/|theta|), theta = dt omega, renormalised (Eq. (5.10));
/// in 2D it adds dt omega to the angle.
template <int D>
Orientation<D> rotateByAngularVelocity(const Orientation<D>& q, const AngVec<D>& omega,
                                       double dt) {
  if constexpr (D == 2) {
    return normalizedOrientation<2>(Eigen::Rotation2Dd(q.angle() + dt * omega[0]));  // Eq. (5.11)
  } else {
    const Vec3 theta = dt * omega;
    const double angle = theta.norm();
    // sin(angle/2)/angle, with its Taylor series where the quotient is 0/0; below 1e-4
    // the next term, angle^4/3840, is under 1e-19 and lost in rounding.
    const double s = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(0.5 * angle) / angle;
    const Eigen::Quaterniond step(std::cos(0.5 * angle), s * theta.x(), s * theta.y(),
                                  s * theta.z());  // Eq. (5.9)
    // World-frame increment: it acts after q, so it multiplies from the left.
    return normalizedOrientation<3>(step * q);  // Eq. (5.10)
  }
}
// [exponential_map]

// [velocity_update]
/// The velocity update of GBF's step, Eq. (5.7): v += dt (g + F/m), L += dt tau, then
/// omega = I_world^{-1} L (Eq. (5.12)). The orientation is first normalised (Eq. (5.10)), so
/// a body whose quaternion was set with the wrong length is still handled consistently.
/// A static body is left untouched.
template <int D>
void advanceVelocity(RigidBody<D>& body, double dt, const ExternalLoads<D>& loads = {}) {
  if (body.isStatic()) return;
  body.orientation = normalizedOrientation<D>(body.orientation);
  if (body.inverseMass > 0.0) {
    body.velocity += dt * (loads.acceleration + body.inverseMass * loads.force);  // Eq. (5.7)
  }
  body.angularMomentum += dt * loads.torque;  // Eq. (5.7)
  body.syncAngularVelocity();                 // Eq. (5.12)
}
// [velocity_update]

// [position_update]
/// The position update of GBF's step, Eqs. (5.8)-(5.12): x += dt v with the velocity the
/// body has now, R <- exp(dt [omega]x) R by the exponential map, and then omega re-derived
/// from the unchanged L at the new orientation (which is how a torque-free body precesses).
/// A static body keeps its pose unless it was given a velocity (a kinematic body); with
/// zero velocities its pose stays bit-identical.
template <int D>
void advancePosition(RigidBody<D>& body, double dt) {
  body.position += dt * body.velocity;  // Eq. (5.8)
  if (body.isStatic()) {
    if (!body.angularVelocity.isZero(0.0)) {
      body.orientation = rotateByAngularVelocity<D>(body.orientation, body.angularVelocity, dt);
    }
    return;  // omega of a static body is prescribed, not derived from L
  }
  body.orientation = rotateByAngularVelocity<D>(normalizedOrientation<D>(body.orientation),
                                                body.angularVelocity, dt);  // Eqs. (5.9)-(5.11)
  body.syncAngularVelocity();                                               // Eq. (5.12)
}
// [position_update]

// [turned_orientation]
/// The orientation a dynamic body reaches in one position update under `rule`: the
/// exponential map at the current omega (Eqs. (5.9)-(5.11)), or in 3D the implicit midpoint
/// rule at the current L (Eqs. (5.25)-(5.28)). In 2D omega is constant between impulses and
/// both rules are the exponential map. A static (kinematic) body always turns by its
/// prescribed omega.
template <int D>
Orientation<D> turnedOrientation(const RigidBody<D>& body, double dt, RotationUpdate rule) {
  const Orientation<D> q = normalizedOrientation<D>(body.orientation);
  if constexpr (D == 3) {
    if (rule == RotationUpdate::ImplicitMidpoint && !body.isStatic()) {
      return rotateByImplicitMidpoint(q, body.angularMomentum, body.inverseInertia, dt);
    }
  }
  return rotateByAngularVelocity<D>(q, body.angularVelocity, dt);
}
// [turned_orientation]

/// The position update with the rotation rule `rule` (\ref ch05_midpoint). With
/// RotationUpdate::ExponentialMap it is advancePosition(body, dt), bit for bit. L is not
/// touched by either rule, so the world angular momentum of a free body is conserved exactly.
template <int D>
void advancePosition(RigidBody<D>& body, double dt, RotationUpdate rule) {
  if (rule == RotationUpdate::ExponentialMap || D == 2 || body.isStatic()) {
    advancePosition<D>(body, dt);
    return;
  }
  body.position += dt * body.velocity;                      // Eq. (5.8)
  body.orientation = turnedOrientation<D>(body, dt, rule);  // Eqs. (5.25)-(5.28)
  body.syncAngularVelocity();                               // Eq. (5.12)
}

// [free_step]
/// One whole step of free motion (no collisions, no contact): Eq. (5.7), then
/// Eqs. (5.8)-(5.12). This is symplectic (semi-implicit) Euler for the translation.
template <int D>
void advanceFreeBody(RigidBody<D>& body, double dt, const ExternalLoads<D>& loads = {}) {
  advanceVelocity<D>(body, dt, loads);
  advancePosition<D>(body, dt);
}

/// One whole step of free motion with the rotation rule `rule`.
template <int D>
void advanceFreeBody(RigidBody<D>& body, double dt, const ExternalLoads<D>& loads,
                     RotationUpdate rule) {
  advanceVelocity<D>(body, dt, loads);
  advancePosition<D>(body, dt, rule);
}
// [free_step]

// [predict_pose]
/// The pose the position update would give, without changing the body:
/// x' = x + dt v, R' = exp(dt [omega]x) R (Eqs. (5.8), (5.9)). Chapter 8's contact stage
/// tests interference at this pose, with the velocities already updated.
template <int D>
Pose<D> predictPose(const RigidBody<D>& body, double dt) {
  Pose<D> pose;
  pose.position = body.position + dt * body.velocity;
  pose.orientation = body.isStatic() && body.angularVelocity.isZero(0.0)
                         ? body.orientation
                         : rotateByAngularVelocity<D>(normalizedOrientation<D>(body.orientation),
                                                      body.angularVelocity, dt);
  return pose;
}

/// The pose after a velocity update with the given loads and then a position update,
/// without changing the body: x' = x + dt (v + dt (g + F/m)), and R' from the omega that
/// L + dt tau would have. Chapter 8's collision stage tests interference at this pose while
/// it applies impulses to the current velocities.
template <int D>
Pose<D> predictPose(const RigidBody<D>& body, double dt, const ExternalLoads<D>& loads) {
  RigidBody<D> ahead = body;
  advanceVelocity<D>(ahead, dt, loads);
  return predictPose<D>(ahead, dt);
}

/// predictPose(body, dt) with the rotation rule `rule`: the pose advancePosition(body, dt,
/// rule) would give. ExponentialMap gives predictPose(body, dt) bit for bit.
template <int D>
Pose<D> predictPose(const RigidBody<D>& body, double dt, RotationUpdate rule) {
  if (rule == RotationUpdate::ExponentialMap || D == 2 || body.isStatic()) {
    return predictPose<D>(body, dt);
  }
  return Pose<D>{body.position + dt * body.velocity, turnedOrientation<D>(body, dt, rule)};
}

/// predictPose(body, dt, loads) with the rotation rule `rule`.
template <int D>
Pose<D> predictPose(const RigidBody<D>& body, double dt, const ExternalLoads<D>& loads,
                    RotationUpdate rule) {
  RigidBody<D> ahead = body;
  advanceVelocity<D>(ahead, dt, loads);
  return predictPose<D>(ahead, dt, rule);
}
// [predict_pose]

}  // namespace stackbook
