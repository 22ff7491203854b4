// Exercise 5.2 (stub): mass properties of a compound body by the parallel-axis theorem.
// Implement: combineMassProperties. Delete every TODO(reader) comment once your code is in:
// while one is left, the exercise counts as not solved and its tests do not run.
// The reference solution is chapters/solutions/ex05_2_compound_body.cpp.
#include "stackbook/exercises/ex05_2_compound_body.hpp"

namespace stackbook::exercises {

template <int D>
MassProperties<D> combineMassProperties([[maybe_unused]] const std::vector<CompoundPart<D>>& parts) {
  // TODO(reader): add the masses, average the placed centres of mass, and move each part's
  // rotated inertia R I R^T to the common centre of mass with the parallel-axis theorem.
  return MassProperties<D>{};  // nothing
}

template MassProperties<2> combineMassProperties<2>(const std::vector<CompoundPart<2>>&);
template MassProperties<3> combineMassProperties<3>(const std::vector<CompoundPart<3>>&);

}  // namespace stackbook::exercises
