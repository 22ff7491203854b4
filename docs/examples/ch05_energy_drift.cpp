// Chapter 5: how much kinetic energy the orientation update adds (Eq. (5.14)), in three
// settings: validation case B23 (a 0.2 x 0.4 x 0.6 m box of density 1000 tumbling at
// omega = (1, 2, 3) rad/s for 5 s); the one-step gain against the prediction; and a fast
// spin near the intermediate axis, where the gain changes the motion. Printed as Markdown
// (\include{doc} ch05_energy_drift.out).
#include <cmath>
#include <cstdio>
#include <random>

#include "stackbook/body/integrate.hpp"
#include "stackbook/body/torque_free.hpp"
#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"

using namespace stackbook;

int main() {
  std::printf("**Tumbling box (\\ref case_B23 \"B23\").** The chapter's step, and for comparison explicit Euler on "
              "Euler's equations (5.5), which integrates omega instead of L.\n\n"
              "| dt (s) | steps | largest E / E0 - 1 | change of the length of L | "
              "explicit Euler: largest E / E0 - 1 | explicit Euler: change of the length of L |\n"
              "|---|---|---|---|---|---|\n");
  for (const double dt : {1e-2, 5e-3, 1e-3, 1e-4}) {
    TriangleMesh mesh = boxMesh(Vec3(0.2, 0.4, 0.6));
    RigidBody<3> box = makeBodyFromMesh<3>(mesh, 1000.0);
    box.setAngularVelocity(Vec3(1.0, 2.0, 3.0));
    const double E0 = box.kineticEnergy(), L0 = box.angularMomentum.norm();
    double Emax = E0;
    const int n = static_cast<int>(std::lround(5.0 / dt));
    for (int step = 0; step < n; ++step) {
      advanceFreeBody<3>(box, dt);
      Emax = std::max(Emax, box.kineticEnergy());
    }
    // Explicit Euler on Eq. (5.5) in the body frame: omega += dt I^-1 (-omega x I omega).
    const Vec3 I = box.inertia;
    Vec3 w(1.0, 2.0, 3.0);
    double EmaxExplicit = E0;
    for (int step = 0; step < n; ++step) {
      w += dt * eulerEquations(I, w);
      EmaxExplicit = std::max(EmaxExplicit, 0.5 * w.dot(I.cwiseProduct(w)));
    }
    std::printf("| %g | %d | %.3e | %g | %.3e | %.3e |\n", dt, n, Emax / E0 - 1.0,
                box.angularMomentum.norm() / L0 - 1.0, EmaxExplicit / E0 - 1.0,
                I.cwiseProduct(w).norm() / L0 - 1.0);
  }

  // One step of random bodies: measured gain over the prediction dt^2/2 a^T I^-1 a.
  std::uniform_real_distribution<double> uniform(-1.0, 1.0), side(0.1, 2.0);
  std::printf("\n**One step, 1000 random bodies.** Measured energy gain divided by Eq. (5.14):\n\n"
              "| dt (s) | smallest ratio | largest ratio |\n|---|---|---|\n");
  for (const double dt : {1e-2, 1e-3, 1e-4}) {
    double lo = 1e300, hi = -1e300;
    std::mt19937_64 local(7);
    for (int trial = 0; trial < 1000; ++trial) {
      const double a = side(local), b = side(local), c = side(local);
      RigidBody<3> body = makeDynamicBody<3>(1.0, Vec3(b * b + c * c, a * a + c * c, a * a + b * b) / 12.0);
      body.orientation = Eigen::Quaterniond(uniform(local), uniform(local), uniform(local), uniform(local)).normalized();
      body.angularMomentum = Vec3(uniform(local), uniform(local), uniform(local));
      body.syncAngularVelocity();
      const Vec3 Lb = body.orientation.inverse() * body.angularMomentum;
      const Vec3 wb = body.inverseInertia.cwiseProduct(Lb);
      const Vec3 gyro = Lb.cross(wb);
      const double predicted = 0.5 * dt * dt * gyro.dot(body.inverseInertia.cwiseProduct(gyro));
      const double E0 = body.kineticEnergy();
      advanceFreeBody<3>(body, dt);
      const double ratio = (body.kineticEnergy() - E0) / predicted;
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
    }
    std::printf("| %g | %.6f | %.6f |\n", dt, lo, hi);
  }

  // The same box as the flip, spun ten times faster and closer to the intermediate axis.
  const Vec3 I = Vec3(0.2 * 0.2 + 0.3 * 0.3, 0.1 * 0.1 + 0.3 * 0.3, 0.1 * 0.1 + 0.2 * 0.2) / 12.0;
  const Vec3 omega0(0.1, 10.0, 0.1);
  const TorqueFreeInvariants inv = torqueFreeInvariants(I, omega0);
  const double T = polhodePeriod(I, inv.energy, inv.momentumSquared).period;
  std::printf("\n**A fast spin near the separatrix.** omega(0) = (0.1, 10, 0.1) rad/s, same box "
              "as the flip; exact flip period %.4f s, so %.1f flips in 20 s.\n\n"
              "| dt (s) | flips in 20 s | energy gain after 20 s |\n|---|---|---|\n",
              T, 2.0 * 20.0 / T);
  for (const double dt : {1e-3, 1e-4}) {
    RigidBody<3> box = makeDynamicBody<3>(1.0, I);
    box.setAngularVelocity(omega0);
    int count = 0;
    double previous = omega0.y();
    const int n = static_cast<int>(std::lround(20.0 / dt));
    for (int step = 0; step < n; ++step) {
      advanceFreeBody<3>(box, dt);
      const double current = (box.orientation.inverse() * box.angularVelocity).y();
      if ((previous > 0.0) != (current > 0.0)) ++count;
      previous = current;
    }
    std::printf("| %g | %d | %+.1f %% |\n", dt, count, 100.0 * (box.kineticEnergy() / inv.energy - 1.0));
  }
}
