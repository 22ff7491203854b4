#pragma once
/// \file
/// \brief The knobs of the frictional impulse (\ref ch03). Each safeguard that the
/// implementation notes leave open is a named parameter here, never a buried constant.

namespace stackbook {

/// Where the kinetic-friction direction T comes from (\ref ch03, "The slip direction").
enum class SlipDirectionRule {
  /// GBF and the notes: T = u_t / |u_t|, the current tangential relative velocity.
  /// When |u_t| is below the slip tolerance the impulse rule below is used instead.
  RelativeVelocity,
  /// T = -j_t / |j_t| from the rejected sticking impulse: the slip the impact itself
  /// creates. Makes the impulse continuous across the stick/slide switch in 3D.
  StickingImpulse,
};

// [friction_settings]
struct FrictionSettings {
  /// K is treated as singular when an LDL^T pivot is <= pivotTolerance * trace(K).
  double pivotTolerance = 1e-12;
  /// |u_t| <= slipTolerance * |u| counts as "no tangential velocity" (erratum 3 of the notes).
  double slipTolerance = 1e-9;
  /// The kinetic denominator n^T K (n - mu T) must be at least painleveMargin * n^T K n;
  /// otherwise mu is lowered to meet it (Painleve guard, erratum 4).
  double painleveMargin = 1e-2;
  /// Never let an impulse add kinetic energy: lower e for a sticking impulse and mu for
  /// a sliding one until Delta KE <= 0 (erratum 5).
  bool preventEnergyGain = true;
  /// Bisection steps used to find the largest energy-safe mu (fixed, so deterministic).
  int energyBisectionSteps = 60;
  /// One step of iterative refinement of the sticking solve when K is ill-conditioned
  /// (largest/smallest pivot ratio above this value).
  double refineConditionAbove = 1e6;
  SlipDirectionRule slipDirection = SlipDirectionRule::RelativeVelocity;
};
// [friction_settings]

}  // namespace stackbook
