#pragma once
/// \file
/// \brief What one time step did (chapter 8): impulses per stage and per branch, sweeps
/// used, detection work and wall time per stage. Counters for reports and benchmarks,
/// never conditions the step depends on.

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "stackbook/collision/detection_counters.hpp"
#include "stackbook/impulse/contact_impulse.hpp"
#include "stackbook/stepping/contact_ledger.hpp"
#include "stackbook/stepping/effects.hpp"

namespace stackbook {

// [stage_counters]
/// The work of one impulse stage (collision or contact).
struct StageCounters {
  std::int64_t sweeps = 0;           ///< sweeps over the pairs actually run
  std::int64_t pairVisits = 0;       ///< (sweep, pair) visits
  std::int64_t impulses = 0;         ///< impulses applied (all branches)
  std::int64_t frictionless = 0;     ///< of those: normal only (mu = 0)
  std::int64_t sticking = 0;         ///< of those: static friction
  std::int64_t sliding = 0;          ///< of those: kinetic friction
  std::int64_t pairIterationCapHits = 0;  ///< pair loops stopped by the cap, not by separation
  std::int64_t pairConvergences = 0;      ///< pair loops ended by the impulse tolerance
  std::int64_t frictionEvaluations = 0;   ///< calls of the frictional impulse (friction effect on)
  std::int64_t elasticImpulses = 0;       ///< impulses applied with e > 0 (restitution effect on)
  std::int64_t rollingImpulses = 0;       ///< rolling/spinning friction impulses applied
  std::int64_t stepConeSticks = 0;        ///< of the sticking ones: admitted by the step's cone only
  std::int64_t patchImpulses = 0;         ///< of the sticking ones: whole patches (chapter 8, Eq. (8.16))
  std::int64_t tiedLandings = 0;          ///< impulses at the centre of tied samples (Eq. (12.7))
  std::int64_t uncarried = 0;  ///< shock pass: bodies that did not carry their load (chapter 12, Eq. (12.4))
  /// Threads (chapter 10): sweeps that ran as islands on several threads, the islands of
  /// those sweeps, and the pairs of the largest island of each (its share of the sweep's
  /// pairs bounds what threads can buy). Zero with one thread; the only counts here that
  /// depend on the thread count.
  std::int64_t islandSweeps = 0;
  std::int64_t islands = 0;
  std::int64_t islandPairs = 0;         ///< pairs of those sweeps
  std::int64_t largestIslandPairs = 0;  ///< summed over those sweeps
  DetectionCounters detection;       ///< broad and narrow phase work
  double seconds = 0.0;              ///< wall time (std::chrono::steady_clock)

  /// Count one applied impulse by its branch.
  void countImpulse(ImpulseBranch branch) {
    ++impulses;
    if (branch == ImpulseBranch::Frictionless) ++frictionless;
    if (branch == ImpulseBranch::Sticking) ++sticking;
    if (branch == ImpulseBranch::Sliding) ++sliding;
  }

  StageCounters& operator+=(const StageCounters& o) {
    sweeps += o.sweeps;
    pairVisits += o.pairVisits;
    impulses += o.impulses;
    frictionless += o.frictionless;
    sticking += o.sticking;
    sliding += o.sliding;
    pairIterationCapHits += o.pairIterationCapHits;
    pairConvergences += o.pairConvergences;
    frictionEvaluations += o.frictionEvaluations;
    elasticImpulses += o.elasticImpulses;
    rollingImpulses += o.rollingImpulses;
    patchImpulses += o.patchImpulses;
    tiedLandings += o.tiedLandings;
    uncarried += o.uncarried;
    stepConeSticks += o.stepConeSticks;
    islandSweeps += o.islandSweeps;
    islands += o.islands;
    islandPairs += o.islandPairs;
    largestIslandPairs += o.largestIslandPairs;
    detection += o.detection;
    seconds += o.seconds;
    return *this;
  }

  /// One line, e.g. "3 sweeps, 12 impulses (0 frictionless, 10 sticking, 2 sliding), ...".
  std::string summary() const {
    std::ostringstream out;
    out << sweeps << " sweeps, " << pairVisits << " pair visits, " << impulses << " impulses ("
        << frictionless << " frictionless, " << sticking << " sticking, " << sliding
        << " sliding, " << elasticImpulses << " elastic, " << rollingImpulses << " rolling, "
        << stepConeSticks << " sticking by the step's cone, " << patchImpulses << " whole patches), "
        << frictionEvaluations << " friction evaluations, " << pairIterationCapHits
        << " pair caps hit, " << seconds * 1e3
        << " ms; " << detection.summary();
    return out.str();
  }
};
// [stage_counters]

// [quarantine]
/// A body the step isolated because its state became non-finite during the step (B21):
/// restored to its pose at the start of the step, its velocity and angular momentum set
/// to zero, and made static (1/m = 0, 1/I = 0), so that it stays in the scene as an
/// immovable obstacle and cannot pass NaN to any other body through a contact.
struct Quarantine {
  int body = -1;        ///< index in World::bodies
  std::string message;  ///< what was found, e.g. "velocity became non-finite in step 1"
};
// [quarantine]

// [sleep_counters]
/// What sleeping did (chapter 8, "Sleeping"); all zero while it is off.
struct SleepCounters {
  std::int64_t sleepingBodySteps = 0;  ///< body-steps not simulated: a sleeping body, one step
  std::int64_t fellAsleep = 0;         ///< times a body fell asleep
  std::int64_t wokenUp = 0;            ///< times a sleeping body was woken
  std::int64_t sleepingAtEnd = 0;      ///< bodies asleep after the (last) step

  SleepCounters& operator+=(const SleepCounters& o) {
    sleepingBodySteps += o.sleepingBodySteps;
    fellAsleep += o.fellAsleep;
    wokenUp += o.wokenUp;
    sleepingAtEnd = o.sleepingAtEnd;
    return *this;
  }
};
// [sleep_counters]

// [welded_counters]
/// What the welded pass did (chapter 9, "The welded pass"); zero under any other step.
struct WeldedCounters {
  std::int64_t passes = 0;         ///< steps whose hook ran the welded pass
  std::int64_t carriedLoads = 0;   ///< contact-stage impulses carried to a lower body (Eq. (9.11))
  std::int64_t weldTries = 0;      ///< bodies tested for a body weld (Eq. (9.12))
  std::int64_t welds = 0;          ///< of those, welded
  std::int64_t islands = 0;        ///< islands the energy guard decided on (Eq. (9.14))
  std::int64_t gbfIslands = 0;     ///< of those, islands that took GBF's pass

  WeldedCounters& operator+=(const WeldedCounters& o) {
    passes += o.passes;
    carriedLoads += o.carriedLoads;
    weldTries += o.weldTries;
    welds += o.welds;
    islands += o.islands;
    gbfIslands += o.gbfIslands;
    return *this;
  }
};
// [welded_counters]

// [step_counters]
/// The work of one or more steps, stage by stage. Add steps up with +=.
struct StepCounters {
  std::int64_t steps = 0;
  StageCounters collision;  ///< stage (1)
  StageCounters contact;    ///< stage (3)
  StageCounters shock;      ///< shock propagation (chapter 9), summed over levels
  SleepCounters sleep;      ///< sleeping (chapter 8): bodies skipped, fallen asleep, woken
  WeldedCounters welded;    ///< the welded pass (chapter 9); its sweeps, and the guard's, are in `shock`
  /// The effects this step ran (for several steps: those of the last one added).
  Effects effects;
  double velocityUpdateSeconds = 0.0;
  double positionUpdateSeconds = 0.0;
  double hookSeconds = 0.0;  ///< time spent in the post-contact hook (chapter 9)
  double totalSeconds = 0.0;
  /// Bodies quarantined (for several steps: all of them, in order).
  std::vector<Quarantine> quarantined;
  /// Under FrictionConeRule::StepTotal, the total impulse each pair exchanged in this
  /// step's contact stage and pass (Eq. (8.13)); empty otherwise. Per step: += does not
  /// add ledgers up.
  ContactLedger contactLedger;

  StepCounters& operator+=(const StepCounters& o) {
    quarantined.insert(quarantined.end(), o.quarantined.begin(), o.quarantined.end());
    steps += o.steps;
    collision += o.collision;
    contact += o.contact;
    shock += o.shock;
    sleep += o.sleep;
    welded += o.welded;
    effects = o.effects;
    velocityUpdateSeconds += o.velocityUpdateSeconds;
    positionUpdateSeconds += o.positionUpdateSeconds;
    hookSeconds += o.hookSeconds;
    totalSeconds += o.totalSeconds;
    return *this;
  }

  /// A few lines for logs and reports.
  std::string summary() const {
    std::ostringstream out;
    out << steps << " steps, " << totalSeconds * 1e3 << " ms; effects: " << effects.summary()
        << "\n  collision: " << collision.summary() << "\n  contact:   " << contact.summary()
        << "\n  shock:     " << shock.summary() << "\n  velocity update "
        << velocityUpdateSeconds * 1e3 << " ms, position update " << positionUpdateSeconds * 1e3
        << " ms, hook " << hookSeconds * 1e3 << " ms";
    if (welded.passes > 0) {
      out << "\n  welded:    " << welded.passes << " passes, " << welded.carriedLoads << " loads carried, "
          << welded.welds << " of " << welded.weldTries << " body welds, " << welded.gbfIslands << " of "
          << welded.islands << " islands kept GBF's pass";
    }
    if (effects.sleeping) {
      out << "\n  sleep:     " << sleep.sleepingBodySteps << " body-steps asleep, " << sleep.fellAsleep
          << " fell asleep, " << sleep.wokenUp << " woken, " << sleep.sleepingAtEnd << " asleep now";
    }
    for (const Quarantine& q : quarantined) out << "\n  quarantined body " << q.body << ": " << q.message;
    return out.str();
  }
};
// [step_counters]

}  // namespace stackbook
