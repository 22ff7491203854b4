// Chapter 12, "Landing on a support": what the landing rules cost and change. Bundled scenes run
// under the default twice, with the rules (lever arms at the start pose, Eq. (8.22); held samples,
// Eq. (12.6); tied landing, Eq. (12.7)) and with the paper's pair rule (tested-pose arms, both rules
// off), for 300 steps on one thread, the two alternated three times; the table gives the smaller
// milliseconds per step of each, the held samples and tied landings counted, and whether the end
// states differ. Printed as Markdown (\include{doc} ch12_landing_cost.out).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <variant>

#include "stackbook/scene/scene.hpp"
#include "stackbook/stacking/welded_pass.hpp"
#include "stackbook/stacking/shock_propagation.hpp"

using namespace stackbook;

namespace {

struct Run {
  double msPerStep = 0.0;
  StepCounters counters;
  double endHeight = 0.0;  // sum of the dynamic bodies' heights at the end, to tell states apart
};

template <int D>
Run run(World<D> world, const StepSettings& settings, int steps) {
  Run out;
  const PostContactHook<D> hook = shockPropagationHook<D>();
  const auto t0 = std::chrono::steady_clock::now();
  for (int n = 0; n < steps; ++n) out.counters += sceneStep<D>(world, settings, hook);
  out.msPerStep = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / steps;
  for (const RigidBody<D>& b : world.bodies) {
    if (!b.isStatic()) out.endHeight += b.position[D - 1];
  }
  return out;
}

StepSettings paperRules(StepSettings s) {
  s.impulsePoint.arms = LeverArms::AtTestedPose;
  s.impulsePoint.heldSamples = false;
  s.impulsePoint.tiedLanding = false;
  return s;
}

template <int D>
void row(const char* name, const Scene& scene) {
  const World<D>& world = std::get<SceneBodies<D>>(scene.bodies).world;
  StepSettings rules = scene.settings;
  rules.parallel.threads = 1;
  const StepSettings paper = paperRules(rules);
  constexpr int kSteps = 300;
  Run withRules, without;
  withRules.msPerStep = without.msPerStep = 1e300;
  for (int rep = 0; rep < 3; ++rep) {  // alternated, the smaller time of each kept
    Run a = run<D>(world, rules, kSteps);
    Run b = run<D>(world, paper, kSteps);
    a.msPerStep = std::min(a.msPerStep, withRules.msPerStep);
    b.msPerStep = std::min(b.msPerStep, without.msPerStep);
    withRules = a;
    without = b;
  }
  const StageCounters& c = withRules.counters.collision;
  const std::int64_t held = c.detection.heldSamples + withRules.counters.contact.detection.heldSamples +
                            withRules.counters.shock.detection.heldSamples;
  const std::int64_t tied = c.tiedLandings + withRules.counters.contact.tiedLandings + withRules.counters.shock.tiedLandings;
  std::printf("| `%s` | %zu | %.3f | %.3f | %.2f | %lld | %lld | %s |\n", name, world.bodies.size(), withRules.msPerStep,
              without.msPerStep, withRules.msPerStep / without.msPerStep, static_cast<long long>(held),
              static_cast<long long>(tied), withRules.endHeight == without.endHeight ? "no" : "yes");
}

}  // namespace

int main() {
  std::printf("| scene | bodies | ms/step, landing rules | ms/step, paper's pair rule | ratio | held samples | "
              "tied landings | end state differs |\n|---|---|---|---|---|---|---|---|\n");
  for (const char* name : {"box_stack_2d", "pyramid_20_2d", "card_house_2d", "seesaw_2d", "box_stack_3d", "pyramid_3d"}) {
    const Scene scene = loadScene(std::string("scenes/") + name + ".json");
    if (scene.dimension == 2) {
      row<2>(name, scene);
    } else {
      row<3>(name, scene);
    }
  }
  std::printf("\nTable: 300 steps of each bundled scene under the default, with the landing rules (the default) and "
              "with the paper's pair rule (`\"leverArms\": \"testedPose\"`, `\"heldSamples\": false`, "
              "`\"tiedLanding\": false`), one thread, the two alternated three times, the smaller time of each.\n");
  return 0;
}
