// Exercise 11.3 (your answer goes here): see ex11_3_windowed_error.hpp and chapter 11.
// Implement: windowedError.
// Delete every TODO(reader) comment once your code is in: while one is left, the exercise
// counts as not solved and its tests do not run.
#include "stackbook/exercises/ex11_3_windowed_error.hpp"

namespace stackbook {

double windowedError(const Integrator& step, const State1& start, int windows, double window, double coarseDt,
                     double fineDt) {
  // TODO(reader): for each window, run both step sizes from the fine state, compare at the
  // window's end, and move the fine state on.
  (void)step;
  (void)start;
  (void)windows;
  (void)window;
  (void)coarseDt;
  (void)fineDt;
  return -1.0;
}

}  // namespace stackbook
