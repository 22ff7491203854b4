// Reference solution of Exercise 8.2: the halving contact restitution schedule.
#include "stackbook/exercises/ex08_2_contact_ramp.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace stackbook::exercises {

std::vector<double> halvingContactRamp(int sweeps) {
  if (sweeps < 1) {
    throw std::invalid_argument("halvingContactRamp: sweeps must be >= 1, got " +
                                std::to_string(sweeps));
  }
  std::vector<double> e;
  e.reserve(static_cast<std::size_t>(sweeps));
  for (int k = 1; k < sweeps; ++k) e.push_back(-std::ldexp(1.0, -k));  // -(1/2)^k, exact
  e.push_back(0.0);
  return e;
}

}  // namespace stackbook::exercises
