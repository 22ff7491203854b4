// Chapter 10, "The bundled pyramids": scenes/pyramid_20_2d.json and scenes/pyramid_3d.json
// run for their whole duration at their dt (1/60 s) under five steps: GBF's (its default
// settings, the pass after the contact stage), the pass as the contact stage
// (passAsContactStage()), the short pair loops the scenes name
// (passAsContactStageShortLoops(), "preset": "passAsContactShortLoops"), those with
// sticking patches (passAsContactStagePatch(), "preset": "passAsContactPatch"), and GBF's step
// with sticking patches: GBF's short loops (gbfStepShortLoops()) with the patch rule, the
// patch preset's level tolerance and the pass's 20 sweeps per level, the nearest step to GBF's
// that the patches can give. Prints one Markdown row per scene and step: the largest horizontal
// drift and the largest speed of any box at the end, the milliseconds and impulses per step and
// how many of those impulses were sticking patches (one thread, on the machine that built the site).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "stackbook/scene/scene.hpp"
#include "stackbook/stacking/shock_propagation.hpp"

using namespace stackbook;

namespace {

struct Outcome {
  double drift = 0.0;     // largest horizontal distance of a box from its start, m
  double speed = 0.0;     // largest speed of a box at the end, m/s
  double msPerStep = 0.0;
  double impulsesPerStep = 0.0;
  double patchesPerStep = 0.0;  // of those, sticking patches
  long steps = 0;
};

template <int D>
Outcome run(const Scene& scene, const StepSettings& settings) {
  const World<D>& start = std::get<SceneBodies<D>>(scene.bodies).world;
  World<D> world = start;
  const long steps = std::lround(scene.duration / settings.dt);
  StepCounters total;
  const auto t0 = std::chrono::steady_clock::now();
  for (long n = 0; n < steps; ++n) total += stackingStep<D>(world, settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Outcome out;
  out.steps = steps;
  out.msPerStep = 1e3 * seconds / static_cast<double>(steps);
  out.impulsesPerStep =
      static_cast<double>(total.collision.impulses + total.contact.impulses + total.shock.impulses) /
      static_cast<double>(steps);
  out.patchesPerStep =
      static_cast<double>(total.collision.patchImpulses + total.contact.patchImpulses + total.shock.patchImpulses) /
      static_cast<double>(steps);
  for (std::size_t b = 0; b < world.bodies.size(); ++b) {
    if (world.bodies[b].isStatic()) continue;
    Vec<D> horizontal = world.bodies[b].position - start.bodies[b].position;
    horizontal[D - 1] = 0.0;  // gravity is along the last axis in both scenes
    out.drift = std::max(out.drift, horizontal.norm());
    out.speed = std::max(out.speed, world.bodies[b].velocity.norm());
  }
  return out;
}

Outcome run(const Scene& scene, const StepSettings& settings) {
  return scene.dimension == 2 ? run<2>(scene, settings) : run<3>(scene, settings);
}

}  // namespace

int main() {
  std::printf("| scene | step | max drift (m) | max speed (m/s) | ms per step | impulses per step | of which patches |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  double seconds = 0.0;
  for (const char* name : {"pyramid_20_2d", "pyramid_3d"}) {
    const Scene scene = loadScene(std::string("scenes/") + name + ".json");
    StepSettings gbf;  // GBF's defaults at the scene's dt
    gbf.dt = scene.settings.dt;
    gbf.parallel.threads = 1;
    const StepSettings pass = passAsContactStage(gbf);
    const StepSettings shortLoops = passAsContactStageShortLoops(gbf);
    const StepSettings patch = passAsContactStagePatch(gbf);
    StepSettings gbfPatch = gbfStepShortLoops(gbf);  // GBF's step: the contact stage runs, the pass follows
    gbfPatch.impulsePoint.rule = ImpulsePointRule::StickingPatch;
    gbfPatch.shock.levelApproachTolerance = patch.shock.levelApproachTolerance;
    gbfPatch.shock.sweepsPerLevel = patch.shock.sweepsPerLevel;
    // The scene names the preset: its settings must be the short loops'.
    if (!(scene.settings.shock.replacesContactStage &&
          scene.settings.shock.pairIterations == shortLoops.shock.pairIterations &&
          scene.settings.shock.pairImpulseTolerance == shortLoops.shock.pairImpulseTolerance &&
          scene.settings.collisionPairIterations == shortLoops.collisionPairIterations &&
          scene.settings.pairImpulseTolerance == shortLoops.pairImpulseTolerance)) {
      std::fprintf(stderr, "%s does not use passAsContactStageShortLoops()\n", name);
      return 1;
    }
    seconds = scene.duration;
    const struct {
      const char* label;
      const StepSettings* settings;
    } steps[] = {{"GBF's step (defaults)", &gbf},
                 {"pass as the contact stage, `passAsContactStage()`", &pass},
                 {"short pair loops, `passAsContactStageShortLoops()` (the scene's preset)", &shortLoops},
                 {"sticking patches, `passAsContactStagePatch()`", &patch},
                 {"GBF's step with sticking patches and 20 sweeps per level", &gbfPatch}};
    for (const auto& s : steps) {
      const Outcome o = run(scene, *s.settings);
      std::printf("| `%s.json` | %s | %.2e | %.2e | %.2f | %.0f | %.0f |\n", name, s.label, o.drift, o.speed,
                  o.msPerStep, o.impulsesPerStep, o.patchesPerStep);
    }
  }
  std::printf("\nTable: the bundled pyramids (210 boxes in 2D, 30 in 3D, mu = 0.6) at dt = 1/60 s for %.0f s "
              "under five steps; drift and speed after the run, one thread.\n",
              seconds);
  return 0;
}
