#pragma once
/// \file
/// \brief Torque-free rotation of a rigid body in closed form, and an independent numerical
/// reference for it (\ref ch05, Eqs. (5.5), (5.14)-(5.16)).
///
/// None of this is used by the simulator; it is what the simulator is checked against:
/// the two invariants of Euler's equations, the precession rates of a symmetric top, the
/// period of the polhode (Landau and Lifshitz, Mechanics, section 37) and a classical
/// fourth-order Runge-Kutta integration of Euler's equations in the body frame.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "stackbook/math/types.hpp"

namespace stackbook {

// [torque_free_invariants]
/// Kinetic energy E = omega . I omega / 2 and squared angular momentum |L|^2 = |I omega|^2 of
/// a body with principal moments `moments` turning at the body-frame angular velocity
/// `omegaBody`: the two quantities Euler's equations conserve.
struct TorqueFreeInvariants {
  double energy = 0.0;           ///< E
  double momentumSquared = 0.0;  ///< L^2
};

inline TorqueFreeInvariants torqueFreeInvariants(const Vec3& moments, const Vec3& omegaBody) {
  const Vec3 L = moments.cwiseProduct(omegaBody);
  return {0.5 * omegaBody.dot(L), L.squaredNorm()};
}
// [torque_free_invariants]

// [euler_equations]
/// Euler's equations for a free body in its principal frame, Eq. (5.5):
/// I1 dw1/dt = (I2 - I3) w2 w3 and cyclically. Returns d(omegaBody)/dt.
inline Vec3 eulerEquations(const Vec3& I, const Vec3& w) {
  return Vec3((I[1] - I[2]) * w[1] * w[2] / I[0], (I[2] - I[0]) * w[2] * w[0] / I[1],
              (I[0] - I[1]) * w[0] * w[1] / I[2]);
}

/// One classical fourth-order Runge-Kutta step of Euler's equations: the independent
/// reference the chapter's tests compare the simulator and the closed forms with.
inline Vec3 eulerEquationsRk4Step(const Vec3& I, const Vec3& w, double dt) {
  const Vec3 k1 = eulerEquations(I, w);
  const Vec3 k2 = eulerEquations(I, w + 0.5 * dt * k1);
  const Vec3 k3 = eulerEquations(I, w + 0.5 * dt * k2);
  const Vec3 k4 = eulerEquations(I, w + dt * k3);
  return w + (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}
// [euler_equations]

// [symmetric_top]
/// Precession rates of a torque-free symmetric top with transverse moment I, axial moment J
/// and body-frame angular velocity omega = (w1, w2, w3) (axis 3 the symmetry axis), Eq. (5.15).
struct SymmetricTopRates {
  double bodyRate = 0.0;   ///< s = (I - J)/I w3: (w1, w2) turns about axis 3 at -s in the body
  double spaceRate = 0.0;  ///< p = |L|/I: the symmetry axis turns about L at p in space
};

inline SymmetricTopRates symmetricTopRates(double I, double J, const Vec3& omegaBody) {
  const Vec3 L(I * omegaBody.x(), I * omegaBody.y(), J * omegaBody.z());
  return {(I - J) / I * omegaBody.z(), L.norm() / I};
}
// [symmetric_top]

// [polhode_period]
/// The period of torque-free motion of a body with three distinct principal moments, from
/// Landau and Lifshitz section 37 (Eq. (5.16)), for the energy E and squared angular momentum
/// L^2. With the moments sorted I1 < I2 < I3:
/// - if L^2 > 2 E I2 the angular velocity circles the axis of I3, and
///   lambda^2 = (I3 - I2)(L^2 - 2 E I1)/(I1 I2 I3), k^2 = (I2 - I1)(2 E I3 - L^2) / ((I3 - I2)(L^2 - 2 E I1));
/// - if L^2 < 2 E I2 it circles the axis of I1, with 1 and 3 exchanged;
/// and the period is T = 4 K(k) / lambda, K the complete elliptic integral of the first kind.
/// An intermediate-axis spin flips every T/2. Throws std::invalid_argument on the separatrix
/// L^2 = 2 E I2 (T infinite), for equal moments, or for E, L^2 no motion can have.
struct PolhodePeriod {
  double period = 0.0;      ///< T
  double modulus = 0.0;     ///< k (std::comp_ellint_1 takes the modulus, not m = k^2)
  double frequency = 0.0;   ///< lambda, with tau = lambda t the argument of sn, cn, dn
  int circledAxis = 0;      ///< index (into `moments`) of the axis omega circles
};

inline PolhodePeriod polhodePeriod(const Vec3& moments, double energy, double momentumSquared) {
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return moments[a] < moments[b]; });
  const double I1 = moments[order[0]], I2 = moments[order[1]], I3 = moments[order[2]];
  const double E = energy, L2 = momentumSquared;
  const auto fail = [&](const char* what) {
    std::ostringstream msg;
    msg << "polhodePeriod: " << what << " (moments " << moments.transpose() << ", E = " << E
        << ", L^2 = " << L2 << ")";
    throw std::invalid_argument(msg.str());
  };
  if (!(I1 > 0.0) || !(I1 < I2) || !(I2 < I3)) fail("the moments must be positive and distinct");
  // Every motion has 2 E I1 <= L^2 <= 2 E I3; equality is a steady spin about an axis.
  if (!(L2 > 2.0 * E * I1) || !(L2 < 2.0 * E * I3)) fail("no precessing motion has these E and L^2");
  PolhodePeriod result;
  double lambda2 = 0.0, k2 = 0.0;
  if (L2 > 2.0 * E * I2) {
    lambda2 = (I3 - I2) * (L2 - 2.0 * E * I1) / (I1 * I2 * I3);
    k2 = (I2 - I1) * (2.0 * E * I3 - L2) / ((I3 - I2) * (L2 - 2.0 * E * I1));
    result.circledAxis = order[2];
  } else if (L2 < 2.0 * E * I2) {
    lambda2 = (I2 - I1) * (2.0 * E * I3 - L2) / (I1 * I2 * I3);
    k2 = (I3 - I2) * (L2 - 2.0 * E * I1) / ((I2 - I1) * (2.0 * E * I3 - L2));
    result.circledAxis = order[0];
  } else {
    fail("the motion lies on the separatrix L^2 = 2 E I2, where the period is infinite");
  }
  result.frequency = std::sqrt(lambda2);
  result.modulus = std::sqrt(k2);
  result.period = 4.0 * std::comp_ellint_1(result.modulus) / result.frequency;
  return result;
}
// [polhode_period]

}  // namespace stackbook
