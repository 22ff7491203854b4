// Exercise 11.4 (your answer goes here): see ex11_4_envelope_order.hpp and chapter 11.
// Implement: upperEnvelope and envelopeOrder.
// Delete every TODO(reader) comment once your code is in: while one is left, the exercise
// counts as not solved and its tests do not run.
#include "stackbook/exercises/ex11_4_envelope_order.hpp"

namespace stackbook {

std::vector<std::size_t> upperEnvelope(const std::vector<double>& dt, const std::vector<double>& error) {
  // TODO(reader): keep the points that no point at a smaller or equal dt beats.
  (void)dt;
  (void)error;
  return {};
}

double envelopeOrder(const std::vector<double>& dt, const std::vector<double>& error) {
  // TODO(reader): the least-squares slope of log(error) against log(dt) on the envelope.
  (void)dt;
  (void)error;
  return -1.0;
}

}  // namespace stackbook
