#pragma once
/// \file
/// \brief Shock propagation (chapter 9): the contact graph of a world from predicted
/// motion, the freeze guard that makes a level infinitely heavy, the bottom-up pass over
/// the topological levels, and the step with the pass as chapter 8's post-contact hook.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <span>
#include <stdexcept>
#include <vector>

#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/contact_levels.hpp"
#include "stackbook/stacking/load_carrying.hpp"
#include "stackbook/stepping/gbf_step.hpp"

namespace stackbook {

// [graph_settings]
/// How the contact graph is found in a world.
struct ContactGraphSettings {
  /// Time step of the prediction (the step's dt).
  double dt = 1e-3;
  /// Apply the world's loads (gravity) to the advanced body. Off, the advanced body keeps
  /// its velocity, nothing singles it out, and only bodies that already approach get edges.
  bool loads = true;
  /// Narrow-phase settings (chapter 7).
  NarrowPhaseSettings narrow;
  /// Broad-phase settings; the margin is raised to cover the extra displacement dt^2 |a|.
  BroadPhaseSettings broad;
  /// How predicted poses turn (the step's rotation rule, chapter 5).
  RotationUpdate rotation = RotationUpdate::ExponentialMap;
  /// Threads for the pairs' tests (chapter 10; the step passes its own): each pair's two tests
  /// read the pair only, so blocks of pairs run at the same time with the serial graph's edges,
  /// in its order. One thread unless set.
  ParallelSettings parallel{1, 16, 256, 4};
};
// [graph_settings]

// [world_contact_graph]
/// The contact graph of `world` after the contact stage of a step (Eq. (9.3)). With v the
/// velocities the contact stage left, every body b is tested at x_b + dt v_b ("old": the
/// pose the position update will give). For each dynamic body p in turn, p alone is
/// advanced with the "new" velocity v_p + dt a_p (a_p its loads, gravity), i.e. to
/// x_p + dt (v_p + dt a_p); if p then interferes with body q at a sample where the
/// relative velocity (p with its new velocity, q with its old one) approaches, the edge
/// q -> p ("p rests on q") is added. Static bodies are never advanced: they get no
/// parents. O(pairs) narrow-phase queries, two per broad-phase pair. With `kept`, a pair's
/// queries start from a copy of the lists the last stage left for it (chapter 7): the same
/// graph, with less work where they cover the advanced poses, and the store unchanged.
template <int D>
ContactGraph worldContactGraph(const World<D>& world, const ContactGraphSettings& settings,
                               DetectionCounters* counters = nullptr, const CandidateListStore<D>* kept = nullptr) {
  const int n = world.size();
  std::vector<CollisionBody<D>> views =
      stageViews<D>(world, Lookahead::Velocity, settings.dt, settings.rotation, settings.parallel);
  // The advanced bodies: a copy of p with v_p + dt a_p and L_p + dt tau_p.
  std::vector<RigidBody<D>> advanced(world.bodies.begin(), world.bodies.end());
  double reach = 0.0;
  for (int p = 0; p < n; ++p) {
    const std::size_t k = static_cast<std::size_t>(p);
    if (world.bodies[k].isStatic() || !settings.loads) continue;
    advanceVelocity<D>(advanced[k], settings.dt, world.loads(p));  // Eq. (5.7)
    const double moved = settings.dt * (advanced[k].velocity - world.bodies[k].velocity).norm();
    reach = std::max(reach, moved);
  }
  BroadPhaseSettings broad = settings.broad;
  broad.margin = std::max(broad.margin, reach);  // the extra dt^2 |a| of the advanced body
  const std::vector<BodyPair> candidates = sweepAndPrune<D>(views, broad, counters);
  // Per pair, which of its bodies rests on the other: bit 0, pair.first advanced approaches
  // pair.second (edge second -> first); bit 1, the reverse. The edges are listed from these in
  // pair order afterwards, so they come out in the serial order whatever the threads.
  const std::size_t count = candidates.size();
  std::vector<unsigned char> rests(count, 0);
  // A pair that asks an exact deepest point (chapter 11) needs the full query, which moves the
  // shared views: such a world builds its graph on one thread.
  bool anyExact = settings.narrow.surfaceQuery == SurfaceQuery::DeepestPoint;
  for (int p = 0; p < n && !anyExact && settings.narrow.surfaceQuery == SurfaceQuery::RoundShapes; ++p) {
    anyExact = world.shapes[static_cast<std::size_t>(p)]->roundSurface();
  }
  // Blocks of consecutive pairs, each counted and caught on its own (in block order below).
  const int threads = anyExact ? 1 : resolvedThreadCount(settings.parallel.threads);
  const std::size_t tasks = static_cast<std::size_t>(threads) *
                            static_cast<std::size_t>(std::max(settings.parallel.runsPerThread, 1));
  const std::size_t grain = std::max<std::size_t>(static_cast<std::size_t>(std::max(settings.parallel.graphPairsPerTask, 1)),
                                                  (count + tasks - 1) / tasks);
  const std::size_t blocks = (count + grain - 1) / grain;
  std::vector<DetectionCounters> blockCounters(blocks);
  std::vector<std::exception_ptr> errors(blocks);
  parallelFor(threads, blocks, 1, [&](std::size_t firstBlock, std::size_t lastBlock) {
    std::vector<InterferenceCandidate<D>> scratch;  // reused by every query of these blocks
    // One candidate pair is tested twice, each body advanced in turn: bound 2 * pairs. The
    // second test sees the pair moved by dt^2 |a| from the first, so chapter 7's candidate
    // lists made by the first usually answer it.
    PairCandidateLists<D> lists;
    for (std::size_t block = firstBlock; block < lastBlock; ++block) {
      DetectionCounters* blockCounter = counters != nullptr ? &blockCounters[block] : nullptr;
      try {
        for (std::size_t k = block * grain; k < std::min(count, (block + 1) * grain); ++k) {
          const BodyPair& pair = candidates[k];
          lists.firstInSecond.made = lists.secondInFirst.made = false;  // a new pair: none yet
          const bool lazy = !pairAsksDeepestPoint<D>(settings.narrow, *world.shapes[static_cast<std::size_t>(pair.first)],
                                                     *world.shapes[static_cast<std::size_t>(pair.second)]);
          if (lazy && kept != nullptr) kept->copyFor(pair.first, pair.second, lists);  // the store is only read
          // [graph_direction_test]
          for (int side = 0; side < 2; ++side) {
            const int p = side == 0 ? pair.first : pair.second;
            const std::size_t i = static_cast<std::size_t>(p);
            if (world.bodies[i].isStatic()) continue;
            // Body p advanced: x_p + dt (v_p + dt a_p).
            const CollisionBody<D> moved = collisionBodyAt<D>(
                advanced[i], *world.shapes[i], predictPose<D>(advanced[i], settings.dt, settings.rotation));
            bool approaching = false;
            if (lazy) {  // the lazy search of chapter 7: the normals of the samples it tests only
              const CollisionBody<D>& a = side == 0 ? moved : views[static_cast<std::size_t>(pair.first)];
              const CollisionBody<D>& b = side == 0 ? views[static_cast<std::size_t>(pair.second)] : moved;
              approaching =
                  deepestApproachingInPair<D>(a, b, pair, settings.narrow, blockCounter, scratch, &lists).has_value();
            } else {  // chapter 11's exact deepest points need the full query (one thread)
              const CollisionBody<D> old = views[i];
              views[i] = moved;
              approaching = deepestApproachingSample<D>(
                                pairInterference<D>(views, pair, settings.narrow, blockCounter), views)
                                .has_value();
              views[i] = old;
            }
            if (approaching) rests[k] |= static_cast<unsigned char>(1u << side);  // edge q -> p
          }
          // [graph_direction_test]
        }
      } catch (...) {
        errors[block] = std::current_exception();  // the rest of this block is not tested
      }
    }
  });
  // The first error in pair order is the one the serial loop would have thrown.
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  if (counters != nullptr) {
    for (const DetectionCounters& c : blockCounters) *counters += c;
  }
  std::vector<ContactPair> edges;
  for (std::size_t k = 0; k < count; ++k) {
    if ((rests[k] & 1u) != 0) edges.push_back(ContactPair{candidates[k].second, candidates[k].first});
    if ((rests[k] & 2u) != 0) edges.push_back(ContactPair{candidates[k].first, candidates[k].second});
  }
  return ContactGraph(n, edges);
}
// [world_contact_graph]

// [unpressed_contacts]
/// `graph` completed with the contacts that gravity does not press (Eq. (9.9), detail 3):
/// every broad-phase pair that interferes at the poses x + dt v but has no edge. Between two
/// dynamic bodies it gets both edges, a cycle, so the two share a level and are swept
/// together (a body wedged sideways between others, any contact in a scene without gravity);
/// with a static partner it gets the edge static -> dynamic. The pass as the contact stage
/// builds its levels from this graph, since no contact stage resolves these contacts for it.
template <int D>
ContactGraph withUnpressedContacts(const World<D>& world, const ContactGraph& graph,
                                   const ContactGraphSettings& settings,
                                   DetectionCounters* counters = nullptr, CandidateListStore<D>* kept = nullptr) {
  const auto ordered = [](int a, int b) { return a < b ? BodyPair{a, b} : BodyPair{b, a}; };
  std::vector<BodyPair> pressed;
  pressed.reserve(graph.edgeCount());
  for (const ContactPair& c : graph.edges()) pressed.push_back(ordered(c.below, c.above));
  std::sort(pressed.begin(), pressed.end());
  const std::vector<CollisionBody<D>> views = stageViews<D>(world, Lookahead::Velocity, settings.dt, settings.rotation);
  std::vector<ContactPair> edges = graph.edges();
  std::vector<InterferenceCandidate<D>> scratch;
  std::vector<InterferenceSample<D>> samples;
  PairCandidateLists<D> lists;
  for (const BodyPair& p : sweepAndPrune<D>(views, settings.broad, counters)) {  // sorted by (i, j)
    if (std::binary_search(pressed.begin(), pressed.end(), ordered(p.first, p.second))) continue;
    const bool exact = pairAsksDeepestPoint<D>(settings.narrow, *world.shapes[static_cast<std::size_t>(p.first)],
                                               *world.shapes[static_cast<std::size_t>(p.second)]);
    if (exact || kept == nullptr) {  // chapter 11's exact points need the full query
      samples = pairInterference<D>(views, p, settings.narrow, counters);
    } else {  // the lists the last stage left answer as the full query does (chapter 7)
      const bool have = kept->swapFor(p.first, p.second, lists);
      if (!have) lists.firstInSecond.made = lists.secondInFirst.made = false;
      pairInterferenceListed<D>(views, p, settings.narrow, counters, scratch, samples, &lists);
      if (have) kept->swapFor(p.first, p.second, lists);
    }
    if (samples.empty()) continue;
    const bool firstStatic = world.bodies[static_cast<std::size_t>(p.first)].isStatic();
    const bool secondStatic = world.bodies[static_cast<std::size_t>(p.second)].isStatic();
    if (!firstStatic) edges.push_back(ContactPair{p.second, p.first});  // p.first rests on p.second
    if (!secondStatic) edges.push_back(ContactPair{p.first, p.second});
  }
  return ContactGraph(graph.bodyCount(), edges);
}
// [unpressed_contacts]

// [freeze_guard]
/// Temporary infinite mass (Eq. (9.4)): freeze(i) sets 1/m and I^{-1} of body i to zero,
/// so by Eq. (1.9) its K is 0, RigidBody::applyImpulse leaves it alone and an impulse
/// against it changes only the other body. The destructor restores every frozen body's
/// exact values (bit for bit), also when an exception leaves the pass. The cached omega
/// is not touched (nothing calls syncAngularVelocity() on a frozen body: applyImpulse
/// returns before it), so velocities and momenta are as they were.
template <int D>
class FreezeGuard {
 public:
  explicit FreezeGuard(World<D>& world) : world_(world) {}
  FreezeGuard(const FreezeGuard&) = delete;
  FreezeGuard& operator=(const FreezeGuard&) = delete;
  ~FreezeGuard() { releaseAll(); }
  // [freeze_and_release]
  /// Freeze body i; a static or already frozen body is left as it is. Returns true if it
  /// was frozen by this call.
  bool freeze(int i) {
    RigidBody<D>& body = world_.bodies.at(static_cast<std::size_t>(i));
    if (body.isStatic()) return false;
    saved_.push_back(Saved{i, body.inverseMass, body.inverseInertia});
    body.inverseMass = 0.0;
    body.inverseInertia.setZero();
    return true;
  }

  /// Restore every frozen body, last frozen first. Called by the destructor.
  void releaseAll() noexcept {
    for (auto it = saved_.rbegin(); it != saved_.rend(); ++it) {
      RigidBody<D>& body = world_.bodies[static_cast<std::size_t>(it->body)];
      body.inverseMass = it->inverseMass;
      body.inverseInertia = it->inverseInertia;
    }
    saved_.clear();
  }
  // [freeze_and_release]
  /// Bodies frozen now.
  std::size_t frozenCount() const { return saved_.size(); }

 private:
  struct Saved {
    int body;
    double inverseMass;
    AngVec<D> inverseInertia;
  };
  World<D>& world_;
  std::vector<Saved> saved_;
};
// [freeze_guard]

/// What one shock-propagation pass found (for the chapter's tables and the benchmark).
struct ShockPassReport {
  std::size_t bodies = 0;
  std::size_t edges = 0;
  std::size_t levels = 0;
  std::size_t pairs = 0;
  double graphSeconds = 0.0;  ///< building the graph and its levels
};

// [shock_pass]
/// True if the step's contact stage runs before the pass: the contact effect runs, with at
/// least one sweep, and the pass does not replace it (ShockSettings::replacesContactStage).
inline bool contactStageRuns(const StepSettings& settings, const Effects& effects) {
  return effects.contact && settings.contactIterations > 0 && !settings.shock.replacesContactStage;
}

/// True if level l of `levels` is one body that rests on static bodies only and supports
/// nothing (a box alone on the ground). The pass skips it: its supporters are infinitely
/// heavy already, freezing it affects no other body, and its contacts were swept by the
/// contact stage under the same rules, so the pass would only add contact sweeps.
/// Ask before the pass freezes anything: a frozen supporter looks static too.
template <int D>
bool isolatedLevel(const World<D>& world, const ContactGraph& graph, const ContactLevels& levels,
                   std::size_t l) {
  const std::span<const int> bodies = levels.bodies(l);
  if (bodies.size() != 1) return false;
  const int b = bodies.front();
  if (!graph.children(b).empty()) return false;
  for (const int parent : graph.parents(b)) {
    if (!world.bodies[static_cast<std::size_t>(parent)].isStatic()) return false;
  }
  return true;
}

// [level_waves]
/// The waves of `levels` (chapter 10, "Threads"): the levels that are not `skipped`, grouped so
/// that the levels of one wave can be swept at the same time. Level l depends on level k < l
/// when a pair of l has its lower body in k and that body is dynamic: l reads the velocities k
/// leaves and needs k frozen. Level l's wave is one more than the latest wave of a level it
/// depends on (0 if none), so every wave depends only on earlier ones. Two levels of one wave
/// touch no common body: each writes only its own bodies and reads only bodies of earlier waves,
/// frozen by then, so sweeping them at the same time, or in any order, performs the same
/// operations on the same data as the bottom-up pass. Waves in order, each level ascending. O(L + m).
template <int D>
std::vector<std::vector<std::size_t>> levelWaves(const World<D>& world, const ContactLevels& levels,
                                                 const std::vector<char>& skipped) {
  std::vector<int> waveOf(levels.levelCount(), -1);
  std::vector<std::vector<std::size_t>> waves;
  for (std::size_t l = 0; l < levels.levelCount(); ++l) {
    if (skipped[l] != 0) continue;
    int wave = 0;
    for (const ContactPair& c : levels.pairs(l)) {
      const std::size_t k = static_cast<std::size_t>(levels.levelOfBody[static_cast<std::size_t>(c.below)]);
      if (k == l || world.bodies[static_cast<std::size_t>(c.below)].isStatic()) continue;
      wave = std::max(wave, waveOf[k] + 1);  // k < l: its wave is known (a skipped level supports nothing)
    }
    waveOf[l] = wave;
    if (static_cast<std::size_t>(wave) >= waves.size()) waves.resize(static_cast<std::size_t>(wave) + 1);
    waves[static_cast<std::size_t>(wave)].push_back(l);
  }
  return waves;
}
// [level_waves]

// [level_waves_sweep]
/// The pass's levels wave by wave (levelWaves()) on `threads` threads: a wave of one level, or
/// of fewer than settings.parallel.minPairs pairs in all, is swept level by level as the
/// bottom-up pass sweeps it (a level's sweeps may split into islands or colours); the levels
/// of a larger wave are swept at the same time, each on one thread, each counting into
/// its own StageCounters, added in level order. Then the wave's bodies are frozen. If levels
/// throw, the exception of the first of them is rethrown (the pass is abandoned, as it would
/// be at that level). sweepLevel(l, settings, counters, pairs, lists) sweeps level l.
template <int D, class SweepLevel>
void sweepLevelWaves(const World<D>& world, const ContactLevels& levels, const std::vector<char>& skipped,
                     int threads, const StepSettings& settings, StageCounters& counters, FreezeGuard<D>& frozen,
                     const SweepLevel& sweepLevel, std::vector<BodyPair>& pairs,
                     std::vector<PairCandidateLists<D>>& lists) {
  StepSettings oneThread = settings;
  oneThread.parallel.threads = 1;
  const std::size_t minPairs = static_cast<std::size_t>(std::max(settings.parallel.minPairs, 2));
  for (const std::vector<std::size_t>& wave : levelWaves<D>(world, levels, skipped)) {
    std::size_t wavePairs = 0;
    for (const std::size_t l : wave) wavePairs += levels.pairs(l).size();
    if (wave.size() == 1 || wavePairs < minPairs) {  // too little to share: level by level
      for (const std::size_t l : wave) sweepLevel(l, settings, counters, pairs, lists);
    } else {
      std::vector<StageCounters> local(wave.size());
      std::vector<std::exception_ptr> error(wave.size());
      parallelFor(threads, wave.size(), 1, [&](std::size_t first, std::size_t last) {
        std::vector<BodyPair> levelPairs;
        std::vector<PairCandidateLists<D>> levelLists;
        for (std::size_t k = first; k < last; ++k) {
          try {
            sweepLevel(wave[k], oneThread, local[k], levelPairs, levelLists);
          } catch (...) {
            error[k] = std::current_exception();
          }
        }
      });
      for (const std::exception_ptr& e : error) {
        if (e) std::rethrow_exception(e);
      }
      for (const StageCounters& c : local) counters += c;
    }
    for (const std::size_t l : wave) {
      for (const int body : levels.bodies(l)) frozen.freeze(body);  // Eq. (9.4)
    }
  }
}
// [level_waves_sweep]

/// One shock-propagation pass over `levels` (built from `graph`): for each level l bottom
/// up, settings.shock.sweepsPerLevel sweeps over the level's pairs with restitution
/// e_s = settings.shock.restitutionAt(s) (at most shock.pairIterations impulses per pair
/// per sweep), then the level's bodies are frozen (Eq. (9.4)) for the levels above.
/// Isolated levels (isolatedLevel()) are skipped when the contact stage has swept them
/// (contactStageRuns()). A sweep that applies no impulse ends its level early. All freezes
/// are released at the end, also on an exception. Work goes to `counters`. Loops: levels (L), sweeps (S), the
/// level's pairs; resolvePair() caps its own loop.
/// `effects` are the step's (resolveEffects()); the overload without them resolves them.
template <int D>
void shockPropagationPass(World<D>& world, const ContactGraph& graph, const ContactLevels& levels,
                          const StepSettings& settings, const Effects& effects,
                          StageCounters& counters, ContactLedger* ledger = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  const ShockSettings& shock = settings.shock;
  StageSpec spec{Lookahead::Velocity, shock.sweepsPerLevel, shock.pairIterations,
                 [&shock](int s, const PairMaterial&) { return shock.restitutionAt(s); }};
  spec.friction = effects.friction;
  spec.rollingFriction = effects.rollingFriction;
  spec.ledger = ledger;  // the step's ledger under FrictionConeRule::StepTotal (Eq. (8.13))
  spec.pairImpulseTolerance = shock.pairImpulseTolerance;
  spec.recorder = settings.contactRecorder;  // chapter 10's contacts output; nullptr: off
  spec.stage = ContactStage::Shock;
  std::vector<CollisionBody<D>> views = stageViews<D>(world, Lookahead::Velocity, settings.dt, settings.rotation,
                                                     settings.parallel, settings.impulsePoint.arms);
  // Isolated levels are skipped only when the contact stage swept them (Eq. (9.9)).
  const bool skipIsolated = contactStageRuns(settings, effects);
  std::vector<char> isolated(levels.levelCount(), 0);  // decided before anything is frozen
  for (std::size_t l = 0; l < levels.levelCount() && skipIsolated; ++l) {
    isolated[l] = isolatedLevel<D>(world, graph, levels, l) ? 1 : 0;
  }  // [shock_levels_loop]
  FreezeGuard<D> frozen(world);
  CandidateListStore<D>& kept = world.candidateLists;  // chapter 7's lists, from the last stage
  kept.matchShapes(world.shapes);
  // The sweeps of level l with `levelSettings`, counted into `levelCounters`; `pairs` and
  // `lists` (chapter 7's candidate lists) are storage the caller keeps between levels.
  const auto sweepLevel = [&](std::size_t l, const StepSettings& levelSettings, StageCounters& levelCounters,
                              std::vector<BodyPair>& pairs, std::vector<PairCandidateLists<D>>& lists) {
    pairs.clear();
    for (const ContactPair& c : levels.pairs(l)) pairs.push_back(BodyPair{c.below, c.above});  // Eq. (9.2)
    // Each pair takes the lists the last stage left for it (World::candidateLists), and
    // gives them back after the level; a pair without kept lists starts with none. Levels
    // have no pair in common, so levels swept at the same time take different entries.
    lists.resize(pairs.size());
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      if (!kept.swapFor(pairs[p].first, pairs[p].second, lists[p])) {
        lists[p].firstInSecond.made = lists[p].secondInFirst.made = false;  // keeps the capacity
      }
    }
    StageSpec levelSpec = spec;
    double largest = 0.0;  // a level sweep's fastest approach (levelApproachTolerance)
    if (shock.levelApproachTolerance > 0.0) levelSpec.largestApproach = &largest;
    // A sweep that applies no impulse ends the level: nothing approaches, and no later
    // sweep can find an approach, since restitution only scales an impulse (Eq. (8.5)).
    for (int s = 1; s <= shock.sweepsPerLevel && !pairs.empty(); ++s) {
      largest = 0.0;
      if (sweepPairs<D>(world, views, pairs, levelSpec, s, settings.dt, levelSettings, levelCounters, &lists) == 0) break;
      if (shock.levelApproachTolerance > 0.0 && largest <= shock.levelApproachTolerance) break;
    }
    for (std::size_t p = 0; p < pairs.size(); ++p) kept.swapFor(pairs[p].first, pairs[p].second, lists[p]);
  };
  std::vector<BodyPair> pairs;
  std::vector<PairCandidateLists<D>> lists;
  const int threads = resolvedThreadCount(settings.parallel.threads);
  if (threads == 1 || spec.recorder != nullptr) {  // one level after the other, bottom up
    for (std::size_t l = 0; l < levels.levelCount(); ++l) {  // Eq. (9.1)
      if (isolated[l] != 0) continue;
      sweepLevel(l, settings, counters, pairs, lists);
      for (const int body : levels.bodies(l)) frozen.freeze(body);  // Eq. (9.4)
    }
  } else {  // waves of levels that do not read each other (chapter 10, "Threads")
    sweepLevelWaves<D>(world, levels, isolated, threads, settings, counters, frozen, sweepLevel, pairs, lists);
  }
  frozen.releaseAll();
  counters.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();  // [shock_levels_loop]
}

template <int D>
void shockPropagationPass(World<D>& world, const ContactGraph& graph, const ContactLevels& levels,
                          const StepSettings& settings, StageCounters& counters) {
  shockPropagationPass<D>(world, graph, levels, settings, resolveEffects<D>(world, settings.effects),
                          counters);
}
// [shock_pass]

/// The contact graph settings a step uses: its dt, its detection settings, and loads only
/// if the gravity effect runs.
inline ContactGraphSettings stepGraphSettings(const StepSettings& settings, const Effects& effects) {
  ContactGraphSettings g;
  g.dt = settings.dt;
  g.loads = effects.gravity;
  g.narrow = settings.detection.narrow;
  g.broad = settings.detection.broad;
  g.rotation = settings.rotation;
  g.parallel = settings.parallel;
  return g;
}

// [approaching_contacts]
/// The supporting contacts of `graph` that still approach faster than `minSpeed`: pairs
/// with an interfering sample at the predicted poses x + dt v whose relative velocity has
/// u_rel . N < -minSpeed (chapter 7's test, with a floor for round-off). After a pass over
/// topological levels every contact was swept last with its lower body frozen; a layering
/// that freezes a body before one of its supporters leaves contacts approaching.
template <int D>
std::size_t approachingContacts(const World<D>& world, const ContactGraph& graph, double dt,
                                double minSpeed, const NarrowPhaseSettings& narrow = {}) {
  const std::vector<CollisionBody<D>> views = stageViews<D>(world, Lookahead::Velocity, dt);
  std::size_t count = 0;
  for (const ContactPair& c : graph.edges()) {  // bound: m
    for (const InterferenceSample<D>& s : pairInterference<D>(views, BodyPair{c.below, c.above}, narrow)) {
      if (normalRelativeVelocity<D>(s, views) < -minSpeed) {  // Eq. (7.5) with a floor
        ++count;
        break;
      }
    }
  }
  return count;
}
// [approaching_contacts]

/// How shock propagation orders the bodies: GBF's topological levels of the condensed
/// graph, or the BFS depth from parentless bodies (kept to show how it fails).
enum class Layering { Topological, BfsDepth };

// [shock_propagation]
/// Shock propagation as a whole, run on the velocities the contact stage left:
/// settings.shock.passes times, build the contact graph (Eq. (9.3)), its levels
/// (topological, Eq. (9.1), unless `layering` asks for BFS depth) and run one pass
/// (shockPropagationPass()). Returns what the last pass found; its work and time are
/// added to `counters`. When `builtEdges` is set, the edges of every graph built are appended
/// to it (the welded pass's islands, chapter 9).
template <int D>
ShockPassReport shockPropagation(World<D>& world, const StepSettings& settings, StageCounters& counters,
                                 Layering layering = Layering::Topological,
                                 ContactLedger* ledger = nullptr,
                                 std::vector<ContactPair>* builtEdges = nullptr) {
  ShockPassReport report;
  const Effects effects = resolveEffects<D>(world, settings.effects);
  for (int pass = 0; pass < settings.shock.passes; ++pass) {
    const auto start = std::chrono::steady_clock::now();
    const ContactGraphSettings graphSettings = stepGraphSettings(settings, effects);
    world.candidateLists.matchShapes(world.shapes);
    ContactGraph graph = worldContactGraph<D>(world, graphSettings, &counters.detection, &world.candidateLists);
    if (!contactStageRuns(settings, effects)) {  // Eq. (9.9): nothing else resolves them
      graph = withUnpressedContacts<D>(world, graph, graphSettings, &counters.detection, &world.candidateLists);
    }
    // [freeze_when_it_carries]
    // Chapter 12: a body that cannot carry its load is joined to its supporters and to the
    // bodies above it, so the pass sweeps them as one level instead of freezing one under the other.
    if (settings.shock.freeze == FreezeRule::WhenItCarries && effects.gravity) {
      const ContactLevels gbfLevels = topologicalLevels(graph);
      const LoadCarrying<D> carrying =
          loadCarrying<D>(world, graph, gbfLevels, settings.dt, settings.rotation, settings.detection.narrow,
                          settings.shock.carryTolerance, &counters.detection, &world.candidateLists);  // Eqs. (12.1)-(12.4)
      counters.uncarried += carrying.uncarried;
      if (carrying.uncarried > 0) graph = joinUncarried(graph, carrying.carries, staticBodies<D>(world), gbfLevels);
    }
    // [freeze_when_it_carries]
    const ContactLevels levels =
        layering == Layering::Topological ? topologicalLevels(graph) : bfsDepthLevels(graph);
    report.graphSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    counters.seconds += report.graphSeconds;
    report.bodies = static_cast<std::size_t>(graph.bodyCount());
    report.edges = graph.edgeCount();
    report.levels = levels.levelCount();
    report.pairs = levels.pairList.size();
    if (builtEdges != nullptr) {
      const std::vector<ContactPair> edges = graph.edges();
      builtEdges->insert(builtEdges->end(), edges.begin(), edges.end());
    }
    shockPropagationPass<D>(world, graph, levels, settings, effects, counters, ledger);
  }
  return report;
}

/// The post-contact hook of chapter 8's gbfStep() that runs shockPropagation() and puts
/// its work in counters.shock.
template <int D>
PostContactHook<D> shockPropagationHook(Layering layering = Layering::Topological) {
  return [layering](World<D>& world, const StepSettings& settings, StepCounters& counters) {
    ContactLedger* ledger =
        settings.frictionCone == FrictionConeRule::StepTotal ? &counters.contactLedger : nullptr;
    shockPropagation<D>(world, settings, counters.shock, layering, ledger);
  };
}

// [pass_as_contact_settings]
/// The settings of the pass as the contact stage (chapter 9, Eq. (9.9)), from `base`: no
/// contact stage (the pass runs whenever contact does and sweeps every level),
/// `sweepsPerLevel` sweeps per level (20 converge the 20-row pyramid of B15; chapter 9's table),
/// one Coulomb cone per step (Eq. (8.13)), since a cube's corner needs mu >= 0.849
/// (Eq. (9.7)), and, when `pairCap` > 0, at most `pairCap` impulses per pair per sweep in the
/// pass and in the collision stage (shock.pairIterations, collisionPairIterations). The
/// default, 0, keeps base's caps (PhysBAM's 10 and 20); 2 (the first impulse and one
/// correction) is cheaper and holds the pyramids stiller at 60 Hz but leaves a stack at
/// dt = 1e-3 short of rest (appendix "The pair caps"). Use it with stackingStep().
inline StepSettings passAsContactStage(StepSettings base = {}, int sweepsPerLevel = 20, int pairCap = 0) {
  base.shock.replacesContactStage = true;
  base.shock.sweepsPerLevel = sweepsPerLevel;
  base.shock.restitution.clear();  // GBF's ramp over the new sweep count
  base.frictionCone = FrictionConeRule::StepTotal;
  if (pairCap > 0) {
    base.shock.pairIterations = pairCap;
    base.collisionPairIterations = pairCap;
  }
  return base;
}
// [pass_as_contact_settings]

// [pass_short_loops_settings]
/// The pass as the contact stage with short pair loops (chapter 9, "Short pair loops"):
/// passAsContactStage() with `sweepsPerLevel` sweeps per level and one cone per step, and in
/// the pass and in the collision stage at most `pairCap` impulses per pair visit, the visit
/// ending early after an impulse |j| <= `pairImpulseTolerance` times its first
/// (shock.pairImpulseTolerance for the pass, pairImpulseTolerance for the collision stage;
/// the contact stage, which would read it too, does not run). The defaults, 20, 5 and 0.2,
/// are the preset of the bundled pyramids: caps of 2 leave a stack at dt = 1e-3 short of
/// rest; caps of 5 with the tolerance keep every claim of PhysBAM's caps that chapter 9 tests.
inline StepSettings passAsContactStageShortLoops(StepSettings base = {}, int sweepsPerLevel = 20,
                                                 int pairCap = 5, double pairImpulseTolerance = 0.2) {
  if (pairCap < 1) throw std::invalid_argument("passAsContactStageShortLoops: pairCap must be at least 1");
  // The range validateStepSettings() requires of both tolerances.
  if (!(pairImpulseTolerance >= 0.0 && pairImpulseTolerance < 1.0)) {
    throw std::invalid_argument("passAsContactStageShortLoops: pairImpulseTolerance must be in [0, 1)");
  }
  base = passAsContactStage(base, sweepsPerLevel, pairCap);
  base.shock.pairImpulseTolerance = pairImpulseTolerance;
  base.pairImpulseTolerance = pairImpulseTolerance;
  return base;
}
// [pass_short_loops_settings]

// [pass_patch_settings]
/// The pass as the contact stage with sticking patches (chapter 8, "A whole patch at once"):
/// passAsContactStageShortLoops() with ImpulsePointRule::StickingPatch in every stage, so a
/// pair touching along a face that friction can hold gets one impulse that stops it, and a
/// level's sweeps end once a sweep acts on no approach faster than `levelApproachTolerance`
/// (default 1e-9 m/s: round-off left by a patch impulse, which the sweeps would otherwise
/// chase through every sweep of the ramp). Pairs the patch cannot hold (sliding, tipping,
/// bouncing) are resolved at their deepest sample as before.
inline StepSettings passAsContactStagePatch(StepSettings base = {}, double levelApproachTolerance = 1e-9) {
  if (!(levelApproachTolerance >= 0.0) || !std::isfinite(levelApproachTolerance)) {
    throw std::invalid_argument("passAsContactStagePatch: levelApproachTolerance must be finite and >= 0");
  }
  base = passAsContactStageShortLoops(base);
  base.impulsePoint.rule = ImpulsePointRule::StickingPatch;
  base.shock.levelApproachTolerance = levelApproachTolerance;
  return base;
}
// [pass_patch_settings]

// [carrying_pass_settings]
/// The carrying pass (chapter 12), the preset "carryingPass" and the default of a scene that
/// names none: the pass as the contact stage with sticking patches (passAsContactStagePatch())
/// that freezes only the bodies that carry their load (FreezeRule::WhenItCarries), with chapter
/// 11's accurate knobs where they are cheap: the implicit midpoint rotation rule and exact
/// deepest points for round shapes (SurfaceQuery::RoundShapes; boxes and meshes keep samples),
/// and the landing rules (withLandingRules(): lever arms at the start pose, held samples, tied
/// landing; chapters 8 and 12).
inline StepSettings carryingPass(StepSettings base = {}) {
  base = passAsContactStagePatch(base);
  base.shock.freeze = FreezeRule::WhenItCarries;
  base.rotation = RotationUpdate::ImplicitMidpoint;
  base.detection.narrow.surfaceQuery = SurfaceQuery::RoundShapes;
  return withLandingRules(base);
}
// [carrying_pass_settings]

// [gbf_short_loops_settings]
/// GBF's step with short pair loops (chapter 9, "Short pair loops in GBF's step"): the
/// contact stage runs and the pass follows it, as in GBF, but every pair visit of the collision
/// and contact stages takes at most `pairCap` impulses and ends after an impulse |j| <=
/// `pairImpulseTolerance` times the visit's first (collisionPairIterations,
/// contactPairIterations, pairImpulseTolerance). The pass keeps base's loop (PhysBAM's cap of
/// 10, no tolerance): it sweeps each level only twice, so what a short visit left there would
/// meet no later sweep. The defaults, 5 and 0.2, are the preset "gbfShortLoops" that the
/// bundled 1000-body piles name. The sweep counts, the ramps and the cone rule are base's, so
/// loads still reach lower bodies (a seesaw tips), unlike under the pass as the contact stage.
inline StepSettings gbfStepShortLoops(StepSettings base = {}, int pairCap = 5, double pairImpulseTolerance = 0.2) {
  if (pairCap < 1) throw std::invalid_argument("gbfStepShortLoops: pairCap must be at least 1");
  if (!(pairImpulseTolerance >= 0.0 && pairImpulseTolerance < 1.0)) {
    throw std::invalid_argument("gbfStepShortLoops: pairImpulseTolerance must be in [0, 1)");
  }
  base.collisionPairIterations = pairCap;
  base.contactPairIterations = pairCap;
  base.pairImpulseTolerance = pairImpulseTolerance;
  return base;
}
// [gbf_short_loops_settings]

/// The welded pass's step (chapter 9, "The welded pass"), in welded_pass.hpp.
template <int D>
StepCounters weldedPassStep(World<D>& world, const StepSettings& settings, Layering layering);

/// GBF's step with shock propagation: gbfStep() with shockPropagationHook(). The pass runs
/// when the shockPropagation effect does (inferred on for two or more dynamic bodies). With
/// settings.shock.welded.enabled, the welded pass's step weldedPassStep() instead.
template <int D>
StepCounters stackingStep(World<D>& world, const StepSettings& settings,
                          Layering layering = Layering::Topological) {
  if (settings.shock.welded.enabled) return weldedPassStep<D>(world, settings, layering);
  return gbfStep<D>(world, settings, shockPropagationHook<D>(layering));
}
// [shock_propagation]

// Compiled once, for D = 2 and 3, in the library (src/stackbook/instantiate_step.cpp): a
// translation unit that includes this header links to those instead of compiling its own.
#define STACKBOOK_EXTERN_SHOCK(D)                                                                 \
  extern template ContactGraph worldContactGraph<D>(const World<D>&, const ContactGraphSettings&,  \
                                                    DetectionCounters*, const CandidateListStore<D>*); \
  extern template ShockPassReport shockPropagation<D>(World<D>&, const StepSettings&,              \
                                                      StageCounters&, Layering, ContactLedger*,    \
                                                      std::vector<ContactPair>*);                  \
  extern template StepCounters stackingStep<D>(World<D>&, const StepSettings&, Layering);       \
  extern template StepCounters weldedPassStep<D>(World<D>&, const StepSettings&, Layering);
STACKBOOK_EXTERN_SHOCK(2)
STACKBOOK_EXTERN_SHOCK(3)
#undef STACKBOOK_EXTERN_SHOCK

}  // namespace stackbook
