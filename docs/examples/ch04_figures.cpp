// Chapter 4's figures, computed with the chapter's functions on the worked example (a unit
// square of mass 1 landing on its corner r = (0.5, -0.5) at v = (1, -2), e = 0): the
// collision matrix of the square lifted into space as a box of height 1 next to the planar
// K, and the corner's velocity after the impulse in the plane and in space.
#include <cmath>
#include <iostream>

#include "figure_svg.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"
#include "stackbook/impulse/planar_reduction.hpp"

using namespace stackbook;
using namespace figure_svg;

namespace {

struct Square {
  RigidBody<2> square = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 6.0));
  RigidBody<2> floor = makeStaticBody<2>();
  Vec2 r{0.5, -0.5}, n{0.0, 1.0};
  RigidBody<3> box, floor3;
  Square() {
    square.velocity = Vec2(1.0, -2.0);
    box = liftToSpace(square, 1.0 / 6.0, 1.0 / 6.0);  // height 1: I_x = I_y = (1 + 1)/12
    floor3 = liftToSpace(floor);
  }
};

// A matrix drawn as a grid of coloured cells with its entries; `highlight` rows/columns
// (the in-plane block) get a thick frame.
template <typename M>
void matrixGrid(Svg& svg, double left, double top, double cellSize, const M& K, int highlight,
                const std::string& title) {
  const View px{0, 0, 1, 1, 0, 1, 1, 0};  // identity: pixel coordinates, y down
  const int rows = static_cast<int>(K.rows());
  svg.textPixels(left + 0.5 * cellSize * rows, top - 12, title, "middle", "#222", 14);
  for (int i = 0; i < rows; ++i) {
    for (int k = 0; k < rows; ++k) {
      const double x = left + k * cellSize, y = top + i * cellSize;
      const double value = std::abs(K(i, k)) < 1e-14 ? 0.0 : K(i, k);
      svg.cell(px, x, y, x + cellSize, y + cellSize, divergingColour(value, 4.0));
      svg.polygon(px, {{x, y}, {x + cellSize, y}, {x + cellSize, y + cellSize}, {x, y + cellSize}},
                  stroke("#999", 1));
      svg.textPixels(x + 0.5 * cellSize, y + 0.5 * cellSize + 5, fmt(value, 4), "middle", "#111", 14);
    }
  }
  if (highlight > 0) {
    const double s = highlight * cellSize;
    svg.polygon(px, {{left, top}, {left + s, top}, {left + s, top + s}, {left, top + s}},
                stroke("#1b7837", 3.5));
  }
}

void reduction(const Square& s) {
  const Mat2 K2 = pairCollisionMatrix<2>(s.square, s.r, s.floor, s.r);
  const Mat3 K3 = pairCollisionMatrix<3>(s.box, liftToSpace(s.r), s.floor3, liftToSpace(s.r));
  Svg svg(640, 330, "The lifted box's 3 x 3 collision matrix and the square's planar 2 x 2 one");
  matrixGrid(svg, 30, 50, 80, K3, 2, "K of the box in space (x, y, z)");
  matrixGrid(svg, 420, 50, 80, K2, 2, "K of the square in the plane");
  const View px{0, 0, 1, 1, 0, 1, 1, 0};
  svg.arrow(px, 300, 130, 405, 130, "#1b7837", 2.5);
  svg.textPixels(352, 120, "the same block", "middle", "#1b7837", 12);
  svg.textPixels(30, 320, "K_xz = K_yz = 0: an in-plane impulse moves nothing out of the plane", "start",
                 "#444", 12);
  svg.save("ch04_block_split.svg");
  std::cout << "ch04_block_split.svg: |K3 block - K2| = " << (K3.topLeftCorner<2, 2>() - K2).norm()
            << "\n";
}

void landing(const Square& s) {
  const Mat2 K2 = pairCollisionMatrix<2>(s.square, s.r, s.floor, s.r);
  const Vec2 u2 = relativeVelocity<2>(s.square, s.r, s.floor, s.r);
  const Vec3 r3 = liftToSpace(s.r), n3 = liftToSpace(s.n);
  const Mat3 K3 = pairCollisionMatrix<3>(s.box, r3, s.floor3, r3);
  const Vec3 u3 = relativeVelocity<3>(s.box, r3, s.floor3, r3);

  Svg svg(600, 400, "The square's corner velocity before and after the impulse, in the plane and in space");
  const View v = View::equal(20, 20, 560, 360, -1.1, 2.3, -2.3, 1.0);
  svg.line(v, -1.1, 0, 2.3, 0, stroke("#555", 2));
  svg.polygon(v, {{-1.0, 0.0}, {0.0, 0.0}, {0.0, 1.0}, {-1.0, 1.0}}, filled("#e8eef7", "#345", 1.5));
  svg.text(v, -0.5, 0.5, "the square", "middle", 0, 4, "#345", 12);
  svg.text(v, 0.0, 0.0, "corner", "end", -6, 16, "#345", 12);
  // The corner at the origin: r = (0.5, -0.5) from the centre (-0.5, 0.5).
  const double cx = 0.0, cy = 0.0;
  svg.arrow(v, cx, cy, cx + u2.x(), cy + u2.y(), "#444", 2.5);
  svg.text(v, cx + u2.x(), cy + u2.y(), "u before = (1, -2)", "start", 8, 4, "#444", 12);
  const char* colours[2] = {"#1b7837", "#d95f02"};
  int k = 0;
  for (const double mu : {1.0, 0.5}) {
    const ContactImpulse<2> j2 = frictionalImpulse<2>(K2, u2, s.n, 0.0, mu);
    const ContactImpulse<3> j3 = frictionalImpulse<3>(K3, u3, n3, 0.0, mu);
    const Vec2 a2 = u2 + K2 * j2.j;
    const Vec3 a3 = u3 + K3 * j3.j;
    if (a2.norm() < 1e-9) svg.circle(v, cx, cy, 7, filled(colours[k], "#fff", 1.5));  // u' = 0: it sticks
    svg.arrow(v, cx, cy, cx + a2.x(), cy + a2.y(), colours[k], 5);
    svg.arrow(v, cx, cy, cx + a3.x(), cy + a3.y(), "#fff", 1.5, "4 4");
    svg.text(v, cx + a2.x(), cy + a2.y(),
             "μ = " + fmt(mu, 1) + " (" + branchName(j2.branch) + "): u' = (" + fmt(a2.x(), 4) + ", " +
                 fmt(std::abs(a2.y()) < 1e-12 ? 0.0 : a2.y(), 1) + ")",
             "start", 8, k == 0 ? -14 : 20, colours[k], 12);
    ++k;
  }
  svg.legend(330, 250, {{stroke("#1b7837", 5), "after, in the plane (D = 2)"},
                        {stroke("#777", 1.5, "4 4"), "after, lifted to space (D = 3)"}});
  svg.save("ch04_landing_corner.svg");
}

}  // namespace

int main() {
  const Square s;
  reduction(s);
  landing(s);
}
