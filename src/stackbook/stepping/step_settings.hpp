#pragma once
/// \file
/// \brief Every knob of the time step (chapter 8), with GBF's defaults: the step size,
/// the loop counts of the collision and contact stages, the contact restitution schedule,
/// the friction safeguards, detection settings, and which order of operations to use.

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "stackbook/body/rotation_update.hpp"
#include "stackbook/collision/impulse_point.hpp"
#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/impulse/patch_impulse.hpp"
#include "stackbook/impulse/friction_settings.hpp"
#include "stackbook/stepping/contact_ledger.hpp"
#include "stackbook/stepping/contact_recorder.hpp"
#include "stackbook/stepping/effects.hpp"
#include "stackbook/stepping/parallel.hpp"
#include "stackbook/stepping/sleep_settings.hpp"

namespace stackbook {

/// The order of operations within one step.
enum class StepOrder {
  /// GBF: collisions at predicted poses, velocity update, contact, position update.
  Gbf,
  /// The traditional order: velocity and position update, then collisions, then contact,
  /// both at the new poses (kept to show what GBF's reordering fixes).
  Traditional,
};

// [pair_order]
/// The order in which a sweep visits its pairs (chapter 10, "Colours").
enum class PairOrder {
  /// The sweep's list order (GBF; the default): the broad phase's sorted (i, j) order in the
  /// collision and contact stages, the contact graph's order in a level of the pass.
  List,
  /// Colour by colour (pairColours(), Eq. (10.10)), each colour in list order. No two pairs
  /// of a colour share a dynamic body, so a colour's pairs may run at the same time even in
  /// one island. A different Gauss-Seidel order, so a different result from List; the same
  /// result for any thread count.
  Colours,
};
// [pair_order]

// [gbf_friction]
/// The friction settings the step uses by default: chapter 3's safeguards with GBF's
/// slip direction T = u_t / |u_t| (SlipDirectionRule::RelativeVelocity), the paper's rule.
/// Chapter 3's own default (Blended, Eq. (3.4)) leans T towards the slip the impact creates
/// by rho = mu j_n(T*) / |j*_t|, with j_n(T*) the normal impulse of a slide along T*
/// (Eq. (3.5)). In the contact stage a sliding contact approaches at about g dt, so rho is
/// of order dt and Blended tends to this rule as dt -> 0 (chapter 8 measures validation
/// case A2 in 3D with both: they agree at the printed precision). They differ at the
/// stick/slide switch in 3D, where this rule's impulse jumps and Blended's does not
/// (chapter 3, continuity): select Blended there.
inline FrictionSettings gbfFrictionSettings() {
  FrictionSettings f;
  f.slipDirection = SlipDirectionRule::RelativeVelocity;
  return f;
}
// [gbf_friction]

// [welded_settings]
/// The welded pass (chapter 9, "The welded pass"): GBF's contact stage runs, and its impulses
/// are carried as loads into a pass that starts from the velocities before that stage. Its own
/// pass is the pass as the contact stage with these loops; GBF's pass (ShockSettings' other
/// fields) runs beside it when the energy guard is on.
struct WeldedPassSettings {
  /// Run the welded pass instead of GBF's pass after the contact stage (off: GBF).
  bool enabled = false;
  /// Sweeps of each level (>= 1), with the ramp e_l = -1 + l / sweepsPerLevel.
  int sweepsPerLevel = 20;
  /// Impulses per pair per level sweep, at most (>= 1).
  int pairIterations = 5;
  /// A pair visit ends after an impulse |j| <= this times its first (>= 0, < 1).
  double pairImpulseTolerance = 0.2;
  /// A level sweep whose largest approach is at most this (m/s, >= 0) ends the level.
  double levelApproachTolerance = 1e-9;
  /// Where the pass's impulses act (chapter 8): a whole sticking patch where one holds.
  ImpulsePointRule impulsePoint = ImpulsePointRule::StickingPatch;
  /// Weld a body whose supporters are at rest, in one impulse, before the pass (Eq. (9.12)).
  bool bodyWelds = true;
  /// The 3D spin test of a body weld (Eq. (9.13)); the pass's own patches keep AllPoints.
  PatchSpinBound weldSpinBound = PatchSpinBound::BestSubset;
  /// Run GBF's pass on a copy too, and let each island keep the welded pass's velocities
  /// only if a body in it was welded and it has no more kinetic energy than GBF's pass left
  /// it (Eq. (9.14)); the other islands take GBF's. Off, nothing bounds what the loads add.
  bool energyGuard = true;
};
// [welded_settings]

// [freeze_rule]
/// Which bodies the shock-propagation pass freezes after their level (chapter 12).
enum class FreezeRule {
  /// Every level (GBF, Eq. (9.4)): a body is frozen before the bodies above it press on it.
  EveryLevel,
  /// Only what carries its load (chapter 12, Eqs. (12.1)-(12.5)): a body whose load from above
  /// passes outside its support is swept together with its supporters and the bodies above it.
  WhenItCarries,
};
// [freeze_rule]

// [shock_settings]
/// The knobs of chapter 9's shock-propagation pass (PhysBAM's defaults): each level of the
/// contact graph is swept `sweepsPerLevel` times with at most `pairIterations` impulses per
/// pair per sweep, sweep l with restitution e_l = -1 + l / sweepsPerLevel (-0.5, 0 for two
/// sweeps) unless `restitution` lists them, then frozen for the levels above.
struct ShockSettings {
  /// Passes over all levels per step (>= 1; GBF: 1).
  int passes = 1;
  /// Sweeps of each level before it is frozen (>= 1; GBF/PhysBAM: 2; chapter 9 explains
  /// why one sweep in a fixed order turns tall stacks).
  int sweepsPerLevel = 2;
  /// Impulses per pair per level sweep, at most (>= 1; PhysBAM: 10).
  int pairIterations = 10;
  /// Restitution of level sweep l = 1..sweepsPerLevel; empty means e_l = -1 + l / sweepsPerLevel.
  std::vector<double> restitution;
  /// The pass as the contact stage (chapter 9, Eq. (9.9)): GBF's step skips its contact
  /// stage and runs the pass whenever contact runs (one dynamic body included), sweeping
  /// every level. Off (GBF): the contact stage runs and the pass follows it. Pair it with
  /// more sweeps per level (20 converge a 20-row pyramid). The traditional order ignores it.
  bool replacesContactStage = false;
  /// The pass's pair loops end after an impulse |j| <= this times the visit's first one
  /// (>= 0, < 1; 0: PhysBAM's loop to separation or the cap). See StepSettings.
  double pairImpulseTolerance = 0.0;
  /// A level sweep whose largest approach speed is at most this (m/s) ends the level (0: only
  /// a sweep with no impulse does).
  double levelApproachTolerance = 0.0;
  /// The welded pass in place of this one (off by default: GBF's pass).
  WeldedPassSettings welded;
  /// Which levels are frozen (GBF: every level; chapter 12: only what carries its load).
  FreezeRule freeze = FreezeRule::EveryLevel;
  /// Under FreezeRule::WhenItCarries, how far (m, >= 0) a body's centre of load may lie outside
  /// its support region, seen along gravity, and still count as carried (Eq. (12.4)).
  double carryTolerance = 0.0;

  /// The restitution of level sweep l (1-based).
  double restitutionAt(int l) const {
    if (!restitution.empty()) return restitution.at(static_cast<std::size_t>(l - 1));
    return -1.0 + static_cast<double>(l) / static_cast<double>(sweepsPerLevel);
  }
};
// [shock_settings]

// [step_settings]
/// The settings of one time step. Defaults are GBF's loop counts as PhysBAM and
/// OpenTissue implement them (5 collision sweeps, 10 contact sweeps, at most 20
/// impulses per pair per sweep, contact restitution ramped -0.9, -0.8, ..., 0).
struct StepSettings {
  /// Time step dt > 0 in seconds. 1e-3 is the course's test default; GBF leaves dt to a
  /// CFL rule (chapter 8, "Pitfalls"): the motion per step must stay well below the
  /// thinnest feature, because detection sees only where bodies will be, not the path.
  double dt = 1e-3;
  /// Collision stage: at most this many sweeps over the pairs (>= 0; 0 skips the stage).
  int collisionIterations = 5;
  /// Collision stage: at most this many deepest-point impulses per pair per sweep (>= 1).
  int collisionPairIterations = 20;
  /// Contact stage: at most this many sweeps (>= 0; 0 skips the stage).
  int contactIterations = 10;
  /// Contact stage: at most this many impulses per pair per sweep (>= 1).
  int contactPairIterations = 20;
  /// Restitution of contact sweep k = 1..contactIterations. Empty (the default) means
  /// GBF's ramp e_k = -1 + k / N with N = contactIterations, which ends at 0; otherwise it
  /// must hold exactly contactIterations values, each in [-1, 0].
  std::vector<double> contactRestitution;
  /// Safeguards of the frictional impulse (chapter 3), used by both stages; GBF's slip
  /// direction by default (gbfFrictionSettings()).
  FrictionSettings friction = gbfFrictionSettings();
  /// Broad- and narrow-phase settings (chapter 7).
  DetectionSettings detection;
  /// Where each impulse of a pair acts: GBF's deepest approaching sample (the default), or
  /// the depth-weighted centre of the approaching samples that share its normal (Eq. (8.10)).
  ImpulsePointSettings impulsePoint;
  /// Which impulse Coulomb's cone bounds in the contact stage and the shock pass: each
  /// impulse alone (GBF, the default) or the pair's total over the step (Eq. (8.13)).
  FrictionConeRule frictionCone = FrictionConeRule::EachImpulse;
  /// GBF's order or the traditional one.
  StepOrder order = StepOrder::Gbf;
  /// How the position update (and every predicted pose) turns a body: GBF's exponential map
  /// (the default) or the energy-conserving implicit midpoint rule (chapter 5, Eq. (5.27)).
  RotationUpdate rotation = RotationUpdate::ExponentialMap;
  /// Overrides of the effects inferred from the scene (effects.hpp); empty: infer all.
  EffectOverrides effects;
  /// Shock propagation (chapter 9); used only when that effect runs.
  ShockSettings shock;
  // [loop_tolerances]
  /// Collision and contact stages: a pair's loop ends after an impulse |j| <= this times
  /// the first impulse of that pair visit (>= 0, < 1; 0, GBF: separation or the cap end it).
  double pairImpulseTolerance = 0.0;
  /// Collision and contact stages: a sweep whose largest approach speed -u_rel . N (at the
  /// samples it acted on) is at most this, in m/s, ends the stage (>= 0; 0, GBF: only a
  /// sweep with no impulse does).
  double stageApproachTolerance = 0.0;
  // [loop_tolerances]
  /// Not a physics setting: where the stages record every impulse they apply (chapter 10's
  /// contacts output). nullptr (the default): nothing is recorded; the trajectory is the
  /// same either way, bit for bit.
  ContactRecorder* contactRecorder = nullptr;
  /// Threads (chapter 10): how many, and how the work is split. The result is bit for bit
  /// the same for any thread count.
  ParallelSettings parallel;
  /// The order of every sweep's pairs: the list's (GBF, the default) or colour by colour,
  /// which lets threads share one island (chapter 10, "Colours"). Unlike `parallel`, this
  /// setting changes the result.
  PairOrder pairOrder = PairOrder::List;
  /// Sleeping (chapter 8): off by default.
  SleepSettings sleep;

  /// The restitution of contact sweep k (1-based), Eq. (8.5).
  double contactRestitutionAt(int k) const {
    if (!contactRestitution.empty()) return contactRestitution.at(static_cast<std::size_t>(k - 1));
    return -1.0 + static_cast<double>(k) / static_cast<double>(contactIterations);  // Eq. (8.5)
  }
};
// [step_settings]

/// `s` with the landing rules on (withLandingRules() of its impulse point): the default step's
/// (chapter 12, "Landing on a support").
inline StepSettings withLandingRules(StepSettings s) {
  s.impulsePoint = withLandingRules(s.impulsePoint);
  return s;
}

/// Throws std::invalid_argument naming the field unless the settings are in range.
inline void validateStepSettings(const StepSettings& s, const char* caller = "validateStepSettings") {
  std::ostringstream msg;
  if (!(std::isfinite(s.dt) && s.dt > 0.0)) {
    msg << "dt must be finite and > 0, got " << s.dt;
  } else if (s.collisionIterations < 0) {
    msg << "collisionIterations must be >= 0, got " << s.collisionIterations;
  } else if (s.collisionPairIterations < 1) {
    msg << "collisionPairIterations must be >= 1, got " << s.collisionPairIterations;
  } else if (s.contactIterations < 0) {
    msg << "contactIterations must be >= 0, got " << s.contactIterations;
  } else if (s.contactPairIterations < 1) {
    msg << "contactPairIterations must be >= 1, got " << s.contactPairIterations;
  } else if (!s.contactRestitution.empty() &&
             s.contactRestitution.size() != static_cast<std::size_t>(s.contactIterations)) {
    msg << "contactRestitution must be empty (GBF ramp) or hold contactIterations = "
        << s.contactIterations << " values, got " << s.contactRestitution.size();
  } else if (!(s.pairImpulseTolerance >= 0.0 && s.pairImpulseTolerance < 1.0)) {
    msg << "pairImpulseTolerance must be in [0, 1), got " << s.pairImpulseTolerance;
  } else if (!(std::isfinite(s.stageApproachTolerance) && s.stageApproachTolerance >= 0.0)) {
    msg << "stageApproachTolerance must be finite and >= 0, got " << s.stageApproachTolerance;
  } else if (!(s.shock.pairImpulseTolerance >= 0.0 && s.shock.pairImpulseTolerance < 1.0)) {
    msg << "shock.pairImpulseTolerance must be in [0, 1), got " << s.shock.pairImpulseTolerance;
  } else if (!(std::isfinite(s.shock.levelApproachTolerance) && s.shock.levelApproachTolerance >= 0.0)) {
    msg << "shock.levelApproachTolerance must be finite and >= 0, got " << s.shock.levelApproachTolerance;
  } else if (s.shock.welded.enabled && s.shock.replacesContactStage) {
    msg << "shock.welded.enabled needs the contact stage, but shock.replacesContactStage is set";
  } else if (s.shock.welded.sweepsPerLevel < 1) {
    msg << "shock.welded.sweepsPerLevel must be >= 1, got " << s.shock.welded.sweepsPerLevel;
  } else if (s.shock.welded.pairIterations < 1) {
    msg << "shock.welded.pairIterations must be >= 1, got " << s.shock.welded.pairIterations;
  } else if (!(s.shock.welded.pairImpulseTolerance >= 0.0 && s.shock.welded.pairImpulseTolerance < 1.0)) {
    msg << "shock.welded.pairImpulseTolerance must be in [0, 1), got " << s.shock.welded.pairImpulseTolerance;
  } else if (!(std::isfinite(s.shock.welded.levelApproachTolerance) && s.shock.welded.levelApproachTolerance >= 0.0)) {
    msg << "shock.welded.levelApproachTolerance must be finite and >= 0, got "
        << s.shock.welded.levelApproachTolerance;
  } else if (!(std::isfinite(s.shock.carryTolerance) && s.shock.carryTolerance >= 0.0)) {
    msg << "shock.carryTolerance must be finite and >= 0, got " << s.shock.carryTolerance;
  } else if (s.shock.passes < 1) {
    msg << "shock.passes must be >= 1, got " << s.shock.passes;
  } else if (s.shock.sweepsPerLevel < 1) {
    msg << "shock.sweepsPerLevel must be >= 1, got " << s.shock.sweepsPerLevel;
  } else if (s.shock.pairIterations < 1) {
    msg << "shock.pairIterations must be >= 1, got " << s.shock.pairIterations;
  } else if (s.parallel.threads < 0) {
    msg << "parallel.threads must be >= 0 (0: all hardware threads), got " << s.parallel.threads;
  } else if (s.parallel.minPairs < 0) {
    msg << "parallel.minPairs must be >= 0, got " << s.parallel.minPairs;
  } else if (s.parallel.bodiesPerTask < 1) {
    msg << "parallel.bodiesPerTask must be >= 1, got " << s.parallel.bodiesPerTask;
  } else if (s.parallel.graphPairsPerTask < 1) {
    msg << "parallel.graphPairsPerTask must be >= 1, got " << s.parallel.graphPairsPerTask;
  } else if (s.parallel.runsPerThread < 1) {
    msg << "parallel.runsPerThread must be >= 1, got " << s.parallel.runsPerThread;
  } else if (!s.shock.restitution.empty() &&
             s.shock.restitution.size() != static_cast<std::size_t>(s.shock.sweepsPerLevel)) {
    msg << "shock.restitution must be empty or hold sweepsPerLevel = " << s.shock.sweepsPerLevel
        << " values, got " << s.shock.restitution.size();
  } else {
    for (std::size_t k = 0; k < s.shock.restitution.size(); ++k) {
      if (!(s.shock.restitution[k] >= -1.0 && s.shock.restitution[k] <= 0.0)) {
        msg << "shock.restitution[" << k << "] must be in [-1, 0], got " << s.shock.restitution[k];
        break;
      }
    }
    for (std::size_t k = 0; msg.str().empty() && k < s.contactRestitution.size(); ++k) {
      if (!(s.contactRestitution[k] >= -1.0 && s.contactRestitution[k] <= 0.0)) {
        msg << "contactRestitution[" << k << "] must be in [-1, 0], got " << s.contactRestitution[k];
        break;
      }
    }
  }
  if (!msg.str().empty()) {
    throw std::invalid_argument(std::string(caller) + ": settings." + msg.str());
  }
  validateImpulsePointSettings(s.impulsePoint, caller);
  validateSleepSettings(s.sleep, caller);
}

}  // namespace stackbook
