// Chapter 6's figures, computed with buildSdfGrid: the signed distance grid of a U-shaped
// polygon (a cup's cross-section) as a colour map, with its zero contour, the polygon and
// normals from the grid's gradient; and a plate thinner than a grid cell, which a coarse
// grid loses and a fine one keeps.
#include <cmath>
#include <iostream>

#include "figure_svg.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

using namespace stackbook;
using namespace figure_svg;

namespace {

// The colour map of grid.value over [x0, x1] x [y0, y1] on an n x n raster, the grid's zero
// contour (green) and the polygon itself (black).
void drawField(Svg& svg, const View& v, const SdfGrid<2>& grid, const Polygon& polygon, int n,
               double range) {
  const double dx = (v.x1 - v.x0) / n, dy = (v.y1 - v.y0) / n;
  std::vector<double> values(static_cast<std::size_t>((n + 1) * (n + 1)));
  auto at = [&](int i, int k) -> double& { return values[static_cast<std::size_t>(k * (n + 1) + i)]; };
  for (int i = 0; i <= n; ++i) {
    for (int k = 0; k <= n; ++k) at(i, k) = grid.value(Vec2(v.x0 + i * dx, v.y0 + k * dy));
  }
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < n; ++k) {
      const double centre = grid.value(Vec2(v.x0 + (i + 0.5) * dx, v.y0 + (k + 0.5) * dy));
      svg.cell(v, v.x0 + i * dx, v.y0 + k * dy, v.x0 + (i + 1) * dx, v.y0 + (k + 1) * dy,
               divergingColour(centre, range));
    }
  }
  // Grid lines of the SDF grid itself, so the reader sees the cell size h (when it is
  // large enough to see).
  const double h = grid.cellSize();
  const Vec2 origin = grid.nodePosition({0, 0});
  for (double x = origin.x(); h * v.width / (v.x1 - v.x0) > 10.0 && x <= v.x1; x += h) {
    if (x >= v.x0) svg.line(v, x, v.y0, x, v.y1, stroke("#000", 0.4, "2 3"));
  }
  for (double y = origin.y(); h * v.width / (v.x1 - v.x0) > 10.0 && y <= v.y1; y += h) {
    if (y >= v.y0) svg.line(v, v.x0, y, v.x1, y, stroke("#000", 0.4, "2 3"));
  }
  for (const auto& f : polygon.faces) {
    const Vec2 &a = polygon.vertices[static_cast<std::size_t>(f[0])],
               &b = polygon.vertices[static_cast<std::size_t>(f[1])];
    svg.line(v, a.x(), a.y(), b.x(), b.y(), stroke("#111", 1.5));
  }
  for (const auto& [a, b] : zeroContour([&](int i, int k) { return at(i, k); }, n + 1, n + 1, v.x0,
                                        v.y0, dx, dy)) {
    svg.line(v, a.first, a.second, b.first, b.second, stroke("#1b7837", 2.5));
  }
}

void cupField() {
  const Polygon cup = uPolygon();
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = 16;
  const SdfGrid<2> grid = buildSdfGrid<2>(cup, settings, "U polygon");
  Svg svg(620, 560, "Signed distance grid of a U-shaped polygon, its zero contour and normals");
  const View v = View::equal(20, 20, 580, 470, -0.75, 0.75, -0.6, 0.6);
  drawField(svg, v, grid, cup, 150, 0.1);
  // Normals from the grid's gradient at points a little outside and inside the surface.
  for (std::size_t s = 0; s < cup.faces.size(); s += 2) {
    const auto& f = cup.faces[s];
    const Vec2 a = cup.vertices[static_cast<std::size_t>(f[0])], b = cup.vertices[static_cast<std::size_t>(f[1])];
    const Vec2 mid = 0.5 * (a + b);
    const Vec2 nrm = grid.normal(mid);
    svg.arrow(v, mid.x(), mid.y(), mid.x() + 0.09 * nrm.x(), mid.y() + 0.09 * nrm.y(), "#222", 1.3);
  }
  // A colour key.
  const View key{160, 515, 300, 14, -0.1, 0.1, 0, 1};
  for (int k = 0; k < 60; ++k) {
    const double a = -0.1 + 0.2 * k / 60.0, b = -0.1 + 0.2 * (k + 1) / 60.0;
    svg.cell(key, a, 0, b, 1, divergingColour(0.5 * (a + b), 0.1));
  }
  svg.textPixels(155, 527, "φ ≤ -0.1 (inside)", "end", "#2166ac", 12);
  svg.textPixels(465, 527, "φ ≥ +0.1 (outside)", "start", "#b2182b", 12);
  svg.textPixels(310, 550, "green: φ = 0 of the grid (h = " + fmt(grid.cellSize(), 4) +
                               ", dotted lines); black: the polygon; arrows: normals ∇φ/|∇φ|",
                 "middle", "#222", 12);
  svg.save("ch06_sdf_cup.svg");
  std::cout << "ch06_sdf_cup.svg: h = " << grid.cellSize() << ", nodes " << grid.nodeCount() << "\n";
}

void thinPlate() {
  const double t = 0.06;
  const Polygon plate = rectanglePolygon(Vec2(1.0, t), 16);
  Svg svg(760, 300, "A plate thinner than a grid cell: a coarse grid loses it, a fine one keeps it");
  int column = 0;
  for (const int cells : {8, 48}) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = cells;
    const SdfGrid<2> grid = buildSdfGrid<2>(plate, settings, "plate");
    const View v = View::equal(20 + 380 * column, 40, 340, 220, -0.62, 0.62, -0.3, 0.3);
    drawField(svg, v, grid, plate, 124, 0.1);
    double largest = -1.0;
    for (int i = 0; i <= 40; ++i) largest = std::max(largest, grid.value(Vec2(-0.4 + 0.02 * i, 0.0)));
    svg.textPixels(v.left + 0.5 * v.width, 26,
                   std::to_string(cells) + " cells across: h = " + fmt(grid.cellSize(), 3) + ", h / t = " +
                       fmt(grid.cellSize() / t, 2),
                   "middle", "#222", 13);
    svg.textPixels(v.left + 0.5 * v.width, v.top + v.height + 20,
                   "largest φ on the mid-line: " + fmt(largest, 3) +
                       (largest > 0.0 ? " (reads as outside)" : " (inside)"),
                   "middle", largest > 0.0 ? "#b2182b" : "#2166ac", 12);
    ++column;
  }
  svg.save("ch06_thin_plate.svg");
}

}  // namespace

int main() {
  cupField();
  thinPlate();
}
