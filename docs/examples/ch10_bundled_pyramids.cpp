// Chapter 10, "The bundled pyramids": scenes/pyramid_20_2d.json and scenes/pyramid_3d.json
// run for their whole duration at their dt (1/60 s) under six steps: GBF's (its default
// settings, the pass after the contact stage), the pass as the contact stage
// (passAsContactStage()), the short pair loops the scenes name
// (passAsContactStageShortLoops(), "preset": "passAsContactShortLoops"), those with
// sticking patches (passAsContactStagePatch(), "preset": "passAsContactPatch"), GBF's step
// with sticking patches: GBF's short loops (gbfStepShortLoops()) with the patch rule, the
// patch preset's level tolerance and the pass's 20 sweeps per level, and the default of a scene
// that names no preset, the carrying pass (carryingPass(), chapter 12).
// scenes/pyramid_204_3d.json (8 levels), which names no preset, runs under GBF's step and the
// default only. Prints one Markdown row per scene and step: the largest horizontal
// drift and the largest speed of any box at the end, the milliseconds and impulses per step and
// how many of those impulses were sticking patches or body welds (one thread, on the machine
// that built the site). Fails unless the default holds all three pyramids (no box drifts 1 mm).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "stackbook/scene/scene.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stacking/solver_preset.hpp"

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
  out.patchesPerStep = static_cast<double>(total.collision.patchImpulses + total.contact.patchImpulses +
                                            total.shock.patchImpulses + total.welded.welds) /
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
  std::printf("| scene | step | max drift (m) | max speed (m/s) | ms per step | impulses per step | of which patches or welds |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  double seconds = 0.0;
  bool defaultHolds = true;
  for (const char* name : {"pyramid_20_2d", "pyramid_3d", "pyramid_204_3d"}) {
    const bool named = std::string(name) != "pyramid_204_3d";  // the two that name a preset
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
    const StepSettings byDefault = applySolverPreset(kDefaultScenePreset, gbf);
    // The scene names the preset: its settings must be the short loops' (the last names none).
    if (!named && scene.settings.shock.freeze != FreezeRule::WhenItCarries) {
      std::fprintf(stderr, "%s names a preset\n", name);
      return 1;
    }
    if (named && !(scene.settings.shock.replacesContactStage &&
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
                 {"GBF's step with sticking patches and 20 sweeps per level", &gbfPatch},
                 {"the default: the carrying pass, `carryingPass()` (chapter 12)", &byDefault}};
    for (const auto& s : steps) {
      if (!named && s.settings != &gbf && s.settings != &byDefault) continue;  // 204 cubes: two steps
      const Outcome o = run(scene, *s.settings);
      if (s.settings == &byDefault) defaultHolds = defaultHolds && o.drift < 1e-3;
      std::printf("| `%s.json` | %s | %.2e | %.2e | %.2f | %.0f | %.0f |\n", name, s.label, o.drift, o.speed,
                  o.msPerStep, o.impulsesPerStep, o.patchesPerStep);
    }
  }
  std::printf("\nTable: the bundled pyramids (210 boxes in 2D, 30 and 204 in 3D, mu = 0.6) at dt = 1/60 s for %.0f s "
              "under six steps (the 204 cubes under two); drift and speed after the run, one thread.\n",
              seconds);
  if (!defaultHolds) {
    std::fprintf(stderr, "the default lets a bundled pyramid drift 1 mm: the chapter's claim no longer holds\n");
    return 1;
  }
  return 0;
}
