// Chapter 9: the pass as the contact stage with sticking patches (passAsContactStagePatch(),
// the preset "passAsContactPatch"; chapter 8's Eq. (8.16)). Stacks and pyramids at a game
// time step stand still to round-off with about one impulse per box and step, and a stack
// that should fall still falls: the patch never glues a box whose weight is not over its
// support.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "../ch08/scene_builders.hpp"
#include "../support/dimensions.hpp"
#include "stack_scenes.hpp"
#include "stackbook/stacking/solver_preset.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;

namespace {

struct PatchRun {
  double moved = 0.0;          ///< the largest distance any box moved (m)
  double energyGain = 0.0;     ///< the largest rise of kinetic plus potential energy over the start (J)
  std::int64_t impulses = 0;   ///< over all steps and stages
  std::int64_t patches = 0;    ///< of those, whole patches
  int steps = 0;
  bool finite = true;
};

/// `seconds` of `world` at 60 Hz under passAsContactStagePatch().
template <int D>
PatchRun runPatch(World<D> world, double seconds) {
  StepSettings settings = passAsContactStagePatch();
  settings.dt = 1.0 / 60.0;
  const World<D> start = world;
  const auto energy = [](const World<D>& w) {
    double e = 0.0;
    for (const RigidBody<D>& b : w.bodies) {
      if (b.isStatic()) continue;
      e += b.kineticEnergy() - b.mass() * w.gravity.dot(b.position);
    }
    return e;
  };
  const double e0 = energy(world);
  PatchRun run;
  run.steps = static_cast<int>(std::lround(seconds / settings.dt));
  for (int n = 0; n < run.steps; ++n) {
    const StepCounters c = stackingStep<D>(world, settings);
    run.impulses += c.collision.impulses + c.contact.impulses + c.shock.impulses;
    run.patches += c.collision.patchImpulses + c.contact.patchImpulses + c.shock.patchImpulses;
    run.energyGain = std::max(run.energyGain, energy(world) - e0);
  }
  for (const RigidBody<D>& b : world.bodies) run.finite = run.finite && b.position.allFinite() && b.velocity.allFinite();
  run.moved = stacks::largestDisplacement<D>(start, world);
  return run;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [patch_preset_test]
TEST_CASE_TEMPLATE("with sticking patches a stack of 10 boxes stands still at 60 Hz with one impulse per box and step",
                   Dim, In2D, In3D) {
  // Each box rests on one box: its patch's impulse stops it whole, through its centre of mass.
  constexpr int D = Dim::value;
  const Material material{0.0, 0.6, 0.0};
  const PatchRun run = runPatch<D>(stacks::boxStack<D>(10, material), 2.0);
  CHECK(run.finite);
  CHECK(run.moved < 1e-9);
  CHECK(run.energyGain < 1e-9);
  CHECK(run.patches > 0);
  CHECK(run.impulses <= 10 * run.steps);
}

TEST_CASE("with sticking patches pyramids stand still at 60 Hz, with one impulse per box and step") {
  // A box on two boxes stops whole on the first of them whose half face can carry it (its
  // centre of pressure is at that half face's edge, Eq. (8.19)); the level's other pair then
  // has nothing left to stop.
  const Material material{0.0, 0.6, 0.0};
  const PatchRun flat = runPatch<2>(stacks::pyramid2d(8, material), 2.0);  // 36 boxes
  CHECK(flat.finite);
  CHECK(flat.moved < 1e-9);
  CHECK(flat.energyGain < 1e-9);
  CHECK(flat.impulses <= 36 * flat.steps);
  const PatchRun solid = runPatch<3>(stacks::pyramid3d(4, material), 2.0);  // 30 cubes
  CHECK(solid.finite);
  CHECK(solid.moved < 1e-9);
  CHECK(solid.energyGain < 1e-9);
  CHECK(solid.impulses <= 30 * solid.steps);
}

TEST_CASE_TEMPLATE("with sticking patches a box whose centre overhangs its support still falls", Dim, In2D, In3D) {
  // Two boxes, the upper shifted by 0.6 of its side: its centre is beyond the lower box's
  // edge, so no pressure on the shared face can hold it (Eq. (8.19)), and it tips off.
  constexpr int D = Dim::value;
  const Material material{0.0, 0.6, 0.0};
  World<D> world = stacks::boxStack<D>(2, material, 0.6);
  const double startHeight = world.bodies[2].position[D - 1];
  const PatchRun run = runPatch<D>(world, 1.5);
  CHECK(run.finite);
  CHECK(run.energyGain < 1e-9);
  StepSettings settings = passAsContactStagePatch();
  settings.dt = 1.0 / 60.0;
  for (int n = 0; n < 90; ++n) stackingStep<D>(world, settings);
  CHECK(world.bodies[2].position[D - 1] < startHeight - 0.2);  // it fell
}
// [patch_preset_test]

}  // TEST_SUITE
