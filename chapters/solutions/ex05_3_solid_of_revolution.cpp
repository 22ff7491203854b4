// Exercise 5.3 (reference solution): a solid of revolution as a closed mesh.
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "stackbook/exercises/ex05_3_solid_of_revolution.hpp"

namespace stackbook::exercises {

TriangleMesh revolveProfile(const std::vector<Vec2>& profile, int segments) {
  const int m = static_cast<int>(profile.size());
  if (m < 3) throw std::invalid_argument("revolveProfile: the profile needs at least 3 points");
  if (segments < 3) {
    std::ostringstream msg;
    msg << "revolveProfile: segments must be at least 3, got " << segments;
    throw std::invalid_argument(msg.str());
  }
  double twiceArea = 0.0;  // shoelace: positive for a counterclockwise (r, z) loop
  for (int k = 0; k < m; ++k) {
    const Vec2& a = profile[static_cast<std::size_t>(k)];
    const Vec2& b = profile[static_cast<std::size_t>((k + 1) % m)];
    if (!a.allFinite() || !(a.x() > 0.0)) {
      std::ostringstream msg;
      msg << "revolveProfile: profile point " << k << " (" << a.transpose()
          << ") must be finite with r > 0 (off the axis)";
      throw std::invalid_argument(msg.str());
    }
    twiceArea += a.x() * b.y() - a.y() * b.x();
  }
  if (!(twiceArea > 0.0)) {
    throw std::invalid_argument("revolveProfile: the profile must run counterclockwise in (r, z)");
  }
  TriangleMesh mesh;
  for (int i = 0; i < segments; ++i) {
    const double u = 2.0 * M_PI * i / segments;
    for (const Vec2& p : profile) {
      mesh.vertices.push_back(Vec3(p.x() * std::cos(u), p.x() * std::sin(u), p.y()));
    }
  }
  // As for the torus: d/du x d/dk points out of the solid when the profile is
  // counterclockwise, so (i, k) -> (i+1, k) -> (i+1, k+1) -> (i, k+1) is outward.
  const auto id = [&](int i, int k) { return (i % segments) * m + (k % m); };
  for (int i = 0; i < segments; ++i) {
    for (int k = 0; k < m; ++k) {
      mesh.faces.push_back({id(i, k), id(i + 1, k), id(i + 1, k + 1)});
      mesh.faces.push_back({id(i, k), id(i + 1, k + 1), id(i, k + 1)});
    }
  }
  return mesh;
}

}  // namespace stackbook::exercises
