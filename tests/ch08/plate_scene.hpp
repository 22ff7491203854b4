#pragma once
// Validation case B18's scene for chapter 8's tests and exercises: a ball falling onto a
// thin static plate, and whether it tunnels.

#include <memory>

#include "scene_builders.hpp"

namespace stackbook::testing {

template <int D>
bool allFinite(const World<D>& w) {
  for (const RigidBody<D>& b : w.bodies) {
    if (!b.position.allFinite() || !b.velocity.allFinite() || !b.angularMomentum.allFinite()) {
      return false;
    }
  }
  return true;
}

template <int D>
double kineticEnergy(const World<D>& w) {
  double e = 0.0;
  for (const RigidBody<D>& b : w.bodies) e += b.kineticEnergy();
  return e;
}

/// B18: a ball of radius 0.1 moving straight down at `speed` (no gravity) towards a static
/// plate 0.02 thick whose top face is at height 0.01. The ball is placed where no sample
/// of the plate lies under it (the plate's samples are 0.25 apart), so only the ball's own
/// samples can find the plate. `phase` in [0, 1) shifts the start by that fraction of one
/// step's travel. Returns true if the ball ends below the plate.
struct PlateRun {
  bool tunnelled = false;
  bool finite = true;
  double energyRatio = 0.0;  ///< final KE / initial KE
};

template <int D>
PlateRun plateRun(double speed, double phase, double dt) {
  World<D> w;
  const double thickness = 0.02, radius = 0.1;
  const Material material{0.5, 0.0, 0.0};
  w.addBody(makeStaticBody<D>(), std::make_shared<BoxShape<D>>(makeBoxShape<D>(boxSize<D>(1.0, thickness))),
            material);
  auto shape = std::make_shared<SphereShape<D>>(makeSphereShape<D>(radius));
  RigidBody<D> b = ball<D>(radius);
  turnLowestSampleDown<D>(b, *shape);  // only the ball's own samples can find the plate
  const double gap = 0.1 + phase * speed * dt;
  b.position = Vec<D>::Constant(0.125);
  b.position[D - 1] = 0.5 * thickness + radius + gap;
  b.velocity = -speed * up<D>();
  b.syncAngularVelocity();
  w.addBody(b, shape, material);
  const double e0 = kineticEnergy<D>(w);
  StepSettings settings;
  settings.dt = dt;
  const double seconds = (gap + 2.0 * radius + 0.2) / speed;
  simulate<D>(w, settings, seconds);
  PlateRun out;
  out.finite = allFinite<D>(w);
  out.tunnelled = w.bodies[1].position[D - 1] < 0.0;
  out.energyRatio = kineticEnergy<D>(w) / e0;
  return out;
}

}  // namespace stackbook::testing
