// Exercise 10.1, reference solution: the regular polygon as a scene shape.
#include "stackbook/exercises/ex10_1_regular_polygon.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

namespace stackbook {

namespace {

[[noreturn]] void reject(const std::string& field, const std::string& what) {
  throw std::invalid_argument("polygon shape: \"" + field + "\" " + what);
}

int integerField(const nlohmann::json& spec, const char* key, int fallback, int lo, int hi) {
  if (!spec.contains(key)) {
    if (fallback < 0) reject(key, "is required");
    return fallback;
  }
  const nlohmann::json& v = spec.at(key);
  if (!v.is_number_integer()) reject(key, "must be an integer, got " + v.dump());
  const auto n = v.get<long long>();
  if (n < lo || n > hi) reject(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + v.dump());
  return static_cast<int>(n);
}

}  // namespace

PolygonShapeBuild regularPolygonShape(const nlohmann::json& spec) {
  if (!spec.is_object()) throw std::invalid_argument("polygon shape: expected a JSON object, got " + spec.dump());
  for (const auto& [key, value] : spec.items()) {
    if (key != "type" && key != "sides" && key != "radius" && key != "sdfResolution") {
      reject(key, "is not a field of a polygon shape (type, sides, radius, sdfResolution)");
    }
  }
  if (!spec.contains("type") || spec.at("type") != "polygon") reject("type", "must be \"polygon\"");
  const int n = integerField(spec, "sides", -1, 3, 1000);
  const int resolution = integerField(spec, "sdfResolution", 32, 4, 1024);
  if (!spec.contains("radius") || !spec.at("radius").is_number()) reject("radius", "must be a number");
  const double R = spec.at("radius").get<double>();
  if (!std::isfinite(R) || !(R > 0.0)) reject("radius", "must be finite and > 0, got " + spec.at("radius").dump());

  // The corners, counterclockwise, one on top. Their mean is the centre, which is also
  // the centroid: the polygon is symmetric under rotation by 2 pi / n.
  std::vector<Vec2> corners;
  for (int k = 0; k < n; ++k) {
    const double angle = 0.5 * M_PI + 2.0 * M_PI * k / n;
    corners.push_back(Vec2(R * std::cos(angle), R * std::sin(angle)));
  }
  // Each side split into 4 segments: the outline's vertices are the body's surface
  // samples (chapter 7), and corners alone would let a side sink into a flat floor.
  std::vector<Vec2> loop;
  for (int k = 0; k < n; ++k) {
    const Vec2 a = corners[static_cast<std::size_t>(k)], b = corners[static_cast<std::size_t>((k + 1) % n)];
    for (int s = 0; s < 4; ++s) loop.push_back(a + (b - a) * (s / 4.0));
  }
  PolygonShapeBuild out;
  out.outline = polygonFromLoop(loop);
  // n triangles (centre, corner k, corner k+1) with apex angle alpha = 2 pi / n:
  // area R^2 sin(alpha) / 2 each; a triangle with a vertex at the origin and the others at
  // p, q has polar moment (A / 6)(p.p + p.q + q.q) = (A / 6) R^2 (2 + cos(alpha)) there.
  const double alpha = 2.0 * M_PI / n;
  const double triangle = 0.5 * R * R * std::sin(alpha);
  out.area = n * triangle;
  out.unitMoment = n * triangle / 6.0 * R * R * (2.0 + std::cos(alpha));
  SdfGridSettings grid;
  grid.cellsAcrossLargestExtent = resolution;
  out.shape = std::make_shared<GridShape<2>>(out.outline, "polygon", grid);
  return out;
}

}  // namespace stackbook
