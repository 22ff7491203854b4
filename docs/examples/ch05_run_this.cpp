// Run this now (chapter 5): a 0.1 x 0.2 x 0.3 box spun near its middle axis, stepped with
// advanceFreeBody (dt = 1 ms) for 60 s. It prints the body-frame angular velocity every
// 5 s (watch the middle component flip) and the drift of |L| and of the energy.
#include <cmath>
#include <cstdio>

#include "stackbook/body/integrate.hpp"

using namespace stackbook;

int main() {
  const Vec3 I = Vec3(0.2 * 0.2 + 0.3 * 0.3, 0.1 * 0.1 + 0.3 * 0.3, 0.1 * 0.1 + 0.2 * 0.2) / 12.0;
  RigidBody<3> box = makeDynamicBody<3>(1.0, I);
  box.setAngularVelocity(Vec3(0.3, 1.0, 0.3));
  const double E0 = box.kineticEnergy(), L0 = box.angularMomentum.norm(), dt = 1e-3;
  std::printf("  t (s)   omega_1   omega_2   omega_3   E/E0 - 1    |L|/|L0| - 1\n");
  for (int k = 0; k <= 60000; ++k) {
    if (k % 5000 == 0) {
      const Vec3 w = box.orientation.inverse() * box.angularVelocity;
      std::printf("%7.1f %9.4f %9.4f %9.4f %11.2e %12.2e\n", k * dt, w.x(), w.y(), w.z(),
                  box.kineticEnergy() / E0 - 1.0, box.angularMomentum.norm() / L0 - 1.0);
    }
    advanceFreeBody<3>(box, dt);
  }
}
