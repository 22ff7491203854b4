#pragma once
/// \file
/// \brief GBF's time step (chapter 8): (1) collisions at the predicted poses with the
/// bodies' restitution, (2) velocity update, (3) contact with a restitution ramp ending
/// at 0, [hook: shock propagation, chapter 9], (4) position update.

#include <algorithm>
#include <chrono>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "stackbook/stepping/effects.hpp"
#include "stackbook/stepping/impulse_stage.hpp"
#include "stackbook/stepping/sleeping.hpp"

namespace stackbook {

// [post_contact_hook]
/// Called once per step between the contact stage and the position update, with the
/// velocities the contact stage left. Chapter 9 passes shock propagation here (contact
/// graph and levels from src/stackbook/stacking/, then one pass freezing each level).
/// Empty by default: chapter 8's step has no shock propagation.
template <int D>
using PostContactHook = std::function<void(World<D>&, const StepSettings&, StepCounters&)>;
// [post_contact_hook]

/// Called once per step after the velocity update and before the contact stage, with the
/// velocities the contact stage will start from (chapter 9's welded pass keeps them).
/// Empty by default.
template <int D>
using PreContactHook = std::function<void(const World<D>&)>;

namespace detail {

/// The checks every step function makes on entry.
template <int D>
void checkStepInput(const World<D>& world, const StepSettings& settings, const char* caller) {
  validateStepSettings(settings, caller);
  validateWorld<D>(world, caller);
}

/// The state of every body at the start of a step, for quarantine().
template <int D>
struct StepStart {
  std::vector<Vec<D>> positions;
  std::vector<Orientation<D>> orientations;

  explicit StepStart(const World<D>& world) {
    positions.reserve(world.bodies.size());
    orientations.reserve(world.bodies.size());
    for (const RigidBody<D>& b : world.bodies) {
      positions.push_back(b.position);
      orientations.push_back(b.orientation);
    }
  }
};

/// The first non-finite field of a body, or nullptr when all are finite.
template <int D>
const char* nonFiniteField(const RigidBody<D>& b) {
  if (!b.velocity.allFinite()) return "velocity";
  if (!b.angularMomentum.allFinite() || !b.angularVelocity.allFinite()) return "angular momentum";
  if (!b.position.allFinite()) return "position";
  if (!orientationFinite<D>(b.orientation)) return "orientation";
  return nullptr;
}

// [quarantine_step]
/// B21: after the position update, every body whose state is not finite is put back at
/// its pose from the start of the step (finite, since validateWorld() checked it), its
/// velocity and angular momentum are zeroed, and it is made static; the step records it
/// in counters.quarantined. The other bodies are untouched, and the next step, which
/// validates the world again, proceeds. O(n) per step.
template <int D>
void quarantine(World<D>& world, const StepStart<D>& start, StepCounters& counters) {
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    RigidBody<D>& b = world.bodies[i];
    const char* field = nonFiniteField<D>(b);
    if (field == nullptr) continue;
    b.position = start.positions[i];
    b.orientation = start.orientations[i];
    b.velocity.setZero();
    b.angularMomentum.setZero();
    b.inverseMass = 0.0;
    b.inverseInertia.setZero();
    b.syncAngularVelocity();
    counters.quarantined.push_back(
        Quarantine{static_cast<int>(i), std::string(field) +
                                            " became non-finite during the step; restored to "
                                            "the pose at its start, stopped and made static"});
  }
}
// [quarantine_step]

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace detail

// [stage_specs]
/// The collision stage's spec: predicted poses (Eq. (8.1)), the pair's own e when the
/// restitution effect runs and e = 0 (plastic) when it does not.
inline StageSpec collisionStageSpec(const StepSettings& s, const Effects& effects,
                                    Lookahead lookahead) {
  StageSpec spec{lookahead, s.collisionIterations, s.collisionPairIterations,
                 [](int, const PairMaterial& m) { return m.restitution; }};
  if (!effects.restitution) spec.restitution = [](int, const PairMaterial&) { return 0.0; };
  spec.friction = effects.friction;
  spec.rollingFriction = effects.rollingFriction;
  spec.recorder = s.contactRecorder;
  spec.stage = ContactStage::Collision;
  spec.pairImpulseTolerance = s.pairImpulseTolerance;
  spec.stageApproachTolerance = s.stageApproachTolerance;
  return spec;
}

/// The contact stage's spec: the ramp e_k of Eq. (8.5) for sweep k, whatever the bodies' e.
inline StageSpec contactStageSpec(const StepSettings& s, const Effects& effects,
                                  Lookahead lookahead) {
  StageSpec spec{lookahead, s.contactIterations, s.contactPairIterations,
                 [&s](int k, const PairMaterial&) { return s.contactRestitutionAt(k); }};
  spec.friction = effects.friction;
  spec.rollingFriction = effects.rollingFriction;
  spec.recorder = s.contactRecorder;
  spec.stage = ContactStage::Contact;
  spec.pairImpulseTolerance = s.pairImpulseTolerance;
  spec.stageApproachTolerance = s.stageApproachTolerance;
  return spec;
}
// [stage_specs]

// [gbf_step]
/// One step of GBF's time integration (chapter 8) in the order of the paper:
/// 1. collision stage: detect at x' = x + dt (v + dt g) (Eq. (8.1)), impulses with the
///    pair's restitution e and friction mu on the current velocities;
/// 2. velocity update v += dt g (Eq. (5.7));
/// 3. contact stage: detect at x' = x + dt v (Eq. (8.2)), sweep k with e_k (Eq. (8.5));
/// 4. hook (shock propagation in chapter 9; nothing by default); `beforeContact`, if given,
///    sees the world between steps 2 and 3;
/// 5. position update x += dt v, R <- exp(dt [omega]x) R (Eqs. (5.8)-(5.12));
/// 6. quarantine: a body whose state became non-finite is restored and made static (B21).
/// Each stage runs only if its effect does (resolveEffects() of the scene and
/// settings.effects); counters.effects records what ran.
/// Throws std::invalid_argument for a bad world or settings. Returns this step's counters.
template <int D>
StepCounters gbfStep(World<D>& world, const StepSettings& settings,
                     const PostContactHook<D>& hook = {}, const PreContactHook<D>& beforeContact = {}) {
  detail::checkStepInput<D>(world, settings, "gbfStep");
  const auto start = std::chrono::steady_clock::now();
  const double dt = settings.dt;
  StepCounters counters;
  counters.steps = 1;
  // [step_sleep_start]
  // Sleeping (StepSettings::sleep): wake the islands an awake body comes near, then make
  // the sleepers static for this step, so the effects below see only the awake bodies.
  const bool sleeping = settings.sleep.enabled;
  if (sleeping) wakeTouched<D>(world, settings, counters.sleep);
  SleepGuard<D> sleepers(world, counters.sleep, sleeping);
  // [step_sleep_start]
  const detail::StepStart<D> stepStart(world);
  Effects effects = resolveEffects<D>(world, settings.effects);
  effects.sleeping = sleeping;
  // [pass_replaces_contact]
  // The pass as the contact stage (chapter 9, Eq. (9.9)): whenever contact runs, the
  // shock-propagation hook runs instead of the contact stage, also for one dynamic body,
  // unless the scene forces the shock-propagation effect off.
  const bool passReplacesContact = settings.shock.replacesContactStage && effects.contact &&
                                   static_cast<bool>(hook) &&
                                   settings.effects.shockPropagation.value_or(true);
  if (passReplacesContact) effects.shockPropagation = true;
  // [pass_replaces_contact]
  effects.shockPropagation = effects.shockPropagation && static_cast<bool>(hook);
  // [gbf_step_order]
  // (1) Collisions: where the bodies would be after a free step, with their own e.
  if (effects.collision) {
    const Lookahead lookahead = effects.gravity ? Lookahead::VelocityAndLoads : Lookahead::Velocity;
    runImpulseStage<D>(world, collisionStageSpec(settings, effects, lookahead), dt, settings,
                       counters.collision);
  }

  // (2) Velocity update with the forces.
  auto t = std::chrono::steady_clock::now();
  // Each body's update reads and writes that body only: blocks of bodies run on several
  // threads (settings.parallel) with the serial loop's result.
  const std::size_t bodyGrain = static_cast<std::size_t>(settings.parallel.bodiesPerTask);
  if (effects.gravity) {
    parallelFor(settings.parallel.threads, world.bodies.size(), bodyGrain,
                [&world, dt](std::size_t begin, std::size_t end) {
                  for (std::size_t k = begin; k < end; ++k) {
                    advanceVelocity<D>(world.bodies[k], dt, world.loads(static_cast<int>(k)));  // Eq. (5.7)
                  }
                });
  }
  counters.velocityUpdateSeconds += detail::secondsSince(t);

  if (beforeContact) beforeContact(world);

  // (3) Contact: where the new velocities would carry the bodies, restitution ramp.
  if (effects.contact && !passReplacesContact) {
    StageSpec contact = contactStageSpec(settings, effects, Lookahead::Velocity);
    if (settings.frictionCone == FrictionConeRule::StepTotal) contact.ledger = &counters.contactLedger;
    runImpulseStage<D>(world, contact, dt, settings, counters.contact);
  }

  // (4) Hook for shock propagation (chapter 9), if that effect runs.
  counters.effects = effects;
  if (effects.shockPropagation) {
    t = std::chrono::steady_clock::now();
    hook(world, settings, counters);
    counters.hookSeconds += detail::secondsSince(t);
  }

  // (5) Position update with the velocities contact left.
  t = std::chrono::steady_clock::now();
  parallelFor(settings.parallel.threads, world.bodies.size(), bodyGrain,
              [&world, dt, &settings](std::size_t begin, std::size_t end) {
                for (std::size_t k = begin; k < end; ++k) {
                  advancePosition<D>(world.bodies[k], dt, settings.rotation);  // Eqs. (5.8)-(5.12)
                }
              });
  counters.positionUpdateSeconds += detail::secondsSince(t);
  detail::quarantine<D>(world, stepStart, counters);  // B21: isolate a body gone non-finite
  // [step_sleep_end]
  sleepers.release();
  if (sleeping) {
    fallAsleep<D>(world, settings, counters.sleep);
    counters.sleep.sleepingAtEnd = std::count(world.asleep.begin(), world.asleep.end(), char{1});
  }
  // [step_sleep_end]
  counters.totalSeconds = detail::secondsSince(start);  // [gbf_step_order]
  return counters;
}
// [gbf_step]

// Compiled once, for D = 2 and 3, in the library (src/stackbook/instantiate_step.cpp): a
// translation unit that includes this header links to those instead of compiling its own.
extern template StepCounters gbfStep<2>(World<2>&, const StepSettings&, const PostContactHook<2>&,
                                        const PreContactHook<2>&);
extern template StepCounters gbfStep<3>(World<3>&, const StepSettings&, const PostContactHook<3>&,
                                        const PreContactHook<3>&);

}  // namespace stackbook
