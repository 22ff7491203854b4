// Exercise 7.1 (your answer goes here): see ex07_1_uniform_grid.hpp and chapter 7.
// Implement: uniformGridPairs. Delete every TODO(reader) comment once your code is in: while one
// is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex07_1_uniform_grid.hpp"

namespace stackbook {

template <int D>
std::vector<BodyPair> uniformGridPairs(const std::vector<BroadPhaseProxy<D>>& proxies,
                                       const UniformGridSettings& settings,
                                       DetectionCounters* counters) {
  // TODO(reader): enter every box in the cells it touches, test each pair that shares a
  // cell once, and return the overlapping pairs sorted by (i, j).
  (void)proxies;
  (void)settings;
  (void)counters;
  return {};
}

template std::vector<BodyPair> uniformGridPairs<2>(const std::vector<BroadPhaseProxy<2>>&,
                                                   const UniformGridSettings&, DetectionCounters*);
template std::vector<BodyPair> uniformGridPairs<3>(const std::vector<BroadPhaseProxy<3>>&,
                                                   const UniformGridSettings&, DetectionCounters*);

}  // namespace stackbook
