// Prints, as a Markdown table, how the error of a grid built from a tessellated sphere
// splits (chapter 6). Icospheres of radius 0.5; 1000 seeded points with |phi| <= 0.25.
// Gap H: the largest distance between mesh and sphere. Grid error: the grid against the
// exact distance to the mesh. Interpolation: the grid of the exact sphere on the same
// nodes, against the sphere. Total: the mesh's grid against the sphere, at most H plus
// the interpolation error.
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

using namespace stackbook;

namespace {

// The largest distance between an inscribed convex mesh and its sphere: R minus the
// smallest distance from the centre to a face's plane.
double tessellationGap(const TriangleMesh& mesh, double R) {
  double gap = 0.0;
  for (const auto& f : mesh.faces) {
    const Vec3 a = mesh.vertices[f[0]], b = mesh.vertices[f[1]], c = mesh.vertices[f[2]];
    gap = std::max(gap, R - std::abs(a.dot((b - a).cross(c - a).normalized())));
  }
  return gap;
}

void tessellationRows() {
  const double R = 0.5;
  const SphereSdf<3> sphere(R);
  const std::function<double(const Vec3&)> phi = [&](const Vec3& x) { return sphere.distance(x); };
  const std::vector<Vec3> points = sampleBand<3>(phi, sphere.bounds(), -0.25, 0.25, 1000, 6);
  for (const int level : {2, 3}) {
    const TriangleMesh mesh = icosphereMesh(R, level);
    const ExactMeshSdf<3> exact(mesh);
    std::vector<double> meshDistance(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) meshDistance[i] = exact.distance(points[i]);
    for (const int cells : {16, 32, 64}) {
      SdfGridSettings settings;
      settings.cellsAcrossLargestExtent = cells;
      const SdfGrid<3> grid = buildSdfGrid<3>(mesh, settings);
      const SdfGrid<3> exactGrid = sampleSdfGrid<3>(phi, mesh.bounds(), settings);
      double gridError = 0.0, interpolation = 0.0, total = 0.0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const double value = grid.value(points[i]);
        gridError = std::max(gridError, std::abs(value - meshDistance[i]));
        interpolation = std::max(interpolation, std::abs(exactGrid.value(points[i]) - phi(points[i])));
        total = std::max(total, std::abs(value - phi(points[i])));
      }
      std::printf("| %d (%zu) | %.2e | %d | %.4f | %.2e | %.2e | %.2e |\n", level,
                  mesh.faces.size(), tessellationGap(mesh, R), cells, grid.cellSize(),
                  gridError, interpolation, total);
    }
  }
}

}  // namespace

int main() {
  std::printf("| level (faces) | gap H | cells | h | grid error | interpolation | total |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  tessellationRows();
  return 0;
}
