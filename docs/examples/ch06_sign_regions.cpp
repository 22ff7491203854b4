// Prints, as a Markdown table, how many winding sums the region sign of chapter 6 needs:
// nodes, connected sign regions, winding sums taken, and the largest distance of a
// computed winding number from an integer.
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

template <int D>
void signRow(const char* name, const SurfaceMesh<D>& mesh, int cells) {
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = cells;
  const SdfGrid<D> grid = buildSdfGrid<D>(mesh, settings);
  std::printf("| %dD %s | %zu | %d | %lld | %lld | %lld | %.1e |\n", D, name, mesh.faces.size(),
              cells, static_cast<long long>(grid.nodeCount()),
              static_cast<long long>(grid.stats().signRegions),
              static_cast<long long>(grid.stats().windingEvaluations),
              grid.stats().maxWindingDeviation);
}

}  // namespace

int main() {
  std::printf("| mesh | faces | cells | nodes | sign regions | winding sums | largest distance of w from an integer |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  signRow<3>("cup", cupBoundary<3>(), 32);
  signRow<3>("ring", ringBoundary<3>(0.5, 0.2), 32);
  signRow<3>("bone", boneBoundary<3>(), 32);
  signRow<3>("sphere (level 3)", icosphereMesh(0.5, 3), 64);
  signRow<2>("star", starPolygon(), 128);
  return 0;
}
