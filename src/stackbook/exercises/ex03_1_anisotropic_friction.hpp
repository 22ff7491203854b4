#pragma once
/// \file
/// \brief Exercise 3.1 (\ref ch03): anisotropic friction, the elliptic cone.
///
/// Brushed metal, wood grain and tyre treads grip harder across one direction than along
/// it. With coefficients mu1 along the unit tangent t1 and mu2 along t2 = n x t1, the
/// friction cone of Eq. (3.3) becomes the elliptic cone
///
///     (j_t . t1 / mu1)^2 + (j_t . t2 / mu2)^2 <= j_n^2 .
///
/// Implement anisotropicFrictionalImpulse like frictionalImpulse of chapter 3, without
/// its safeguards:
/// 1. not approaching, immovable, or mu1 = mu2 = 0: the frictionless impulse of chapter 2;
/// 2. the sticking trial j* of Eq. (3.2), accepted when j*_n > 0 and j* lies in the
///    elliptic cone;
/// 3. otherwise slide with the friction that dissipates most for the slip direction s
///    (s = u_t/|u_t|, or s = -j*_t/|j*_t| when u_t = 0): among the friction impulses per
///    unit normal impulse f on the ellipse, the one that minimises f . s. Write
///    M = diag(mu1, mu2) in the (t1, t2) basis; then f = -M^2 s / |M s|. The impulse is
///    j = j_n (n + f) with j_n = -(1 + e) u_n / (n^T K (n + f)); when that denominator is not
///    positive, return the frictionless impulse.
/// Set branch, restitution and friction (friction: the coefficient along the slip, |f|).

#include "stackbook/impulse/contact_impulse.hpp"

namespace stackbook::exercises {

/// Coefficients of anisotropic friction: mu1 along the unit tangent t1, mu2 along n x t1.
struct AnisotropicFriction {
  Vec3 t1 = Vec3::UnitX();
  double mu1 = 0.0;
  double mu2 = 0.0;
};

/// Impulse with restitution e and elliptic-cone friction (Exercise 3.1). t1 must be a unit
/// vector perpendicular to the unit normal n.
ContactImpulse<3> anisotropicFrictionalImpulse(const Mat3& K, const Vec3& u, const Vec3& n, double e,
                                               const AnisotropicFriction& friction);

}  // namespace stackbook::exercises
