// Run this now (chapter 8): the unit box on a 20-degree incline (mu = 0.5, e = 1), one
// second under GBF's order and under the traditional order. Friction holds the box; the
// program prints how far it slid and how high it rose above the slope, every 0.2 s.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "../../tests/ch08/scene_builders.hpp"

using namespace stackbook;

int main() {
  for (const StepOrder order : {StepOrder::Gbf, StepOrder::Traditional}) {
    std::printf("%s order:\n   t (s)   slid (m)    lift (m)\n", order == StepOrder::Gbf ? "GBF's" : "traditional");
    testing::InclineScene<2> scene = testing::makeIncline<2>(20.0 * std::numbers::pi / 180.0, 0.5, 1.0);
    StepSettings settings;
    settings.order = order;
    const long steps = std::lround(1.0 / settings.dt), every = std::lround(0.2 / settings.dt);
    for (long n = 1; n <= steps; ++n) {
      step<2>(scene.world, settings);
      if (n % every == 0) {
        std::printf("%8.1f %10.2e %11.2e\n", static_cast<double>(n) * settings.dt, scene.travelled(), scene.lift());
      }
    }
  }
}
