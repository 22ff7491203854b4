// Exercise 12.2 (your answer goes here): see ex12_2_critical_offset.hpp and chapter 12.
// Implement: criticalOffset. Delete every TODO(reader) comment once your code is in: while
// one is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex12_2_critical_offset.hpp"

namespace stackbook {

double criticalOffset(int n) {
  // TODO(reader): write the centre of load of box j and the boxes above it, compare it with the
  // end of box j's patch on box j - 1 (and box 1's on the ground), and keep the smallest bound.
  (void)n;
  return 0.0;
}

}  // namespace stackbook
