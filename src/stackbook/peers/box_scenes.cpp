// The box scenes of the peers (box_scenes.hpp).
#include "stackbook/peers/box_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <string>

namespace peers {

namespace {

BoxScene withGround(int dimension, std::string name, std::string description) {
  BoxScene s;
  s.name = std::move(name);
  s.description = std::move(description);
  s.dimension = dimension;
  BoxSpec ground;
  ground.mass = 0.0;
  if (dimension == 2) {
    ground.size = Eigen::Vector3d(200.0, 1.0, 1.0);
    ground.centre = Eigen::Vector3d(0.0, -0.5, 0.0);
  } else {
    ground.size = Eigen::Vector3d(200.0, 200.0, 1.0);
    ground.centre = Eigen::Vector3d(0.0, 0.0, -0.5);
  }
  s.boxes.push_back(ground);
  return s;
}

BoxSpec unitBox(int dimension, double x, double y, double up) {
  BoxSpec b;
  b.centre = dimension == 2 ? Eigen::Vector3d(x, up, 0.0) : Eigen::Vector3d(x, y, up);
  return b;
}

}  // namespace

int BoxScene::top() const {
  int best = 1;
  const int upAxis = dimension - 1;
  for (int i = 1; i < static_cast<int>(boxes.size()); ++i) {
    if (boxes[static_cast<std::size_t>(i)].centre[upAxis] > boxes[static_cast<std::size_t>(best)].centre[upAxis]) {
      best = i;
    }
  }
  return best;
}

Eigen::Vector3d BoxScene::gravityVector() const {
  if (hasGravityVector) return gravityVec;
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  g.x() = gravity * std::sin(tilt);
  g[dimension - 1] = -gravity * std::cos(tilt);
  return g;
}

double BoxScene::inclineDistance(double t) const {
  const double a = gravity * std::sin(tilt) - friction * gravity * std::cos(tilt);
  return std::max(0.0, 0.5 * a * t * t);
}

BoxScene incline(int dimension, double degrees, double mu) {
  char title[96];
  std::snprintf(title, sizeof title, "%dD block on a %g degree incline, mu %g", dimension, degrees, mu);
  BoxScene s = withGround(dimension, "incline" + std::to_string(dimension) + "d", title);
  s.tilt = degrees * std::numbers::pi / 180.0;
  s.friction = mu;
  s.boxes.push_back(unitBox(dimension, 0.0, 0.0, 0.5));
  return s;
}

BoxScene stack(int dimension, int n) {
  BoxScene s = withGround(dimension, "stack" + std::to_string(dimension) + "d_" + std::to_string(n),
                          std::to_string(dimension) + "D stack of " + std::to_string(n) + " boxes");
  for (int k = 0; k < n; ++k) s.boxes.push_back(unitBox(dimension, 0.0, 0.0, k + 0.5));
  return s;
}

BoxScene pyramid2d(int base) {
  BoxScene s = withGround(2, "pyramid2d_" + std::to_string(base),
                          "2D pyramid, base " + std::to_string(base) + " (" +
                              std::to_string(base * (base + 1) / 2) + " boxes)");
  for (int row = 0; row < base; ++row) {
    const int count = base - row;
    for (int i = 0; i < count; ++i) s.boxes.push_back(unitBox(2, -0.5 * count + 0.5 + i, 0.0, row + 0.5));
  }
  return s;
}

BoxScene pyramid3d(int levels) {
  int cubes = 0;
  for (int l = 1; l <= levels; ++l) cubes += l * l;
  BoxScene s = withGround(3, "pyramid3d_" + std::to_string(levels),
                          "3D pyramid, " + std::to_string(levels) + " levels (" + std::to_string(cubes) + " cubes)");
  for (int layer = 0; layer < levels; ++layer) {
    const int count = levels - layer;
    for (int i = 0; i < count; ++i) {
      for (int j = 0; j < count; ++j) {
        s.boxes.push_back(unitBox(3, -0.5 * count + 0.5 + i, -0.5 * count + 0.5 + j, layer + 0.5));
      }
    }
  }
  return s;
}

}  // namespace peers
