// Exercise 11.1 (your answer goes here): see ex11_1_observed_order.hpp and chapter 11.
#include "stackbook/exercises/ex11_1_observed_order.hpp"

namespace stackbook {

std::vector<double> observedOrders(const std::vector<double>& knob, const std::vector<double>& error) {
  // TODO(reader): check the input, then one slope per consecutive pair of points.
  (void)knob;
  (void)error;
  return {};
}

}  // namespace stackbook
