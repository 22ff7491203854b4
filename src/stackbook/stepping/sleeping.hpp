#pragma once
/// \file
/// \brief Sleeping (chapter 8, "Sleeping"): bodies whose island has been at rest for a
/// while stop being simulated until an awake body comes near them. A sleeping body is
/// made infinitely heavy for the step (1/m = 0, I^{-1} = 0, its velocity zero), so every
/// stage, the effects and shock propagation treat it as static, and nothing in it moves.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "stackbook/collision/broad_phase.hpp"
#include "stackbook/stepping/impulse_stage.hpp"
#include "stackbook/stepping/step_counters.hpp"
#include "stackbook/stepping/step_settings.hpp"
#include "stackbook/stepping/world.hpp"

namespace stackbook {

// [body_islands]
/// The island of every body: connected components of the dynamic bodies (sleeping ones
/// included) over the pairs whose boxes overlap at `views` (static bodies join nothing),
/// numbered by their lowest body; -1 for a static body. O(n log n + pairs).
template <int D>
std::vector<int> bodyIslands(const World<D>& world, const std::vector<CollisionBody<D>>& views,
                             const BroadPhaseSettings& broad) {
  const std::size_t n = world.bodies.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&parent](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      int& p = parent[static_cast<std::size_t>(i)];
      p = parent[static_cast<std::size_t>(p)];  // path halving
      i = p;
    }
    return i;
  };
  const auto dynamic = [&world](int i) { return !world.bodies[static_cast<std::size_t>(i)].isStatic(); };
  for (const BodyPair& p : sweepAndPrune<D>(views, broad)) {
    if (!dynamic(p.first) || !dynamic(p.second)) continue;
    const int a = find(p.first), b = find(p.second);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
  std::vector<int> island(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    if (dynamic(static_cast<int>(i))) island[i] = find(static_cast<int>(i));
  }
  return island;
}
// [body_islands]

namespace detail {

template <int D>
void sizeSleepState(World<D>& world) {
  world.restTime.resize(world.bodies.size(), 0.0);
  world.asleep.resize(world.bodies.size(), 0);
}

}  // namespace detail

// [wake_touched]
/// At the start of a step: every sleeping island that contains an awake dynamic body
/// wakes (its bodies' rest time starts again from 0). Islands are found at the collision
/// stage's predicted poses with boxes grown by settings.sleep.wakeMargin, so a body about
/// to be touched this step is awake before the collision stage looks. Nothing happens,
/// and nothing is computed, while no body sleeps.
template <int D>
void wakeTouched(World<D>& world, const StepSettings& settings, SleepCounters& counters) {
  detail::sizeSleepState<D>(world);
  if (std::none_of(world.asleep.begin(), world.asleep.end(), [](char a) { return a != 0; })) return;
  const std::vector<CollisionBody<D>> views =
      stageViews<D>(world, Lookahead::VelocityAndLoads, settings.dt, settings.rotation, settings.parallel);  // Eq. (8.1)
  BroadPhaseSettings broad = settings.detection.broad;
  broad.margin = std::max(broad.margin, settings.sleep.wakeMargin);
  const std::vector<int> island = bodyIslands<D>(world, views, broad);
  std::vector<char> awake(world.bodies.size(), 0);
  for (std::size_t i = 0; i < island.size(); ++i) {
    if (island[i] >= 0 && world.asleep[i] == 0) awake[static_cast<std::size_t>(island[i])] = 1;
  }
  for (std::size_t i = 0; i < island.size(); ++i) {
    if (island[i] >= 0 && world.asleep[i] != 0 && awake[static_cast<std::size_t>(island[i])] != 0) {
      world.asleep[i] = 0;
      world.restTime[i] = 0.0;
      ++counters.wokenUp;
    }
  }
}
// [wake_touched]

// [sleep_guard]
/// Makes the sleeping bodies infinitely heavy for one step (1/m = 0, I^{-1} = 0: static to
/// every stage) and restores their exact values when released or destroyed.
template <int D>
class SleepGuard {
 public:
  SleepGuard(World<D>& world, SleepCounters& counters, bool active = true) : world_(world) {
    for (std::size_t i = 0; active && i < world.asleep.size() && i < world.bodies.size(); ++i) {
      RigidBody<D>& b = world.bodies[i];
      if (world.asleep[i] == 0 || b.isStatic()) continue;
      saved_.push_back(Saved{i, b.inverseMass, b.inverseInertia});
      b.inverseMass = 0.0;
      b.inverseInertia.setZero();
    }
    counters.sleepingBodySteps += static_cast<std::int64_t>(saved_.size());
  }
  SleepGuard(const SleepGuard&) = delete;
  SleepGuard& operator=(const SleepGuard&) = delete;
  ~SleepGuard() { release(); }

  void release() noexcept {
    for (const Saved& s : saved_) {
      world_.bodies[s.body].inverseMass = s.inverseMass;
      world_.bodies[s.body].inverseInertia = s.inverseInertia;
    }
    saved_.clear();
  }

 private:
  struct Saved {
    std::size_t body;
    double inverseMass;
    AngVec<D> inverseInertia;
  };
  World<D>& world_;
  std::vector<Saved> saved_;
};
// [sleep_guard]

// [fall_asleep]
/// At the end of a step: every awake dynamic body at rest (|v| < linearSpeed and
/// |omega| < angularSpeed) adds dt to its rest time, any other starts again from 0. An
/// island (at the current poses, boxes grown by wakeMargin) whose bodies all sleep or have
/// rested for settings.sleep.time falls asleep: velocity and angular momentum are set to
/// zero, which takes energy out and never puts any in. The islands are computed only
/// when some awake body has rested long enough, so a scene in motion pays one loop.
template <int D>
void fallAsleep(World<D>& world, const StepSettings& settings, SleepCounters& counters) {
  detail::sizeSleepState<D>(world);
  const SleepSettings& sleep = settings.sleep;
  const double ready = sleep.time - 1e-9 * settings.dt;  // rest time is a sum of dt's
  bool anyReady = false;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody<D>& b = world.bodies[i];
    if (b.isStatic() || world.asleep[i] != 0) continue;
    const bool atRest = b.velocity.norm() < sleep.linearSpeed && b.angularVelocity.norm() < sleep.angularSpeed;
    world.restTime[i] = atRest ? world.restTime[i] + settings.dt : 0.0;
    anyReady = anyReady || world.restTime[i] >= ready;
  }
  if (!anyReady) return;
  const std::vector<CollisionBody<D>> views =
      stageViews<D>(world, Lookahead::Current, settings.dt, settings.rotation, settings.parallel);
  BroadPhaseSettings broad = settings.detection.broad;
  broad.margin = std::max(broad.margin, sleep.wakeMargin);
  const std::vector<int> island = bodyIslands<D>(world, views, broad);
  std::vector<char> restless(world.bodies.size(), 0);
  for (std::size_t i = 0; i < island.size(); ++i) {
    if (island[i] >= 0 && world.asleep[i] == 0 && world.restTime[i] < ready) {
      restless[static_cast<std::size_t>(island[i])] = 1;
    }
  }
  for (std::size_t i = 0; i < island.size(); ++i) {
    if (island[i] < 0 || world.asleep[i] != 0 || restless[static_cast<std::size_t>(island[i])] != 0) continue;
    RigidBody<D>& b = world.bodies[i];
    world.asleep[i] = 1;
    b.velocity.setZero();
    b.angularMomentum.setZero();
    b.syncAngularVelocity();
    ++counters.fellAsleep;
  }
}
// [fall_asleep]

}  // namespace stackbook
