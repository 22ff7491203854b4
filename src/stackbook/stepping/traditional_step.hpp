#pragma once
/// \file
/// \brief The traditional order of a rigid-body step (chapter 8): move with the forces,
/// then resolve collisions, then contact, both at the new poses. Kept beside GBF's step
/// (gbf_step.hpp) with the same stages and knobs, so that the only difference between
/// the two is the order, and the chapter can show what the order changes.

#include <chrono>

#include "stackbook/stepping/gbf_step.hpp"

namespace stackbook {

// [traditional_step]
/// One step in the traditional order:
/// 1. velocity update v += dt g and position update x += dt v (Eqs. (5.7)-(5.12));
/// 2. collision stage at the new poses with the pair's e and mu;
/// 3. contact stage at the new poses with the ramp e_k (Eq. (8.5));
/// 4. hook (as in gbfStep());
/// 5. quarantine of bodies gone non-finite (as in gbfStep()).
/// A body resting on a slope falls into it by dt^2 g cos(theta) in step 1, and with
/// e > 0 the collision stage then reflects that approach: the body hops, the "vibration"
/// GBF's order removes. Throws std::invalid_argument for a bad world or settings.
template <int D>
StepCounters traditionalStep(World<D>& world, const StepSettings& settings,
                             const PostContactHook<D>& hook = {}) {
  detail::checkStepInput<D>(world, settings, "traditionalStep");
  const auto start = std::chrono::steady_clock::now();
  const double dt = settings.dt;
  StepCounters counters;
  counters.steps = 1;
  const detail::StepStart<D> stepStart(world);
  Effects effects = resolveEffects<D>(world, settings.effects);
  effects.shockPropagation = effects.shockPropagation && static_cast<bool>(hook);
  counters.effects = effects;
  // [traditional_order]
  auto t = std::chrono::steady_clock::now();
  if (effects.gravity) {
    for (int i = 0; i < world.size(); ++i) {
      advanceVelocity<D>(world.bodies[static_cast<std::size_t>(i)], dt, world.loads(i));  // Eq. (5.7)
    }
  }
  counters.velocityUpdateSeconds += detail::secondsSince(t);
  t = std::chrono::steady_clock::now();
  for (RigidBody<D>& body : world.bodies) advancePosition<D>(body, dt, settings.rotation);  // Eqs. (5.8)-(5.12)
  counters.positionUpdateSeconds += detail::secondsSince(t);

  if (effects.collision) {
    runImpulseStage<D>(world, collisionStageSpec(settings, effects, Lookahead::Current), dt,
                       settings, counters.collision);
  }
  if (effects.contact) {
    runImpulseStage<D>(world, contactStageSpec(settings, effects, Lookahead::Current), dt,
                       settings, counters.contact);
  }
  if (effects.shockPropagation) {  // [traditional_order]
    t = std::chrono::steady_clock::now();
    hook(world, settings, counters);
    counters.hookSeconds += detail::secondsSince(t);
  }
  detail::quarantine<D>(world, stepStart, counters);  // B21
  counters.totalSeconds = detail::secondsSince(start);
  return counters;
}
// [traditional_step]

// [step]
/// One step in the order settings.order chooses: gbfStep() or traditionalStep().
template <int D>
StepCounters step(World<D>& world, const StepSettings& settings,
                  const PostContactHook<D>& hook = {}) {
  return settings.order == StepOrder::Gbf ? gbfStep<D>(world, settings, hook)
                                          : traditionalStep<D>(world, settings, hook);
}
// [step]

// Compiled once, for D = 2 and 3, in the library (src/stackbook/instantiate_step.cpp): a
// translation unit that includes this header links to those instead of compiling its own.
extern template StepCounters traditionalStep<2>(World<2>&, const StepSettings&,
                                                const PostContactHook<2>&);
extern template StepCounters traditionalStep<3>(World<3>&, const StepSettings&,
                                                const PostContactHook<3>&);

}  // namespace stackbook
