#pragma once
// Chapter 12's tests: the step settings of a scene that names no preset.
#include "stackbook/stacking/solver_preset.hpp"

namespace stackbook::testing {

/// The default a scene without a preset runs (kDefaultScenePreset), at time step dt.
inline StepSettings defaultStepAt(double dt) {
  StepSettings s = applySolverPreset(kDefaultScenePreset, StepSettings{});
  s.dt = dt;
  return s;
}

}  // namespace stackbook::testing
