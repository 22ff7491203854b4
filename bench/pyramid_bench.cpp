// Chapters 8 and 9 benchmark: validation case B15, a 2D pyramid of unit boxes standing on
// the ground with shock propagation, under the step's friction and iteration settings.
// Build in release mode and run:
//   ./build/release/bench/pyramid_bench [base boxes] [seconds] [mu] [first row] [last row]
// Prints, per setting (rows 1..7, all by default): the mirror error max |x_i + x_mirror(i)|
// (B15 asks < 1e-3 after 10 s for a base of 20), the largest displacement of any box from
// its start, the time per step and the impulses per step. The analytic answer is a pyramid
// that does not move: both errors are zero. B15 itself (base 20, 10 s) with the pass as
// the contact stage: pyramid_bench 20 10 0.5 5 6.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "../tests/ch09/stack_scenes.hpp"

using namespace stackbook;

namespace {

struct Setting {
  const char* name;
  FrictionConeRule cone;
  ImpulsePointRule point;
  int sweepsPerLevel;
  int contactIterations;
  bool passReplacesContact = false;  // Eq. (9.9)
};

void run(const Setting& setting, int base, double seconds, double mu) {
  const World<2> start = stacks::pyramid2d(base, Material{0.0, mu, 0.0});
  World<2> world = start;
  StepSettings settings;
  if (setting.passReplacesContact) settings = passAsContactStage(settings, setting.sweepsPerLevel);
  settings.frictionCone = setting.cone;
  settings.impulsePoint.rule = setting.point;
  settings.shock.sweepsPerLevel = setting.sweepsPerLevel;
  settings.contactIterations = setting.contactIterations;
  const auto t0 = std::chrono::steady_clock::now();
  const StepCounters c = stacks::run<2>(world, settings, seconds, true);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double mirror = stacks::mirrorError(world, base);
  const double moved = stacks::largestDisplacement<2>(start, world);
  std::printf("| %s | %.2e | %.2e | %.2f | %.0f |\n", setting.name, mirror, moved,
              1e3 * wall / static_cast<double>(c.steps),
              static_cast<double>(c.contact.impulses + c.shock.impulses) / static_cast<double>(c.steps));
}

}  // namespace

int main(int argc, char** argv) {
  const int base = argc > 1 ? std::atoi(argv[1]) : 5;
  const double seconds = argc > 2 ? std::atof(argv[2]) : 1.0;
  const double mu = argc > 3 ? std::atof(argv[3]) : 0.5;
  const int first = argc > 4 ? std::atoi(argv[4]) : 1;
  const int last = argc > 5 ? std::atoi(argv[5]) : 7;
  if (base < 1 || !(seconds > 0.0) || !(mu >= 0.0) || first < 1 || last > 7 || first > last) {
    std::fprintf(stderr,
                 "usage: pyramid_bench [base boxes >= 1] [seconds > 0] [mu >= 0] [first row >= 1] "
                 "[last row <= 7]\n");
    return 2;
  }
  std::printf("2D pyramid, base %d (%d boxes), mu %.2f, %.2f s, dt 1e-3, shock propagation on\n\n",
              base, base * (base + 1) / 2, mu, seconds);
  std::printf("| setting | mirror error (m) | largest displacement (m) | ms/step | impulses/step |\n");
  std::printf("|---|---|---|---|---|\n");
  const Setting settings[] = {
      {"GBF: cone per impulse, deepest sample, 2 level sweeps, 10 contact sweeps",
       FrictionConeRule::EachImpulse, ImpulsePointRule::Deepest, 2, 10},
      {"centre of the samples (Eq. 8.10)", FrictionConeRule::EachImpulse,
       ImpulsePointRule::DepthWeightedCentre, 2, 10},
      {"one cone per step (Eq. 8.13)", FrictionConeRule::StepTotal, ImpulsePointRule::Deepest, 2, 10},
      {"one cone per step, 6 level sweeps, 30 contact sweeps", FrictionConeRule::StepTotal,
       ImpulsePointRule::Deepest, 6, 30},
      {"the pass as the contact stage (Eq. 9.9), 20 level sweeps, one cone per step",
       FrictionConeRule::StepTotal, ImpulsePointRule::Deepest, 20, 0, true},
      {"the pass as the contact stage, 20 level sweeps, cone per impulse", FrictionConeRule::EachImpulse,
       ImpulsePointRule::Deepest, 20, 0, true},
      {"the pass as the contact stage, 8 level sweeps, one cone per step", FrictionConeRule::StepTotal,
       ImpulsePointRule::Deepest, 8, 0, true},
  };
  for (int row = first; row <= last; ++row) run(settings[row - 1], base, seconds, mu);
  return 0;
}
