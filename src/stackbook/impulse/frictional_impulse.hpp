#pragma once
/// \file
/// \brief The frictional impulse: try sticking, else slide on the friction cone
/// (\ref ch03, Eqs. (3.1)-(3.10)), with the safeguards the implementation notes leave out.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "stackbook/impulse/friction_settings.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"

namespace stackbook {

namespace detail {

// [collision_matrix_factor]
/// The LDL^T factorisation of K, made once per contact and used for every solve.
/// ok() is false when K is singular: a pivot <= settings.pivotTolerance * trace(K).
/// When K is ill-conditioned (pivot ratio above settings.refineConditionAbove), each
/// solve takes one step of iterative refinement.
template <int D>
class CollisionMatrixFactor {
 public:
  CollisionMatrixFactor(const Mat<D>& K, const FrictionSettings& settings)
      : K_(K), ldlt_(K) {
    const Vec<D> pivots = ldlt_.vectorD();
    const double smallest = pivots.minCoeff();
    ok_ = ldlt_.info() == Eigen::Success && smallest > settings.pivotTolerance * K.trace();
    refine_ = ok_ && pivots.maxCoeff() > settings.refineConditionAbove * smallest;
  }

  bool ok() const { return ok_; }

  /// K^{-1} rhs; only meaningful when ok().
  Vec<D> solve(const Vec<D>& rhs) const {
    Vec<D> x = ldlt_.solve(rhs);
    if (refine_) x += ldlt_.solve(Vec<D>(rhs - K_ * x));  // residual, then correct
    return x;
  }

 private:
  Mat<D> K_;
  Eigen::LDLT<Mat<D>> ldlt_;
  bool ok_ = false;
  bool refine_ = false;
};
// [collision_matrix_factor]

/// Throws std::invalid_argument naming the input unless mu is finite and >= 0, e is in
/// [-1, 1], n is a unit vector, u and K are finite and the settings are in range.
template <int D>
void checkFrictionInput(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n, double e, double mu,
                        const FrictionSettings& s) {
  const auto fail = [](const char* what, double value) {
    std::ostringstream msg;
    msg << "frictionalImpulse: " << what << ", got " << value;
    throw std::invalid_argument(msg.str());
  };
  if (!(std::isfinite(mu) && mu >= 0.0)) fail("friction mu must be finite and >= 0", mu);
  if (!(e >= -1.0 && e <= 1.0)) fail("restitution e must be in [-1, 1]", e);
  if (!n.allFinite() || !(std::abs(n.squaredNorm() - 1.0) <= 1e-9)) {
    fail("normal n must be a unit vector (|n| = 1 within 1e-9); |n|", n.norm());
  }
  if (!u.allFinite()) fail("relative velocity u must be finite; |u|", u.norm());
  if (!K.allFinite()) fail("collision matrix K must be finite; trace(K)", K.trace());
  if (!(s.pivotTolerance >= 0.0 && s.pivotTolerance < 1.0)) {
    fail("FrictionSettings::pivotTolerance must be in [0, 1)", s.pivotTolerance);
  }
  if (!(s.slipTolerance >= 0.0 && s.slipTolerance < 1.0)) {
    fail("FrictionSettings::slipTolerance must be in [0, 1)", s.slipTolerance);
  }
  if (!(s.painleveMargin > 0.0 && s.painleveMargin < 1.0)) {
    fail("FrictionSettings::painleveMargin must be in (0, 1)", s.painleveMargin);
  }
  if (s.energyBisectionSteps < 1 || s.energyBisectionSteps > 200) {
    fail("FrictionSettings::energyBisectionSteps must be in [1, 200]", s.energyBisectionSteps);
  }
  if (!(s.refineConditionAbove >= 1.0)) {
    fail("FrictionSettings::refineConditionAbove must be >= 1", s.refineConditionAbove);
  }
}

// [sliding_impulse]
/// The kinetic impulse j = j_n (n - mu T), j_n = -(1 + e) u_n / (n^T K (n - mu T))
/// (Eq. (3.5)). Returns zero when the denominator is not positive: an impulse never pulls.
template <int D>
Vec<D> slidingImpulse(const Mat<D>& K, double un, const Vec<D>& n, const Vec<D>& T, double e,
                      double mu) {
  const Vec<D> k = n - mu * T;
  const double denominator = n.dot(K * k);
  if (!(denominator > 0.0)) return Vec<D>::Zero();
  return (-(1.0 + e) * un / denominator) * k;
}
// [sliding_impulse]

}  // namespace detail

// [sticking_solve]
/// Solve K j = rhs with an LDL^T factorisation (never an explicit inverse), refined once
/// when K is ill-conditioned. Returns false when K is singular to within
/// settings.pivotTolerance * trace(K) (\ref ch03, "Solving K j = b").
template <int D>
bool solveCollisionMatrix(const Mat<D>& K, const Vec<D>& rhs, const FrictionSettings& settings,
                          Vec<D>& j) {
  const detail::CollisionMatrixFactor<D> factor(K, settings);
  if (!factor.ok()) return false;
  j = factor.solve(rhs);
  return j.allFinite();
}
// [sticking_solve]

// [energy_change]
/// Kinetic-energy change of the pair when impulse j acts on relative velocity u:
/// Delta KE = j^T (u + K j / 2) (Eq. (3.8)).
template <int D>
double impulseEnergyChange(const Mat<D>& K, const Vec<D>& u, const Vec<D>& j) {
  return j.dot(u + 0.5 * (K * j));
}
// [energy_change]

// [frictional_impulse_stick]
/// Impulse with restitution e and Coulomb friction mu for the relative contact velocity
/// u along the unit normal n (apply +j to the first body, -j to the second), \ref ch03.
/// 1. Not approaching, or immovable: no impulse (Eq. (2.1)). mu = 0: exactly the
///    frictionless impulse of Eq. (2.3).
/// 2. Sticking trial j* = K^{-1}(-e u_n n - u) (Eq. (3.2)), with |e| lowered to e_max when
///    it would add energy (Eq. (3.9)); accepted inside the cone |j*_t| <= mu j*_n (Eq. (3.3)).
/// 3. Otherwise slide: j = j_n (n - mu T) (Eq. (3.5)), T by settings.slipDirection
///    (Eq. (3.4)), with the Painleve guard (Eq. (3.7)) and the energy guard (Eq. (3.10)).
/// A singular K skips step 2 and slides along u_t (or applies the normal impulse).
/// Throws std::invalid_argument on bad input (see detail::checkFrictionInput).
template <int D>
ContactImpulse<D> frictionalImpulse(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n, double e,
                                    double mu, const FrictionSettings& settings = {}) {
  detail::checkFrictionInput<D>(K, u, n, e, mu, settings);
  // Step 1: the chapter-2 impulse covers separation, immovable pairs and mu = 0.
  const ContactImpulse<D> frictionless =
      frictionlessImpulse<D>(K, u, n, e, settings.pivotTolerance);
  if (mu == 0.0 || frictionless.branch != ImpulseBranch::Frictionless) return frictionless;
  ContactImpulse<D> result = frictionless;
  result.friction = mu;
  const double un = u.dot(n);
  const Vec<D> ut = u - un * n;
  const bool slipping = ut.norm() > settings.slipTolerance * u.norm();

  // Step 2: the sticking trial, target u' = -e u_n n (Eq. (3.1)). It is affine in e:
  // j*(e) = -(1 + e) u_n K^{-1} n - K^{-1} u_t, so one factorisation and two solves serve.
  const detail::CollisionMatrixFactor<D> factor(K, settings);
  Vec<D> jStick = Vec<D>::Zero();
  bool haveStick = factor.ok();
  if (haveStick) {
    const Vec<D> x = factor.solve(n);   // K^{-1} n
    const Vec<D> z = factor.solve(ut);  // K^{-1} u_t
    double eStick = e;
    if (settings.preventEnergyGain) {
      // 2 Delta KE(e) = (e^2 - 1) u_n^2 n.x - 2 u_n u_t.x - u_t.z (Eqs. (3.8), (3.9)).
      const double nx = n.dot(x);
      const double coupling = 2.0 * un * ut.dot(x) + ut.dot(z);
      if ((e * e - 1.0) * un * un * nx > coupling) {
        const double eMax = std::sqrt(std::max(0.0, 1.0 + coupling / (un * un * nx)));
        eStick = std::copysign(eMax, e);
        result.restitutionLowered = true;
      }
    }
    jStick = -(1.0 + eStick) * un * x - z;  // Eq. (3.2)
    haveStick = jStick.allFinite();
    const double jnStick = jStick.dot(n);
    const Vec<D> jtStick = jStick - jnStick * n;
    if (haveStick && jnStick > 0.0 && jtStick.norm() <= mu * jnStick) {  // Eq. (3.3)
      result.j = jStick;
      result.restitution = eStick;
      result.branch = ImpulseBranch::Sticking;
      return result;
    }
  } else {
    result.singularK = true;
  }
  // [frictional_impulse_stick]

  // [frictional_impulse_slip]
  // Step 3: slide. The slip direction T (Eq. (3.4)): the slip before the impulse, the
  // slip the impact creates (T*), or a blend of the two.
  result.restitution = e;
  result.restitutionLowered = false;
  const double jnStick = haveStick ? jStick.dot(n) : 0.0;
  const Vec<D> jtStick = haveStick ? Vec<D>(jStick - jnStick * n) : Vec<D>::Zero();
  const double jtNorm = jtStick.norm();
  const bool haveImpactSlip = jtNorm > 0.0;
  if (!slipping && !haveImpactSlip) {
    // No slip now and none the impact would create: friction has nothing to oppose.
    result = frictionless;
    result.singularK = !factor.ok();
    return result;
  }
  const Vec<D> impactSlip = haveImpactSlip ? Vec<D>(-jtStick / jtNorm) : Vec<D>::Zero();
  const Vec<D> velocitySlip = slipping ? Vec<D>(ut / ut.norm()) : Vec<D>::Zero();
  bool useImpactSlip = !slipping;
  Vec<D> T = slipping ? velocitySlip : impactSlip;
  if (slipping && haveImpactSlip) {
    switch (settings.slipDirection) {
      case SlipDirectionRule::Blended:
        if (impactSlip.dot(velocitySlip) <= 0.0) {
          useImpactSlip = true;  // the impact reverses the slip
        } else {
          // rho: the friction mu j_n that sliding along T* supplies, over the |j*_t|
          // that sticking needs (Eq. (3.4)); its denominator is positive (Eq. (3.6)).
          const double jnImpact = -(1.0 + e) * un / n.dot(K * Vec<D>(n - mu * impactSlip));
          const double rho = std::min(1.0, mu * jnImpact / jtNorm);
          T = ((1.0 - rho) * velocitySlip + rho * impactSlip).normalized();
        }
        break;
      case SlipDirectionRule::RelativeVelocity:
        break;
      case SlipDirectionRule::StickingImpulse:
        useImpactSlip = true;
        break;
    }
  }
  if (useImpactSlip) T = impactSlip;
  result.slipFromImpulse = useImpactSlip;
  // [frictional_impulse_slip]

  // [frictional_impulse_guards]
  // Painleve guard (Eq. (3.7)). Along T* the denominator is positive and j_n <= |j*_t| / mu
  // (Eq. (3.6)); along any other T it must keep margin * n^T K n, which caps j_n at
  // 1 / margin times the frictionless one. A T that fails falls back to T*; without T*
  // (singular K) mu is lowered until the margin holds.
  const double knn = n.dot(K * n);
  const double margin = settings.painleveMargin * knn;
  if (!useImpactSlip && haveImpactSlip && knn - mu * n.dot(K * T) < margin) {
    T = impactSlip;
    useImpactSlip = true;
    result.slipFromImpulse = true;
  }
  double muUsed = mu;
  const double knt = n.dot(K * T);
  const double denominator = knn - mu * knt;
  if (useImpactSlip ? !(denominator > 0.0) : denominator < margin) {
    muUsed = (knn - margin) / knt;  // knt > 0 here; the new denominator is the margin
    result.frictionLowered = true;
  }
  Vec<D> j = detail::slidingImpulse<D>(K, un, n, T, e, muUsed);

  // Energy guard (Eq. (3.10)): the largest mu' <= muUsed whose sliding impulse adds no
  // energy. Delta KE(mu') has the sign of a quadratic that is <= 0 at mu' = 0 (e <= 1), so
  // exactly one sign change lies in [0, muUsed]; bisection finds it with fixed work.
  if (settings.preventEnergyGain && impulseEnergyChange<D>(K, u, j) > 0.0) {
    double safe = 0.0, unsafe = muUsed;
    for (int step = 0; step < settings.energyBisectionSteps; ++step) {
      const double mid = 0.5 * (safe + unsafe);
      if (impulseEnergyChange<D>(K, u, detail::slidingImpulse<D>(K, un, n, T, e, mid)) > 0.0) {
        unsafe = mid;
      } else {
        safe = mid;
      }
    }
    result.frictionLowered = true;
    if (safe == 0.0) {
      // Any friction at all along T would add energy: apply the normal impulse alone.
      result.j = frictionless.j;
      result.friction = 0.0;
      result.branch = ImpulseBranch::Frictionless;
      return result;
    }
    muUsed = safe;
    j = detail::slidingImpulse<D>(K, un, n, T, e, muUsed);
  }
  result.j = j;
  result.friction = muUsed;
  result.branch = ImpulseBranch::Sliding;
  return result;
}
// [frictional_impulse_guards]

// Compiled once, for D = 2 and 3, in the library (src/stackbook/instantiate_2d_3d.cpp).
extern template ContactImpulse<2> frictionalImpulse<2>(const Mat<2>&, const Vec<2>&, const Vec<2>&,
                                                       double, double, const FrictionSettings&);
extern template ContactImpulse<3> frictionalImpulse<3>(const Mat<3>&, const Vec<3>&, const Vec<3>&,
                                                       double, double, const FrictionSettings&);

}  // namespace stackbook
