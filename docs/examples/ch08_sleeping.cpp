// Chapter 8, "Sleeping": a column of three unit boxes with a fourth released 1.5 m above
// it, run for 1 s with shock propagation, once awake and once with sleeping on (rest
// thresholds 0.05 m/s and 0.05 rad/s, 0.3 s at rest). Prints when the column fell asleep
// and woke, the body-steps skipped, how far the two runs end apart, the energy at the end
// of each, and the step time of each (\include{doc} ch08_sleeping.out).
#include <algorithm>
#include <cstdio>

#include "../../tests/ch08/scene_builders.hpp"  // boxes, slab and gravity of the tests
#include "stackbook/stacking/shock_propagation.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

template <int D>
double totalEnergy(const World<D>& world) {
  double e = 0.0;
  for (const RigidBody<D>& b : world.bodies) {
    if (!b.isStatic()) e += b.kineticEnergy() - b.mass() * world.gravity.dot(b.position);
  }
  return e;
}

template <int D>
World<D> stackWithDrop() {
  World<D> world;
  world.gravity = -kG * up<D>();
  const Material wood{0.0, 0.6, 0.0};
  addSlab<D>(world, 0.0, wood);
  for (int k = 0; k <= 3; ++k) {
    RigidBody<D> box = unitBox<D>();
    box.position = (0.5 + k + (k == 3 ? 1.5 : 0.0)) * up<D>();
    world.addBody(box, unitBoxShape<D>(), wood);
  }
  return world;
}

constexpr int kSteps = 1000;  // 1 s of 1 ms steps: the drop lands at 0.55 s and the column sleeps again

template <int D>
void row() {
  World<D> awake = stackWithDrop<D>();
  World<D> sleepy = awake;
  StepSettings off;
  StepSettings on;
  on.sleep.enabled = true;
  on.sleep.time = 0.3;
  double asleepAt = -1.0, wokeAt = -1.0, awakeSeconds = 0.0, sleepySeconds = 0.0;
  StepCounters total;
  for (int n = 1; n <= kSteps; ++n) {
    awakeSeconds += stackingStep<D>(awake, off).totalSeconds;
    const StepCounters c = stackingStep<D>(sleepy, on);
    sleepySeconds += c.totalSeconds;
    total += c;
    if (asleepAt < 0.0 && c.sleep.sleepingAtEnd == 3) asleepAt = n * on.dt;
    if (wokeAt < 0.0 && c.sleep.wokenUp > 0) wokeAt = n * on.dt;
  }
  double apart = 0.0;
  for (std::size_t i = 1; i < awake.bodies.size(); ++i) {
    apart = std::max(apart, (awake.bodies[i].position - sleepy.bodies[i].position).norm());
  }
  std::printf("| %dD | %.3f | %.3f | %lld of %d | %.1e | %.4f | %.4f | %.2f |\n", D, asleepAt, wokeAt,
              static_cast<long long>(total.sleep.sleepingBodySteps), 4 * kSteps, apart, totalEnergy<D>(awake),
              totalEnergy<D>(sleepy), awakeSeconds / sleepySeconds);
}

}  // namespace

int main() {
  std::printf("| D | column asleep at (s) | woken at (s) | body-steps asleep | end positions apart (m) | "
              "end energy awake (J) | end energy with sleeping (J) | step time, awake / sleeping |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  row<2>();
  row<3>();
  return 0;
}
