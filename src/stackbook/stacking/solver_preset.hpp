#pragma once
/// \file
/// \brief The named step settings (chapter 9): one table that a scene's
/// `"solver": {"preset": ...}` and peers_bench's stackbook columns both read.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stacking/welded_pass.hpp"

namespace stackbook {

// [solver_presets]
/// A named set of step settings.
enum class SolverPreset {
  Gbf,                     ///< GBF's step with shock propagation: StepSettings{} (chapters 8 and 9)
  PassAsContact,           ///< the pass as the contact stage: passAsContactStage()
  PassAsContactShortLoops,  ///< that with short pair loops: passAsContactStageShortLoops()
  GbfShortLoops,            ///< GBF's step with short pair loops: gbfStepShortLoops()
  PassAsContactPatch,       ///< the pass as the contact stage with sticking patches: passAsContactStagePatch()
  WeldedPass,               ///< GBF's step with short loops and the welded pass: gbfStepWeldedPass()
  CarryingPass              ///< the pass as the contact stage freezing what carries its load: carryingPass()
};

/// Every preset with the word a scene names it by, in the order the scene format lists them.
inline constexpr std::array<std::pair<SolverPreset, std::string_view>, 7> kSolverPresets{{
    {SolverPreset::Gbf, "gbf"},
    {SolverPreset::PassAsContact, "passAsContact"},
    {SolverPreset::PassAsContactShortLoops, "passAsContactShortLoops"},
    {SolverPreset::GbfShortLoops, "gbfShortLoops"},
    {SolverPreset::PassAsContactPatch, "passAsContactPatch"},
    {SolverPreset::WeldedPass, "weldedPass"},
    {SolverPreset::CarryingPass, "carryingPass"},
}};

/// `base` with every field a preset sets put back to GBF's, StepSettings{}'s: the pair caps
/// and loop tolerances of the three loops, whether the pass replaces the contact stage, its
/// sweeps, ramp and level tolerance, the welded pass, the freeze rule, the cone rule, the impulse point rule and its landing rules, the rotation rule and the surface query. Every preset starts from this, so a preset means the
/// same settings whatever `base` came from (a scene that names one preset, timed under another).
inline StepSettings withGbfLoops(StepSettings base) {
  const StepSettings gbf;
  base.collisionPairIterations = gbf.collisionPairIterations;
  base.contactPairIterations = gbf.contactPairIterations;
  base.pairImpulseTolerance = gbf.pairImpulseTolerance;
  base.frictionCone = gbf.frictionCone;
  base.shock.replacesContactStage = gbf.shock.replacesContactStage;
  base.shock.sweepsPerLevel = gbf.shock.sweepsPerLevel;
  base.shock.pairIterations = gbf.shock.pairIterations;
  base.shock.restitution = gbf.shock.restitution;
  base.shock.pairImpulseTolerance = gbf.shock.pairImpulseTolerance;
  base.shock.levelApproachTolerance = gbf.shock.levelApproachTolerance;
  base.shock.welded = gbf.shock.welded;
  base.shock.freeze = gbf.shock.freeze;
  base.rotation = gbf.rotation;
  base.detection.narrow.surfaceQuery = gbf.detection.narrow.surfaceQuery;
  base.shock.carryTolerance = gbf.shock.carryTolerance;
  base.impulsePoint.rule = gbf.impulsePoint.rule;
  base.impulsePoint.arms = gbf.impulsePoint.arms;
  base.impulsePoint.heldSamples = gbf.impulsePoint.heldSamples;
  base.impulsePoint.tiedLanding = gbf.impulsePoint.tiedLanding;
  return base;
}

/// The settings of `preset` from `base`: the fields withGbfLoops() names are the preset's,
/// base's other fields (dt, threads, sweep counts, ...) are kept.
inline StepSettings applySolverPreset(SolverPreset preset, StepSettings base) {
  base = withGbfLoops(std::move(base));
  switch (preset) {
    case SolverPreset::PassAsContact: return passAsContactStage(base);
    case SolverPreset::PassAsContactShortLoops: return passAsContactStageShortLoops(base);
    case SolverPreset::GbfShortLoops: return gbfStepShortLoops(base);
    case SolverPreset::PassAsContactPatch: return passAsContactStagePatch(base);
    case SolverPreset::WeldedPass: return gbfStepWeldedPass(base);
    case SolverPreset::CarryingPass: return carryingPass(base);
    case SolverPreset::Gbf: break;
  }
  return base;
}
// [solver_presets]

// [default_scene_preset]
/// The preset of a scene that names none, and so of `stackbook run` on such a scene
/// (chapter 12, "The default step"). StepSettings{} itself stays GBF's step.
inline constexpr SolverPreset kDefaultScenePreset = SolverPreset::CarryingPass;
// [default_scene_preset]

/// The word a scene names `preset` by.
inline std::string_view solverPresetName(SolverPreset preset) {
  for (const auto& [p, word] : kSolverPresets) {
    if (p == preset) return word;
  }
  return "?";
}

/// The preset a scene's word names, or none.
inline std::optional<SolverPreset> solverPresetNamed(std::string_view word) {
  for (const auto& [p, name] : kSolverPresets) {
    if (name == word) return p;
  }
  return std::nullopt;
}

/// The words, quoted and joined as an error message lists them: "a", "b" or "c".
inline std::string solverPresetWords() {
  std::string text;
  for (std::size_t i = 0; i < kSolverPresets.size(); ++i) {
    if (i > 0) text += i + 1 == kSolverPresets.size() ? " or " : ", ";
    text += '"';
    text += kSolverPresets[i].second;
    text += '"';
  }
  return text;
}

}  // namespace stackbook
