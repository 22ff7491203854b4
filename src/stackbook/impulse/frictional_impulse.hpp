#pragma once
/// \file
/// \brief The frictional impulse: try sticking, else slide on the friction cone
/// (\ref ch03, Eqs. (3.1)-(3.9)), with the safeguards the implementation notes leave out.

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "stackbook/impulse/friction_settings.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"

namespace stackbook {

// [sticking_solve]
/// Solve K j = rhs with an LDL^T factorisation (never an explicit inverse).
/// Returns false when K is singular to within settings.pivotTolerance * trace(K).
template <int D>
bool solveCollisionMatrix(const Mat<D>& K, const Vec<D>& rhs, const FrictionSettings& settings,
                          Vec<D>& j) {
  const Eigen::LDLT<Mat<D>> ldlt(K);
  if (ldlt.info() != Eigen::Success) return false;
  const Vec<D> pivots = ldlt.vectorD();
  const double smallest = pivots.minCoeff();
  if (!(smallest > settings.pivotTolerance * K.trace())) return false;
  j = ldlt.solve(rhs);
  if (pivots.maxCoeff() > settings.refineConditionAbove * smallest) {
    j += ldlt.solve(Vec<D>(rhs - K * j));  // one step of iterative refinement
  }
  return j.allFinite();
}
// [sticking_solve]

/// Kinetic-energy change of the pair when impulse j acts on relative velocity u:
/// Delta KE = j^T (u + K j / 2) (Eq. (3.8)).
template <int D>
double impulseEnergyChange(const Mat<D>& K, const Vec<D>& u, const Vec<D>& j) {
  return j.dot(u + 0.5 * (K * j));
}

namespace detail {

// [sliding_impulse]
/// The kinetic impulse j = j_n (n - mu T), j_n = -(1 + e) u_n / (n^T K (n - mu T))
/// (Eq. (3.5)). Returns zero when the denominator is not positive.
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

// [frictional_impulse]
/// Impulse with restitution e and Coulomb friction mu for the relative contact velocity
/// u along the unit normal n (apply +j to the first body, -j to the second).
/// 1. Not approaching, or immovable: no impulse (Eq. (2.1)).
/// 2. mu = 0: exactly the frictionless impulse of Eq. (2.3).
/// 3. Sticking trial j* = K^{-1}(-e u_n n - u) (Eq. (3.2)); accept if it pushes and lies in
///    the cone |j*_t| <= mu j*_n (Eq. (3.3)), lowering e if it would add energy (Eq. (3.9)).
/// 4. Otherwise slide: j = j_n (n - mu T) (Eq. (3.5)), with the Painleve guard (Eq. (3.7))
///    and the energy guard lowering mu where needed.
template <int D>
ContactImpulse<D> frictionalImpulse(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n, double e,
                                    double mu, const FrictionSettings& settings = {}) {
  // Steps 1 and 2: the chapter-2 impulse covers separation, immovable pairs and mu = 0.
  ContactImpulse<D> result = frictionlessImpulse<D>(K, u, n, e, settings.pivotTolerance);
  if (mu == 0.0 || result.branch != ImpulseBranch::Frictionless) return result;
  const ContactImpulse<D> frictionless = result;
  result.friction = mu;
  const double un = u.dot(n);
  const Vec<D> ut = u - un * n;

  // Step 3: the sticking trial, target u' = -e u_n n (Eq. (3.1)).
  Vec<D> jStick;
  if (!solveCollisionMatrix<D>(K, Vec<D>(-e * un * n - u), settings, jStick)) {
    result = frictionless;  // singular K with n^T K n > 0: the normal impulse still works
    result.singularK = true;
    return result;
  }
  if (settings.preventEnergyGain && impulseEnergyChange<D>(K, u, jStick) > 0.0) {
    // Eq. (3.9): the largest |e| whose sticking impulse adds no energy.
    Vec<D> Kinv_u, Kinv_n;
    solveCollisionMatrix<D>(K, u, settings, Kinv_u);
    solveCollisionMatrix<D>(K, n, settings, Kinv_n);
    const double eMax = std::sqrt(std::max(0.0, u.dot(Kinv_u)) / (un * un * n.dot(Kinv_n)));
    if (std::abs(e) > eMax) {
      result.restitution = std::copysign(eMax, e);
      result.restitutionLowered = true;
      solveCollisionMatrix<D>(K, Vec<D>(-result.restitution * un * n - u), settings, jStick);
    }
  }
  const double jnStick = jStick.dot(n);
  const Vec<D> jtStick = jStick - jnStick * n;
  if (jnStick > 0.0 && jtStick.norm() <= mu * jnStick) {  // Eq. (3.3): inside the cone
    result.j = jStick;
    result.branch = ImpulseBranch::Sticking;
    return result;
  }

  // Step 4: slide. The slip direction T (Eq. (3.4)).
  result.restitution = e;
  result.restitutionLowered = false;
  Vec<D> T;
  const bool slipping = ut.norm() > settings.slipTolerance * u.norm();
  if (settings.slipDirection == SlipDirectionRule::RelativeVelocity && slipping) {
    T = ut.normalized();
  } else if (jtStick.norm() > 0.0) {
    T = -jtStick.normalized();  // the slip the impact itself would create
    result.slipFromImpulse = true;
  } else {
    return frictionless;  // no tangential tendency at all: friction does nothing
  }

  // Painleve guard (Eq. (3.7)): keep n^T K (n - mu T) >= margin * n^T K n > 0.
  const double knn = n.dot(K * n);
  const double knt = n.dot(K * T);
  double muUsed = mu;
  if (knn - mu * knt < settings.painleveMargin * knn) {
    muUsed = (1.0 - settings.painleveMargin) * knn / knt;  // knt > 0 here
    result.frictionLowered = true;
  }
  Vec<D> j = detail::slidingImpulse<D>(K, un, n, T, e, muUsed);

  // Energy guard: the largest mu' <= muUsed whose sliding impulse adds no energy.
  // At mu' = 0 the impulse is frictionless and dissipates (e <= 1), so a root exists.
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
    muUsed = safe;
    result.frictionLowered = true;
    j = detail::slidingImpulse<D>(K, un, n, T, e, muUsed);
  }
  result.j = j;
  result.friction = muUsed;
  result.branch = ImpulseBranch::Sliding;
  return result;
}
// [frictional_impulse]

}  // namespace stackbook
