// Chapter 8, "Ending the loops": what the pair-iteration caps and the loop tolerances cost
// and what they do to accuracy, on a resting pile at a game time step.
//
//   loop_tolerance_bench SCENE SIZE [seconds] [dt] [first row] [last row]
//
//   SCENE  pyramid2d (SIZE = base boxes), pyramid3d (SIZE = layers), stack2d, stack3d (SIZE boxes)
//
// Prints one row per setting: the largest horizontal drift of any box from its start (the
// analytic answer is 0), the mirror error of a 2D pyramid (max |x_i + x_mirror(i)|), the sag
// of a stack's top box, the largest speed left, the time per step and the impulses per step.
// Rows 8-22 look for a setting of GBF's step (the contact stage, then the pass) that holds a
// pyramid as still at 60 Hz as the pass as the contact stage (rows 4-7) does. Rows 23-25 try
// the pass without its restitution ramp, and chapter 8's centre rule, with and without it.
// Rows 26-28 try chapter 8's sticking patch in the pass's short loops, without and with the
// level tolerance that passAsContactStagePatch() sets, and with pair caps of 2 and no ramp.
// Build in release mode:
//   cmake --preset release && cmake --build --preset release --target loop_tolerance_bench
//   ./build/release/bench/loop_tolerance_bench pyramid2d 20 10 0.0166666667
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../tests/ch09/stack_scenes.hpp"

using namespace stackbook;

namespace {

struct Row {
  const char* name;
  StepSettings settings;
};

StepSettings capped(StepSettings s, int cap) {
  s.collisionPairIterations = cap;
  s.contactPairIterations = cap;
  s.shock.pairIterations = cap;
  return s;
}

StepSettings tolerances(StepSettings s, double fraction, double speed) {
  s.pairImpulseTolerance = fraction;
  s.stageApproachTolerance = speed;
  s.shock.pairImpulseTolerance = fraction;
  s.shock.levelApproachTolerance = speed;
  return s;
}

template <int D>
struct Accuracy {
  double drift = 0.0;
  double maxSpeed = 0.0;
};

template <int D>
Accuracy<D> accuracy(const World<D>& start, const World<D>& now) {
  Accuracy<D> a;
  for (std::size_t k = 0; k < now.bodies.size(); ++k) {
    if (now.bodies[k].isStatic()) continue;
    Vec<D> horizontal = now.bodies[k].position - start.bodies[k].position;
    horizontal[D - 1] = 0.0;
    a.drift = std::max(a.drift, horizontal.norm());
    a.maxSpeed = std::max(a.maxSpeed, now.bodies[k].velocity.norm());
  }
  return a;
}

template <int D>
void runRows(const World<D>& start, const Row* rows, int first, int last, double seconds, double dt,
             int pyramidBase, bool stack) {
  for (int r = first; r <= last; ++r) {
    World<D> world = start;
    StepSettings settings = rows[r - 1].settings;
    settings.dt = dt;
    const auto t0 = std::chrono::steady_clock::now();
    const StepCounters c = stacks::run<D>(world, settings, seconds, true);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Accuracy<D> a = accuracy<D>(start, world);
    double mirror = 0.0, sag = 0.0;
    if constexpr (D == 2) {
      if (pyramidBase > 0) mirror = stacks::mirrorError(world, pyramidBase);
    }
    if (stack) sag = stacks::measureStack<D>(start, world, 1, world.size() - 1).sag;
    const double steps = static_cast<double>(c.steps);
    std::printf("| %d | %s | %.2e | %.2e | %.2e | %.2e | %.3f | %.0f |\n", r, rows[r - 1].name, a.drift, mirror,
                sag, a.maxSpeed, 1e3 * wall / steps,
                static_cast<double>(c.collision.impulses + c.contact.impulses + c.shock.impulses) / steps);
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string scene = argc > 1 ? argv[1] : "pyramid2d";
  const int size = argc > 2 ? std::atoi(argv[2]) : 20;
  const double seconds = argc > 3 ? std::atof(argv[3]) : 10.0;
  const double dt = argc > 4 ? std::atof(argv[4]) : 1.0 / 60.0;
  const int first = argc > 5 ? std::atoi(argv[5]) : 1;
  const StepSettings gbf;
  const StepSettings pass = passAsContactStage();
  StepSettings gbfStepCone = gbf;
  gbfStepCone.frictionCone = FrictionConeRule::StepTotal;
  StepSettings gbfShock20 = gbf;
  gbfShock20.shock.sweepsPerLevel = 20;
  StepSettings gbfBoth = gbfShock20;
  gbfBoth.frictionCone = FrictionConeRule::StepTotal;
  StepSettings gbfContact20 = gbfBoth;
  gbfContact20.contactIterations = 20;
  StepSettings gbfPasses2 = gbfBoth;
  gbfPasses2.shock.passes = 2;
  StepSettings gbfBoth40 = gbfBoth;
  gbfBoth40.shock.sweepsPerLevel = 40;
  StepSettings gbfBothContact5 = capped(gbfBoth, 2);
  gbfBothContact5.contactIterations = 5;
  const auto withContact = [](StepSettings s, int sweeps) {
    s.contactIterations = sweeps;
    return s;
  };
  // Rows 23-25: chapter 8's impulse point at the centre of the samples that share a normal,
  // and the pass without its restitution ramp (every level sweep with e = 0), which ends a
  // level once a sweep acts on nothing faster than 1e-9 m/s.
  const auto centre = [](StepSettings s) {
    s.impulsePoint.rule = ImpulsePointRule::DepthWeightedCentre;
    return s;
  };
  const auto patch = [](StepSettings s) {
    s.impulsePoint.rule = ImpulsePointRule::StickingPatch;
    return s;
  };
  const auto noRamp = [](StepSettings s) {
    s.shock.restitution.assign(static_cast<std::size_t>(s.shock.sweepsPerLevel), 0.0);
    s.shock.levelApproachTolerance = 1e-9;
    return s;
  };
  const Row rows[] = {
      {"GBF: contact stage, then the pass", gbf},
      {"GBF, pair loops capped at 2", capped(gbf, 2)},
      {"GBF, tolerances 0.05 of the first impulse, 1e-4 m/s", tolerances(gbf, 0.05, 1e-4)},
      {"the pass as the contact stage, 20 sweeps per level, one cone per step", pass},
      {"the pass as the contact stage, pair loops capped at 2", capped(pass, 2)},
      {"the pass as the contact stage, tolerances 0.05, 1e-4 m/s", tolerances(pass, 0.05, 1e-4)},
      {"the pass as the contact stage, capped at 2, tolerances 0.05, 1e-4 m/s", tolerances(capped(pass, 2), 0.05, 1e-4)},
      {"GBF, one cone per step", gbfStepCone},
      {"GBF, 20 sweeps per level", gbfShock20},
      {"GBF, one cone per step, 20 sweeps per level", gbfBoth},
      {"GBF, one cone per step, 20 sweeps per level, 20 contact sweeps", gbfContact20},
      {"GBF, one cone per step, 20 sweeps per level, 2 passes", gbfPasses2},
      {"GBF, one cone per step, 20 sweeps per level, capped at 2", capped(gbfBoth, 2)},
      {"GBF, one cone per step, 20 sweeps per level, capped at 1", capped(gbfBoth, 1)},
      {"GBF, one cone per step, 40 sweeps per level, capped at 2", capped(gbfBoth40, 2)},
      {"GBF, one cone per step, 20 sweeps per level, capped at 2, 5 contact sweeps", gbfBothContact5},
      {"GBF, one cone per step, 20 sweeps per level, capped at 2, tolerances 0.05, 1e-4 m/s", tolerances(capped(gbfBoth, 2), 0.05, 1e-4)},
      {"GBF, 20 sweeps per level, capped at 2", capped(gbfShock20, 2)},
      {"GBF, one cone per step, 20 sweeps per level, capped at 2, 3 contact sweeps", withContact(capped(gbfBoth, 2), 3)},
      {"GBF, one cone per step, 20 sweeps per level, capped at 2, 2 contact sweeps", withContact(capped(gbfBoth, 2), 2)},
      {"GBF, one cone per step, 40 sweeps per level, capped at 2, 5 contact sweeps", withContact(capped(gbfBoth40, 2), 5)},
      {"GBF, one cone per step, 20 sweeps per level, capped at 2, 1 contact sweep", withContact(capped(gbfBoth, 2), 1)},
      {"the pass as the contact stage, capped at 2, no ramp (e = 0), level tolerance 1e-9 m/s",
       noRamp(capped(pass, 2))},
      {"the pass as the contact stage, centre rule, capped at 1", centre(capped(pass, 1))},
      {"the pass as the contact stage, centre rule, capped at 1, no ramp (e = 0), level tolerance 1e-9 m/s",
       noRamp(centre(capped(pass, 1)))},
      {"the pass as the contact stage, short loops, sticking patch, no level tolerance",
       patch(passAsContactStageShortLoops())},
      {"the pass as the contact stage, short loops, sticking patch, level tolerance 1e-9 m/s "
       "(passAsContactStagePatch())",
       passAsContactStagePatch()},
      {"the pass as the contact stage, capped at 2, sticking patch, no ramp (e = 0), level tolerance 1e-9 m/s",
       noRamp(patch(capped(pass, 2)))},
  };
  const int count = static_cast<int>(sizeof rows / sizeof rows[0]);
  const int last = argc > 6 ? std::atoi(argv[6]) : count;
  if (size < 1 || !(seconds > 0.0) || !(dt > 0.0) || first < 1 || last > count || first > last) {
    std::fprintf(stderr, "usage: loop_tolerance_bench pyramid2d|pyramid3d|stack2d|stack3d SIZE [seconds] [dt] "
                         "[first row] [last row <= %d]\n", count);
    return 2;
  }
  const Material material{0.0, 0.6, 0.0};
  std::printf("%s %d, mu 0.6, %.2f s at dt %.5f s, shock propagation on\n\n", scene.c_str(), size, seconds, dt);
  std::printf("| row | setting | max drift (m) | mirror error (m) | top sag (m) | max speed (m/s) | ms/step | "
              "impulses/step |\n|---|---|---|---|---|---|---|---|\n");
  if (scene == "pyramid2d") {
    runRows<2>(stacks::pyramid2d(size, material), rows, first, last, seconds, dt, size, false);
  } else if (scene == "pyramid3d") {
    runRows<3>(stacks::pyramid3d(size, material), rows, first, last, seconds, dt, 0, false);
  } else if (scene == "stack2d") {
    runRows<2>(stacks::boxStack<2>(size, material), rows, first, last, seconds, dt, 0, true);
  } else if (scene == "stack3d") {
    runRows<3>(stacks::boxStack<3>(size, material), rows, first, last, seconds, dt, 0, true);
  } else {
    std::fprintf(stderr, "loop_tolerance_bench: unknown scene %s\n", scene.c_str());
    return 2;
  }
  return 0;
}
