// Chapter 8, validation case B18: how fast can a ball hit a thin plate before it tunnels?
// A ball of radius 0.1 (icosphere samples in 3D, 48-gon in 2D) falls without gravity onto
// a static plate 0.02 thick, at a spot where no plate sample lies under it, starting at 8
// phases of one step's travel; e = 0.5, so a clean bounce keeps KE'/KE = e^2 = 0.25.
// Printed as Markdown for the course page (\include{doc} ch08_tunnelling.out).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/stepping/gbf_step.hpp"

using namespace stackbook;

namespace {

struct Outcome {
  bool tunnelled = false;
  bool finite = true;
  double energyRatio = 0.0;
};

template <int D>
Outcome run(double speed, double phase, double dt) {
  World<D> w;
  const double thickness = 0.02, radius = 0.1;
  const Material material{0.5, 0.0, 0.0};
  Vec<D> plate = Vec<D>::Constant(1.0);
  plate[D - 1] = thickness;
  w.addBody(makeStaticBody<D>(), std::make_shared<BoxShape<D>>(makeBoxShape<D>(plate)), material);
  auto shape = std::make_shared<SphereShape<D>>(makeSphereShape<D>(radius));
  const double k = D == 3 ? 0.4 : 0.5;
  RigidBody<D> b = makeDynamicBody<D>(1.0, AngVec<D>::Constant(k * radius * radius));
  Vec<D> lowest = shape->surfaceSamples().front();
  for (const Vec<D>& s : shape->surfaceSamples()) {
    if (s[D - 1] < lowest[D - 1]) lowest = s;
  }
  if constexpr (D == 3) {
    b.orientation = Eigen::Quaterniond::FromTwoVectors(lowest, Vec3(0.0, 0.0, -1.0));
  }
  const double gap = 0.1 + phase * speed * dt;
  b.position = Vec<D>::Constant(0.125);
  b.position[D - 1] = 0.5 * thickness + radius + gap;
  b.velocity = Vec<D>::Zero();
  b.velocity[D - 1] = -speed;
  b.syncAngularVelocity();
  w.addBody(b, shape, material);
  const double e0 = w.bodies[1].kineticEnergy();
  StepSettings settings;
  settings.dt = dt;
  const long steps = std::lround((gap + 2.0 * radius + 0.2) / speed / dt) + 1;
  for (long n = 0; n < steps; ++n) gbfStep<D>(w, settings);
  Outcome out;
  const RigidBody<D>& f = w.bodies[1];
  out.finite = f.position.allFinite() && f.velocity.allFinite();
  out.tunnelled = f.position[D - 1] < 0.0;
  out.energyRatio = f.kineticEnergy() / e0;
  return out;
}

template <int D>
void table(double dt) {
  for (const double speed : {5.0, 9.5, 10.5, 20.0, 40.0, 80.0, 160.0, 320.0}) {
    int tunnelled = 0, finite = 0;
    double maxRatio = 0.0;
    const int phases = 8;
    for (int p = 0; p < phases; ++p) {
      const Outcome o = run<D>(speed, static_cast<double>(p) / phases, dt);
      tunnelled += o.tunnelled ? 1 : 0;
      finite += o.finite ? 1 : 0;
      maxRatio = std::max(maxRatio, o.energyRatio);
    }
    std::printf("| %dD | %g | %.3f | %d of %d | %d of %d | %.3f |\n", D, speed, speed * dt / 0.02,
                tunnelled, phases, finite, phases, maxRatio);
  }
}

}  // namespace

int main() {
  std::printf("| dimension | v (m/s) | v dt / h | tunnelled | finite | largest KE'/KE |\n"
              "|---|---|---|---|---|---|\n");
  table<2>(1e-3);
  table<3>(1e-3);
}
