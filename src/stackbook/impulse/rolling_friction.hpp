#pragma once
/// \file
/// \brief Rolling and spinning friction (chapter 8, GBF section 5.5): after a sticking
/// impulse, a pure angular impulse tau (a couple) that brakes the relative rotation of
/// the pair, bounded by mu_r j_n, together with the linear impulse j' at the contact that
/// keeps the contact point sticking. Dimension-generic: in 2D the one angular component
/// is rolling; in 3D the component along the normal is spinning, the rest rolling.

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "stackbook/body/rigid_body.hpp"
#include "stackbook/impulse/collision_matrix.hpp"

namespace stackbook {

// [rolling_impulse]
/// The result of rollingFrictionImpulse(): +j at ra and +tau on body a, -j at rb and -tau
/// on body b.
template <int D>
struct RollingFrictionImpulse {
  Vec<D> j = Vec<D>::Zero();           ///< linear impulse j' at the contact (Eq. (8.6))
  AngVec<D> tau = AngVec<D>::Zero();   ///< angular impulse (couple) tau (Eq. (8.6))
  double scale = 0.0;  ///< s of Eq. (8.7): 1 stops the relative rotation, < 1 the bound acted
  bool singular = false;  ///< the coupled matrix was not positive definite: nothing applied

  /// True when the impulse changes nothing.
  bool isZero() const { return j.isZero(0.0) && tau.isZero(0.0); }
};
// [rolling_impulse]

/// The rolling part of an angular vector: all of it in 2D, the part normal to n in 3D.
template <int D>
AngVec<D> rollingPart(const AngVec<D>& w, const Vec<D>& n) {
  if constexpr (D == 2) {
    (void)n;
    return w;
  } else {
    return w - w.dot(n) * n;
  }
}

/// The spinning part of an angular vector: zero in 2D, the part along n in 3D.
template <int D>
AngVec<D> spinningPart(const AngVec<D>& w, const Vec<D>& n) {
  if constexpr (D == 2) {
    (void)n;
    return AngVec<D>::Zero();
  } else {
    return w.dot(n) * n;
  }
}

// [rolling_friction]
/// Rolling and spinning friction after a sticking impulse with normal part jn > 0 (chapter
/// 8, Eqs. (8.6)-(8.7)). muRolling is a length: the couple it may exert is at most
/// muRolling times the normal impulse, separately for rolling and for spinning, the
/// classical rolling-resistance law (torque = mu_r times normal force) applied to impulses.
///
/// The impulse pair (j', tau) keeps the contact point's relative velocity (Delta u = 0) and
/// changes the relative angular velocity w = w_a - w_b by Delta w:
///   [ K_T  C ] [ j'  ]   [ 0       ]
///   [ C^T  W ] [ tau ] = [ Delta w ],  C = ra*^T Ia^-1 + rb*^T Ib^-1,  W = Ia^-1 + Ib^-1,
/// a symmetric (D + D(D-1)/2)-square system, positive definite when one body can both
/// translate and rotate freely; it is solved with an LDLT factorisation. The target is
/// Delta w = -w (stop the relative rotation); if the couple that needs, tau*, exceeds the
/// bound, the whole solution is scaled by s = min(1, mu_r jn / |tau*_roll|,
/// mu_r jn / |tau*_spin|) (Eq. (8.7)). One scale for both keeps the direction of Delta w, so
/// the rotation is braked and never reversed, and the kinetic energy change
/// -(s - s^2/2) w^T S^{-1} w (S the Schur complement) is never positive when the contact
/// point is at rest after the sticking impulse. A static partner contributes zero blocks.
template <int D>
RollingFrictionImpulse<D> rollingFrictionImpulse(const RigidBody<D>& a, const Vec<D>& ra,
                                                 const RigidBody<D>& b, const Vec<D>& rb,
                                                 const Vec<D>& n, double jn, double muRolling) {
  constexpr int A = D * (D - 1) / 2;
  constexpr int N = D + A;
  RollingFrictionImpulse<D> out;
  const AngVec<D> w = a.angularVelocity - b.angularVelocity;
  if (!(jn > 0.0) || !(muRolling > 0.0) || w.isZero(0.0)) return out;
  // [rolling_system]
  const AngMat<D> Ia = a.inverseInertiaWorld(), Ib = b.inverseInertiaWorld();
  Eigen::Matrix<double, N, N> M;
  M.template topLeftCorner<D, D>() = pairCollisionMatrix<D>(a, ra, b, rb);  // Eq. (1.10)
  const Eigen::Matrix<double, D, A> C =
      crossMatrix<D>(ra).transpose() * Ia + crossMatrix<D>(rb).transpose() * Ib;
  M.template topRightCorner<D, A>() = C;
  M.template bottomLeftCorner<A, D>() = C.transpose();
  M.template bottomRightCorner<A, A>() = Ia + Ib;
  // [rolling_system]
  const Eigen::LDLT<Eigen::Matrix<double, N, N>> ldlt(M);
  const auto d = ldlt.vectorD();
  const double scaleOfM = M.diagonal().cwiseAbs().maxCoeff();
  if (ldlt.info() != Eigen::Success || !(d.minCoeff() > 1e-12 * scaleOfM)) {
    out.singular = true;
    return out;
  }  // [rolling_scale]
  Eigen::Matrix<double, N, 1> rhs = Eigen::Matrix<double, N, 1>::Zero();
  rhs.template tail<A>() = -w;  // Delta u = 0, Delta w = -w
  const Eigen::Matrix<double, N, 1> x = ldlt.solve(rhs);  // Eq. (8.6)
  const AngVec<D> tauStop = x.template tail<A>();

  const double bound = muRolling * jn;  // Eq. (8.7)
  double s = 1.0;
  const double roll = rollingPart<D>(tauStop, n).norm();
  const double spin = spinningPart<D>(tauStop, n).norm();
  if (roll > bound) s = std::min(s, bound / roll);
  if (spin > bound) s = std::min(s, bound / spin);
  out.scale = s;
  out.j = s * x.template head<D>();
  out.tau = s * tauStop;
  return out;  // [rolling_scale]
}

/// Apply the impulses of rollingFrictionImpulse(): +j at ra and +tau to a, -j at rb and -tau
/// to b (L += r x j + tau). Static bodies are left untouched.
template <int D>
void applyRollingFriction(RigidBody<D>& a, const Vec<D>& ra, RigidBody<D>& b, const Vec<D>& rb,
                          const RollingFrictionImpulse<D>& impulse) {
  applyPairImpulse<D>(a, ra, b, rb, impulse.j);
  a.applyAngularImpulse(impulse.tau);
  b.applyAngularImpulse(-impulse.tau);
}
// [rolling_friction]

}  // namespace stackbook
