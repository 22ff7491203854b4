// Chapter 5: the procedural meshes are closed, outward-oriented and lie on their surfaces.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <utility>

#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"

using namespace stackbook;

namespace {

/// Closed and consistently oriented, checked independently of computeMassProperties: every
/// directed edge occurs exactly once, and so does its reverse.
bool isClosedAndConsistent(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& f : mesh.faces) {
    for (std::size_t k = 0; k < 3; ++k) ++count[{f[k], f[(k + 1) % 3]}];
  }
  for (const auto& [edge, n] : count) {
    const auto reverse = count.find({edge.second, edge.first});
    if (n != 1 || reverse == count.end() || reverse->second != 1) return false;
  }
  return true;
}

/// Signed volume by the divergence theorem with the apex at the origin, Eq. (5.17).
double signedVolume(const TriangleMesh& mesh) {
  double v = 0.0;
  for (const auto& f : mesh.faces) {
    v += mesh.vertices[static_cast<std::size_t>(f[0])].dot(
             mesh.vertices[static_cast<std::size_t>(f[1])].cross(
                 mesh.vertices[static_cast<std::size_t>(f[2])])) / 6.0;
  }
  return v;
}

/// Euler characteristic V - E + F; E = 3F/2 for a closed triangle mesh.
long eulerCharacteristic(const TriangleMesh& mesh) {
  const long V = static_cast<long>(mesh.vertices.size()), F = static_cast<long>(mesh.faces.size());
  return V - 3 * F / 2 + F;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("every 3D primitive is closed and outward-oriented with the right topology") {
  struct Case {
    const char* name;
    TriangleMesh mesh;
    long euler;  // 2 for a sphere-like surface, 0 for a torus
  };
  const Case cases[] = {
      {"box", boxMesh(Vec3(1.0, 2.0, 3.0)), 2},
      {"box 5x5", boxMesh(Vec3(1.0, 2.0, 3.0), 5), 2},
      {"icosphere 0", icosphereMesh(1.0, 0), 2},
      {"icosphere 3", icosphereMesh(0.5, 3), 2},
      {"torus", torusMesh(1.0, 0.3, 24, 12), 0},
      {"cylinder", cylinderMesh(0.5, 2.0, 16), 2},
      {"cylinder banded", cylinderMesh(0.5, 2.0, 16, 4, 3), 2},
  };
  for (const Case& c : cases) {
    CAPTURE(c.name);
    CHECK(isClosedAndConsistent(c.mesh));
    CHECK(signedVolume(c.mesh) > 0.0);
    CHECK(eulerCharacteristic(c.mesh) == c.euler);
  }
}

TEST_CASE("a box subdivided n x n has 6n^2 + 2 vertices and 12n^2 triangles on its faces") {
  const Vec3 size(0.4, 1.0, 2.5);
  for (const int n : {1, 2, 7}) {
    CAPTURE(n);
    const TriangleMesh mesh = boxMesh(size, n);
    CHECK(mesh.vertices.size() == static_cast<std::size_t>(6 * n * n + 2));
    CHECK(mesh.faces.size() == static_cast<std::size_t>(12 * n * n));
    for (const Vec3& p : mesh.vertices) {
      // On the surface: some coordinate is at +-size/2, none beyond.
      const Vec3 t = (2.0 * p.array() / size.array()).abs();
      CHECK(t.maxCoeff() == doctest::Approx(1.0).epsilon(1e-15));
    }
    CHECK(signedVolume(mesh) == doctest::Approx(size.prod()).epsilon(1e-14));
  }
}

TEST_CASE("curved primitives have every vertex on the smooth surface") {
  for (const Vec3& p : icosphereMesh(0.7, 3).vertices) {
    CHECK(p.norm() == doctest::Approx(0.7).epsilon(1e-15));
  }
  CHECK(icosphereMesh(1.0, 3).vertices.size() == 10u * 64u + 2u);
  for (const Vec3& p : torusMesh(2.0, 0.5, 20, 10).vertices) {
    const double ring = std::hypot(p.x(), p.y()) - 2.0;
    CHECK(std::hypot(ring, p.z()) == doctest::Approx(0.5).epsilon(1e-14));
  }
  for (const Vec3& p : cylinderMesh(0.5, 2.0, 16, 2, 3).vertices) {
    const bool onSide = std::abs(std::hypot(p.x(), p.y()) - 0.5) < 1e-15;
    const bool onCap = std::abs(std::abs(p.z()) - 1.0) < 1e-15 && std::hypot(p.x(), p.y()) <= 0.5;
    CHECK((onSide || onCap));
  }
}

TEST_CASE("the 2D primitives run counterclockwise around their area") {
  const Polygon rectangle = rectanglePolygon(Vec2(2.0, 3.0), 4);
  CHECK(rectangle.vertices.size() == 16u);
  CHECK(computeMassProperties<2>(rectangle).measure == doctest::Approx(6.0).epsilon(1e-15));
  const Polygon hexagon = regularPolygon(1.0, 6);
  for (const Vec2& p : hexagon.vertices) CHECK(p.norm() == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(computeMassProperties<2>(hexagon).measure ==
        doctest::Approx(1.5 * std::sqrt(3.0)).epsilon(1e-15));
}

TEST_CASE("primitives reject bad sizes and counts with a message") {
  CHECK_THROWS_WITH_AS(boxMesh(Vec3(1.0, -2.0, 1.0)), "boxMesh: size.y must be finite and positive, got -2",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(boxMesh(Vec3::Ones(), 0), "boxMesh: subdivisions must be at least 1, got 0",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(icosphereMesh(std::nan(""), 1), doctest::Contains("radius must be finite"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(torusMesh(1.0, 1.5), doctest::Contains("must be smaller than majorRadius"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(cylinderMesh(1.0, 1.0, 2), doctest::Contains("segments must be at least 3"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(regularPolygon(1.0, 2), doctest::Contains("sides must be at least 3"),
                       std::invalid_argument);
}

}  // TEST_SUITE
