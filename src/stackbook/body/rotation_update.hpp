#pragma once
/// \file
/// \brief The rotation rules of the position update (\ref ch05_midpoint): GBF's exponential
/// map at the angular velocity the step starts with (Eqs. (5.9)-(5.11)), or the implicit
/// midpoint rule on the body-frame angular momentum (Eqs. (5.25)-(5.28)), which conserves the
/// kinetic energy of a free body as well as its angular momentum.

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

#include "stackbook/math/rotation.hpp"
#include "stackbook/math/types.hpp"

namespace stackbook {

// [rotation_update]
/// How the position update turns a dynamic body.
enum class RotationUpdate {
  /// GBF: R <- exp(dt [omega]x) R with omega = I_world^{-1} L at the start of the update
  /// (Eqs. (5.9)-(5.11)). Gains energy on a tumbling body (Eq. (5.14)).
  ExponentialMap,
  /// The implicit midpoint rule on the body-frame momentum Pi = R^T L (Eq. (5.25)): the body
  /// turns by the Cayley rotation of dt Omega_mid, Omega_mid = I^{-1} (Pi + Pi')/2
  /// (Eq. (5.27)). Conserves E and |L| of a free body; costs a small Newton solve.
  ImplicitMidpoint,
};
// [rotation_update]

/// The scene-file spelling of a rotation rule: "exponentialMap" or "implicitMidpoint".
inline const char* rotationUpdateName(RotationUpdate rule) {
  return rule == RotationUpdate::ImplicitMidpoint ? "implicitMidpoint" : "exponentialMap";
}

/// The rule spelled `name`; throws std::invalid_argument naming the accepted spellings.
inline RotationUpdate rotationUpdateFromName(const std::string& name) {
  if (name == "exponentialMap") return RotationUpdate::ExponentialMap;
  if (name == "implicitMidpoint") return RotationUpdate::ImplicitMidpoint;
  throw std::invalid_argument("rotation must be \"exponentialMap\" or \"implicitMidpoint\", got \"" +
                              name + "\"");
}

/// What the midpoint rule's Newton solve does: it stops when a correction is below
/// `tolerance` times |Pi| or after `maxIterations` corrections.
struct MidpointSolve {
  double tolerance = 1e-15;
  int maxIterations = 20;
};

// [midpoint_momentum]
/// The body-frame momentum Pi' after one implicit midpoint step of Euler's equations
/// dPi/dt = Pi x I^{-1} Pi (Eq. (5.25)): the root of
/// F(Pi') = Pi' - Pi - dt m x I^{-1} m, m = (Pi + Pi')/2, by Newton's method with the
/// Jacobian J = 1 - dt/2 ([m]x I^{-1} - [I^{-1} m]x) (Eq. (5.26)), started from Pi' = Pi.
/// A zero inverse moment (a locked axis) is allowed. `iterations`, if given, receives the
/// number of Newton corrections made.
inline Vec3 midpointBodyMomentum(const Vec3& Pi, const Vec3& inverseInertia, double dt,
                                 const MidpointSolve& solve = {}, int* iterations = nullptr) {
  const auto skew = [](const Vec3& a) {
    Mat3 s;
    s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
    return s;
  };
  Vec3 next = Pi;
  const double scale = Pi.norm();
  int k = 0;
  while (k < solve.maxIterations) {
    const Vec3 m = 0.5 * (Pi + next);
    const Vec3 w = inverseInertia.cwiseProduct(m);
    const Vec3 F = next - Pi - dt * m.cross(w);  // Eq. (5.25)
    const Mat3 J = Mat3::Identity() -
                   0.5 * dt * (skew(m) * inverseInertia.asDiagonal().toDenseMatrix() - skew(w));  // Eq. (5.26)
    const Vec3 correction = J.partialPivLu().solve(F);
    next -= correction;
    ++k;
    if (!(correction.norm() > solve.tolerance * scale)) break;
  }
  if (iterations != nullptr) *iterations = k;
  return next;
}
// [midpoint_momentum]

// [midpoint_rotation]
/// The orientation after one implicit midpoint step of a body with world angular momentum L
/// (unchanged by the step) and body-frame inverse moments `inverseInertia`: with
/// Omega_mid = I^{-1} (Pi + Pi')/2 the body turns by the Cayley rotation
/// (1 - dt/2 [Omega_mid]x)^{-1} (1 + dt/2 [Omega_mid]x), whose unit quaternion is
/// (1, dt Omega_mid / 2) / |(1, dt Omega_mid / 2)| (Eq. (5.27)); the increment is in the body
/// frame, so it multiplies from the right: q' = q (x) q_step (Eq. (5.28)).
inline Eigen::Quaterniond rotateByImplicitMidpoint(const Eigen::Quaterniond& q, const Vec3& L,
                                                   const Vec3& inverseInertia, double dt,
                                                   const MidpointSolve& solve = {}) {
  const Vec3 Pi = q.conjugate() * L;
  const Vec3 next = midpointBodyMomentum(Pi, inverseInertia, dt, solve);
  const Vec3 half = 0.5 * dt * inverseInertia.cwiseProduct(0.5 * (Pi + next));  // dt Omega_mid / 2
  const Eigen::Quaterniond step(1.0, half.x(), half.y(), half.z());          // Eq. (5.27)
  const Eigen::Quaterniond turned = q * step.normalized();                    // Eq. (5.28)
  return turned.normalized();
}
// [midpoint_rotation]

}  // namespace stackbook
