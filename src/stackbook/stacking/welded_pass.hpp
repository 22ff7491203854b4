#pragma once
/// \file
/// \brief The welded pass (chapter 9, "The welded pass"): GBF's contact stage runs as in GBF's
/// step, so loads reach lower bodies; then every body goes back to its velocity before that
/// stage, receives the stage's impulses from the bodies above it (Eq. (9.11)), is welded to
/// supporters at rest when friction and the patch can hold it (Eq. (9.12)), and the pass as
/// the contact stage finishes the level sweeps. An energy guard keeps GBF's own pass whenever
/// it leaves less kinetic energy (Eq. (9.14)).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "stackbook/impulse/patch_impulse.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stepping/traditional_step.hpp"

namespace stackbook {

// [carried_loads]
/// Eq. (9.11): every dynamic body back to its velocities in `before` (the bodies as the contact
/// stage found them), plus each contact-stage impulse (a record of stage Contact in
/// `impulses`) that it received from a partner at a higher level of `levels`: +j for the
/// record's owner, -j for its other body, at the record's point, the lever arm measured from
/// the body's centre at the start of the step. An impulse between bodies of one level, from
/// below, or with a static partner is not carried: the pass resolves those contacts itself.
/// Returns the number of impulses carried. O(bodies + records).
template <int D>
std::int64_t carryLoads(World<D>& world, const std::vector<RigidBody<D>>& before, const ContactRecorder& impulses,
                        const ContactLevels& levels) {
  for (std::size_t k = 0; k < world.bodies.size(); ++k) {
    RigidBody<D>& b = world.bodies[k];
    if (b.isStatic()) continue;
    b.velocity = before[k].velocity;
    b.angularMomentum = before[k].angularMomentum;
    b.angularVelocity = before[k].angularVelocity;
  }
  std::int64_t carried = 0;
  const auto give = [&](int body, int partner, const Vec<D>& point, const Vec<D>& j) {
    RigidBody<D>& b = world.bodies[static_cast<std::size_t>(body)];
    if (b.isStatic() || world.bodies[static_cast<std::size_t>(partner)].isStatic()) return;
    if (levels.levelOfBody[static_cast<std::size_t>(partner)] <= levels.levelOfBody[static_cast<std::size_t>(body)]) {
      return;
    }
    b.applyImpulse(Vec<D>(point - b.position), j);  // the load from above
    ++carried;
  };
  for (const ContactRecord& r : impulses.records()) {
    if (r.stage != ContactStage::Contact) continue;
    Vec<D> point, j;
    for (int c = 0; c < D; ++c) {
      point[c] = r.point[static_cast<std::size_t>(c)];
      j[c] = r.impulse[static_cast<std::size_t>(c)];
    }
    give(r.owner, r.other, point, j);
    give(r.other, r.owner, point, Vec<D>(-j));
  }
  return carried;
}
// [carried_loads]

// [body_welds]
/// Eq. (9.12), bottom up over `levels`: a dynamic body whose supporters in `graph` at lower
/// levels (or static) are all at rest (static, or welded earlier in this call) is welded to
/// them: at the poses x + dt v, the interference samples of those pairs that approach (the
/// supporters at rest) give the deepest one's normal n, the samples whose normal turned to the
/// body is within settings.impulsePoint.normalCosine of n form the patch, and chapter 8's
/// sticking patch against a static partner (stickingPatchImpulse() with friction the least mu
/// of the pairs and the spin test `spinBound`) stops the body in one impulse if friction and
/// the patch can carry it. A body with a supporter still moving, with no approaching sample,
/// or whose patch cannot carry the stop is left to the pass. Each weld is recorded (stage
/// Shock, against the lowest-numbered supporter) when `recorder` is set. Returns, per body,
/// 1 if it was welded.
template <int D>
std::vector<char> bodyWelds(World<D>& world, const ContactGraph& graph, const ContactLevels& levels,
                            const StepSettings& settings, PatchSpinBound spinBound, WeldedCounters& counters,
                            ContactRecorder* recorder) {
  std::vector<CollisionBody<D>> views = stageViews<D>(world, Lookahead::Velocity, settings.dt, settings.rotation);
  const std::size_t n = world.bodies.size();
  std::vector<char> atRest(n, 0), welded(n, 0);
  for (std::size_t k = 0; k < n; ++k) atRest[k] = world.bodies[k].isStatic() ? 1 : 0;
  const RigidBody<D> ground;  // the supporters at rest, as one static partner
  std::vector<int> supporters;
  std::vector<Vec<D>> points, normals;  // samples of the body's supporting pairs, normals turned to the body
  std::vector<Vec<D>> patch;
  for (std::size_t l = 0; l < levels.levelCount(); ++l) {
    for (const int b : levels.bodies(l)) {
      RigidBody<D>& body = world.bodies[static_cast<std::size_t>(b)];
      if (body.isStatic()) continue;
      supporters.clear();
      bool resting = true;
      for (const int a : graph.parents(b)) {
        const std::size_t ka = static_cast<std::size_t>(a);
        if (!world.bodies[ka].isStatic() && levels.levelOfBody[ka] >= static_cast<int>(l)) continue;
        supporters.push_back(a);
        resting = resting && atRest[ka] != 0;
      }
      if (supporters.empty() || !resting) continue;
      points.clear();
      normals.clear();
      double mu = std::numeric_limits<double>::infinity();
      double deepest = std::numeric_limits<double>::infinity();
      int chosen = -1;
      const Vec<D>& xb = views[static_cast<std::size_t>(b)].pose.position;
      for (const int a : supporters) {
        mu = std::min(mu, world.pairMaterial(b, a).friction);
        for (const InterferenceSample<D>& m : pairInterference<D>(views, BodyPair{a, b}, settings.detection.narrow)) {
          const Vec<D> nb = m.owner == b ? m.normal : Vec<D>(-m.normal);
          points.push_back(m.point);
          normals.push_back(nb);
          if (body.pointVelocity(Vec<D>(m.point - xb)).dot(nb) < 0.0 && m.depth < deepest) {
            deepest = m.depth;
            chosen = static_cast<int>(points.size()) - 1;
          }
        }
      }
      if (chosen < 0) continue;  // nothing approaches: the pass has nothing to stop here
      ++counters.weldTries;
      const Vec<D> n0 = normals[static_cast<std::size_t>(chosen)];
      patch.clear();
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (normals[i].dot(n0) >= settings.impulsePoint.normalCosine) patch.push_back(points[i]);
      }
      const std::optional<PatchImpulse<D>> weld =
          stickingPatchImpulse<D>(body, xb, ground, xb, patch, n0, 0.0, mu, spinBound);
      if (!weld) continue;
      body.applyImpulse(Vec<D>(weld->point - xb), weld->J);
      body.applyAngularImpulse(weld->L);
      if (recorder != nullptr) recorder->record<D>(ContactStage::Shock, b, supporters.front(), weld->pressure, n0, weld->J);
      atRest[static_cast<std::size_t>(b)] = welded[static_cast<std::size_t>(b)] = 1;
      ++counters.welds;
      views[static_cast<std::size_t>(b)].setPose(testedPose<D>(world, b, Lookahead::Velocity, settings.dt, settings.rotation));
    }
  }
  return welded;
}
// [body_welds]

// [welded_pass_settings]
/// The settings the welded pass sweeps its levels with: `settings` as the pass as the contact
/// stage (Eq. (9.9): every level swept, unpressed contacts included) with the loops, impulse
/// point and step cone (Eq. (8.13)) of settings.shock.welded.
inline StepSettings weldedPassSweepSettings(StepSettings settings) {
  const WeldedPassSettings& w = settings.shock.welded;
  settings.shock.replacesContactStage = true;
  settings.shock.passes = 1;
  settings.shock.sweepsPerLevel = w.sweepsPerLevel;
  settings.shock.pairIterations = w.pairIterations;
  settings.shock.pairImpulseTolerance = w.pairImpulseTolerance;
  settings.shock.levelApproachTolerance = w.levelApproachTolerance;
  settings.shock.restitution.clear();  // the ramp e_l = -1 + l / sweepsPerLevel
  settings.impulsePoint.rule = w.impulsePoint;
  settings.frictionCone = FrictionConeRule::StepTotal;
  return settings;
}
// [welded_pass_settings]

// [coupled_islands]
/// The islands of dynamic bodies that `edges` and the records of `impulses` couple (a static
/// body couples nothing): island[k] is the smallest index of body k's island, -1 for a static
/// body. Union-find with path halving, O((n + m) alpha(n)).
template <int D>
std::vector<int> coupledIslands(const World<D>& world, const std::vector<ContactPair>& edges,
                                const ContactRecorder& impulses) {
  const std::size_t n = world.bodies.size();
  std::vector<int> root(n);
  for (std::size_t k = 0; k < n; ++k) root[k] = static_cast<int>(k);
  const auto find = [&root](int k) {
    while (root[static_cast<std::size_t>(k)] != k) {
      root[static_cast<std::size_t>(k)] = root[static_cast<std::size_t>(root[static_cast<std::size_t>(k)])];
      k = root[static_cast<std::size_t>(k)];
    }
    return k;
  };
  const auto join = [&](int a, int b) {
    if (world.bodies[static_cast<std::size_t>(a)].isStatic() || world.bodies[static_cast<std::size_t>(b)].isStatic()) return;
    const int ra = find(a), rb = find(b);
    if (ra != rb) root[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);  // the smaller index leads
  };
  for (const ContactPair& c : edges) join(c.below, c.above);
  for (const ContactRecord& r : impulses.records()) join(r.owner, r.other);
  std::vector<int> island(n, -1);
  for (std::size_t k = 0; k < n; ++k) {
    if (!world.bodies[k].isStatic()) island[k] = find(static_cast<int>(k));
  }
  return island;
}
// [coupled_islands]

// [welded_pass]
/// The welded pass, run as the post-contact hook on the velocities the contact stage left:
/// `before` holds the bodies as the contact stage found them and `impulses` the impulses of
/// that stage. With the guard on, GBF's pass (settings.shock) first runs on a copy of the
/// world. Then the contact graph and its levels (Eq. (9.1)) are built from the velocities
/// `before` (unpressed contacts included, Eq. (9.9)), the loads are carried (Eq. (9.11)), the
/// bodies welded (Eq. (9.12)) and the levels swept (weldedPassSweepSettings()). The guard
/// (Eq. (9.14)) then decides island by island (coupledIslands() of every graph either pass
/// built and of the contact stage's impulses): an island keeps the welded pass's velocities
/// only if one of its bodies was welded and its kinetic energy is at most what GBF's pass left
/// it; otherwise it takes the copy's. Records go to settings.contactRecorder (the welded pass's
/// for the islands that keep it, then GBF's for the others); work to counters.shock (both
/// passes) and counters.welded; counters.contactLedger is the welded pass's.
template <int D>
void weldedPass(World<D>& world, const std::vector<RigidBody<D>>& before, const ContactRecorder& impulses,
                const StepSettings& settings, StepCounters& counters, Layering layering = Layering::Topological) {
  const WeldedPassSettings& w = settings.shock.welded;
  ContactRecorder* const out = settings.contactRecorder;
  ++counters.welded.passes;
  std::vector<ContactPair> edges;  // every graph either pass builds: what may couple two bodies
  // Eq. (9.14): GBF's own pass on a copy, as GBF's step would run it.
  std::optional<World<D>> gbf;
  ContactRecorder gbfRecords;
  if (w.energyGuard) {
    gbf.emplace(world);
    StepSettings g = settings;
    g.shock.welded.enabled = false;
    g.contactRecorder = out != nullptr ? &gbfRecords : nullptr;
    ContactLedger gbfLedger = counters.contactLedger;
    shockPropagation<D>(*gbf, g, counters.shock, layering,
                        g.frictionCone == FrictionConeRule::StepTotal ? &gbfLedger : nullptr, &edges);
  }
  // The graph of the motion the contact stage started from.
  const StepSettings sweeps = weldedPassSweepSettings(settings);
  const Effects effects = resolveEffects<D>(world, settings.effects);
  const ContactGraphSettings graphSettings = stepGraphSettings(settings, effects);
  std::vector<RigidBody<D>> after = world.bodies;
  for (std::size_t k = 0; k < world.bodies.size(); ++k) {
    if (!world.bodies[k].isStatic()) world.bodies[k] = before[k];
  }
  ContactGraph graph = worldContactGraph<D>(world, graphSettings, &counters.shock.detection);
  graph = withUnpressedContacts<D>(world, graph, graphSettings, &counters.shock.detection);
  world.bodies.swap(after);
  const ContactLevels levels = layering == Layering::Topological ? topologicalLevels(graph) : bfsDepthLevels(graph);
  const std::vector<ContactPair> built = graph.edges();
  edges.insert(edges.end(), built.begin(), built.end());
  // Eqs. (9.11) and (9.12), then the level sweeps.
  counters.welded.carriedLoads += carryLoads<D>(world, before, impulses, levels);
  ContactRecorder weldedRecords;
  StepSettings passSettings = sweeps;
  passSettings.contactRecorder = out != nullptr ? &weldedRecords : nullptr;
  std::vector<char> welded(world.bodies.size(), 0);
  if (w.bodyWelds) {
    welded = bodyWelds<D>(world, graph, levels, sweeps, w.weldSpinBound, counters.welded, passSettings.contactRecorder);
  }
  ContactLedger ledger;  // the pass's own cone, Eq. (8.13)
  shockPropagation<D>(world, passSettings, counters.shock, layering, &ledger, &edges);
  counters.contactLedger = ledger;
  // Eq. (9.14), island by island.
  std::vector<char> keepsGbf(world.bodies.size(), 0);  // by island leader
  if (gbf) {
    const std::vector<int> island = coupledIslands<D>(world, edges, impulses);
    const std::size_t n = world.bodies.size();
    std::vector<char> anyWeld(n, 0), leader(n, 0);
    std::vector<double> weldedEnergy(n, 0.0), gbfEnergy(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      if (island[k] < 0) continue;
      const std::size_t i = static_cast<std::size_t>(island[k]);
      leader[i] = 1;
      anyWeld[i] = static_cast<char>(anyWeld[i] | welded[k]);
      weldedEnergy[i] += world.bodies[k].kineticEnergy();
      gbfEnergy[i] += gbf->bodies[k].kineticEnergy();
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (leader[i] == 0) continue;
      ++counters.welded.islands;
      if (anyWeld[i] == 0 || gbfEnergy[i] < weldedEnergy[i]) {
        keepsGbf[i] = 1;
        ++counters.welded.gbfIslands;
      }
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (island[k] < 0 || keepsGbf[static_cast<std::size_t>(island[k])] == 0) continue;
      RigidBody<D>& b = world.bodies[k];
      const RigidBody<D>& g = gbf->bodies[k];
      b.velocity = g.velocity;
      b.angularMomentum = g.angularMomentum;
      b.angularVelocity = g.angularVelocity;
    }
    if (out != nullptr) {
      const auto kept = [&](const ContactRecord& r, bool fromGbf) {
        const int body = world.bodies[static_cast<std::size_t>(r.owner)].isStatic() ? r.other : r.owner;
        const int i = island[static_cast<std::size_t>(body)];
        return i >= 0 && (keepsGbf[static_cast<std::size_t>(i)] != 0) == fromGbf;
      };
      for (const ContactRecord& r : weldedRecords.records()) {
        if (kept(r, false)) out->add(r);
      }
      for (const ContactRecord& r : gbfRecords.records()) {
        if (kept(r, true)) out->add(r);
      }
    }
  } else if (out != nullptr) {
    for (const ContactRecord& r : weldedRecords.records()) out->add(r);
  }
}
// [welded_pass]

// [welded_pass_preset]
/// The preset "weldedPass" (chapter 9, "The welded pass"), from `base`: base's step (GBF's
/// loops when the preset is applied by name) with the welded pass, WeldedPassSettings'
/// defaults, in place of GBF's pass. An island where nothing welds then ends the step exactly
/// as GBF's step would.
inline StepSettings gbfStepWeldedPass(StepSettings base = {}) {
  base.shock.welded = WeldedPassSettings{};
  base.shock.welded.enabled = true;
  return base;
}
// [welded_pass_preset]

// [welded_pass_step]
/// GBF's step (gbfStep()) with the welded pass as its post-contact hook: the bodies are kept
/// after the velocity update, the contact stage's impulses recorded, and weldedPass() run
/// after the contact stage. Same stages, effects, sleeping and quarantine as gbfStep(); the
/// welded pass runs when the shockPropagation effect does.
template <int D>
StepCounters weldedPassStep(World<D>& world, const StepSettings& settings, Layering layering) {
  thread_local std::vector<RigidBody<D>> before;  // kept between steps with their capacity
  thread_local ContactRecorder stages;            // the collision and contact stages' impulses
  stages.clear();
  StepSettings recorded = settings;
  recorded.contactRecorder = &stages;
  ContactRecorder* const out = settings.contactRecorder;
  std::size_t forwarded = 0;  // records of `stages` already passed on to `out`
  const auto forward = [&]() {
    if (out == nullptr) return;
    for (; forwarded < stages.size(); ++forwarded) out->add(stages.records()[forwarded]);
  };
  const PreContactHook<D> keep = [](const World<D>& w) { before = w.bodies; };
  const PostContactHook<D> pass = [&](World<D>& w, const StepSettings&, StepCounters& counters) {
    forward();  // the stages' impulses come first, then the pass's
    weldedPass<D>(w, before, stages, settings, counters, layering);
  };
  const StepCounters counters = gbfStep<D>(world, recorded, pass, keep);
  forward();  // a step whose hook did not run
  return counters;
}
// [welded_pass_step]

// [scene_step]
/// The step a scene runs (chapter 10, `stackbook run`): with GBF's order and the welded pass on
/// (the preset weldedPass, chapter 9), weldedPassStep(); otherwise step() in the scene's
/// order with `hook` (shock propagation). The traditional order ignores the welded pass.
template <int D>
StepCounters sceneStep(World<D>& world, const StepSettings& settings, const PostContactHook<D>& hook) {
  if (settings.order == StepOrder::Gbf && settings.shock.welded.enabled) {
    return weldedPassStep<D>(world, settings, Layering::Topological);
  }
  return step<D>(world, settings, hook);
}
// [scene_step]

}  // namespace stackbook
