// Reference solution of Exercise 8.3: m g R sin(theta) <= mu_r m g cos(theta).
#include "stackbook/exercises/ex08_3_rolling_rest_angle.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace stackbook::exercises {

double rollingRestAngle(double rollingFriction, double radius) {
  if (!(std::isfinite(rollingFriction) && rollingFriction >= 0.0) ||
      !(std::isfinite(radius) && radius > 0.0)) {
    std::ostringstream msg;
    msg << "rollingRestAngle: need mu_r >= 0 and R > 0, got mu_r = " << rollingFriction
        << ", R = " << radius;
    throw std::invalid_argument(msg.str());
  }
  return std::atan2(rollingFriction, radius);  // tan(theta) = mu_r / R
}

}  // namespace stackbook::exercises
