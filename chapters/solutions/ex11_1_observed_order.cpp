// Exercise 11.1, reference solution: see ex11_1_observed_order.hpp and chapter 11.
#include <cmath>
#include <stdexcept>
#include <string>

#include "stackbook/exercises/ex11_1_observed_order.hpp"

namespace stackbook {

std::vector<double> observedOrders(const std::vector<double>& knob, const std::vector<double>& error) {
  if (knob.size() != error.size()) throw std::invalid_argument("observedOrders: knob and error sizes differ");
  if (knob.size() < 2) throw std::invalid_argument("observedOrders: need at least two points");
  for (std::size_t k = 0; k < knob.size(); ++k) {
    if (!(std::isfinite(knob[k]) && knob[k] > 0.0 && std::isfinite(error[k]) && error[k] > 0.0)) {
      throw std::invalid_argument("observedOrders: point " + std::to_string(k) + " must have finite values > 0");
    }
  }
  std::vector<double> orders;
  for (std::size_t k = 0; k + 1 < knob.size(); ++k) {
    if (knob[k] == knob[k + 1]) throw std::invalid_argument("observedOrders: two equal knob values");
    orders.push_back(std::log(error[k] / error[k + 1]) / std::log(knob[k] / knob[k + 1]));
  }
  return orders;
}

}  // namespace stackbook
