// Chapter 9, "Short pair loops": the claims that chapter 9's tests make of the pass as the
// contact stage, measured under four pair-loop settings: PhysBAM's caps (10 in the pass, 20
// in the collision stage; passAsContactStage()), caps of 2 (passAsContactStage(base, 20,
// 2)), caps of 4 and of 5 (passAsContactStageShortLoops(base, 20, 4) and its defaults) with
// the visit ended after an impulse of at most 0.2 times its first, and those with sticking
// patches (passAsContactStagePatch(), chapter 8's Eq. (8.16)). Prints one Markdown row per claim with the test's
// bound; a value that misses its bound is in bold. Unit boxes of mass 1, dt = 1e-3.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "../../tests/ch09/stack_scenes.hpp"

using namespace stackbook;

namespace {

constexpr int kSettings = 5;

StepSettings settingsAt(int k) {
  switch (k) {
    case 0: return passAsContactStage();
    case 1: return passAsContactStage(StepSettings{}, 20, 2);
    case 2: return passAsContactStageShortLoops(StepSettings{}, 20, 4);
    case 3: return passAsContactStageShortLoops();
    default: return passAsContactStagePatch();
  }
}

/// One row: the claim, its bound (the value must be below it) and the value per setting.
void row(const char* claim, double bound, const double (&value)[kSettings], const char* format = "%.2e") {
  std::printf("| %s | < %.3g |", claim, bound);
  for (const double v : value) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    std::printf(v < bound ? " %s |" : " **%s** |", text);
  }
  std::printf("\n");
}

template <int D>
void stackRows(const char* name) {
  double speed[kSettings], drift[kSettings];
  const World<D> start = stacks::boxStack<D>(10, Material{0.0, 0.5, 0.0});
  for (int k = 0; k < kSettings; ++k) {
    World<D> world = start;
    stacks::run<D>(world, settingsAt(k), 0.2, true);
    const stacks::StackState<D> s = stacks::measureStack<D>(start, world, 1, 10);
    speed[k] = s.maxSpeed;
    drift[k] = s.drift;
  }
  const double gdt = stacks::kG * StepSettings{}.dt;
  row((std::string(name) + ", 0.2 s: largest speed (m/s), bound 1e-6 g dt").c_str(), 1e-6 * gdt, speed);
  row((std::string(name) + ", 0.2 s: largest horizontal drift (m)").c_str(), 1e-9, drift);
}

}  // namespace

int main() {
  std::printf("| claim (chapter 9's tests) | bound | PhysBAM's caps, `passAsContactStage()` | caps of 2 | "
              "caps of 4, tolerance 0.2 | caps of 5, tolerance 0.2, `passAsContactStageShortLoops()` | "
              "sticking patches, `passAsContactStagePatch()` |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  stackRows<2>("2D stack of 10");
  stackRows<3>("3D stack of 10");
  {
    // The early exit: 100 steps of a 3-box stack with 50 sweeps allowed per level use
    // fewer than half of the 100 * 3 * 50 sweeps.
    double sweeps[kSettings];
    for (int k = 0; k < kSettings; ++k) {
      World<2> world = stacks::boxStack<2>(3, Material{0.0, 0.5, 0.0});
      StepSettings s = settingsAt(k);
      s.shock.sweepsPerLevel = 50;
      StepCounters total;
      for (int n = 0; n < 100; ++n) total += stackingStep<2>(world, s);
      sweeps[k] = static_cast<double>(total.shock.sweeps);
    }
    row("3-box stack, 100 steps, 50 sweeps allowed per level: level sweeps used", 100 * 3 * 50 / 2, sweeps, "%.0f");
  }
  {
    const World<2> start = stacks::pyramid2d(20, Material{0.0, 0.5, 0.0});
    double mirror[kSettings], moved[kSettings];
    for (int k = 0; k < kSettings; ++k) {
      World<2> world = start;
      stacks::run<2>(world, settingsAt(k), 1.0, true);
      mirror[k] = stacks::mirrorError(world, 20);
      moved[k] = stacks::largestDisplacement<2>(start, world);
    }
    row("2D pyramid, base 20, 1 s: mirror error (m)", 1e-4, mirror);
    row("2D pyramid, base 20, 1 s: largest displacement (m)", 1e-3, moved);
  }
  {
    const World<3> start = stacks::pyramid3d(3, Material{0.0, 0.5, 0.0});
    double moved[kSettings];
    for (int k = 0; k < kSettings; ++k) {
      World<3> world = start;
      stacks::run<3>(world, settingsAt(k), 0.25, true);
      moved[k] = stacks::largestDisplacement<3>(start, world);
    }
    row("3D pyramid of 14 cubes, 0.25 s: largest displacement (m)", 0.5 * 2.5e-5, moved);
  }
  {
    // A17 at 25 degrees: mu_req = 0.2332. Above it (0.25) no card moves 1 mm in 2 s; below
    // it (0.22) both centres drop below half their height, so the higher of the two
    // centres' heights over their start must be below 0.5.
    const double beta = 25.0 * M_PI / 180.0;
    double stands[kSettings], falls[kSettings];
    for (int k = 0; k < kSettings; ++k) {
      World<2> up = stacks::cardFrame(beta, Material{0.0, 0.25, 0.0});
      World<2> down = stacks::cardFrame(beta, Material{0.0, 0.22, 0.0});
      const World<2> frame = up;
      stacks::run<2>(up, settingsAt(k), 2.0, true);
      stacks::run<2>(down, settingsAt(k), 2.0, true);
      stands[k] = 0.0;
      falls[k] = 0.0;
      for (const std::size_t card : {std::size_t{1}, std::size_t{2}}) {
        stands[k] = std::max(stands[k], (up.bodies[card].position - frame.bodies[card].position).norm());
        falls[k] = std::max(falls[k], down.bodies[card].position.y() / frame.bodies[card].position.y());
      }
    }
    row("A-frame at mu 0.25, 2 s: largest card displacement (m)", 1e-3, stands);
    row("A-frame at mu 0.22, 2 s: higher card centre over its start height", 0.5, falls, "%.2f");
  }
  std::printf("\nTable: the claims of chapter 9's tests of the pass as the contact stage under four pair-loop "
              "settings and with sticking patches (20 sweeps per level, one cone per step), dt = 1e-3; bold: the claim fails.\n");
  return 0;
}
