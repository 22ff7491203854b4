// The piles of peers_bench and pile_scaling_bench (pile_scenes.hpp).
#include "pile_scenes.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <stdexcept>

namespace peers {

std::string scenesDir() {
#ifdef STACKBOOK_SCENES_DIR
  return STACKBOOK_SCENES_DIR;
#else
  return "scenes";
#endif
}

namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", x);
  return text;
}

}  // namespace

PileSpec pile2d(int n, const std::string& cacheDir) {
  // Bodies 3..6 of the scene are the four arrays (L, U, star, bone), 25 x 10 each.
  if (n < 4 || n % 2 != 0 || n > 1000) throw std::invalid_argument("pile2d: n must be even, in [4, 1000]");
  PileSpec p;
  p.name = "pile2d_" + std::to_string(n);
  p.description = "2D pile of " + std::to_string(n) + " nonconvex bodies (L, U, star, bone), formed";
  p.file = scenesDir() + "/pile_1000_2d_full.json";
  p.cacheDir = cacheDir;
  double y = 0.6;
  int left = n;
  for (int kind = 0; kind < 4; ++kind) {
    const int count = left / (4 - kind);  // the kinds share n as evenly as they can
    left -= count;
    const int columns = std::min(25, count);
    const int rows = (count + columns - 1) / columns;
    if (columns * rows != count) throw std::invalid_argument("pile2d: n/4 must fill whole rows of 25 (or be < 25)");
    const std::string body = "bodies." + std::to_string(3 + kind);
    p.overrides.push_back(body + ".array.count=[" + std::to_string(columns) + "," + std::to_string(rows) + "]");
    p.overrides.push_back(body + ".position=[-9," + number(y) + "]");
    y += 0.75 * rows;
  }
  // Forming: the fall from the top row and a second to come to rest.
  p.formSeconds = std::sqrt(2.0 * y / 9.81) + 1.5;
  return p;
}

PileSpec pile3d(int n, const std::string& cacheDir) {
  std::array<int, 3> count{};
  if (n == 1000) {
    count = {10, 5, 5};
  } else if (n == 100) {
    count = {5, 5, 1};
  } else if (n == 8) {
    count = {2, 1, 1};
  } else {
    throw std::invalid_argument("pile3d: n must be 8, 100 or 1000");
  }
  PileSpec p;
  p.name = "pile3d_" + std::to_string(n);
  p.description = "3D pile of " + std::to_string(n) + " nonconvex bodies (torus, cup, bone, L), formed";
  p.file = scenesDir() + "/pile_1000_3d_full.json";
  p.cacheDir = cacheDir;
  // Bodies 5..8 of the scene are the four arrays, 10 x 5 x 5 each, 0.8 m apart.
  double z = 0.5;
  for (int kind = 0; kind < 4; ++kind) {
    const std::string body = "bodies." + std::to_string(5 + kind);
    p.overrides.push_back(body + ".array.count=[" + std::to_string(count[0]) + "," + std::to_string(count[1]) + "," +
                          std::to_string(count[2]) + "]");
    const double x = -0.4 * (count[0] - 1);
    const double yy = -0.4 * (count[1] - 1);
    p.overrides.push_back(body + ".position=[" + number(x) + "," + number(yy) + "," + number(z) + "]");
    z += 0.8 * count[2];
  }
  p.formSeconds = std::sqrt(2.0 * z / 9.81) + 1.5;
  return p;
}

}  // namespace peers
