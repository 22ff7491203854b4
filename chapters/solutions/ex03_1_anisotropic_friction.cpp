// Exercise 3.1 (chapter 3): anisotropic friction, the reference solution.
#include "stackbook/exercises/ex03_1_anisotropic_friction.hpp"

#include <cmath>

#include <Eigen/Cholesky>

#include "stackbook/impulse/frictionless_impulse.hpp"

namespace stackbook::exercises {

ContactImpulse<3> anisotropicFrictionalImpulse(const Mat3& K, const Vec3& u, const Vec3& n, double e,
                                               const AnisotropicFriction& friction) {
  const ContactImpulse<3> frictionless = frictionlessImpulse<3>(K, u, n, e);
  if (frictionless.branch != ImpulseBranch::Frictionless ||
      (friction.mu1 == 0.0 && friction.mu2 == 0.0)) {
    return frictionless;
  }
  const Vec3 t1 = friction.t1, t2 = n.cross(t1);
  const double un = u.dot(n);
  const Vec3 ut = u - un * n;

  // Sticking trial (Eq. (3.2)), tested against the ellipse instead of the circle.
  const Eigen::LDLT<Mat3> ldlt(K);
  const Vec3 jStick = ldlt.solve(Vec3(-e * un * n - u));
  const double jn = jStick.dot(n);
  const double a = jStick.dot(t1) / friction.mu1, b = jStick.dot(t2) / friction.mu2;
  ContactImpulse<3> result = frictionless;
  if (jn > 0.0 && a * a + b * b <= jn * jn) {
    result.j = jStick;
    result.branch = ImpulseBranch::Sticking;
    return result;
  }

  // Slide: the friction on the ellipse that dissipates most for the slip direction s.
  const Vec3 jt = jStick - jn * n;
  Vec3 s;
  if (ut.norm() > 1e-9 * u.norm()) {
    s = ut.normalized();
  } else if (jt.norm() > 0.0) {
    s = -jt.normalized();
  } else {
    return frictionless;
  }
  const double s1 = s.dot(t1), s2 = s.dot(t2);
  const double scale = std::hypot(friction.mu1 * s1, friction.mu2 * s2);
  const Vec3 f = -(friction.mu1 * friction.mu1 * s1 * t1 + friction.mu2 * friction.mu2 * s2 * t2) / scale;
  const Vec3 k = n + f;
  const double denominator = n.dot(K * k);
  if (!(denominator > 0.0)) return frictionless;
  result.j = (-(1.0 + e) * un / denominator) * k;
  result.branch = ImpulseBranch::Sliding;
  result.friction = f.norm();
  return result;
}

}  // namespace stackbook::exercises
