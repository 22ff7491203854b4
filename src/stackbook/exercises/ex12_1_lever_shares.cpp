// Exercise 12.1 (your answer goes here): see ex12_1_lever_shares.hpp and chapter 12.
// Implement: leverShares. Delete every TODO(reader) comment once your code is in: while
// one is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex12_1_lever_shares.hpp"

namespace stackbook {

std::vector<double> leverShares(double centre, const std::vector<double>& entries) {
  // TODO(reader): find the nearest entries on either side of `centre` and split the load
  // between them by the lever rule; the other entries get 0.
  (void)centre;
  return std::vector<double>(entries.size(), 0.0);
}

}  // namespace stackbook
