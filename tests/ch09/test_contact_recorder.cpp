// The step's optional contact recorder (chapter 10's contacts output): each applied
// impulse is recorded once with its stage, and the recorded impulses account for the
// bodies' momentum change; without a recorder, and with one, the trajectory is the same
// bit for bit.
#include <doctest/doctest.h>

#include <cmath>

#include "../ch08/scene_builders.hpp"
#include "stack_scenes.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::stacks;

namespace {

/// Sum of the recorded impulses acting on body b: +j where it owns the sample, -j where
/// it is the other body (applyPairImpulse()), skipping shock sweeps in which b is the
/// lower, frozen body (frozen bodies take no impulse, Eq. (9.4)).
template <int D>
Vec<D> impulseOn(const ContactRecorder& recorder, int b, bool skipShockBelow) {
  Vec<D> sum = Vec<D>::Zero();
  for (const ContactRecord& r : recorder.records()) {
    Vec<D> j;
    for (int k = 0; k < D; ++k) j[k] = r.impulse[static_cast<std::size_t>(k)];
    if (skipShockBelow && r.stage == ContactStage::Shock) {
      // In a two-box stack the pass's only pair with b as the lower body is (b, b + 1).
      if ((r.owner == b && r.other == b + 1) || (r.other == b && r.owner == b + 1)) continue;
    }
    if (r.owner == b) sum += j;
    if (r.other == b) sum -= j;
  }
  return sum;
}

/// A box dropped 2 cm onto the ground with a sideways velocity and a spin, so that the
/// collision stage (the landing), the contact stage (resting) and friction all act; with
/// a second box on top for the stack case.
template <int D>
World<D> droppedBoxes(int count) {
  const Material material{0.3, 0.5, 0.0};
  World<D> world = groundWorld<D>(material);
  for (int k = 0; k < count; ++k) {
    Vec<D> centre = (0.52 + 1.0 * k) * stacks::up<D>();
    const int b = addBox<D>(world, Vec<D>::Constant(1.0), 1.0, centre, material);
    RigidBody<D>& body = world.bodies[static_cast<std::size_t>(b)];
    body.velocity[0] = 0.4;
    body.velocity[D - 1] = -0.5;
  }
  return world;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("Recorded impulses account for a dropped box's momentum change", Dim, testing::In2D,
                   testing::In3D) {
  constexpr int D = Dim::value;
  World<D> world = droppedBoxes<D>(1);
  const RigidBody<D> start = world.bodies[1];
  ContactRecorder recorder;
  StepSettings settings;
  settings.contactRecorder = &recorder;
  StepCounters total;
  const int steps = 400;
  for (int n = 0; n < steps; ++n) total += stackingStep<D>(world, settings);
  const RigidBody<D>& end = world.bodies[1];

  // One record per applied impulse, the collision stage's and the contact stage's.
  CHECK(total.collision.impulses > 0);
  CHECK(total.contact.impulses > 0);
  CHECK(recorder.size() == static_cast<std::size_t>(total.collision.impulses + total.contact.impulses +
                                                    total.shock.impulses));
  for (const ContactRecord& r : recorder.records()) {
    CHECK(((r.owner == 0 && r.other == 1) || (r.owner == 1 && r.other == 0)));
    Vec<D> n;
    for (int k = 0; k < D; ++k) n[k] = r.normal[static_cast<std::size_t>(k)];
    CHECK(std::abs(n.norm() - 1.0) < 1e-12);
  }
  // m (v_end - v_start) = sum of impulses + m g T (Eq. (5.7) once per step).
  const double T = steps * settings.dt;
  const Vec<D> expected = end.mass() * (end.velocity - start.velocity) - end.mass() * T * world.gravity;
  const Vec<D> recorded = impulseOn<D>(recorder, 1, false);
  // Invariant tier: the two sides add the same doubles in a different order.
  CHECK((recorded - expected).norm() < 1e-12 * (1.0 + end.mass() * stacks::kG * T) * steps);
}

TEST_CASE_TEMPLATE("Recorded impulses of a two-box stack: all three stages, the top box's momentum", Dim,
                   testing::In2D, testing::In3D) {
  constexpr int D = Dim::value;
  World<D> world = droppedBoxes<D>(2);
  const RigidBody<D> start = world.bodies[2];
  const RigidBody<D> lowerStart = world.bodies[1];
  ContactRecorder recorder;
  StepSettings settings;
  settings.contactRecorder = &recorder;
  StepCounters total;
  const int steps = 300;
  for (int n = 0; n < steps; ++n) total += stackingStep<D>(world, settings);
  CHECK(total.shock.impulses > 0);
  int perStage[3] = {0, 0, 0};
  for (const ContactRecord& r : recorder.records()) ++perStage[static_cast<int>(r.stage)];
  CHECK(perStage[0] == total.collision.impulses);
  CHECK(perStage[1] == total.contact.impulses);
  CHECK(perStage[2] == total.shock.impulses);
  // The top box (body 2) is never frozen while its pairs are swept: every impulse counts.
  const RigidBody<D>& end = world.bodies[2];
  const double T = steps * settings.dt;
  const Vec<D> expected = end.mass() * (end.velocity - start.velocity) - end.mass() * T * world.gravity;
  CHECK((impulseOn<D>(recorder, 2, false) - expected).norm() < 1e-12 * (1.0 + stacks::kG * T) * steps);
  // The lower box (body 1) is frozen during the top pair's shock sweeps.
  const RigidBody<D>& lowerEnd = world.bodies[1];
  const Vec<D> lower =
      lowerEnd.mass() * (lowerEnd.velocity - lowerStart.velocity) - lowerEnd.mass() * T * world.gravity;
  CHECK((impulseOn<D>(recorder, 1, true) - lower).norm() < 1e-12 * (1.0 + stacks::kG * T) * steps);
}

TEST_CASE_TEMPLATE("A contact recorder changes no bit of the trajectory", Dim, testing::In2D, testing::In3D) {
  constexpr int D = Dim::value;
  for (const StepOrder order : {StepOrder::Gbf, StepOrder::Traditional}) {
    World<D> off = boxStack<D>(4, Material{0.2, 0.6, 0.0}, 0.1);
    World<D> on = off;
    StepSettings settings;
    settings.order = order;
    ContactRecorder recorder;
    StepSettings recording = settings;
    recording.contactRecorder = &recorder;
    const PostContactHook<D> hook = shockPropagationHook<D>();
    for (int n = 0; n < 200; ++n) {
      step<D>(off, settings, hook);
      step<D>(on, recording, hook);
    }
    CHECK(recorder.size() > 0);
    CHECK(testing::stateHash<D>(on) == testing::stateHash<D>(off));
  }
}

}  // TEST_SUITE
