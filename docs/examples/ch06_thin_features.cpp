// Prints, as a Markdown table, what a grid does to a plate thinner than a few cells
// (chapter 6, Pitfalls). The plate is 1 x 1 x t with t = 0.04, its grid resolved by n
// cells across its largest side (h = 1/n). At 400 seeded points of the mid-plane z = 0
// the exact signed distance is -t/2 = -0.02; the table gives the grid's largest value
// there and the share of points the grid calls outside. The last column is the normal a
// point 3t/4 below the top face gets: the nearest face is the bottom one, so the exact
// normal already points down, through the plate: a vertex pushed that deep is pushed out
// of the far side.
#include <algorithm>
#include <cstdio>
#include <random>

#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

using namespace stackbook;

int main() {
  const double t = 0.04;
  const TriangleMesh plate = boxMesh(Vec3(1.0, 1.0, t), 4);
  std::printf("| cells | h | h / t | largest phi on the mid-plane | mid-plane points outside | "
              "normal z at depth 3t/4 |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const int cells : {8, 16, 32, 64, 128}) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = cells;
    const SdfGrid<3> grid = buildSdfGrid<3>(plate, settings, "plate");
    std::mt19937_64 engine(3);
    double largest = -1.0;
    int outside = 0;
    const int count = 400;
    for (int i = 0; i < count; ++i) {
      const double x = -0.4 + 0.8 * static_cast<double>(engine() >> 11) * 0x1.0p-53;
      const double y = -0.4 + 0.8 * static_cast<double>(engine() >> 11) * 0x1.0p-53;
      const double phi = grid.value(Vec3(x, y, 0.0));
      largest = std::max(largest, phi);
      outside += phi > 0.0 ? 1 : 0;
    }
    const Vec3 deep(0.1, 0.2, 0.5 * t - 0.75 * t);
    std::printf("| %d | %.4f | %.2f | %+.4f | %d %% | %+.3f |\n", cells, grid.cellSize(),
                grid.cellSize() / t, largest, 100 * outside / count, grid.normal(deep).z());
  }
  return 0;
}
