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

namespace stackbook {

// [solver_presets]
/// A named set of step settings.
enum class SolverPreset {
  Gbf,                     ///< GBF's step with shock propagation: StepSettings{} (chapters 8 and 9)
  PassAsContact,           ///< the pass as the contact stage: passAsContactStage()
  PassAsContactShortLoops  ///< that with short pair loops: passAsContactStageShortLoops()
};

/// Every preset with the word a scene names it by, in the order the scene format lists them.
inline constexpr std::array<std::pair<SolverPreset, std::string_view>, 3> kSolverPresets{{
    {SolverPreset::Gbf, "gbf"},
    {SolverPreset::PassAsContact, "passAsContact"},
    {SolverPreset::PassAsContactShortLoops, "passAsContactShortLoops"},
}};

/// The settings of `preset` from `base`: base's other fields (dt, threads, ...) are kept.
inline StepSettings applySolverPreset(SolverPreset preset, StepSettings base) {
  switch (preset) {
    case SolverPreset::PassAsContact: return passAsContactStage(base);
    case SolverPreset::PassAsContactShortLoops: return passAsContactStageShortLoops(base);
    case SolverPreset::Gbf: break;
  }
  return base;
}
// [solver_presets]

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
