// Exercise 8.2 (your answer goes here): see ex08_2_contact_ramp.hpp and chapter 8.
// Implement: halvingContactRamp. Delete every TODO(reader) comment once your code is in: while
// one is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex08_2_contact_ramp.hpp"

namespace stackbook::exercises {

std::vector<double> halvingContactRamp(int sweeps) {
  // TODO(reader): e_k = -(1/2)^k for k < sweeps, and 0 for the last sweep.
  (void)sweeps;
  return {};
}

}  // namespace stackbook::exercises
