// Exercise 9.2 (your answer goes here): see ex09_2_softened_freezing.hpp and chapter 9.
// Implement: softenedShockPass. Delete every TODO(reader) comment once your code is in: while
// one is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex09_2_softened_freezing.hpp"

namespace stackbook {

template <int D>
void softenedShockPass(World<D>& world, const ContactGraph& graph, const ContactLevels& levels,
                       const StepSettings& settings, double softness, StageCounters& counters) {
  // TODO(reader): sweep each level as shockPropagationPass() does, then scale the level's
  // inverse masses and inertias by `softness`; restore them all at the end.
  (void)world;
  (void)graph;
  (void)levels;
  (void)settings;
  (void)softness;
  (void)counters;
}

template void softenedShockPass<2>(World<2>&, const ContactGraph&, const ContactLevels&,
                                   const StepSettings&, double, StageCounters&);
template void softenedShockPass<3>(World<3>&, const ContactGraph&, const ContactLevels&,
                                   const StepSettings&, double, StageCounters&);

}  // namespace stackbook
