#pragma once
/// \file
/// \brief The knobs of the frictional impulse (\ref ch03). Each safeguard that the
/// implementation notes leave open is a named parameter here, never a buried constant.

namespace stackbook {

// [slip_direction_rule]
/// Where the kinetic-friction direction T comes from (\ref ch03, Eq. (3.4)); friction
/// acts along -T. Two directions are at hand: the slip before the impulse,
/// u_t / |u_t|, and the slip the impact itself creates, T* = -j*_t / |j*_t|, from the
/// rejected sticking trial j* of Eq. (3.2). When |u_t| is below the slip tolerance, every
/// rule takes T*.
enum class SlipDirectionRule {
  /// The default. T* when the impact reverses the slip (T* . u_t <= 0); otherwise the
  /// unit vector along (1 - rho) u_t / |u_t| + rho T*, where rho = mu j_n(T*) / |j*_t| in
  /// (0, 1] is the friction that sliding along T* supplies, as a fraction of the friction
  /// sticking needs. GBF's direction for a fast slide (rho -> 0, also as dt -> 0 in a
  /// time step), T* at the switch (rho -> 1), so the impulse is continuous there; in 2D
  /// it equals StickingImpulse.
  Blended,
  /// GBF and the notes as printed: T = u_t / |u_t|, the slip before the impulse.
  RelativeVelocity,
  /// T = T* always: the slip the impact creates. Continuous at the switch and its kinetic
  /// denominator is always positive (Eq. (3.6)), but in 3D it turns a fast slide's
  /// friction away from -u_t when K is anisotropic in the tangent plane.
  StickingImpulse,
};
// [slip_direction_rule]

// [friction_settings]
/// Settings of frictionalImpulse (\ref ch03). The defaults are the ones the course uses.
struct FrictionSettings {
  /// K is treated as singular when an LDL^T pivot is <= pivotTolerance * trace(K),
  /// that is when its condition number exceeds about 1 / pivotTolerance.
  double pivotTolerance = 1e-12;
  /// |u_t| <= slipTolerance * |u| counts as "no tangential velocity" (erratum 3 of the notes).
  double slipTolerance = 1e-9;
  /// Unless T is the impact's slip direction T* (whose denominator is always positive,
  /// Eq. (3.6)), the kinetic denominator n^T K (n - mu T) must be at least
  /// painleveMargin * n^T K n, which caps j_n at 1 / painleveMargin times the frictionless
  /// one (Eq. (3.7)). Below it T falls back to T*; without T* (singular K), mu is lowered
  /// until the margin holds. In (0, 1).
  double painleveMargin = 1e-2;
  /// Never let an impulse add kinetic energy: lower |e| of a sticking impulse to e_max
  /// (Eq. (3.9)) and mu of a sliding one to the largest energy-safe value (Eq. (3.10)).
  bool preventEnergyGain = true;
  /// Bisection steps used to find the largest energy-safe mu (fixed, so deterministic;
  /// 60 steps resolve mu to 2^-60 of its value). In [1, 200].
  int energyBisectionSteps = 60;
  /// One step of iterative refinement of every solve with K when the largest/smallest
  /// LDL^T pivot exceeds this value (K ill-conditioned). Below 1e3 the forward error bound
  /// cond(K) eps is under 2.2e-13 anyway; above it refinement brings the backward error
  /// down to one rounding (\ref ch03, "Solving K j = b"). At least 1.
  double refineConditionAbove = 1e3;
  /// How the slip direction T is chosen when the contact slides.
  SlipDirectionRule slipDirection = SlipDirectionRule::Blended;
};
// [friction_settings]

}  // namespace stackbook
