// Exercise 10.2, reference solution: a row of dominoes as a generated scene.
#include "stackbook/exercises/ex10_2_domino_scene.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace stackbook {

nlohmann::json dominoRowScene(const DominoRow& row) {
  const auto positive = [](double x, const char* name) {
    if (!std::isfinite(x) || !(x > 0.0)) {
      throw std::invalid_argument(std::string("dominoRowScene: ") + name + " must be finite and > 0");
    }
  };
  if (row.count < 1) throw std::invalid_argument("dominoRowScene: count must be >= 1");
  positive(row.height, "height");
  positive(row.thickness, "thickness");
  positive(row.spacing, "spacing");
  positive(row.dt, "dt");
  positive(row.duration, "duration");
  if (!(row.spacing > row.thickness && row.spacing < row.height)) {
    throw std::invalid_argument("dominoRowScene: spacing must be in (thickness, height)");
  }
  if (!std::isfinite(row.push) || !std::isfinite(row.friction) || row.friction < 0.0) {
    throw std::invalid_argument("dominoRowScene: push must be finite and friction finite and >= 0");
  }
  using nlohmann::json;
  const double length = (row.count - 1) * row.spacing;
  const double groundThickness = 0.5;
  json bodies = json::array();
  bodies.push_back({{"name", "ground"},
                    {"static", true},
                    {"shape", {{"type", "box"}, {"size", {length + 4.0 * row.height, groundThickness}}}},
                    {"position", {0.5 * length, -0.5 * groundThickness}},
                    {"material", "wood"}});
  for (int k = 0; k < row.count; ++k) {
    json domino{{"name", "domino" + std::to_string(k)},
                {"shape", {{"type", "box"}, {"size", {row.thickness, row.height}}}},
                {"position", {k * row.spacing, 0.5 * row.height}},
                {"material", "wood"}};
    if (k == 0) {
      // Rigid rotation at -push about the bottom corner on the +x side, c = (t/2, 0) from
      // the bottom centre: v = omega x (x - c) with x - c = (-t/2, h/2), and in 2D
      // omega x r = omega (-r_y, r_x). Spinning about the centre instead would drive the
      // other corner into the ground, and the contact would take most of the spin away.
      domino["angularVelocity"] = -row.push;
      domino["velocity"] = {row.push * 0.5 * row.height, row.push * 0.5 * row.thickness};
    }
    bodies.push_back(domino);
  }
  return json{{"description", "A row of " + std::to_string(row.count) + " dominoes; the first is tipped over"},
              {"dimension", 2},
              {"dt", row.dt},
              {"duration", row.duration},
              {"materials", {{"wood", {{"friction", row.friction}, {"restitution", 0.0}}}}},
              {"bodies", bodies}};
}

}  // namespace stackbook
