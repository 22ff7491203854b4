// Chapter 6: the closest point on a segment or triangle, and the nearest face of a mesh.
#include <doctest/doctest.h>

#include <cmath>

#include "stackbook/geometry/face_bvh.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;

namespace {

// The projection q of x onto a convex set C is characterised by q in C and
// (x - q).(p - q) <= 0 for every p in C. The left side is linear in p, so for a simplex it
// suffices to check its vertices. This test knows nothing of the Voronoi regions.
template <int D>
void checkIsProjection(const Vec<D>& x, const FaceClosestPoint<D>& result,
                       const std::array<Vec<D>, D>& vertices) {
  double sum = 0.0;
  Vec<D> combination = Vec<D>::Zero();
  double scale = (x - vertices[0]).squaredNorm();
  for (int k = 0; k < D; ++k) {
    CHECK(result.weights[k] >= 0.0);
    sum += result.weights[k];
    combination += result.weights[k] * vertices[k];
    scale = std::max(scale, (vertices[k] - vertices[0]).squaredNorm());
  }
  CHECK(sum == doctest::Approx(1.0).epsilon(1e-12));
  CHECK_EIGEN_NEAR(combination, result.point, 1e-12, 1e-12);
  for (int k = 0; k < D; ++k) {
    CHECK((x - result.point).dot(vertices[k] - result.point) <= 1e-12 * scale);
  }
  CHECK(result.squaredDistance == doctest::Approx((x - result.point).squaredNorm()).epsilon(1e-12));
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_voronoi_regions]
TEST_CASE("closest point on a triangle is found in each of its seven Voronoi regions") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  struct Case {
    Vec3 x;
    Vec3 expected;
    unsigned feature;  // bit k: vertex k carries weight
  };
  const Case cases[] = {
      {Vec3(-1, -1, 1), Vec3(0, 0, 0), 1u},          // vertex a
      {Vec3(2, -0.5, 0.5), Vec3(1, 0, 0), 2u},       // vertex b
      {Vec3(-0.5, 3, -2), Vec3(0, 1, 0), 4u},        // vertex c
      {Vec3(0.5, -1, 2), Vec3(0.5, 0, 0), 3u},       // edge ab
      {Vec3(0.6, 0.6, -1), Vec3(0.5, 0.5, 0), 6u},   // edge bc: foot of (0.6, 0.6) on x + y = 1
      {Vec3(-2, 0.25, 1), Vec3(0, 0.25, 0), 5u},     // edge ca
      {Vec3(0.2, 0.3, 0.7), Vec3(0.2, 0.3, 0), 7u},  // face
  };
  for (const Case& c0 : cases) {
    CAPTURE(c0.x.transpose());
    const FaceClosestPoint<3> r = closestPointOnTriangle(c0.x, a, b, c);
    CHECK_EIGEN_NEAR(r.point, c0.expected, 1e-15, 1e-15);
    CHECK(r.feature == c0.feature);
    CHECK(r.squaredDistance == doctest::Approx((c0.x - c0.expected).squaredNorm()).epsilon(1e-15));
  }
}
// [test_voronoi_regions]

TEST_CASE("closest point on a segment clamps the projection to the segment") {
  const Vec2 a(0, 0), b(2, 0);
  CHECK(closestPointOnSegment(Vec2(-1, 1), a, b).feature == 1u);
  CHECK(closestPointOnSegment(Vec2(3, -1), a, b).feature == 2u);
  const FaceClosestPoint<2> mid = closestPointOnSegment(Vec2(0.5, 3), a, b);
  CHECK(mid.feature == 3u);
  CHECK_EIGEN_NEAR(mid.point, Vec2(0.5, 0), 1e-15, 1e-15);
  CHECK(mid.squaredDistance == doctest::Approx(9.0).epsilon(1e-15));
  CHECK(mid.weights[1] == doctest::Approx(0.25).epsilon(1e-15));
}

TEST_CASE("closest point satisfies the projection inequality for random triangles and segments") {
  RandomSource random(61);
  for (int trial = 0; trial < 2000; ++trial) {
    CAPTURE(trial);
    const std::array<Vec3, 3> t = {random.vector<3>(-1, 1), random.vector<3>(-1, 1),
                                   random.vector<3>(-1, 1)};
    const Vec3 x = random.vector<3>(-3, 3);
    checkIsProjection<3>(x, closestPointOnTriangle(x, t[0], t[1], t[2]), t);
    const std::array<Vec2, 2> s = {random.vector<2>(-1, 1), random.vector<2>(-1, 1)};
    const Vec2 y = random.vector<2>(-3, 3);
    checkIsProjection<2>(y, closestPointOnSegment(y, s[0], s[1]), s);
  }
}

TEST_CASE("closest point on a degenerate triangle is the nearest point of its edges") {
  // Collinear vertices: zero area, so the face region does not exist.
  const Vec3 a(0, 0, 0), b(1, 1, 1), c(3, 3, 3);
  const Vec3 x(3, 1, 2);  // projects onto (2, 2, 2), between b and c
  const FaceClosestPoint<3> r = closestPointOnTriangle(x, a, b, c);
  // The nearest point of the line through the three points, which lies between b and c.
  const Vec3 direction = Vec3(1, 1, 1).normalized();
  const Vec3 expected = x.dot(direction) * direction;
  CHECK_EIGEN_NEAR(r.point, expected, 1e-14, 1e-14);
  CHECK(std::isfinite(r.squaredDistance));
}

TEST_CASE_TEMPLATE("the face hierarchy finds the same distance as a loop over every face", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(62 + D);
  const SurfaceMesh<D> meshes[] = {cupBoundary<D>({}, 24, 0.1), ringBoundary<D>(0.5, 0.2, 32, 12),
                                   lShapeBoundary<D>(0.5, 3)};
  for (const SurfaceMesh<D>& mesh : meshes) {
    const FaceBvh<D> tree(mesh, 4);
    for (int trial = 0; trial < 300; ++trial) {
      const Vec<D> x = random.vector<D>(-1.5, 1.5);
      const NearestFace<D> fast = tree.nearest(mesh, x);
      const NearestFace<D> slow = nearestFaceBruteForce<D>(mesh, x);
      CHECK(fast.distance() == doctest::Approx(slow.distance()).epsilon(1e-14));
      // The hint only seeds the bound: a wrong hint must not change the answer.
      const NearestFace<D> hinted = tree.nearest(mesh, x, static_cast<int>(mesh.faces.size()) / 2);
      CHECK(hinted.distance() == doctest::Approx(slow.distance()).epsilon(1e-14));
    }
  }
}

}  // TEST_SUITE
