// Exercise 11.1 (your answer goes here): see ex11_1_observed_order.hpp and chapter 11.
// Implement: observedOrders.
// Delete every TODO(reader) comment once your code is in: while one is left, the exercise
// counts as not solved and its tests do not run.
#include "stackbook/exercises/ex11_1_observed_order.hpp"

namespace stackbook {

std::vector<double> observedOrders(const std::vector<double>& knob, const std::vector<double>& error) {
  // TODO(reader): check the input, then one slope per consecutive pair of points.
  (void)knob;
  (void)error;
  return {};
}

}  // namespace stackbook
