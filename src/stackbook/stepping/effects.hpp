#pragma once
/// \file
/// \brief The effects a time step can simulate (chapter 8): which stages and branches a
/// scene needs, inferred from its bodies and materials, with per-scene overrides, and a
/// printable account of what a step actually ran.

#include <algorithm>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>

#include "stackbook/stepping/world.hpp"

namespace stackbook {

// [effects]
/// One switch per effect. Each gates a stage or a branch of the step, and each is off
/// only when running it could change nothing in the scene (inferEffects()), so that
/// skipping it changes the time and not the trajectory; chapter 8's tests run every
/// scene both ways and compare the state bit for bit.
struct Effects {
  /// Gravity (and any other load): the velocity update's v += dt g and the loads in the
  /// collision stage's prediction (Eq. (8.1)). Needed when g != 0 and a body is dynamic.
  bool gravity = true;
  /// The collision stage (stage 1): detection at the predicted poses and impulses with
  /// the pair's restitution. Needed when a dynamic body can touch another body.
  bool collision = true;
  /// Restitution: the collision stage reads each pair's e and the impulse runs its
  /// restitution branch (the energy-safe e_max of Eq. (3.9)). Off, the collision stage is
  /// plastic (e = 0). Needed when some material has e > 0.
  bool restitution = true;
  /// The contact stage (stage 3) with the restitution ramp of Eq. (8.5). Needed when a
  /// dynamic body can touch another body.
  bool contact = true;
  /// Static and kinetic friction (chapter 3). Off, every impulse is the frictionless one
  /// of chapter 2. Needed when some pair has mu > 0.
  bool friction = true;
  /// Rolling and spinning friction after a sticking impulse (Eq. (8.7)). Needed when
  /// some pair has a rolling coefficient > 0 and mu > 0 (it acts only on sticking).
  bool rollingFriction = false;
  /// Shock propagation (chapter 9): the bottom-up pass over the contact graph's levels.
  /// Needed when two dynamic bodies can touch each other (a body can rest on another
  /// dynamic body); runs only in a step that is given the pass.
  bool shockPropagation = false;
  /// Sleeping (StepSettings::sleep): islands at rest stop being simulated until an awake
  /// body comes near. Never inferred: it changes results where bodies rest, so it runs
  /// only when the settings ask for it (and the step has a dynamic body).
  bool sleeping = false;

  bool operator==(const Effects&) const = default;

  /// The effects that are on, e.g. "gravity collision contact friction", or "none".
  std::string summary() const {
    std::ostringstream out;
    const auto put = [&out](bool on, const char* name) {
      if (!on) return;
      if (out.tellp() > 0) out << ' ';
      out << name;
    };
    put(gravity, "gravity");
    put(collision, "collision");
    put(restitution, "restitution");
    put(contact, "contact");
    put(friction, "friction");
    put(rollingFriction, "rolling-friction");
    put(shockPropagation, "shock-propagation");
    put(sleeping, "sleeping");
    return out.tellp() > 0 ? out.str() : std::string("none");
  }
};
// [effects]

// [effect_overrides]
/// A scene's overrides: an unset field keeps the inferred value, a set one forces it.
/// Forcing an effect on is always safe (it can only cost time); forcing one off
/// changes the physics on purpose, e.g. GBF's seesaw and plank demonstrations, which
/// run the same scene with and without contact processing.
struct EffectOverrides {
  std::optional<bool> gravity;
  std::optional<bool> collision;
  std::optional<bool> restitution;
  std::optional<bool> contact;
  std::optional<bool> friction;
  std::optional<bool> rollingFriction;
  std::optional<bool> shockPropagation;

  /// Every effect forced on (the reference run of the bit-identity tests).
  static EffectOverrides allOn() {
    return EffectOverrides{true, true, true, true, true, true, true};
  }
};
// [effect_overrides]

// [infer_effects]
/// The largest pair coefficient min(c_a, c_b) over the pairs that can touch (at least one
/// body dynamic), in O(n): with d1 >= d2 the two largest values among dynamic bodies and s1
/// the largest among static ones, it is min(d1, max(d2, s1)), because the body with d1
/// pairs best with the largest other value, and any pair without it has both values at
/// most max(d2, s1). Zero when no pair can touch.
template <int D, typename Coefficient>
double largestPairCoefficient(const World<D>& world, Coefficient coefficient) {
  double d1 = 0.0, d2 = 0.0, s1 = 0.0;
  int dynamic = 0;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const double c = coefficient(world.materials[i]);
    if (world.bodies[i].isStatic()) {
      s1 = std::max(s1, c);
      continue;
    }
    ++dynamic;
    if (c > d1) {
      d2 = d1;
      d1 = c;
    } else if (c > d2) {
      d2 = c;
    }
  }
  if (dynamic == 0 || world.size() < 2) return 0.0;
  return std::min(d1, std::max(d2, s1));
}

/// The effects the scene needs, from its bodies and materials alone; O(n). The pair rule
/// (Eq. (8.4)) combines coefficients by min, so friction is needed only if some pair that
/// can touch has min(mu_a, mu_b) > 0, and likewise for e. Rolling friction is inferred
/// from the pair rolling coefficient and needs friction (it acts after sticking impulses).
template <int D>
Effects inferEffects(const World<D>& world) {
  int dynamic = 0;
  for (const RigidBody<D>& body : world.bodies) dynamic += body.isStatic() ? 0 : 1;
  const bool touching = world.size() >= 2 && dynamic >= 1;
  Effects e;
  e.gravity = dynamic >= 1 && !world.gravity.isZero(0.0);
  e.collision = touching;
  e.contact = touching;
  e.restitution =
      largestPairCoefficient<D>(world, [](const Material& m) { return m.restitution; }) > 0.0;
  e.friction = largestPairCoefficient<D>(world, [](const Material& m) { return m.friction; }) > 0.0;
  e.rollingFriction =
      e.friction &&
      largestPairCoefficient<D>(world, [](const Material& m) { return m.rollingFriction; }) > 0.0;
  e.shockPropagation = dynamic >= 2;
  return e;
}
// [infer_effects]

// [resolve_effects]
/// The effects a step runs: the inferred ones with the scene's overrides applied.
template <int D>
Effects resolveEffects(const World<D>& world, const EffectOverrides& overrides) {
  Effects e = inferEffects<D>(world);
  const auto apply = [](bool& value, const std::optional<bool>& forced) {
    if (forced) value = *forced;
  };
  apply(e.gravity, overrides.gravity);
  apply(e.collision, overrides.collision);
  apply(e.restitution, overrides.restitution);
  apply(e.contact, overrides.contact);
  apply(e.friction, overrides.friction);
  apply(e.rollingFriction, overrides.rollingFriction);
  apply(e.shockPropagation, overrides.shockPropagation);
  return e;
}
// [resolve_effects]

}  // namespace stackbook
