// Chapter 5: the intermediate-axis (Dzhanibekov) flip of a 0.1 x 0.2 x 0.3 m box of 1 kg.
// The period from Landau and Lifshitz (Eq. (5.16)), the same period measured on a
// fourth-order Runge-Kutta integration of Euler's equations, and the period of the chapter's
// integrator at three time steps. Printed as Markdown (\include{doc} ch05_dzhanibekov.out).
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "stackbook/body/integrate.hpp"
#include "stackbook/body/torque_free.hpp"

using namespace stackbook;

namespace {

/// Times at which the y component of the body-frame angular velocity changes sign.
std::vector<double> flips(double y0, double dt, double duration, const std::function<double()>& step) {
  std::vector<double> times;
  double previous = y0;
  const int n = static_cast<int>(std::lround(duration / dt));
  for (int k = 1; k <= n; ++k) {
    const double current = step();
    if ((previous > 0.0) != (current > 0.0)) times.push_back((k - 1 + previous / (previous - current)) * dt);
    previous = current;
  }
  return times;
}

}  // namespace

int main() {
  const Vec3 I = Vec3(0.2 * 0.2 + 0.3 * 0.3, 0.1 * 0.1 + 0.3 * 0.3, 0.1 * 0.1 + 0.2 * 0.2) / 12.0;
  const Vec3 omega0(0.3, 1.0, 0.3);
  const TorqueFreeInvariants inv = torqueFreeInvariants(I, omega0);
  const PolhodePeriod P = polhodePeriod(I, inv.energy, inv.momentumSquared);
  std::printf("| quantity | value |\n|---|---|\n");
  std::printf("| principal moments (kg m^2) | %.6g, %.6g, %.6g |\n", I.x(), I.y(), I.z());
  std::printf("| body-frame omega(0) (rad/s) | 0.3, 1, 0.3 |\n");
  std::printf("| energy E (J) | %.6e |\n", inv.energy);
  std::printf("| L^2 against 2 E I2, I2 the middle moment | %.6e > %.6e: omega circles the x axis, "
              "the largest moment |\n", inv.momentumSquared, 2.0 * inv.energy * I.y());
  std::printf("| lambda (1/s) | %.6f |\n", P.frequency);
  std::printf("| modulus k | %.8f |\n", P.modulus);
  std::printf("| K(k) | %.6f |\n", std::comp_ellint_1(P.modulus));
  std::printf("| period T (s) | **%.6f** |\n", P.period);
  std::printf("| time between flips T/2 (s) | %.6f |\n\n", 0.5 * P.period);
  std::printf("| integrator | dt (s) | steps per period | measured T (s) | relative error |\n"
              "|---|---|---|---|---|\n");
  {
    const double dt = P.period / 40000.0;
    Vec3 w = omega0;
    const std::vector<double> t = flips(omega0.y(), dt, 1.6 * P.period, [&] {
      w = eulerEquationsRk4Step(I, w, dt);
      return w.y();
    });
    std::printf("| Runge-Kutta 4 on Euler's equations | %.3g | 40000 | %.9f | %.1e |\n", dt,
                t[2] - t[0], (t[2] - t[0]) / P.period - 1.0);
  }
  std::vector<double> measured;
  for (const double dt : {1e-3, 5e-4, 2.5e-4}) {
    RigidBody<3> box = makeDynamicBody<3>(1.0, I);
    box.setAngularVelocity(omega0);
    const std::vector<double> t = flips(omega0.y(), dt, 1.25 * P.period, [&] {
      advanceFreeBody<3>(box, dt);
      return (box.orientation.inverse() * box.angularVelocity).y();
    });
    measured.push_back(t[2] - t[0]);
    std::printf("| advanceFreeBody (Eqs. (5.7)-(5.12)) | %g | %.0f | %.6f | %+.4f %% |\n", dt,
                P.period / dt, t[2] - t[0], 100.0 * ((t[2] - t[0]) / P.period - 1.0));
  }
  const double richardson = 2.0 * measured[1] - measured[0];
  std::printf("\n- Error ratios between successive rows: %.3f and %.3f. Richardson extrapolation "
              "2 T(dt/2) - T(dt) from the first two rows: %.6f s (%+.3f %%).\n",
              (measured[0] - P.period) / (measured[1] - P.period),
              (measured[1] - P.period) / (measured[2] - P.period), richardson,
              100.0 * (richardson / P.period - 1.0));
  const double wrong = 4.0 * std::comp_ellint_1(P.modulus * P.modulus) / P.frequency;
  std::printf("- Passing the parameter k^2 = %.6f instead of the modulus to std::comp_ellint_1 gives "
              "K = %.6f and T = %.6f s, %+.1f %% off.\n",
              P.modulus * P.modulus, std::comp_ellint_1(P.modulus * P.modulus), wrong,
              100.0 * (wrong / P.period - 1.0));
}
