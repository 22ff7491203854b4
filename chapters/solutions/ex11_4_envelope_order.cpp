// Exercise 11.4, reference solution: see ex11_4_envelope_order.hpp and chapter 11.
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "stackbook/exercises/ex11_4_envelope_order.hpp"

namespace stackbook {

std::vector<std::size_t> upperEnvelope(const std::vector<double>& dt, const std::vector<double>& error) {
  if (dt.size() != error.size()) throw std::invalid_argument("upperEnvelope: dt and error differ in size");
  if (dt.size() < 2) throw std::invalid_argument("upperEnvelope: a curve needs two points");
  for (std::size_t k = 0; k < dt.size(); ++k) {
    if (!(dt[k] > 0.0) || !(error[k] > 0.0)) throw std::invalid_argument("upperEnvelope: dt and error must be > 0");
    for (std::size_t j = 0; j < k; ++j) {
      if (dt[j] == dt[k]) throw std::invalid_argument("upperEnvelope: two points at the same dt");
    }
  }
  std::vector<std::size_t> envelope;
  for (std::size_t k = 0; k < dt.size(); ++k) {
    bool beaten = false;
    for (std::size_t j = 0; j < dt.size() && !beaten; ++j) {
      beaten = j != k && dt[j] <= dt[k] && error[j] > error[k];
    }
    if (!beaten) envelope.push_back(k);
  }
  return envelope;
}

double envelopeOrder(const std::vector<double>& dt, const std::vector<double>& error) {
  const std::vector<std::size_t> envelope = upperEnvelope(dt, error);
  if (envelope.size() < 2) throw std::invalid_argument("envelopeOrder: the envelope has fewer than two points");
  double mx = 0.0, my = 0.0;
  for (std::size_t k : envelope) {
    mx += std::log(dt[k]);
    my += std::log(error[k]);
  }
  const double n = static_cast<double>(envelope.size());
  mx /= n;
  my /= n;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t k : envelope) {
    const double x = std::log(dt[k]) - mx;
    sxy += x * (std::log(error[k]) - my);
    sxx += x * x;
  }
  return sxy / sxx;
}

}  // namespace stackbook
