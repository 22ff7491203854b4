// Chapter 9 benchmark: box stacks with and without shock propagation, and the cost of
// each stage of the step. Build in release mode and run:
//   ./build/release/bench/stack_bench [dimension 2|3] [boxes] [seconds] [mu] [e]
// Prints, for shock propagation off and on: horizontal drift, sag of the top box, the
// largest speed, the largest gap between neighbours, and the time and work per stage.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../tests/ch09/stack_scenes.hpp"

using namespace stackbook;

namespace {

void printStage(const char* name, const StageCounters& c, long steps) {
  std::printf("  %-9s %8.3f ms/step  %9.1f pair visits/step  %8.1f impulses/step  %9.1f narrow queries/step\n",
              name, 1e3 * c.seconds / static_cast<double>(steps),
              static_cast<double>(c.pairVisits) / static_cast<double>(steps),
              static_cast<double>(c.impulses) / static_cast<double>(steps),
              static_cast<double>(c.detection.pairQueries) / static_cast<double>(steps));
}

template <int D>
void runStack(int boxes, double seconds, double mu, double e) {
  const Material material{e, mu, 0.0};
  StepSettings settings;
  for (const bool shock : {false, true}) {
    const World<D> start = stacks::boxStack<D>(boxes, material);
    World<D> world = start;
    const auto t0 = std::chrono::steady_clock::now();
    const StepCounters c = stacks::run<D>(world, settings, seconds, shock);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const stacks::StackState<D> s = stacks::measureStack<D>(start, world, 1, boxes);
    const long steps = c.steps;
    std::printf("%dD stack of %d, mu %.2f, e %.2f, %.2f s, shock %s: drift %.3e m, sag %.3e m "
                "(ideal %.1e), max speed %.3e m/s, largest gap %.3e m, %.2f s wall\n",
                D, boxes, mu, e, seconds, shock ? "on " : "off", s.drift, s.sag, boxes * 1e-4,
                s.maxSpeed, s.largestGap, wall);
    printStage("collision", c.collision, steps);
    printStage("contact", c.contact, steps);
    printStage("shock", c.shock, steps);
    std::printf("  total     %8.3f ms/step\n", 1e3 * c.totalSeconds / static_cast<double>(steps));
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int dimension = argc > 1 ? std::atoi(argv[1]) : 2;
  const int boxes = argc > 2 ? std::atoi(argv[2]) : 10;
  const double seconds = argc > 3 ? std::atof(argv[3]) : 1.0;
  const double mu = argc > 4 ? std::atof(argv[4]) : 0.5;
  const double e = argc > 5 ? std::atof(argv[5]) : 0.0;
  if (dimension == 3) {
    runStack<3>(boxes, seconds, mu, e);
  } else {
    runStack<2>(boxes, seconds, mu, e);
  }
  return 0;
}
