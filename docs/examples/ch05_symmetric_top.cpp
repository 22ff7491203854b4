// Chapter 5: validation case A12, the torque-free symmetric top (transverse moment 0.04,
// axial 0.02 kg m^2, body-frame omega = (1, 0, 10) rad/s), integrated for 10 s. Printed as
// Markdown for the course page (\include{doc} ch05_symmetric_top.out).
#include <cmath>
#include <cstdio>

#include "stackbook/body/integrate.hpp"
#include "stackbook/body/torque_free.hpp"

using namespace stackbook;

namespace {

struct Run {
  double bodyPhase, spacePhase, energyGain, spin, momentumChange;
};

Run run(double dt) {
  const double I = 0.04, J = 0.02, T = 10.0;
  const Vec3 omega0(1.0, 0.0, 10.0);
  const SymmetricTopRates rates = symmetricTopRates(I, J, omega0);
  RigidBody<3> top = makeDynamicBody<3>(1.0, Vec3(I, I, J));
  top.setAngularVelocity(omega0);
  const Vec3 L = top.angularMomentum, Lhat = L.normalized();
  const double E0 = top.kineticEnergy();
  const Vec3 e30 = Vec3::UnitZ();
  const Vec3 b1 = (e30 - e30.dot(Lhat) * Lhat).normalized(), b2 = Lhat.cross(b1);
  double bodyPhase = 0.0, spacePhase = 0.0, bodyAngle = 0.0, spaceAngle = 0.0;
  const int n = static_cast<int>(std::lround(T / dt));
  for (int step = 0; step < n; ++step) {
    advanceFreeBody<3>(top, dt);
    const Vec3 wb = top.orientation.inverse() * top.angularVelocity;
    const double b = std::atan2(-wb.y(), wb.x());
    bodyPhase += std::remainder(b - bodyAngle, 2.0 * M_PI);
    bodyAngle = b;
    const Vec3 e3 = top.orientation * Vec3::UnitZ();
    const double s = std::atan2(e3.dot(b2), e3.dot(b1));
    spacePhase += std::remainder(s - spaceAngle, 2.0 * M_PI);
    spaceAngle = s;
  }
  const Vec3 wb = top.orientation.inverse() * top.angularVelocity;
  return {bodyPhase - rates.bodyRate * T, spacePhase - rates.spaceRate * T,
          top.kineticEnergy() - E0, wb.z() - omega0.z(), (top.angularMomentum - L).norm()};
}

}  // namespace

int main() {
  const SymmetricTopRates rates = symmetricTopRates(0.04, 0.02, Vec3(1.0, 0.0, 10.0));
  std::printf("Closed forms (Eq. (5.15)): s = %.6f rad/s, p = %.6f rad/s; over 10 s the body-frame "
              "phase is %.4f rad and the space phase %.4f rad. The kinetic energy is %.4f J.\n\n",
              rates.bodyRate, rates.spaceRate, 10.0 * rates.bodyRate, 10.0 * rates.spaceRate,
              0.5 * (0.04 * 1.0 + 0.02 * 100.0));
  std::printf("| dt (s) | body phase error (rad) | space phase error (rad) | energy gain (J) | "
              "bound T dt / 2 (J) | w3 change (rad/s) | change of L |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const double dt : {1e-3, 5e-4, 2.5e-4}) {
    const Run r = run(dt);
    std::printf("| %g | %.4e | %.2e | %.4e | %.4e | %.4e | %g |\n", dt, r.bodyPhase, r.spacePhase,
                r.energyGain, 10.0 * dt / 2.0, r.spin, r.momentumChange);
  }
}
