// Chapter 9, "The welded pass": bundled scenes at their own dt for their whole duration under
// GBF's step and under GBF's step with the welded pass (the preset "weldedPass", the default of a
// scene that names none), and two variants that each drop one part of the welded pass: its body
// welds (Eq. (9.12)) on the bundled 2D pyramid of 21 boxes and its energy guard (Eq. (9.14)) on the
// seesaw. Prints one Markdown row per scene and step: the largest distance a body moved, the
// largest rise of the total energy over its start, the plank's angle where there is a plank, the
// milliseconds per step (one thread), the impulses of GBF's contact stage per step, the body welds per step and the share of islands that kept
// GBF's pass. Fails if a row stops showing what the section says: the welded pass holds every
// stack and pyramid to 1e-9 m without gaining energy, ends the seesaw and the card house exactly
// where GBF's step does, without body welds is GBF's step, and without the guard gains energy.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"
#include "stackbook/stacking/solver_preset.hpp"

using namespace stackbook;

namespace {

struct Outcome {
  double moved = 0.0;                  // largest distance of a body from its start at the end, m
  double energyGain = 0.0;             // largest rise of kinetic plus potential energy, J
  double plankDegrees = std::nan("");  // the plank's angle at the end, where there is one
  double msPerStep = 0.0;
  double weldsPerStep = 0.0;
  double contactImpulsesPerStep = 0.0;  // GBF's contact stage
  double gbfIslandShare = 0.0;         // islands that kept GBF's pass, of those decided
};

template <int D>
Outcome run(const Scene& scene, const StepSettings& settings) {
  const SceneBodies<D>& bodies = std::get<SceneBodies<D>>(scene.bodies);
  World<D> world = bodies.world;
  const long steps = std::lround(scene.duration / settings.dt);
  const double e0 = worldEnergy<D>(world).total();
  Outcome out;
  StepCounters total;
  const auto t0 = std::chrono::steady_clock::now();
  for (long n = 0; n < steps; ++n) {
    total += stackingStep<D>(world, settings);
    out.energyGain = std::max(out.energyGain, worldEnergy<D>(world).total() - e0);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.msPerStep = 1e3 * seconds / static_cast<double>(steps);
  out.weldsPerStep = static_cast<double>(total.welded.welds) / static_cast<double>(steps);
  out.contactImpulsesPerStep = static_cast<double>(total.contact.impulses) / static_cast<double>(steps);
  if (total.welded.islands > 0) {
    out.gbfIslandShare = static_cast<double>(total.welded.gbfIslands) / static_cast<double>(total.welded.islands);
  }
  for (std::size_t b = 0; b < world.bodies.size(); ++b) {
    out.moved = std::max(out.moved, (world.bodies[b].position - bodies.world.bodies[b].position).norm());
    if constexpr (D == 2) {
      if (bodies.visuals[b].name == "plank") {
        const Vec2 axis = world.bodies[b].orientation * Vec2(1.0, 0.0);
        out.plankDegrees = std::atan2(axis.y(), axis.x()) * 180.0 / M_PI;
      }
    }
  }
  return out;
}

Outcome run(const Scene& scene, const StepSettings& settings) {
  return scene.dimension == 2 ? run<2>(scene, settings) : run<3>(scene, settings);
}

void print(const char* name, const char* label, const Outcome& o, bool welded) {
  char angle[32] = "-";
  if (!std::isnan(o.plankDegrees)) {
    std::snprintf(angle, sizeof angle, "%.2f", std::abs(o.plankDegrees) < 0.005 ? 0.0 : o.plankDegrees);
  }
  char welds[32] = "-", share[32] = "-";
  if (welded) {
    std::snprintf(welds, sizeof welds, "%.1f", o.weldsPerStep);
    std::snprintf(share, sizeof share, "%.0f %%", 100.0 * o.gbfIslandShare);
  }
  std::printf("| `%s.json` | %s | %.2e | %.2e | %s | %.3f | %.0f | %s | %s |\n", name, label, o.moved, o.energyGain,
              angle, o.msPerStep, o.contactImpulsesPerStep, welds, share);
}

}  // namespace

int main() {
  std::printf("| scene | step | largest move (m) | largest energy gain (J) | plank angle (deg) | ms per step | "
              "contact-stage impulses per step | body welds per step | islands that kept GBF's pass |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  bool ok = true;
  const auto fail = [&ok](const char* what) {
    std::fprintf(stderr, "ch09_welded_pass: %s\n", what);
    ok = false;
  };
  for (const char* name : {"seesaw_2d", "card_house_2d", "plank_on_two_stacks_2d", "box_stack_2d", "box_stack_3d",
                           "pyramid_2d", "pyramid_3d", "pyramid_20_2d"}) {
    Scene scene = loadScene(std::string("scenes/") + name + ".json");
    scene.settings.parallel.threads = 1;
    const StepSettings gbf = applySolverPreset(SolverPreset::Gbf, scene.settings);
    const StepSettings welded = applySolverPreset(SolverPreset::WeldedPass, scene.settings);
    const Outcome g = run(scene, gbf);
    const Outcome w = run(scene, welded);
    print(name, "GBF's step", g, false);
    print(name, "the welded pass (the default)", w, true);
    const std::string n = name;
    const bool loads = n == "seesaw_2d" || n == "card_house_2d";
    if (loads) {  // nothing welds: every island keeps GBF's pass, so the run is GBF's
      if (w.moved != g.moved || w.energyGain != g.energyGain || w.weldsPerStep != 0.0) {
        fail("a scene of loads no longer runs exactly as under GBF's step");
      }
    } else if (!(w.moved < 1e-9 && w.energyGain < 1e-9)) {
      fail("the welded pass no longer holds a stack or pyramid to 1e-9 m");
    }
    if (n == "seesaw_2d") {
      StepSettings unguarded = welded;
      unguarded.shock.welded.energyGuard = false;
      const Outcome u = run(scene, unguarded);
      print(name, "the welded pass without the guard", u, true);
      if (!(u.energyGain > 1.0)) fail("without the guard the seesaw no longer gains energy");
    }
    if (n == "pyramid_2d") {
      StepSettings unwelded = welded;
      unwelded.shock.welded.bodyWelds = false;
      const Outcome u = run(scene, unwelded);
      print(name, "the welded pass without body welds", u, true);
      if (u.moved != g.moved || u.energyGain != g.energyGain) fail("without body welds the pyramid is not GBF's");
    }
  }
  std::printf("\nTable: bundled scenes at their own dt for their whole duration under GBF's step and under the "
              "welded pass, one thread.\n");
  return ok ? 0 : 1;
}
