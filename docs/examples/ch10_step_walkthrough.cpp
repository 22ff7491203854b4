// Chapter 10: one step of the bundled demo (scenes/pyramid_2d.json) walked end to end.
// Loads the scene exactly as `stackbook run` does, lets the pyramid settle for a while,
// then takes one more step and prints what each stage of that step did, as the Markdown
// that chapters/10_simulator.md includes.
#include <cstdio>
#include <string>
#include <variant>

#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stepping/traditional_step.hpp"

namespace {

using stackbook::StageCounters;

void stageRow(const char* name, const StageCounters& s) {
  std::printf("| %s | %lld | %lld | %lld | %lld | %lld | %lld | %lld | %lld | %.3f |\n", name,
              static_cast<long long>(s.sweeps), static_cast<long long>(s.pairVisits),
              static_cast<long long>(s.impulses), static_cast<long long>(s.sticking),
              static_cast<long long>(s.sliding), static_cast<long long>(s.detection.pairQueries),
              static_cast<long long>(s.detection.phiQueries),
              static_cast<long long>(s.detection.interferenceSamples), s.seconds * 1e3);
}

}  // namespace

int main() {
  using namespace stackbook;
  const Scene scene = loadScene("scenes/pyramid_2d.json");
  World<2> world = std::get<SceneBodies<2>>(scene.bodies).world;
  const StepSettings& settings = scene.settings;
  const Effects effects = resolveEffects<2>(world, settings.effects);
  int dynamic = 0;
  for (const RigidBody<2>& b : world.bodies) dynamic += b.isStatic() ? 0 : 1;

  std::printf("The scene: %d bodies (%d dynamic), dt = %g s, %d collision iterations, %d contact "
              "iterations, %d shock-propagation pass with %d sweeps per level; the effects it runs: %s. ",
              scene.bodyCount(), dynamic, settings.dt, settings.collisionIterations,
              settings.contactIterations, settings.shock.passes, settings.shock.sweepsPerLevel,
              effects.summary().c_str());

  const PostContactHook<2> hook = shockPropagationHook<2>();
  const double settle = 1.0;
  const int settleSteps = static_cast<int>(settle / settings.dt + 0.5);
  for (int n = 0; n < settleSteps; ++n) step<2>(world, settings, hook);
  const EnergyReport before = worldEnergy<2>(world);
  const double depthBefore = maxPenetration<2>(world);
  const StepCounters c = step<2>(world, settings, hook);
  const double depthAfter = maxPenetration<2>(world);

  std::printf("After %d steps (t = %g s) the pyramid has settled: kinetic energy %.3g J, deepest "
              "interpenetration %.3g m. Step %d then does this:\n\n",
              settleSteps, settle, before.kinetic, depthBefore, settleSteps + 1);
  std::printf("| stage | sweeps | pair visits | impulses | sticking | sliding | pair queries | "
              "phi queries | samples inside | wall ms |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  stageRow("(1) collision", c.collision);
  std::printf("| (2) velocity update | | | | | | | | | %.3f |\n", c.velocityUpdateSeconds * 1e3);
  stageRow("(3) contact", c.contact);
  stageRow("(4) shock propagation", c.shock);
  std::printf("| (5) position update | | | | | | | | | %.3f |\n", c.positionUpdateSeconds * 1e3);
  std::printf("\nThe whole step took %.3f ms of wall time; afterwards the deepest interpenetration is "
              "%.3g m.\n",
              c.totalSeconds * 1e3, depthAfter);
  return 0;
}
