// Chapter 10, "Threads": bundled scenes stepped with 1, 2 and 4 threads. Prints one Markdown
// row per scene: how many islands the split sweeps had, the share of all pair visits that
// one thread must make alone (the largest island of each split sweep, and every sweep too
// small or too connected to split), which bounds the speed-up by 1 / share, whether the
// state bits after the run agree for 1, 2 and 4 threads, and the
// measured ratio of step time, 1 thread over 2 (min of two alternating runs, on the
// machine that built the site).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "stackbook/scene/scene.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stacking/welded_pass.hpp"
#include "stackbook/stepping/traditional_step.hpp"

using namespace stackbook;

namespace {

template <int D>
std::uint64_t stateHash(const World<D>& world) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    for (int b = 0; b < 8; ++b) {
      h ^= (bits >> (8 * b)) & 0xffu;
      h *= 1099511628211ull;
    }
  };
  for (const RigidBody<D>& b : world.bodies) {
    for (int k = 0; k < D; ++k) mix(b.position[k]), mix(b.velocity[k]);
    for (int k = 0; k < b.angularMomentum.size(); ++k) mix(b.angularMomentum[k]);
    if constexpr (D == 2) {
      mix(b.orientation.angle());
    } else {
      for (int k = 0; k < 4; ++k) mix(b.orientation.coeffs()[k]);
    }
  }
  return h;
}

struct Outcome {
  std::uint64_t hash = 0;
  double seconds = 0.0;
  StageCounters all;  // collision + contact + shock
};

template <int D>
Outcome run(const Scene& scene, int threads, int steps) {
  World<D> world = std::get<SceneBodies<D>>(scene.bodies).world;
  StepSettings settings = scene.settings;
  settings.parallel.threads = threads;
  const PostContactHook<D> hook = shockPropagationHook<D>();
  Outcome out;
  for (int n = 0; n < steps; ++n) {
    const StepCounters c = sceneStep<D>(world, settings, hook);
    out.seconds += c.totalSeconds;
    out.all += c.collision;
    out.all += c.contact;
    out.all += c.shock;
  }
  out.hash = stateHash<D>(world);
  return out;
}

Outcome run(const Scene& scene, int threads, int steps) {
  return scene.dimension == 2 ? run<2>(scene, threads, steps) : run<3>(scene, threads, steps);
}

}  // namespace

int main() {
  struct Row {
    const char* scene;
    int steps;
  };
  // Few steps each, so the docs build stays quick: the island counts, shares and hashes
  // are exact for the steps run; the measured ratio of so short a run is only indicative.
  const Row rows[] = {{"many_pyramids_2d", 30}, {"shapes_in_bin_2d", 300}, {"pyramid_20_2d", 10},
                      {"pyramid_3d", 8}};
  std::printf("| scene | steps | islands per split sweep | share of pair visits on one thread | "
              "bound from the islands, 2 threads | same state bits, 1 / 2 / 4 threads | measured speed-up, 2 threads |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const Row& row : rows) {
    const Scene scene = loadScene(std::string("scenes/") + row.scene + ".json");
    std::vector<double> one, two;
    Outcome o1, o2;
    for (int r = 0; r < 2; ++r) {  // alternating, so a change in the machine's load hits both
      o1 = run(scene, 1, row.steps);
      o2 = run(scene, 2, row.steps);
      one.push_back(o1.seconds);
      two.push_back(o2.seconds);
    }
    const Outcome o4 = run(scene, 4, row.steps);
    const bool same = o1.hash == o2.hash && o2.hash == o4.hash;
    const StageCounters& c = o2.all;
    const double sweepsSplit = static_cast<double>(c.islandSweeps);
    const double share = c.islandPairs > 0 ? static_cast<double>(c.largestIslandPairs) /
                                                 static_cast<double>(c.islandPairs)
                                           : 1.0;
    // Sweeps that were not split ran on one thread: count their pairs as one island.
    const double splitPairs = static_cast<double>(c.islandPairs);
    const double allPairs = static_cast<double>(c.pairVisits);
    const double serialShare = allPairs > 0 ? (allPairs - splitPairs + share * splitPairs) / allPairs : 1.0;
    const double bound = std::min(2.0, 1.0 / serialShare);
    std::printf("| %s | %d | %.1f | %.2f | %.2f | %s | %.2f |\n", row.scene, row.steps,
                sweepsSplit > 0 ? static_cast<double>(c.islands) / sweepsSplit : 1.0,
                serialShare, bound, same ? "yes" : "**no**",
                *std::min_element(one.begin(), one.end()) / *std::min_element(two.begin(), two.end()));
  }
  return 0;
}
