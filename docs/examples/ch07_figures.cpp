// Chapter 7's figures, computed with pairInterference: two U-shaped bodies (GridShape, a
// signed distance grid each, their vertices as samples) hooked into each other, with every
// sample and the ones found inside the other body, and their normals; and a box whose
// two thin planks crossing like an X, whose overlap only samples along the edges find.
#include <cmath>
#include <iostream>
#include <numbers>

#include "figure_svg.hpp"
#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

using namespace stackbook;
using namespace figure_svg;

namespace {

Points worldOutline(const Polygon& mesh, const RigidBody<2>& body) {
  Points p;
  for (const Vec2& v : mesh.vertices) {
    const Vec2 w = body.position + body.orientation * v;
    p.emplace_back(w.x(), w.y());
  }
  return p;
}

void drawMesh(Svg& svg, const View& v, const Polygon& mesh, const RigidBody<2>& body,
              const std::string& fill, const std::string& edge) {
  // The mesh's segments form one loop; draw it filled, then its samples.
  Points loop;
  int at = mesh.faces.front()[0];
  for (std::size_t k = 0; k < mesh.faces.size(); ++k) {
    const Vec2 w = body.position + body.orientation * mesh.vertices[static_cast<std::size_t>(at)];
    loop.emplace_back(w.x(), w.y());
    for (const auto& f : mesh.faces) {
      if (f[0] == at) {
        at = f[1];
        break;
      }
    }
  }
  svg.polygon(v, loop, filled(fill, edge, 1.5, 0.85));
  for (const auto& [x, y] : worldOutline(mesh, body)) svg.circle(v, x, y, 2.2, filled("#555", "none", 0));
}

void drawFound(Svg& svg, const View& v, const std::vector<InterferenceSample<2>>& found) {
  for (const InterferenceSample<2>& s : found) {
    svg.circle(v, s.point.x(), s.point.y(), 4.5, filled("#b2182b", "#fff", 1));
    svg.arrow(v, s.point.x(), s.point.y(), s.point.x() + 0.12 * s.normal.x(),
              s.point.y() + 0.12 * s.normal.y(), "#b2182b", 1.6);
  }
}

void hookedCups() {
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = 32;
  const GridShape<2> cupA(uPolygon(), "cup A", settings);
  const GridShape<2> cupB(uPolygon(), "cup B", settings);
  RigidBody<2> a = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.1));
  RigidBody<2> b = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.1));
  b.orientation = Eigen::Rotation2Dd(std::numbers::pi + 0.05);  // upside down, a little turned
  b.position = Vec2(0.62, 0.06);
  const std::vector<CollisionBody<2>> bodies = {collisionBody<2>(a, cupA), collisionBody<2>(b, cupB)};
  const std::vector<InterferenceSample<2>> found = pairInterference<2>(bodies, {0, 1});

  Svg svg(600, 520, "Two U-shaped bodies hooked into each other: samples and the interference found");
  const View v = View::equal(20, 20, 560, 440, -0.7, 1.3, -0.55, 0.65);
  drawMesh(svg, v, cupA.mesh(), a, "#e8eef7", "#345");
  drawMesh(svg, v, cupB.mesh(), b, "#f7ece0", "#743");
  drawFound(svg, v, found);
  svg.text(v, 0.0, -0.45, "A: upright", "middle", 0, 8, "#345", 13);
  svg.text(v, 0.95, 0.55, "B: upside down", "middle", 0, 0, "#743", 13);
  int fromA = 0, fromB = 0;
  for (const auto& s : found) (s.owner == 0 ? fromA : fromB)++;
  svg.textPixels(300, 490, "grey dots: samples (mesh vertices); red: " + std::to_string(fromA) +
                               " samples of A inside B and " + std::to_string(fromB) + " of B inside A,",
                 "middle", "#222", 12);
  svg.textPixels(300, 508, "each with the normal of the body it is inside (the way out)", "middle", "#222", 12);
  svg.save("ch07_hooked_cups.svg");
  std::cout << "ch07_hooked_cups.svg: " << fromA << " samples of A in B, " << fromB << " of B in A\n";
}

void edgeSamples() {
  // Two thin planks crossing like an X: their outlines cross, but no corner of either is
  // inside the other, so corner samples alone see nothing.
  Svg svg(760, 300, "Two crossing planks: corner samples miss the overlap, samples along the edges find it");
  int column = 0;
  for (const int subdivisions : {1, 12}) {
    const BoxShape<2> plank(BoxSdf<2>(Vec2(1.0, 0.08)), rectanglePolygon(Vec2(2.0, 0.16), subdivisions));
    RigidBody<2> a = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.1));
    RigidBody<2> b = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.1));
    a.orientation = Eigen::Rotation2Dd(0.3);
    b.orientation = Eigen::Rotation2Dd(-0.3);
    const std::vector<CollisionBody<2>> bodies = {collisionBody<2>(a, plank), collisionBody<2>(b, plank)};
    const std::vector<InterferenceSample<2>> found = pairInterference<2>(bodies, {0, 1});
    const View v = View::equal(20 + 380 * column, 40, 340, 220, -1.05, 1.05, -0.45, 0.45);
    drawMesh(svg, v, plank.mesh(), a, "#e8eef7", "#345");
    drawMesh(svg, v, plank.mesh(), b, "#f7ece0", "#743");
    drawFound(svg, v, found);
    svg.textPixels(v.left + 0.5 * v.width, 26,
                   std::to_string(plank.surfaceSamples().size()) + " samples on each plank", "middle", "#222", 13);
    svg.textPixels(v.left + 0.5 * v.width, v.top + v.height + 22,
                   found.empty() ? "no sample inside the other plank: the overlap is not seen"
                                 : std::to_string(found.size()) + " samples inside the other plank",
                   "middle", found.empty() ? "#b2182b" : "#1b7837", 12);
    ++column;
  }
  svg.save("ch07_edge_samples.svg");
}

}  // namespace

int main() {
  hookedCups();
  edgeSamples();
}
