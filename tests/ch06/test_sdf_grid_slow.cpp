// Chapter 6, long runs (label ch06_slow): fine grids and fine meshes.
//   ctest --preset all -L ch06_slow
#include <doctest/doctest.h>

#include <cmath>
#include <functional>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/sdf_grid.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

TEST_CASE("the grid of a fine icosphere converges until the tessellation gap") {
  // Level 4 (5120 faces), gap H = R - min plane distance. The grid error against the mesh
  // itself falls with h (the mesh's distance has kinks along its edges, so the order
  // lies between 1 and 2); the error against the sphere is at most H plus the
  // interpolation error of the exact sphere on the same nodes (Eq. (6.12)).
  const double R = 0.5;
  const TriangleMesh mesh = icosphereMesh(R, 4);
  double H = 0.0;
  for (const auto& f : mesh.faces) {
    const Vec3 a = mesh.vertices[f[0]], b = mesh.vertices[f[1]], c = mesh.vertices[f[2]];
    H = std::max(H, R - std::abs(a.dot((b - a).cross(c - a).normalized())));
  }
  const SphereSdf<3> sphere(R);
  const std::function<double(const Vec3&)> phi = [&](const Vec3& x) { return sphere.distance(x); };
  const std::vector<Vec3> points = sampleBand<3>(phi, sphere.bounds(), -0.25, 0.25, 600, 95);
  const ExactMeshSdf<3> exact(mesh);
  std::vector<double> meshDistance;
  for (const Vec3& x : points) meshDistance.push_back(exact.distance(x));
  double previous = 0.0;
  for (const int cells : {16, 32, 64}) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = cells;
    const SdfGrid<3> grid = buildSdfGrid<3>(mesh, settings);
    const SdfGrid<3> exactGrid = sampleSdfGrid<3>(phi, mesh.bounds(), settings);
    double gridError = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double value = grid.value(points[i]);
      gridError = std::max(gridError, std::abs(value - meshDistance[i]));
      CHECK(std::abs(value - phi(points[i])) <=
            H + std::abs(exactGrid.value(points[i]) - phi(points[i])) + 1e-12);
    }
    CAPTURE(cells);
    CAPTURE(gridError);
    if (previous > 0.0) CHECK(gridError < previous / 1.8);
    previous = gridError;
  }
}

TEST_CASE_TEMPLATE("the sign by region equals the sign by winding number on finer grids", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  const SurfaceMesh<D> meshes[] = {cupBoundary<D>({}, 32), ringBoundary<D>(0.5, 0.2, 32, 16),
                                   boneBoundary<D>({}, 32)};
  for (const SurfaceMesh<D>& mesh : meshes) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = D == 3 ? 24 : 160;
    const SdfGrid<D> regions = buildSdfGrid<D>(mesh, settings);
    settings.sign = SdfSignMethod::WindingNumberPerNode;
    const SdfGrid<D> perNode = buildSdfGrid<D>(mesh, settings);
    CHECK(regions.values() == perNode.values());
  }
}

TEST_CASE_TEMPLATE("interpolation stays second order up to 128 cells", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const TorusSdf<D> torus(0.5, 0.2);
  const std::function<double(const Vec<D>&)> phi = [&](const Vec<D>& x) { return torus.distance(x); };
  const std::vector<Vec<D>> points = sampleBand<D>(phi, torus.bounds(), -0.1, 0.1, 2000, 96);
  double previous = 0.0;
  for (const int cells : {32, 64, 128}) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = cells;
    const SdfGrid<D> grid = sampleSdfGrid<D>(phi, torus.bounds(), settings);
    double worst = 0.0;
    for (const Vec<D>& x : points) worst = std::max(worst, std::abs(grid.value(x) - phi(x)));
    if (previous > 0.0) {
      CAPTURE(cells);
      CHECK(std::log2(previous / worst) > 1.8);
      CHECK(std::log2(previous / worst) < 2.2);
    }
    previous = worst;
  }
}

}  // TEST_SUITE
