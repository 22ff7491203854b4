#pragma once
/// \file
/// \brief Exercise 9.2: softened freezing, Unreal Chaos style: instead of making a settled
/// level infinitely heavy, make it heavier by a factor (\ref ch09).

#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/contact_levels.hpp"
#include "stackbook/stepping/step_counters.hpp"
#include "stackbook/stepping/step_settings.hpp"
#include "stackbook/stepping/world.hpp"

namespace stackbook {

/// The pass of shockPropagationPass() with one change: after a level is swept, the inverse
/// mass and inverse inertia of its bodies are multiplied by `softness` in [0, 1] (Eq. (9.4)
/// is softness = 0; softness = 1 freezes nothing) instead of being set to zero, and
/// restored exactly at the end (also on an exception). Isolated levels are skipped as in
/// the chapter. With softness = 0 the result must be bit-identical to
/// shockPropagationPass(). Throws std::invalid_argument for softness outside [0, 1].
template <int D>
void softenedShockPass(World<D>& world, const ContactGraph& graph, const ContactLevels& levels,
                       const StepSettings& settings, double softness, StageCounters& counters);

}  // namespace stackbook
