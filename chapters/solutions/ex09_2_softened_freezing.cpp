// Exercise 9.2, reference solution: softened freezing (chapter 9).
#include "stackbook/exercises/ex09_2_softened_freezing.hpp"

#include <sstream>
#include <stdexcept>
#include <vector>

#include "stackbook/stacking/shock_propagation.hpp"

namespace stackbook {

namespace {

/// Scales inverse masses and restores them exactly in its destructor.
template <int D>
class SoftenGuard {
 public:
  SoftenGuard(World<D>& world, double softness) : world_(world), softness_(softness) {}
  SoftenGuard(const SoftenGuard&) = delete;
  SoftenGuard& operator=(const SoftenGuard&) = delete;
  ~SoftenGuard() {
    for (auto it = saved_.rbegin(); it != saved_.rend(); ++it) {
      RigidBody<D>& body = world_.bodies[static_cast<std::size_t>(it->body)];
      body.inverseMass = it->inverseMass;
      body.inverseInertia = it->inverseInertia;
    }
  }
  void soften(int i) {
    RigidBody<D>& body = world_.bodies.at(static_cast<std::size_t>(i));
    if (body.isStatic()) return;
    saved_.push_back(Saved{i, body.inverseMass, body.inverseInertia});
    body.inverseMass *= softness_;
    body.inverseInertia *= softness_;
  }

 private:
  struct Saved {
    int body;
    double inverseMass;
    AngVec<D> inverseInertia;
  };
  World<D>& world_;
  double softness_;
  std::vector<Saved> saved_;
};

}  // namespace

template <int D>
void softenedShockPass(World<D>& world, const ContactGraph& graph, const ContactLevels& levels,
                       const StepSettings& settings, double softness, StageCounters& counters) {
  if (!(softness >= 0.0 && softness <= 1.0)) {
    std::ostringstream msg;
    msg << "softenedShockPass: softness must be in [0, 1], got " << softness;
    throw std::invalid_argument(msg.str());
  }
  const ShockSettings& shock = settings.shock;
  StageSpec spec{Lookahead::Velocity, shock.sweepsPerLevel, shock.pairIterations,
                 [&shock](int s, const PairMaterial&) { return shock.restitutionAt(s); }};
  const Effects effects = resolveEffects<D>(world, settings.effects);
  spec.friction = effects.friction;
  spec.rollingFriction = effects.rollingFriction;
  std::vector<CollisionBody<D>> views = stageViews<D>(world, Lookahead::Velocity, settings.dt);
  std::vector<char> isolated(levels.levelCount(), 0);
  for (std::size_t l = 0; l < levels.levelCount(); ++l) {
    isolated[l] = isolatedLevel<D>(world, graph, levels, l) ? 1 : 0;
  }
  SoftenGuard<D> softened(world, softness);
  std::vector<BodyPair> pairs;
  for (std::size_t l = 0; l < levels.levelCount(); ++l) {
    if (isolated[l] != 0) continue;
    pairs.clear();
    for (const ContactPair& c : levels.pairs(l)) pairs.push_back(BodyPair{c.below, c.above});
    for (int s = 1; s <= shock.sweepsPerLevel && !pairs.empty(); ++s) {
      sweepPairs<D>(world, views, pairs, spec, s, settings.dt, settings, counters);
    }
    for (const int body : levels.bodies(l)) softened.soften(body);
  }
}

template void softenedShockPass<2>(World<2>&, const ContactGraph&, const ContactLevels&,
                                   const StepSettings&, double, StageCounters&);
template void softenedShockPass<3>(World<3>&, const ContactGraph&, const ContactLevels&,
                                   const StepSettings&, double, StageCounters&);

}  // namespace stackbook
