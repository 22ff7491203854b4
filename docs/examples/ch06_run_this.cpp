// Run this now (chapter 6): the signed distance grid of the U-shaped polygon (a cup's
// cross-section) at three resolutions, against the exact distance to the polygon, at a
// few points: inside the wall, in the cavity (outside the body, inside its hull), below.
#include <cstdio>

#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

using namespace stackbook;

int main() {
  const Polygon cup = uPolygon();
  const ExactMeshSdf<2> exact(cup);
  const Vec2 points[] = {Vec2(0.45, 0.0), Vec2(0.0, 0.1), Vec2(0.0, -0.36), Vec2(0.0, -0.6)};
  std::printf("point            exact phi");
  for (const int cells : {8, 16, 64}) std::printf("   grid %2d cells", cells);
  std::printf("\n");
  SdfGridSettings settings;
  std::vector<SdfGrid<2>> grids;
  for (const int cells : {8, 16, 64}) {
    settings.cellsAcrossLargestExtent = cells;
    grids.push_back(buildSdfGrid<2>(cup, settings, "U polygon"));
  }
  for (const Vec2& p : points) {
    std::printf("(%5.2f, %5.2f)  %10.5f", p.x(), p.y(), exact.distance(p));
    for (const SdfGrid<2>& g : grids) std::printf("  %15.5f", g.value(p));
    std::printf("\n");
  }
}
