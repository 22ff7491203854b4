// Chapter 6 exercises: suite ch06_exercises, skipped by default. The exercises preset builds
// them into build/exercises/tests/ch06/test_ch06_exercises. It registers one CTest entry per
// exercise, ex06.1 to ex06.3, with the labels exercise and ch06. Run all of them, or one, with
//   ctest --preset exercises -L ch06
//   ctest --preset exercises -R ex06.1
// An entry runs its tests once its stub has no "// TODO(reader)" comment left. The binary
// runs them at any time:
//   build/exercises/tests/ch06/test_ch06_exercises --no-skip -ts=ch06_exercises -tc="Exercise 6.1*"
// The main build runs them against the reference solutions: ctest --preset solutions -L ch06
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>

#include "stackbook/exercises/ex06_1_rounded_box.hpp"
#include "stackbook/exercises/ex06_2_pseudo_normal_sign.hpp"
#include "stackbook/exercises/ex06_3_narrow_band.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/sdf_grid.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;
namespace ex = stackbook::exercises;

namespace {

template <int D>
Vec<D> randomIn(RandomSource& random, const Aabb<D>& box) {
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = random.uniform(box.lower[k], box.upper[k]);
  return x;
}

template <int D>
Vec<D> halfExtents() {
  Vec<D> h = Vec<D>::Constant(0.2);
  h[0] = 0.5;
  h[1] = 0.3;
  return h;
}

TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b, const Vec3& shiftB) {
  TriangleMesh m = a;
  const int offset = static_cast<int>(a.vertices.size());
  for (const Vec3& v : b.vertices) m.vertices.push_back(v + shiftB);
  for (auto f : b.faces) {
    for (int& i : f) i += offset;
    m.faces.push_back(f);
  }
  return m;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER "_exercises" * doctest::skip()) {

// --- Exercise 6.1: the rounded box --------------------------------------------------------

TEST_CASE_TEMPLATE("Exercise 6.1: a rounded box with radius 0 is the box", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const ex::RoundedBoxSdf<D> rounded(halfExtents<D>(), 0.0);
  const BoxSdf<D> box(halfExtents<D>());
  RandomSource random(91);
  for (int trial = 0; trial < 300; ++trial) {
    const Vec<D> x = randomIn<D>(random, box.bounds().inflated(0.5));
    CHECK(rounded.distance(x) == doctest::Approx(box.distance(x)).epsilon(1e-14));
    CHECK_EIGEN_NEAR(rounded.normal(x), box.normal(x), 1e-14, 1e-14);
  }
}

TEST_CASE_TEMPLATE("Exercise 6.1: a cube rounded by its half side is the ball", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const ex::RoundedBoxSdf<D> rounded(Vec<D>::Constant(0.4), 0.4);
  const SphereSdf<D> ball(0.4);
  RandomSource random(92);
  for (int trial = 0; trial < 300; ++trial) {
    const Vec<D> x = randomIn<D>(random, ball.bounds().inflated(0.5));
    CHECK(rounded.distance(x) == doctest::Approx(ball.distance(x)).epsilon(1e-14));
    CHECK_EIGEN_NEAR(rounded.normal(x), ball.normal(x), 1e-14, 1e-14);
  }
}

TEST_CASE("Exercise 6.1: rounded edges and corners are at the hand-computed distances") {
  // Half extents (0.5, 0.3, 0.2), radius 0.1: inner box (0.4, 0.2, 0.1).
  const ex::RoundedBoxSdf<3> rounded(Vec3(0.5, 0.3, 0.2), 0.1);
  CHECK(rounded.distance(Vec3(1.0, 0.0, 0.0)) == doctest::Approx(0.5));   // face: 0.6 - 0.1
  CHECK(rounded.distance(Vec3::Zero()) == doctest::Approx(-0.2));         // centre: -min h
  // Along the corner's diagonal from the inner corner, at distance s: phi = s - rho.
  const Vec3 inner(0.4, 0.2, 0.1);
  const Vec3 diagonal = Vec3(1, 1, 1).normalized();
  for (const double s : {0.05, 0.1, 0.3}) {
    CHECK(rounded.distance(inner + s * diagonal) == doctest::Approx(s - 0.1).epsilon(1e-14));
    CHECK_EIGEN_NEAR(rounded.normal(inner + s * diagonal), diagonal, 1e-14, 1e-14);
  }
  // The box's sharp corner is outside the rounded box by |(0.1, 0.1, 0.1)| - 0.1.
  CHECK(rounded.distance(Vec3(0.5, 0.3, 0.2)) == doctest::Approx(std::sqrt(0.03) - 0.1));
}

TEST_CASE_TEMPLATE("Exercise 6.1: the rounded box is an analytic shape with projected samples",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const double rho = 0.1;
  const ex::RoundedBoxSdf<D> sdf(halfExtents<D>(), rho);
  // A subdivided box, each vertex moved to its nearest surface point x - phi(x) N(x).
  SurfaceMesh<D> mesh;
  if constexpr (D == 3) {
    mesh = boxMesh(2.0 * halfExtents<3>(), 6);
  } else {
    mesh = rectanglePolygon(2.0 * halfExtents<2>(), 6);
  }
  for (Vec<D>& p : mesh.vertices) p -= sdf.distance(p) * sdf.normal(p);
  const AnalyticShape<D, ex::RoundedBoxSdf<D>> shape(sdf, mesh);
  // Every sample is rho from the inner box: the corners were pulled onto the rounding.
  const Vec<D> inner = (halfExtents<D>().array() - rho).matrix();
  for (const Vec<D>& p : shape.surfaceSamples()) {
    const Vec<D> nearestInner = p.cwiseMax(Vec<D>(-inner)).cwiseMin(inner);
    CHECK((p - nearestInner).norm() == doctest::Approx(rho).epsilon(1e-12));
  }
  CHECK(findMeshDefects<D>(shape.mesh()).ok());
}

TEST_CASE("Exercise 6.1: a radius larger than the smallest half extent is rejected") {
  CHECK_THROWS_WITH_AS(ex::RoundedBoxSdf<3>(Vec3(0.5, 0.3, 0.2), 0.25), doctest::Contains("radius"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(ex::RoundedBoxSdf<2>(Vec2(0.5, -0.3), 0.1), doctest::Contains("half extent"),
                       std::invalid_argument);
}

// --- Exercise 6.2: pseudo-normal sign ------------------------------------------------------

TEST_CASE("Exercise 6.2: a box corner's pseudo-normal is its diagonal whatever the triangulation") {
  // Each corner of the 12-triangle box touches 3 squares, cut into 1 or 2 triangles at
  // that corner: a plain average of triangle normals leans toward the cut faces, the
  // angle-weighted one gives each square pi/2 and so the diagonal.
  const TriangleMesh box = boxMesh(Vec3(2, 2, 2));
  const ex::PseudoNormalSign sign(box);
  for (std::size_t v = 0; v < box.vertices.size(); ++v) {
    CHECK_EIGEN_NEAR(sign.vertexPseudoNormal(static_cast<int>(v)), box.vertices[v].normalized(),
                     1e-14, 1e-14);
  }
  // An edge of the cube bisects its two faces; a diagonal inside a face is that face.
  CHECK_EIGEN_NEAR(sign.edgePseudoNormal(0, 1), Vec3(-1, -1, 0).normalized(), 1e-14, 1e-14);
}

TEST_CASE("Exercise 6.2: the pseudo-normal sign agrees with the winding number on closed meshes") {
  const TriangleMesh meshes[] = {cupBoundary<3>({}, 24, 0.1), ringBoundary<3>(0.5, 0.2, 24, 12),
                                 boneBoundary<3>({}, 24, 0.08), lShapeBoundary<3>(0.5, 2)};
  RandomSource random(93);
  for (const TriangleMesh& mesh : meshes) {
    const ex::PseudoNormalSign sign(mesh);
    int inside = 0;
    for (int trial = 0; trial < 400; ++trial) {
      // Half the points anywhere in the box, half within 0.01 of a vertex (near corners
      // and edges, where the feature classification matters).
      Vec3 x = randomIn<3>(random, mesh.bounds().inflated(0.1));
      if (trial % 2) {
        const std::size_t v = static_cast<std::size_t>(random.uniform(0, double(mesh.vertices.size()) - 1e-9));
        x = mesh.vertices[v] + random.vector<3>(-0.01, 0.01);
      }
      const bool expected = insideByWindingNumber<3>(mesh, x);
      inside += expected ? 1 : 0;
      CHECK(sign.inside(x) == expected);
    }
    CHECK(inside > 20);
  }
}

TEST_CASE("Exercise 6.2: overlapping shells fool the pseudo-normal but not the winding number") {
  // Two unit spheres 1.2 apart stored as two closed shells (a union not merged into one
  // surface). The point (0.15, 0, 0) is inside the first sphere and 0.05 outside the
  // second, whose surface is the nearest one: the pseudo-normal of that surface says
  // "outside", the winding number counts 1 + 0 and says "inside".
  const TriangleMesh ball = icosphereMesh(1.0, 3);
  const TriangleMesh two = merged(ball, ball, Vec3(1.2, 0, 0));
  const ex::PseudoNormalSign sign(two);
  const Vec3 fooled(0.15, 0, 0);
  CHECK(insideByWindingNumber<3>(two, fooled));
  CHECK_FALSE(sign.inside(fooled));
  // Away from the second shell both agree.
  CHECK(sign.inside(Vec3(-0.5, 0, 0)));
  CHECK(insideByWindingNumber<3>(two, Vec3(-0.5, 0, 0)));
}

TEST_CASE("Exercise 6.2: an open sheet has sides for the pseudo-normal but not for the winding number") {
  // The square [-1, 1]^2 at z = 0 with normal +z: "inside" is below it.
  TriangleMesh sheet;
  sheet.vertices = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
  sheet.faces = {{0, 1, 2}, {0, 2, 3}};
  const ex::PseudoNormalSign sign(sheet);
  CHECK(sign.inside(Vec3(0.1, 0.2, -0.01)));
  CHECK_FALSE(sign.inside(Vec3(0.1, 0.2, 0.01)));
  CHECK(sign.inside(Vec3(3.0, 0.0, -0.5)));  // below, beyond the rim: nearest is an edge
  // The winding number just below the middle is a little under 1/2: undecided.
  const double w = windingNumber<3>(sheet, Vec3(0.1, 0.2, -0.01));
  CHECK(w > 0.45);
  CHECK(w < 0.5);
}

// --- Exercise 6.3: narrow band ---------------------------------------------------------------

TEST_CASE_TEMPLATE("Exercise 6.3: the narrow-band grid interpolates the clamped dense grid", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  SurfaceMesh<D> mesh;
  if constexpr (D == 3) {
    mesh = icosphereMesh(0.5, 2);
  } else {
    mesh = regularPolygon(0.5, 64);
  }
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = D == 3 ? 24 : 64;
  const SdfGrid<D> dense = buildSdfGrid<D>(mesh, settings);
  const double h = dense.cellSize();
  const double w = 2.0 * std::sqrt(double(D)) * h;
  const ex::NarrowBandGrid<D> band(dense, w, 4);
  // The reference: a dense grid of the clamped node values (same layout).
  std::vector<double> clamped = dense.values();
  for (double& v : clamped) v = std::clamp(v, -w, w);
  const SdfGrid<D> reference(dense.box().lower, h, dense.nodeCounts(), clamped,
                             SdfGradientMethod::CentralDifferences);
  RandomSource random(94);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec<D> x = randomIn<D>(random, dense.box().inflated(0.2));
    CHECK(band.value(x) == doctest::Approx(reference.value(x)).epsilon(1e-14));
    // So: equal to the dense grid near the surface, the same sign everywhere.
    if (std::abs(dense.value(x)) < h) CHECK(band.value(x) == doctest::Approx(dense.value(x)).epsilon(1e-14));
    if (std::abs(dense.value(x)) > 1e-12) CHECK(band.value(x) * dense.value(x) > 0.0);
  }
}

TEST_CASE("Exercise 6.3: the band's memory grows with the surface and not the volume") {
  const TriangleMesh mesh = icosphereMesh(0.5, 2);
  double ratio[2] = {0.0, 0.0};
  for (int level = 0; level < 2; ++level) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = level == 0 ? 24 : 48;
    const SdfGrid<3> dense = buildSdfGrid<3>(mesh, settings);
    const ex::NarrowBandGrid<3> band(dense, 2.0 * std::sqrt(3.0) * dense.cellSize(), 4);
    CHECK(band.storedNodes() > 0);
    CHECK(band.storedNodes() < dense.nodeCount());
    CHECK(band.memoryBytes() >= band.storedNodes() * sizeof(double));
    ratio[level] = double(band.memoryBytes()) / double(dense.memoryBytes());
  }
  // Stored nodes ~ area / h^2 against nodes ~ volume / h^3: halving h halves the ratio.
  CAPTURE(ratio[0]);
  CAPTURE(ratio[1]);
  CHECK(ratio[1] < 0.7 * ratio[0]);
}

TEST_CASE("Exercise 6.3: a band narrower than a cell diagonal is rejected") {
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = 16;
  const SdfGrid<2> dense = buildSdfGrid<2>(regularPolygon(0.5, 16), settings);
  CHECK_THROWS_AS(ex::NarrowBandGrid<2>(dense, dense.cellSize(), 4), std::invalid_argument);
  CHECK_THROWS_AS(ex::NarrowBandGrid<2>(dense, 2.0 * dense.cellSize(), 1), std::invalid_argument);
}

}  // TEST_SUITE
