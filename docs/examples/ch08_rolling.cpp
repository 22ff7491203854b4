// Chapter 8: rolling friction on a ball rolling on level ground (Eq. (8.8)), and what the
// discretisation itself costs a rolling ball. The ball's samples are a ring in its rolling
// plane (as in tests/ch08/scenes.hpp), so it rolls as a regular polygon of `segments`
// sides. Printed as Markdown for the course page (\include{doc} ch08_rolling.out).
#include <cmath>
#include <cstdio>
#include <memory>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/stepping/gbf_step.hpp"

using namespace stackbook;

namespace {

constexpr double kG = 9.81;

template <int D>
std::shared_ptr<const Shape<D>> ring(double radius, int segments) {
  if constexpr (D == 2) {
    return std::make_shared<SphereShape<2>>(SphereSdf<2>(radius), regularPolygon(radius, segments));
  } else {
    SurfaceMesh<3> mesh;
    for (int k = 0; k < segments; ++k) {
      const double t = 2.0 * M_PI * k / segments;
      mesh.vertices.push_back(Vec3(radius * std::cos(t), 0.0, radius * std::sin(t)));
    }
    mesh.vertices.push_back(Vec3(0.0, radius, 0.0));
    mesh.vertices.push_back(Vec3(0.0, -radius, 0.0));
    for (int k = 0; k < segments; ++k) {
      mesh.faces.push_back({k, (k + 1) % segments, segments});
      mesh.faces.push_back({(k + 1) % segments, k, segments + 1});
    }
    return std::make_shared<SphereShape<3>>(SphereSdf<3>(radius), std::move(mesh));
  }
}

struct Run {
  double speed = 0.0;
  StepCounters counters;
};

/// A ball of radius R rolling at v0 along axis 0 for `seconds`; returns its final speed.
template <int D>
Run roll(double v0, double muR, double dt, int segments, double seconds) {
  const double R = 0.25, k = D == 3 ? 0.4 : 0.5;
  World<D> w;
  Vec<D> up = Vec<D>::Zero();
  up[D - 1] = 1.0;
  w.gravity = -kG * up;
  const Material m{0.0, 0.5, muR};
  Vec<D> slab = Vec<D>::Constant(20.0);
  slab[D - 1] = 1.0;
  w.addBody(makeStaticBody<D>(Vec<D>(-0.5 * up)), std::make_shared<BoxShape<D>>(makeBoxShape<D>(slab)),
            m);
  RigidBody<D> b = makeDynamicBody<D>(1.0, AngVec<D>::Constant(k * R * R));
  b.position = R * up;
  b.velocity[0] = v0;
  AngVec<D> omega = AngVec<D>::Zero();
  omega[D == 2 ? 0 : 1] = D == 2 ? -v0 / R : v0 / R;
  b.setAngularVelocity(omega);
  w.addBody(b, ring<D>(R, segments), m);
  StepSettings settings;
  settings.dt = dt;
  Run out;
  const long steps = std::lround(seconds / dt);
  for (long n = 0; n < steps; ++n) out.counters += gbfStep<D>(w, settings);
  out.speed = w.bodies[1].velocity[0];
  return out;
}

}  // namespace

int main() {
  const double R = 0.25, muR = 0.05, v0 = 0.5, T = 0.1;
  std::printf("Rolling friction mu_r = %g m, R = %g m, v0 = %g m/s, measured over %g s "
              "(1000-gon):\n\n", muR, R, v0, T);
  std::printf("| dimension | dt (s) | predicted a (m/s^2) | measured (v0 - v) / T | error |\n"
              "|---|---|---|---|---|\n");
  for (const double dt : {1e-3, 5e-4}) {
    for (const int d : {2, 3}) {
      const double k = d == 3 ? 0.4 : 0.5, a = muR * kG / (R * (1.0 + k));  // Eq. (8.8)
      const Run r = d == 2 ? roll<2>(v0, muR, dt, 1000, T) : roll<3>(v0, muR, dt, 1000, T);
      const double measured = (v0 - r.speed) / T;
      std::printf("| %dD | %g | %.4f | %.4f | %+.2f %% |\n", d, dt, a, measured,
                  100.0 * (measured - a) / a);
    }
  }
  const Run counted = roll<2>(v0, muR, 1e-3, 1000, T);
  std::printf("\nIn the 2D run at dt = 1e-3 (%lld steps) the contact stage applied %lld sticking "
              "impulses and %lld rolling-friction impulse pairs; %lld of its pair loops stopped "
              "at the cap of %d.\n\n",
              static_cast<long long>(counted.counters.steps),
              static_cast<long long>(counted.counters.contact.sticking),
              static_cast<long long>(counted.counters.contact.rollingImpulses),
              static_cast<long long>(counted.counters.contact.pairIterationCapHits),
              StepSettings{}.contactPairIterations);
  std::printf("Without rolling friction (2D, v0 = 1 m/s, 0.1 s): the speed lost to the "
              "discretisation alone.\n\n| polygon sides | dt (s) | v0 - v (m/s) |\n|---|---|---|\n");
  for (const int segments : {1000, 2000, 4000}) {
    for (const double dt : {1e-3, 5e-4}) {
      std::printf("| %d | %g | %.2e |\n", segments, dt, 1.0 - roll<2>(1.0, 0.0, dt, segments, 0.1).speed);
    }
  }
}
