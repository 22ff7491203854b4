// Chapter 10, "Colours": bundled scenes swept in list order and colour by colour. Prints one
// Markdown row per scene and order: the largest horizontal displacement of any dynamic body
// from its start, the kinetic energy at the end, impulses per step, and the step time with 1
// and 2 threads (the faster of two alternating runs each, on the machine that built the
// site) with their ratio. Colour by colour is another Gauss-Seidel order, so the first three
// columns differ from the list order's; they are the same for any thread count (a test).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stepping/traditional_step.hpp"

using namespace stackbook;

namespace {

struct ColoursOutcome {
  double drift = 0.0;    // largest horizontal displacement of a dynamic body, m
  double kinetic = 0.0;  // kinetic energy at the end, J
  double impulses = 0.0; // per step
  double seconds = 0.0;  // step time, summed
};

template <int D>
ColoursOutcome run(const Scene& scene, PairOrder order, int threads, int steps) {
  World<D> world = std::get<SceneBodies<D>>(scene.bodies).world;
  const World<D> start = world;
  StepSettings settings = scene.settings;
  settings.pairOrder = order;
  settings.parallel.threads = threads;
  const PostContactHook<D> hook = shockPropagationHook<D>();
  ColoursOutcome out;
  std::int64_t impulses = 0;
  for (int n = 0; n < steps; ++n) {
    const StepCounters c = step<D>(world, settings, hook);
    out.seconds += c.totalSeconds;
    impulses += c.collision.impulses + c.contact.impulses + c.shock.impulses;
  }
  out.impulses = static_cast<double>(impulses) / steps;
  // "Up" is against gravity; horizontal is what is left of a displacement.
  const Vec<D> up = world.gravity.norm() > 0.0 ? Vec<D>(-world.gravity.normalized()) : Vec<D>::UnitY();
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody<D>& b = world.bodies[i];
    if (b.isStatic()) continue;
    const Vec<D> d = b.position - start.bodies[i].position;
    out.drift = std::max(out.drift, (d - d.dot(up) * up).norm());
  }
  out.kinetic = worldEnergy<D>(world).kinetic;
  return out;
}

ColoursOutcome run(const Scene& scene, PairOrder order, int threads, int steps) {
  return scene.dimension == 2 ? run<2>(scene, order, threads, steps) : run<3>(scene, order, threads, steps);
}

}  // namespace

int main() {
  struct Row {
    const char* scene;
    const char* label;
    std::vector<std::string> overrides;
    int steps;
  };
  // The bin of shapes, a small pile that lands within its 1.5 s; the pyramid of base 20 at
  // 60 Hz as bundled (the pass as the contact stage, whose levels hold a few dozen pairs),
  // for 10 s, long enough for its drift to mean something; and the same pyramid under GBF's
  // step, whose contact stage sweeps all of its pairs, one island of several hundred, for 2 s.
  const Row rows[] = {{"shapes_in_bin_2d", "shapes_in_bin_2d", {}, 1500},
                      {"pyramid_20_2d", "pyramid_20_2d", {}, 600},
                      {"pyramid_20_2d", "pyramid_20_2d, GBF's step", {"solver.preset=\"gbf\""}, 120}};
  std::printf("| scene | steps | pair order | max horizontal drift (m) | kinetic energy at the end (J) | "
              "impulses per step | ms/step, 1 thread | ms/step, 2 threads | speed-up, 2 threads |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& row : rows) {
    const Scene scene = loadScene(std::string("scenes/") + row.scene + ".json", row.overrides);
    for (const PairOrder order : {PairOrder::List, PairOrder::Colours}) {
      std::vector<double> one, two;
      ColoursOutcome o1;
      for (int r = 0; r < 2; ++r) {  // alternating, so a change in the machine's load hits both
        o1 = run(scene, order, 1, row.steps);
        one.push_back(o1.seconds);
        two.push_back(run(scene, order, 2, row.steps).seconds);
      }
      const double ms1 = 1e3 * *std::min_element(one.begin(), one.end()) / row.steps;
      const double ms2 = 1e3 * *std::min_element(two.begin(), two.end()) / row.steps;
      std::printf("| %s | %d | %s | %.3g | %.3g | %.0f | %.3g | %.3g | %.2f |\n", row.label, row.steps,
                  order == PairOrder::List ? "list" : "colours", o1.drift, o1.kinetic, o1.impulses, ms1, ms2,
                  ms1 / ms2);
    }
  }
  return 0;
}
