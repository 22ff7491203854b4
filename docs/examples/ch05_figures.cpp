// Chapter 5's figures, computed with advanceFreeBody: a box spun near its middle axis
// tumbles (its body-frame angular velocity, with Runge-Kutta 4 on Euler's equations as a
// reference), and how far the kinetic energy of a tumbling box strays from its start with
// the chapter's step and with explicit Euler on omega.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "figure_svg.hpp"
#include "stackbook/body/integrate.hpp"
#include "stackbook/body/torque_free.hpp"
#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"

using namespace stackbook;
using namespace figure_svg;

namespace {

void tumbling() {
  // A 0.1 x 0.2 x 0.3 box of mass 1, spun mostly about its middle axis (as in the chapter).
  const Vec3 I = Vec3(0.2 * 0.2 + 0.3 * 0.3, 0.1 * 0.1 + 0.3 * 0.3, 0.1 * 0.1 + 0.2 * 0.2) / 12.0;
  const Vec3 omega0(0.3, 1.0, 0.3);
  const TorqueFreeInvariants inv = torqueFreeInvariants(I, omega0);
  const double period = polhodePeriod(I, inv.energy, inv.momentumSquared).period;
  const double duration = 2.2 * period, dt = 1e-3;
  RigidBody<3> box = makeDynamicBody<3>(1.0, I);
  box.setAngularVelocity(omega0);
  Vec3 reference = omega0;
  const int n = static_cast<int>(std::lround(duration / dt));
  Points w[3], ref[3];
  for (int k = 0; k <= n; ++k) {
    const Vec3 body = box.orientation.inverse() * box.angularVelocity;
    if (k % 20 == 0) {
      for (int c = 0; c < 3; ++c) {
        w[c].emplace_back(k * dt, body[c]);
        ref[c].emplace_back(k * dt, reference[c]);
      }
    }
    advanceFreeBody<3>(box, dt);
    reference = eulerEquationsRk4Step(I, reference, dt);
  }
  Svg svg(660, 430, "Body-frame angular velocity of a box spun near its middle axis");
  const View v{80, 20, 550, 270, 0.0, duration, -1.3, 1.3};
  svg.axes(v, "time (s)", "ω in the body frame (rad/s)", 8, 6);
  const char* colours[3] = {"#1b7837", "#b2182b", "#2166ac"};
  for (int c = 0; c < 3; ++c) {
    svg.polyline(v, ref[c], stroke("#999", 4.5));
    svg.polyline(v, w[c], stroke(colours[c], 1.8));
  }
  svg.legend(90, 338, {{stroke("#b2182b", 1.8), "ω_2, about the middle axis: it flips"},
                      {stroke("#1b7837", 1.8), "ω_1"},
                      {stroke("#2166ac", 1.8), "ω_3"},
                      {stroke("#999", 4.5), "Runge-Kutta 4 on Euler's equations"}});
  svg.save("ch05_tumbling.svg");
  std::cout << "ch05_tumbling.svg: polhode period " << period << " s\n";
}

void energyDrift() {
  TriangleMesh mesh = boxMesh(Vec3(0.2, 0.4, 0.6));
  RigidBody<3> box = makeBodyFromMesh<3>(mesh, 1000.0);
  box.setAngularVelocity(Vec3(1.0, 2.0, 3.0));
  const double E0 = box.kineticEnergy(), L0 = box.angularMomentum.norm(), duration = 5.0, dt = 1e-3;
  const Vec3 I = box.inertia;
  Vec3 w(1.0, 2.0, 3.0);  // explicit Euler on Euler's equations (5.5), body frame
  Points stepE, stepL, eulerE, eulerL;
  const int n = static_cast<int>(std::lround(duration / dt));
  double top = 0.0;
  for (int k = 1; k <= n; ++k) {
    advanceFreeBody<3>(box, dt);
    w += dt * eulerEquations(I, w);
    if (k % 10 == 0) {
      const double t = k * dt;
      stepE.emplace_back(t, 100.0 * (box.kineticEnergy() / E0 - 1.0));
      stepL.emplace_back(t, 100.0 * (box.angularMomentum.norm() / L0 - 1.0));
      eulerE.emplace_back(t, 100.0 * (0.5 * w.dot(I.cwiseProduct(w)) / E0 - 1.0));
      eulerL.emplace_back(t, 100.0 * (I.cwiseProduct(w).norm() / L0 - 1.0));
      top = std::max({top, stepE.back().second, eulerE.back().second, eulerL.back().second});
    }
  }
  Svg svg(660, 400, "Energy and angular momentum of a tumbling box: the chapter's step against explicit Euler");
  const View v{80, 20, 550, 290, 0.0, duration, -0.05 * top, 1.1 * top};
  svg.axes(v, "time (s)", "change since the start (%)", 5, 6);
  svg.polyline(v, eulerL, stroke("#1b7837", 2.2, "7 4"));
  // The two energy curves nearly coincide: Euler's is drawn wide and pale underneath, so
  // that both show.
  svg.polyline(v, eulerE, stroke("#7fbf7b", 6.0));
  svg.polyline(v, stepL, stroke("#b2182b", 2.2, "7 4"));
  svg.polyline(v, stepE, stroke("#b2182b", 2.2));
  svg.legend(90, 28, {{stroke("#b2182b", 2.2), "the chapter's step: energy"},
                      {stroke("#b2182b", 2.2, "7 4"), "the chapter's step: |L|"},
                      {stroke("#7fbf7b", 6.0), "explicit Euler on ω: energy"},
                      {stroke("#1b7837", 2.2, "7 4"), "explicit Euler on ω: |L|"}});
  svg.textPixels(355, 385, "both with dt = 1 ms; a 0.2 x 0.4 x 0.6 box spun at (1, 2, 3) rad/s", "middle", "#444", 12);
  svg.save("ch05_energy_drift.svg");
}

}  // namespace

int main() {
  tumbling();
  energyDrift();
}
