#pragma once
/// \file
/// \brief One impulse stage of the time step (chapter 8): sweeps over the broad-phase
/// pairs, and per pair the loop "detect at the tested poses, take the deepest approaching
/// sample, apply one frictional impulse to the current velocities, re-predict the pair".
/// GBF's collision stage and contact stage are both this loop, with different poses and
/// restitution; the traditional order runs it at the current poses.

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <vector>

#include "stackbook/body/integrate.hpp"
#include "stackbook/collision/impulse_point.hpp"
#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"
#include "stackbook/impulse/patch_impulse.hpp"
#include "stackbook/impulse/rolling_friction.hpp"
#include "stackbook/stepping/contact_ledger.hpp"
#include "stackbook/stepping/contact_recorder.hpp"
#include "stackbook/stepping/pair_colours.hpp"
#include "stackbook/stepping/pair_islands.hpp"
#include "stackbook/stepping/parallel.hpp"
#include "stackbook/stepping/step_counters.hpp"
#include "stackbook/stepping/step_settings.hpp"
#include "stackbook/stepping/world.hpp"

namespace stackbook {

// [lookahead]
/// Where a stage tests the bodies.
enum class Lookahead {
  /// At the current pose x (the traditional order, after the position update).
  Current,
  /// At x' = x + dt v: the contact stage, after the velocity update (Eq. (8.2)).
  Velocity,
  /// At x' = x + dt (v + dt g): the collision stage, before the velocity update
  /// (Eq. (8.1)); the loads are the world's.
  VelocityAndLoads,
};
// [lookahead]

/// The pose body i is tested at under the given lookahead, turned by the step's rotation rule.
template <int D>
Pose<D> testedPose(const World<D>& world, int i, Lookahead lookahead, double dt,
                   RotationUpdate rotation = RotationUpdate::ExponentialMap) {
  const RigidBody<D>& body = world.bodies[static_cast<std::size_t>(i)];
  switch (lookahead) {
    case Lookahead::Current: return poseOf<D>(body);
    case Lookahead::Velocity: return predictPose<D>(body, dt, rotation);                         // Eq. (8.2)
    case Lookahead::VelocityAndLoads: return predictPose<D>(body, dt, world.loads(i), rotation);  // Eq. (8.1)
  }
  return poseOf<D>(body);
}

/// The friction coefficient with which the step-total rule (Eq. (8.13)) asks chapter 3
/// for its sticking trial: large enough that the per-impulse cone test never rejects a
/// trial with j_n > 0, finite so that chapter 3's input check and guards apply unchanged.
inline constexpr double kUnboundedTrialFriction = 1e6;

// [stage_spec]
/// What distinguishes one impulse stage from another.
struct StageSpec {
  Lookahead lookahead = Lookahead::Current;
  int sweeps = 0;          ///< at most this many sweeps; a sweep with no impulse ends the stage
  int pairIterations = 1;  ///< at most this many impulses per pair per sweep
  /// Restitution for sweep k (1-based) of the pair: the pair's own e in the collision
  /// stage, the ramp e_k in the contact stage.
  std::function<double(int sweep, const PairMaterial&)> restitution;
  /// The friction effect: on, the frictional impulse of chapter 3 with the pair's mu; off,
  /// the frictionless impulse of chapter 2 (what chapter 3 returns for mu = 0, bit for bit).
  bool friction = true;
  /// The rolling-friction effect (Eq. (8.7)): after a sticking impulse, damp the relative
  /// rolling and spinning by the pair's rolling coefficient.
  bool rollingFriction = false;
  /// The step's contact ledger under FrictionConeRule::StepTotal (Eq. (8.13)); nullptr:
  /// GBF's cone on each impulse alone.
  ContactLedger* ledger = nullptr;
  /// Where to record each applied impulse (chapter 10's contacts output), tagged `stage`;
  /// nullptr (the default): nothing is recorded.
  ContactRecorder* recorder = nullptr;
  ContactStage stage = ContactStage::Contact;
  /// End a pair's loop after an impulse of magnitude at most this fraction of the visit's
  /// first one (>= 0; 0: only separation or the cap end it, GBF). Chapter 8, "Ending the loops".
  double pairImpulseTolerance = 0.0;
  /// runImpulseStage() and the shock pass: a sweep whose largest approach speed
  /// -u_rel . N at the samples it acted on was at most this (m/s, >= 0) ends the stage or
  /// level (0: only a sweep without impulses does, GBF).
  double stageApproachTolerance = 0.0;
  /// When set, resolvePair() raises it to the largest approach speed it acted on.
  double* largestApproach = nullptr;
};
// [stage_spec]

// [apply_patch_impulse]
/// The sticking patch in a pair visit (chapter 8, "A whole patch at once"): the samples that
/// share the chosen sample `s`'s normal, turned to its owner, form the patch; if friction and
/// the patch can carry the impulse that stops the pair's whole relative twist (Eq. (8.16)),
/// it is applied (+J, +L to the owner at the patch mean, -J, -L to the other), recorded and
/// counted, and |J| is returned; otherwise nothing changes and -1 is returned. Kept out of
/// line so that GBF's loop, which never takes it, keeps its own code as it was.
template <int D>
[[gnu::noinline]] double applyPatchImpulse(World<D>& world, const std::vector<CollisionBody<D>>& views,
                                           const BodyPair& pair, const InterferenceSample<D>& s,
                                           const std::vector<InterferenceSample<D>>& samples, double e, double mu,
                                           const StageSpec& spec, const StepSettings& settings,
                                           StageCounters& counters) {
  thread_local std::vector<Vec<D>> patch;  // reused, as the pair loop's buffers are
  patch.clear();
  // Points, centres and normal where the views measure lever arms (Eq. (8.22)): at the tested
  // poses, or each point carried back with its owner to the poses at the start of the step.
  const bool atStart = views[static_cast<std::size_t>(s.owner)].arms == LeverArms::AtStartPose;
  for (const InterferenceSample<D>& m : samples) {
    const double sign = m.owner == s.owner ? 1.0 : -1.0;  // turned to the chosen sample's owner
    if (!(sign * m.normal.dot(s.normal) >= settings.impulsePoint.normalCosine)) continue;
    const CollisionBody<D>& carrier = views[static_cast<std::size_t>(m.owner)];
    patch.push_back(atStart ? Vec<D>(carrier.body->position + carrier.leverArm(m.point)) : m.point);
  }
  RigidBody<D>& owner = world.bodies[static_cast<std::size_t>(s.owner)];
  RigidBody<D>& other = world.bodies[static_cast<std::size_t>(s.other)];
  const Vec<D> xo = atStart ? owner.position : views[static_cast<std::size_t>(s.owner)].pose.position;
  const Vec<D> xb = atStart ? other.position : views[static_cast<std::size_t>(s.other)].pose.position;
  const Vec<D> normal = views[static_cast<std::size_t>(s.other)].carriedDirection(s.normal);
  const std::optional<PatchImpulse<D>> weld = stickingPatchImpulse<D>(owner, xo, other, xb, patch, normal, e, mu);
  if (!weld) return -1.0;
  owner.applyImpulse(weld->point - xo, weld->J);
  owner.applyAngularImpulse(weld->L);
  other.applyImpulse(weld->point - xb, -weld->J);
  other.applyAngularImpulse(-weld->L);
  if (spec.ledger != nullptr) spec.ledger->record<D>(pair, s.owner, weld->J, normal);
  if (spec.recorder != nullptr) {
    spec.recorder->record<D>(spec.stage, s.owner, s.other, weld->pressure, normal, weld->J);
  }
  counters.countImpulse(ImpulseBranch::Sticking);
  ++counters.patchImpulses;
  return weld->J.norm();
}
// [apply_patch_impulse]

// [pair_impulse]
/// The impulse loop for one pair: at most spec.pairIterations times, detect interference
/// at the tested poses (views), take the deepest approaching sample (chapter 7) or the
/// centre of the samples that share its normal (settings.impulsePoint), and apply
/// the frictional impulse of chapter 3 to the bodies' current velocities; then re-predict
/// the two bodies so the next detection sees the effect. Returns the number of impulses.
///
/// Lever arms: r is measured from each body's centre at its *tested* pose to the sample
/// point at that pose (Eq. (8.3)), and u_rel = u_owner(r_owner) - u_other(r_other) uses the
/// current v and omega. PhysBAM instead maps the sample back to the pose at the start of
/// the step and evaluates r, N and u there. We keep point, normal and lever arm from one
/// configuration, the one where the interference was found: then the impulse's torque
/// is the torque about the centre that the detected geometry implies, it is the same
/// u_rel as chapter 7's deepestApproachingSample() used to pick the sample, and the
/// difference from PhysBAM's choice is O(dt |omega| |r|) and vanishes with dt.
template <int D>
int resolvePair(World<D>& world, std::vector<CollisionBody<D>>& views, const BodyPair& pair,
                const StageSpec& spec, int sweep, double dt, const StepSettings& settings,
                StageCounters& counters, PairCandidateLists<D>* lists = nullptr) {
  int applied = 0;
  // The candidates of the lazy deepest-sample search, kept across calls (one buffer per
  // thread), so that a pair query allocates nothing once the buffer has grown.
  thread_local std::vector<InterferenceCandidate<D>> scratch;
  thread_local std::vector<InterferenceSample<D>> samples;  // the centre rule's, reused likewise
  double firstImpulse = 0.0;  // |j| of the visit's first impulse (pairImpulseTolerance)
  // Tied samples land together (Eq. (12.7)).
  const bool landing = settings.impulsePoint.tiedLanding;
  const TiedLanding ties{settings.impulsePoint.tieTolerance, settings.impulsePoint.normalCosine};
  // An exact deepest point (chapter 11) is found by pairInterference() alone.
  const bool exactPair = pairAsksDeepestPoint<D>(settings.detection.narrow, *views[static_cast<std::size_t>(pair.first)].shape,
                                                 *views[static_cast<std::size_t>(pair.second)].shape);
  // After each impulse of size `magnitude`: re-predict the pair, and say whether the visit
  // has converged.
  const auto repredict = [&](int iteration, double magnitude) {
    // Re-predict the pair's dynamic bodies. A static body's tested pose cannot change (no
    // impulse moves it), so it is left alone: the views of static bodies stay constant
    // for the whole sweep, which is what lets islands run at the same time (chapter 10).
    if (!world.bodies[static_cast<std::size_t>(pair.first)].isStatic()) {
      views[static_cast<std::size_t>(pair.first)].setPose(
          testedPose<D>(world, pair.first, spec.lookahead, dt, settings.rotation));
    }
    if (!world.bodies[static_cast<std::size_t>(pair.second)].isStatic()) {
      views[static_cast<std::size_t>(pair.second)].setPose(
          testedPose<D>(world, pair.second, spec.lookahead, dt, settings.rotation));
    }
    // [pair_converged]
    // The loop has converged when an impulse is a small fraction of the visit's first one
    // (chapter 8, "Ending the loops"); off (0), GBF's loop runs to separation or the cap.
    if (spec.pairImpulseTolerance > 0.0) {
      if (iteration == 0) {
        firstImpulse = magnitude;
      } else if (magnitude <= spec.pairImpulseTolerance * firstImpulse) {
        ++counters.pairConvergences;
        return true;
      }
    }
    // [pair_converged]
    return false;
  };
  for (int iteration = 0; iteration < spec.pairIterations; ++iteration) {
    // GBF's rule needs normals only until the deepest approaching sample is found: the
    // lazy search picks the same sample with the same bits (chapter 7). The centre rule
    // needs every sample's normal; it asks through the same candidate lists, which give
    // pairInterference()'s samples with the same bits. The exact deepest points of chapter
    // 11 are found by pairInterference() alone.  // [pair_deepest_impulse]
    std::optional<InterferenceSample<D>> point;
    if (exactPair) {
      point = impulsePoint<D>(pairInterference<D>(views, pair, settings.detection.narrow, &counters.detection),
                              views, settings.impulsePoint, &counters.detection);  // Eqs. (7.6), (8.10)
    } else if (settings.impulsePoint.rule == ImpulsePointRule::Deepest) {
      point = deepestApproachingInPair<D>(views, pair, settings.detection.narrow, &counters.detection, scratch, lists,
                                          landing ? &ties : nullptr);  // Eqs. (7.6), (12.7)
    } else {
      pairInterferenceListed<D>(views, pair, settings.detection.narrow, &counters.detection, scratch, samples, lists);
      point = impulsePoint<D>(samples, views, settings.impulsePoint, &counters.detection);  // Eq. (8.10)
      if (point && landing && settings.impulsePoint.rule == ImpulsePointRule::StickingPatch) {
        point = tiedLandingPoint<D>(*point, samples, views, ties);  // Eq. (12.7)
      }
    }
    if (!point) return applied;
    if (landing && !exactPair && point->sampleIndex < 0 &&
        settings.impulsePoint.rule != ImpulsePointRule::DepthWeightedCentre) {
      ++counters.tiedLandings;
    }
    const InterferenceSample<D>& s = *point;
    RigidBody<D>& owner = world.bodies[static_cast<std::size_t>(s.owner)];
    RigidBody<D>& other = world.bodies[static_cast<std::size_t>(s.other)];
    // [pair_lever_arms]
    // Lever arms and normal where the views measure them: at the tested pose (Eq. (8.3)) or
    // carried back to the pose at the start of the step (Eq. (8.22)).
    const bool carried = s.isBodyPoint();  // an exact deepest point keeps Eq. (8.3)
    const Vec<D> rOwner = views[static_cast<std::size_t>(s.owner)].leverArm(s.point, carried);  // Eq. (8.3)
    const Vec<D> rOther = views[static_cast<std::size_t>(s.other)].leverArm(s.point, carried);
    const Vec<D> normal = views[static_cast<std::size_t>(s.other)].carriedDirection(s.normal, carried);
    // [pair_lever_arms]
    const Mat<D> K = pairCollisionMatrix<D>(owner, rOwner, other, rOther);  // Eq. (1.10)
    const Vec<D> u = relativeVelocity<D>(owner, rOwner, other, rOther);     // Eq. (8.3)
    if (spec.largestApproach != nullptr) {
      *spec.largestApproach = std::max(*spec.largestApproach, -u.dot(normal));
    }
    const PairMaterial material = world.pairMaterial(s.owner, s.other);     // Eq. (8.4)
    const double e = spec.restitution(sweep, material);
    // [pair_patch_impulse]
    // The sticking patch (Eq. (8.16)) is tried first; if it holds, it is the visit's impulse.
    if (settings.impulsePoint.rule == ImpulsePointRule::StickingPatch && spec.friction && !exactPair) {
      const double welded = applyPatchImpulse<D>(world, views, pair, s, samples, e, material.friction, spec,
                                                 settings, counters);
      if (welded >= 0.0) {
        ++applied;
        if (repredict(iteration, welded)) return applied;
        continue;
      }
    }
    // [pair_patch_impulse]
    ContactImpulse<D> impulse;  // [pair_deepest_impulse]
    if (spec.friction) {
      ++counters.frictionEvaluations;
      impulse = frictionalImpulse<D>(K, u, normal, e, material.friction, settings.friction);
      // [pair_step_cone]
      // One cone per step (Eq. (8.13)): a sticking trial this impulse alone would reject is
      // taken when the pair's total impulse of the step stays inside the cone. The trial is
      // chapter 3's, with its energy guard; only the per-impulse cone test is lifted.
      if (spec.ledger != nullptr && impulse.branch == ImpulseBranch::Sliding) {
        ++counters.frictionEvaluations;
        const ContactImpulse<D> trial = frictionalImpulse<D>(
            K, u, normal, e, kUnboundedTrialFriction, settings.friction);
        if (trial.branch == ImpulseBranch::Sticking &&
            spec.ledger->admits<D>(pair, s.owner, trial.j, normal, material.friction)) {
          impulse = trial;
          impulse.friction = material.friction;
          ++counters.stepConeSticks;
        }
      }
      // [pair_step_cone]
    } else {
      impulse = frictionlessImpulse<D>(K, u, normal, e, settings.friction.pivotTolerance);
    }
    if (impulse.j.isZero(0.0)) return applied;  // immovable or no response: nothing to iterate
    applyPairImpulse<D>(owner, rOwner, other, rOther, impulse.j);  // +j owner, -j other
    if (spec.ledger != nullptr) spec.ledger->record<D>(pair, s.owner, impulse.j, normal);
    if (spec.recorder != nullptr) {
      spec.recorder->record<D>(spec.stage, s.owner, s.other, s.point, normal, impulse.j);
    }
    counters.countImpulse(impulse.branch);
    if (impulse.restitution > 0.0) ++counters.elasticImpulses;
    // [pair_rolling]
    // Rolling and spinning friction act only after a sticking impulse, and only when the
    // effect runs and the pair's coefficient is positive: with mu_r = 0 nothing here runs,
    // so the trajectory is bit for bit the one without the effect (Eqs. (8.6)-(8.7)).
    if (spec.rollingFriction && material.rollingFriction > 0.0 &&
        impulse.branch == ImpulseBranch::Sticking) {
      const RollingFrictionImpulse<D> rolling = rollingFrictionImpulse<D>(
          owner, rOwner, other, rOther, normal, impulse.j.dot(normal), material.rollingFriction);
      if (!rolling.isZero()) {
        applyRollingFriction<D>(owner, rOwner, other, rOther, rolling);
        ++counters.rollingImpulses;
      }
    }
    // [pair_rolling]
    ++applied;
    if (repredict(iteration, impulse.j.norm())) return applied;
  }
  ++counters.pairIterationCapHits;
  return applied;
}
// [pair_impulse]

// [stage_views]
/// The collision view of every body at its tested pose under `lookahead`, measuring lever
/// arms as `arms` says (Eq. (8.22)); with `heldSamples` and the collision stage's lookahead,
/// each view also keeps its load drop dt^2 a (Eq. (12.6)). Each view depends on its own body
/// only, so blocks of bodies are built on several threads (settings.bodiesPerTask per block
/// at least) with the same result.
template <int D>
std::vector<CollisionBody<D>> stageViews(const World<D>& world, Lookahead lookahead, double dt,
                                         RotationUpdate rotation = RotationUpdate::ExponentialMap,
                                         const ParallelSettings& parallel = {1, 16, 256, 4},
                                         LeverArms arms = LeverArms::AtTestedPose, bool heldSamples = false) {
  std::vector<CollisionBody<D>> views(world.bodies.size());
  const bool drops = heldSamples && lookahead == Lookahead::VelocityAndLoads;
  parallelFor(parallel.threads, views.size(), static_cast<std::size_t>(parallel.bodiesPerTask),
              [&](std::size_t begin, std::size_t end) {
                for (std::size_t k = begin; k < end; ++k) {
                  const int i = static_cast<int>(k);
                  views[k] = collisionBodyAt<D>(world.bodies[k], *world.shapes[k],
                                                testedPose<D>(world, i, lookahead, dt, rotation));
                  views[k].measureArms(arms);
                  if (drops) {  // x' - (x + dt v), Eqs. (8.1), (8.2)
                    views[k].loadDrop = views[k].pose.position - testedPose<D>(world, i, Lookahead::Velocity, dt, rotation).position;
                  }
                }
              });
  return views;
}
// [stage_views]

// [sweep_islands]
/// One sweep with its islands (pairIslands()) run at the same time on up to `threads`
/// threads, each island's pairs in the sweep's order. Each island counts into its own
/// StageCounters, and they are added in island order afterwards, so the counts are the
/// serial sweep's. If pairs throw, the exception of the first of them in the sweep's order
/// is rethrown: the one the serial sweep would have thrown, since the islands before it
/// ran exactly as they would have.
template <int D>
int sweepIslands(World<D>& world, std::vector<CollisionBody<D>>& views,
                 const std::vector<BodyPair>& pairs, const PairIslands& islands,
                 const StageSpec& spec, int sweep, double dt, const StepSettings& settings,
                 StageCounters& counters, int threads, std::vector<PairCandidateLists<D>>* lists = nullptr) {
  const std::size_t count = islands.islandCount();
  // Largest islands first, so that a big island is not started last (ties: island order).
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&islands](std::size_t a, std::size_t b) { return islands.size(a) > islands.size(b); });
  std::vector<StageCounters> local(count);
  std::vector<int> applied(count, 0);
  // A contact recorder wants the impulses in the serial order: each island records into
  // its own, noting the pair of every record, and the records are merged by pair below.
  // The largest approach speed of the loop tolerances (spec.largestApproach) is raised by
  // every pair: each island raises its own, and the maximum of those is the serial one
  // (a maximum does not depend on the order it is taken in).
  const bool recording = spec.recorder != nullptr;
  const bool measuring = spec.largestApproach != nullptr;
  const bool ownSpec = recording || measuring;
  std::vector<StageSpec> islandSpec(ownSpec ? count : 0, spec);
  std::vector<ContactRecorder> recorders(recording ? count : 0);
  std::vector<std::vector<std::size_t>> recordPair(recording ? count : 0);
  std::vector<double> largest(measuring ? count : 0, measuring ? *spec.largestApproach : 0.0);
  for (std::size_t c = 0; c < islandSpec.size(); ++c) {
    if (recording) islandSpec[c].recorder = &recorders[c];
    if (measuring) islandSpec[c].largestApproach = &largest[c];
  }
  std::vector<std::exception_ptr> error(count);
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> errorPair(count, kNone);
  parallelFor(threads, count, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      const std::size_t c = order[k];
      for (std::size_t i = islands.begin[c]; i < islands.begin[c + 1]; ++i) {
        const std::size_t p = islands.pairs[i];
        try {
          ++local[c].pairVisits;
          applied[c] += resolvePair<D>(world, views, pairs[p], ownSpec ? islandSpec[c] : spec, sweep,
                                       dt, settings, local[c], lists != nullptr ? &(*lists)[p] : nullptr);
          if (recording) recordPair[c].resize(recorders[c].size(), p);
        } catch (...) {
          error[c] = std::current_exception();
          errorPair[c] = p;
          break;
        }
      }
    }
  });
  std::size_t firstError = kNone, firstErrorIsland = 0;
  for (std::size_t c = 0; c < count; ++c) {
    if (errorPair[c] < firstError) {
      firstError = errorPair[c];
      firstErrorIsland = c;
    }
  }
  if (firstError != kNone) std::rethrow_exception(error[firstErrorIsland]);
  for (const double l : largest) *spec.largestApproach = std::max(*spec.largestApproach, l);
  if (recording) {  // all of a pair's records are consecutive, and pairs in list order
    std::vector<std::array<std::size_t, 3>> order3;  // (pair, island, index in island)
    for (std::size_t c = 0; c < count; ++c) {
      for (std::size_t r = 0; r < recordPair[c].size(); ++r) order3.push_back({recordPair[c][r], c, r});
    }
    std::sort(order3.begin(), order3.end());
    for (const auto& [p, c, r] : order3) spec.recorder->add(recorders[c].records()[r]);
  }
  ++counters.islandSweeps;
  counters.islands += static_cast<std::int64_t>(count);
  counters.islandPairs += static_cast<std::int64_t>(pairs.size());
  counters.largestIslandPairs += static_cast<std::int64_t>(islands.size(order.front()));
  int total = 0;
  for (std::size_t c = 0; c < count; ++c) {  // island order: the same sums for any thread count
    counters += local[c];
    total += applied[c];
  }
  return total;
}
// [sweep_islands]

// [sweep_colours]
/// One sweep colour by colour (PairOrder::Colours): the classes of `colours` in turn, each in
/// list order. A colour of at least settings.parallel.minPairs pairs is cut into `threads`
/// times parallel.runsPerThread runs of consecutive pairs, which sweepIslands() runs at the
/// same time: the colour's pairs share no dynamic body, so Eq. (10.8) holds for them pair by
/// pair and any split gives the serial colour's result. The overflow class, whose pairs may
/// share bodies, runs in order on this thread, as does every smaller colour.
template <int D>
int sweepColours(World<D>& world, std::vector<CollisionBody<D>>& views, const std::vector<BodyPair>& pairs,
                 const PairColours& colours, const StageSpec& spec, int sweep, double dt,
                 const StepSettings& settings, StageCounters& counters, int threads,
                 std::vector<PairCandidateLists<D>>* lists) {
  const std::size_t minPairs = static_cast<std::size_t>(std::max(settings.parallel.minPairs, 2));
  int applied = 0;
  PairIslands runs;
  for (std::size_t c = 0; c < colours.classCount(); ++c) {
    const std::size_t n = colours.size(c);
    const std::size_t first = colours.begin[c];
    if (threads > 1 && colours.independent(c) && n >= minPairs) {
      const std::size_t perThread = static_cast<std::size_t>(std::max(settings.parallel.runsPerThread, 1));
      const std::size_t parts = std::min(n, static_cast<std::size_t>(threads) * perThread);
      runs.pairs.assign(colours.pairs.begin() + static_cast<std::ptrdiff_t>(first),
                        colours.pairs.begin() + static_cast<std::ptrdiff_t>(first + n));
      runs.begin.resize(parts + 1);
      for (std::size_t r = 0; r <= parts; ++r) runs.begin[r] = r * n / parts;
      applied += sweepIslands<D>(world, views, pairs, runs, spec, sweep, dt, settings, counters, threads, lists);
      continue;
    }
    for (std::size_t i = first; i < first + n; ++i) {
      const std::size_t p = colours.pairs[i];
      ++counters.pairVisits;
      applied += resolvePair<D>(world, views, pairs[p], spec, sweep, dt, settings, counters,
                                lists != nullptr ? &(*lists)[p] : nullptr);
    }
  }
  return applied;
}
// [sweep_colours]

// [sweep_pairs]
/// One sweep over a given list of pairs: resolvePair() on each, in list order. Returns
/// the number of impulses applied. Chapter 9's shock propagation sweeps each level's
/// pairs with this, the stages below sweep the broad phase's pairs. With more than one
/// thread (settings.parallel) and at least settings.parallel.minPairs pairs, the pairs'
/// islands run at the same time (sweepIslands()), which performs the same floating-point
/// operations on the same data as the loop below (chapter 10, Eq. (10.8)). Under
/// PairOrder::Colours the sweep goes colour by colour instead (sweepColours(), Eq. (10.10)).
template <int D>
int sweepPairs(World<D>& world, std::vector<CollisionBody<D>>& views,
               const std::vector<BodyPair>& pairs, const StageSpec& spec, int sweep, double dt,
               const StepSettings& settings, StageCounters& counters,
               std::vector<PairCandidateLists<D>>* lists = nullptr) {
  ++counters.sweeps;
  if (lists != nullptr && lists->size() != pairs.size()) lists->resize(pairs.size());
  const int threads = resolvedThreadCount(settings.parallel.threads);
  if (settings.pairOrder == PairOrder::Colours && pairs.size() > 1) {
    return sweepColours<D>(world, views, pairs, pairColours<D>(world, pairs), spec, sweep, dt, settings,
                           counters, threads, lists);
  }
  if (threads > 1 && pairs.size() >= static_cast<std::size_t>(std::max(settings.parallel.minPairs, 2))) {
    const PairIslands islands = pairIslands<D>(world, pairs);
    if (islands.islandCount() > 1) {
      return sweepIslands<D>(world, views, pairs, islands, spec, sweep, dt, settings, counters, threads, lists);
    }
  }
  int applied = 0;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    ++counters.pairVisits;
    applied += resolvePair<D>(world, views, pairs[p], spec, sweep, dt, settings, counters,
                              lists != nullptr ? &(*lists)[p] : nullptr);
  }
  return applied;
}
// [sweep_pairs]

/// The candidate lists of `pairs` (chapter 7), carried over from the last sweep: the lists
/// of a pair in `previous` (held by `lists`, in the same order) move over, a new pair starts
/// with none. Both pair lists are in the broad phase's sorted (i, j) order, so one merge
/// finds them. The result is built in `spare`, storage kept for the stage, and swapped into
/// `lists`, so that a sweep allocates nothing once both have grown; when the pairs are the
/// last sweep's, `lists` is already the result. Lists change the work of a query, never its
/// answer (CandidateList::covers()), so which list a pair gets affects the time only.
template <int D>
void carryCandidateLists(const std::vector<BodyPair>& previous, const std::vector<BodyPair>& pairs,
                         std::vector<PairCandidateLists<D>>& lists, std::vector<PairCandidateLists<D>>& spare) {
  if (pairs == previous && lists.size() == pairs.size()) return;
  spare.resize(pairs.size());
  std::size_t j = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    while (j < previous.size() && previous[j] < pairs[i]) ++j;
    if (j < previous.size() && j < lists.size() && previous[j] == pairs[i]) {
      std::swap(spare[i], lists[j]);  // the pair's lists; lists[j] takes spare storage
    } else {
      spare[i].firstInSecond.made = spare[i].secondInFirst.made = false;  // keeps the capacity
    }
  }
  std::swap(lists, spare);
}

// [impulse_stage]
/// One stage: up to spec.sweeps sweeps; each sweep finds the overlapping pairs at the
/// tested poses (sweep and prune's list, found once and kept while it answers: KeptBroadPhase,
/// chapter 7; fixed (i, j) order) and runs resolvePair() on each.
/// A sweep that applies no impulse ends the stage. Deterministic: the pair order is the
/// broad phase's sorted order and no unordered container is involved.
template <int D>
void runImpulseStage(World<D>& world, const StageSpec& spec, double dt,
                     const StepSettings& settings, StageCounters& counters) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<CollisionBody<D>> views =
      stageViews<D>(world, spec.lookahead, dt, settings.rotation, settings.parallel, settings.impulsePoint.arms,
                    settings.impulsePoint.heldSamples);
  // The residual test (chapter 8, "Ending the loops"): with a tolerance, a sweep whose
  // fastest approach was at most stageApproachTolerance ends the stage too.
  StageSpec measured = spec;
  double largest = 0.0;
  if (spec.stageApproachTolerance > 0.0) measured.largestApproach = &largest;
  // Candidate lists (chapter 7): the stage starts with the lists the world kept from the
  // last stage, and a pair the broad phase reports again in the next sweep keeps its lists
  // (carryCandidateLists()); at the end the stage's lists go back to the world.
  CandidateListStore<D>& kept = world.candidateLists;
  kept.matchShapes(world.shapes);
  std::vector<BodyPair> previousPairs;
  std::vector<PairCandidateLists<D>> lists, spare;
  previousPairs.swap(kept.pairs);
  lists.swap(kept.lists);
  // The broad phase's pairs at each sweep, found once and kept while they answer (chapter 7).
  KeptBroadPhase<D> broad;
  for (int sweep = 1; sweep <= spec.sweeps; ++sweep) {
    const std::vector<BodyPair> pairs = broad.pairs(views, settings.detection.broad, &counters.detection);
    carryCandidateLists<D>(previousPairs, pairs, lists, spare);
    previousPairs = pairs;
    largest = 0.0;
    if (sweepPairs<D>(world, views, pairs, measured, sweep, dt, settings, counters, &lists) == 0) break;
    if (spec.stageApproachTolerance > 0.0 && largest <= spec.stageApproachTolerance) break;
  }
  if (lists.size() == previousPairs.size()) {  // lists[k] belongs to previousPairs[k]
    kept.pairs.swap(previousPairs);
    kept.lists.swap(lists);
  }
  counters.seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
// [impulse_stage]

// Compiled once, for D = 2 and 3, in the library (src/stackbook/instantiate_step.cpp): a
// translation unit that includes this header links to those instead of compiling its own.
#define STACKBOOK_EXTERN_IMPULSE_STAGE(D)                                                  \
  extern template int resolvePair<D>(World<D>&, std::vector<CollisionBody<D>>&, const BodyPair&, \
                                     const StageSpec&, int, double, const StepSettings&,        \
                                     StageCounters&, PairCandidateLists<D>*);                    \
  extern template std::vector<CollisionBody<D>> stageViews<D>(const World<D>&, Lookahead, double, \
                                                              RotationUpdate, const ParallelSettings&, LeverArms, bool); \
  extern template int sweepPairs<D>(World<D>&, std::vector<CollisionBody<D>>&,                  \
                                    const std::vector<BodyPair>&, const StageSpec&, int, double, \
                                    const StepSettings&, StageCounters&,                        \
                                    std::vector<PairCandidateLists<D>>*);                       \
  extern template void runImpulseStage<D>(World<D>&, const StageSpec&, double,                  \
                                          const StepSettings&, StageCounters&);
STACKBOOK_EXTERN_IMPULSE_STAGE(2)
STACKBOOK_EXTERN_IMPULSE_STAGE(3)
#undef STACKBOOK_EXTERN_IMPULSE_STAGE

}  // namespace stackbook
