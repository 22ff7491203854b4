// A program outside the stackbook tree: a unit cube dropped from 0.1 m onto a static
// plane (a thin wide box), two seconds of GBF's step with shock propagation. It prints
// where the cube came to rest and exits 0 only if it rests on the plane, at height 1/2.
#include <cmath>
#include <cstdio>
#include <memory>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/stacking/shock_propagation.hpp"

int main() {
  using namespace stackbook;
  World<3> world;
  world.gravity = Vec3(0.0, 0.0, -9.81);
  const Material material{0.2, 0.5, 0.0};  // restitution, friction, rolling friction
  // The plane: a static slab 20 m wide and 1 m thick whose top face is z = 0.
  world.addBody(makeStaticBody<3>(Vec3(0.0, 0.0, -0.5), Eigen::Quaterniond::Identity()),
                std::make_shared<BoxShape<3>>(makeBoxShape<3>(Vec3(20.0, 20.0, 1.0))), material);
  // The cube: mass 1, I = m (a^2 + b^2) / 12 = 1/6 about each axis.
  RigidBody<3> cube = makeDynamicBody<3>(1.0, Vec3::Constant(1.0 / 6.0));
  cube.position = Vec3(0.0, 0.0, 0.6);
  const int c = world.addBody(cube, std::make_shared<BoxShape<3>>(makeBoxShape<3>(Vec3::Constant(1.0))),
                              material);

  StepSettings settings;  // GBF's defaults, dt = 1e-3
  for (int n = 0; n < 2000; ++n) stackingStep<3>(world, settings);

  const RigidBody<3>& b = world.bodies[static_cast<std::size_t>(c)];
  std::printf("cube at rest: height %.4f m (expected 0.5), speed %.2e m/s\n", b.position.z(),
              b.velocity.norm());
  const bool ok = std::abs(b.position.z() - 0.5) < 5e-3 && b.velocity.norm() < 1e-2;
  std::printf("%s\n", ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}
