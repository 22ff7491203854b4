// Chapter 9 benchmark: what GBF's contact stage leaves behind for the pass (Eq. (9.8)), and
// the pass as the contact stage (Eq. (9.9)), on the 2D pyramid of validation B15.
// Build in release mode and run:
//   ./build/release/bench/contact_residual_bench [base boxes] [seconds]
// (defaults 20 and 0.25). Prints three tables:
//   1. one cone per step and 20 sweeps per level, with 0 (the pass as the contact stage),
//      1, 2, 5, 10 and 20 contact sweeps: the mirror error and the time per step;
//   2. the pass as the contact stage with S = 8, 12, 20, 30 sweeps per level;
//   3. the velocities the pass leaves on a 5-box-base pyramid after 1 s (GBF's contact
//      stage, 20 sweeps per level), under each friction cone rule: the bottom row's largest
//      sliding and vertical speeds, and the fastest box above it.
// The analytic answer is a pyramid at rest: every number but the times should be zero.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "../tests/ch09/stack_scenes.hpp"

using namespace stackbook;

namespace {

struct Result {
  double mirror = 0.0;
  double msPerStep = 0.0;
  double sweepsPerStep = 0.0;
};

Result runPyramid(int base, double seconds, const StepSettings& settings) {
  World<2> world = stacks::pyramid2d(base, Material{0.0, 0.5, 0.0});
  const auto t0 = std::chrono::steady_clock::now();
  const StepCounters c = stacks::run<2>(world, settings, seconds, true);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double steps = static_cast<double>(c.steps);
  return {stacks::mirrorError(world, base), 1e3 * wall / steps, static_cast<double>(c.shock.sweeps) / steps};
}

void contactSweepsTable(int base, double seconds) {
  std::printf("| contact sweeps | mirror error (m) | ms per step |\n|---|---|---|\n");
  for (const int sweeps : {0, 1, 2, 5, 10, 20}) {
    StepSettings settings;
    if (sweeps == 0) {
      settings = passAsContactStage();
    } else {
      settings.contactIterations = sweeps;
      settings.shock.sweepsPerLevel = 20;
      settings.frictionCone = FrictionConeRule::StepTotal;
    }
    const Result r = runPyramid(base, seconds, settings);
    std::printf("| %d%s | %.2e | %.2f |\n", sweeps, sweeps == 0 ? " (the pass as the contact stage)" : "",
                r.mirror, r.msPerStep);
  }
  std::printf("\nTable: base-%d pyramid, mu 0.5, one cone per step, 20 sweeps per level, %.2f s.\n\n",
              base, seconds);
}

void sweepsPerLevelTable(int base, double seconds) {
  std::printf("| sweeps per level S | mirror error (m) | ms per step | level sweeps per step |\n|---|---|---|---|\n");
  for (const int s : {8, 12, 20, 30}) {
    const Result r = runPyramid(base, seconds, passAsContactStage(StepSettings{}, s));
    std::printf("| %d | %.2e | %.2f | %.0f |\n", s, r.mirror, r.msPerStep, r.sweepsPerStep);
  }
  std::printf("\nTable: base-%d pyramid, mu 0.5, the pass as the contact stage (Eq. (9.9)), %.2f s.\n\n",
              base, seconds);
}

void leftoverTable() {
  const int base = 5;
  std::printf("| cone | bottom row: largest sliding speed (m/s) | bottom row: largest vertical speed (m/s) | "
              "fastest box above: (v_x, v_y, omega) |\n|---|---|---|---|\n");
  for (const FrictionConeRule cone : {FrictionConeRule::EachImpulse, FrictionConeRule::StepTotal}) {
    StepSettings settings;
    settings.shock.sweepsPerLevel = 20;
    settings.frictionCone = cone;
    World<2> world = stacks::pyramid2d(base, Material{0.0, 0.5, 0.0});
    stacks::run<2>(world, settings, 1.0, true);
    double slide = 0.0, vertical = 0.0, fastest = -1.0;
    Vec3 above = Vec3::Zero();
    for (int k = 1; k < world.size(); ++k) {
      const RigidBody<2>& b = world.bodies[static_cast<std::size_t>(k)];
      if (k <= base) {  // bodies 1..base are the bottom row
        slide = std::max(slide, std::abs(b.velocity.x()));
        vertical = std::max(vertical, std::abs(b.velocity.y()));
      } else if (b.velocity.norm() > fastest) {
        fastest = b.velocity.norm();
        above = Vec3(b.velocity.x(), b.velocity.y(), b.angularVelocity[0]);
      }
    }
    std::printf("| %s | %.1e | %.1e | (%.1e, %.1e, %.1e) |\n",
                cone == FrictionConeRule::EachImpulse ? "each impulse (GBF)" : "one per step (Eq. (8.13))",
                slide, vertical, above.x(), above.y(), above.z());
  }
  std::printf("\nTable: velocities after the pass, base-5 pyramid, mu 0.5, GBF's contact stage, "
              "20 sweeps per level, after 1 s.\n");
}

}  // namespace

int main(int argc, char** argv) {
  const int base = argc > 1 ? std::atoi(argv[1]) : 20;
  const double seconds = argc > 2 ? std::atof(argv[2]) : 0.25;
  if (base < 1 || !(seconds > 0.0)) {
    std::fprintf(stderr, "usage: contact_residual_bench [base boxes >= 1] [seconds > 0]\n");
    return 2;
  }
  contactSweepsTable(base, seconds);
  sweepsPerLevelTable(base, seconds);
  leftoverTable();
  return 0;
}
