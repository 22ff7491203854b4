// Reference solution of Exercise 8.1: the CFL time step of Eq. (8.9).
#include "stackbook/exercises/ex08_1_cfl_time_step.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace stackbook::exercises {

double cflTimeStep(double speed, double gravity, double thickness, double safety) {
  std::ostringstream msg;
  if (!(std::isfinite(speed) && speed >= 0.0)) {
    msg << "speed must be finite and >= 0, got " << speed;
  } else if (!(std::isfinite(gravity) && gravity >= 0.0)) {
    msg << "gravity must be finite and >= 0, got " << gravity;
  } else if (!(std::isfinite(thickness) && thickness > 0.0)) {
    msg << "thickness must be finite and > 0, got " << thickness;
  } else if (!(safety > 0.0 && safety <= 1.0)) {
    msg << "safety must be in (0, 1], got " << safety;
  }
  if (!msg.str().empty()) throw std::invalid_argument("cflTimeStep: " + msg.str());
  const double c = 0.5 * safety * thickness;  // g dt^2 + v dt - c = 0, Eq. (8.9)
  if (speed == 0.0 && gravity == 0.0) return std::numeric_limits<double>::infinity();
  // dt = (-v + sqrt(v^2 + 4 g c)) / (2 g) = 2 c / (v + sqrt(v^2 + 4 g c)): no cancellation
  return 2.0 * c / (speed + std::sqrt(speed * speed + 4.0 * gravity * c));
}

}  // namespace stackbook::exercises
