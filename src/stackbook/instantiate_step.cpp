/// \file
/// \brief The time step of chapters 8 and 9, compiled once for D = 2 and D = 3. The headers
/// declare these instantiations `extern`, so the chapters' tests and the program link to
/// them instead of compiling the whole step in every translation unit (the step is the
/// largest template in the library; compiling it once keeps a cold build short).

#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stacking/welded_pass.hpp"
#include "stackbook/stepping/gbf_step.hpp"
#include "stackbook/stepping/impulse_stage.hpp"
#include "stackbook/stepping/traditional_step.hpp"

namespace stackbook {

#define STACKBOOK_INSTANTIATE_STEP(D)                                                          \
  template int resolvePair<D>(World<D>&, std::vector<CollisionBody<D>>&, const BodyPair&,      \
                              const StageSpec&, int, double, const StepSettings&,              \
                              StageCounters&, PairCandidateLists<D>*);                         \
  template std::vector<CollisionBody<D>> stageViews<D>(const World<D>&, Lookahead, double,     \
                                                       RotationUpdate, const ParallelSettings&, LeverArms, bool); \
  template int sweepPairs<D>(World<D>&, std::vector<CollisionBody<D>>&,                        \
                             const std::vector<BodyPair>&, const StageSpec&, int, double,      \
                             const StepSettings&, StageCounters&,                              \
                             std::vector<PairCandidateLists<D>>*);                             \
  template void runImpulseStage<D>(World<D>&, const StageSpec&, double, const StepSettings&,   \
                                   StageCounters&);                                            \
  template StepCounters gbfStep<D>(World<D>&, const StepSettings&, const PostContactHook<D>&,   \
                                   const PreContactHook<D>&);                                  \
  template StepCounters traditionalStep<D>(World<D>&, const StepSettings&,                     \
                                           const PostContactHook<D>&);                         \
  template ContactGraph worldContactGraph<D>(const World<D>&, const ContactGraphSettings&,     \
                                             DetectionCounters*, const CandidateListStore<D>*); \
  template ShockPassReport shockPropagation<D>(World<D>&, const StepSettings&, StageCounters&, \
                                               Layering, ContactLedger*, std::vector<ContactPair>*); \
  template StepCounters stackingStep<D>(World<D>&, const StepSettings&, Layering);          \
  template StepCounters weldedPassStep<D>(World<D>&, const StepSettings&, Layering);

STACKBOOK_INSTANTIATE_STEP(2)
STACKBOOK_INSTANTIATE_STEP(3)

#undef STACKBOOK_INSTANTIATE_STEP

}  // namespace stackbook
