// Exercise 11.2 (your answer goes here): see ex11_2_apex_heights.hpp and chapter 11.
// Implement: apexHeights and apexError.
// Delete every TODO(reader) comment once your code is in: while one is left, the exercise
// counts as not solved and its tests do not run.
#include "stackbook/exercises/ex11_2_apex_heights.hpp"

namespace stackbook {

std::vector<double> apexHeights(const std::vector<double>& heights) {
  // TODO(reader): the local maxima of the recorded heights.
  (void)heights;
  return {};
}

double apexError(const std::vector<double>& heights, double h0, double e, int count) {
  // TODO(reader): compare the first `count` apexes with e^{2k} h0.
  (void)heights;
  (void)h0;
  (void)e;
  (void)count;
  return -1.0;
}

}  // namespace stackbook
