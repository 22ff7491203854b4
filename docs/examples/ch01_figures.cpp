// Chapter 1's figures, computed with the chapter's functions: a box pushed at a corner
// (the lever arm r, the impulse j, what it does to the centre and to the corner) and K's
// action on every unit impulse at that corner (an ellipse whose axes are K's eigenvectors).
#include <cmath>
#include <iostream>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "figure_svg.hpp"
#include "stackbook/impulse/collision_matrix.hpp"

using namespace stackbook;
using namespace figure_svg;

namespace {

// A 2 x 1 box of mass 1, turned by 20 degrees; the corner it is pushed at.
struct Setup {
  double w = 2.0, h = 1.0, m = 1.0;
  RigidBody<2> box = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 * (4.0 + 1.0) / 12.0));
  RigidBody<2> ground = makeStaticBody<2>();
  Vec2 corner = Vec2::Zero();
  Setup() {
    box.position = Vec2(0.0, 0.0);
    box.orientation = Eigen::Rotation2Dd(20.0 * std::numbers::pi / 180.0);
    corner = box.position + box.orientation * Vec2(0.5 * w, -0.5 * h);
  }
  Points outline() const {
    Points p;
    for (const Vec2& c : {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}) {
      const Vec2 q = box.position + box.orientation * Vec2(0.5 * w * c.x(), 0.5 * h * c.y());
      p.emplace_back(q.x(), q.y());
    }
    return p;
  }
};

void leverArm(const Setup& s) {
  const Vec2 r = s.corner - s.box.position;
  const Vec2 j(0.0, 0.35);  // a push straight up at the corner
  RigidBody<2> moved = s.box;
  RigidBody<2> ground = s.ground;
  const Vec2 before = relativeVelocity<2>(moved, r, ground, Vec2::Zero());
  applyPairImpulse<2>(moved, r, ground, Vec2::Zero(), j);
  const Vec2 du = relativeVelocity<2>(moved, r, ground, Vec2::Zero()) - before;  // = K j
  const Vec2 dv = moved.velocity - s.box.velocity;                               // = j / m
  const double dw = moved.angularVelocity[0] - s.box.angularVelocity[0];

  Svg svg(640, 440, "A box pushed at a corner: the lever arm, the impulse and its effect");
  const View v = View::equal(20, 20, 600, 400, -2.2, 2.4, -1.3, 1.6);
  svg.polygon(v, s.outline(), filled("#e8eef7", "#345", 1.5));
  svg.circle(v, 0, 0, 4, filled("#222"));
  svg.text(v, 0, 0, "x", "end", -8, -6, "#222", 15, true);
  svg.arrow(v, 0, 0, r.x(), r.y(), "#777", 1.5, "5 3");
  svg.text(v, 0.5 * r.x(), 0.5 * r.y(), "r", "start", 4, 18, "#555", 15, true);
  svg.arrow(v, s.corner.x(), s.corner.y(), s.corner.x() + j.x(), s.corner.y() + j.y(), "#1b7837", 3);
  svg.text(v, s.corner.x() + j.x(), s.corner.y() + j.y(), "impulse j", "start", 14, 8, "#1b7837");
  svg.arrow(v, 0, 0, dv.x(), dv.y(), "#2166ac", 3);
  svg.text(v, dv.x(), dv.y(), "Δv = j/m", "start", 8, 10, "#2166ac");
  svg.arrow(v, s.corner.x(), s.corner.y(), s.corner.x() + du.x(), s.corner.y() + du.y(), "#b2182b", 3);
  svg.text(v, s.corner.x() + du.x(), s.corner.y() + du.y(), "Δu = K j at the corner", "end", -12, 6,
           "#b2182b");
  // The spin the lever arm adds: an arc about the centre, in the sense of dw.
  Points arc;
  for (int k = 0; k <= 24; ++k) {
    const double a = (200.0 + (dw > 0 ? 1 : -1) * 5.0 * k) * std::numbers::pi / 180.0;
    arc.emplace_back(0.3 * std::cos(a), 0.3 * std::sin(a));
  }
  svg.polyline(v, arc, stroke("#2166ac", 2));
  const auto& tip = arc.back();
  svg.arrow(v, arc[arc.size() - 5].first, arc[arc.size() - 5].second, tip.first, tip.second, "#2166ac", 2);
  // Below the box, clear of its outline: the box's lowest corner is at y = -0.81.
  svg.text(v, -0.2, -1.05, "spin Δω = r × j / I = " + fmt(dw, 3) + " (blue arc)", "middle", 0, 0, "#2166ac");
  svg.text(v, s.corner.x(), s.corner.y(), "p", "start", 6, 14, "#222", 15, true);
  svg.save("ch01_lever_arm.svg");
  std::cout << "ch01_lever_arm.svg: |K j| = " << du.norm() << ", |j/m| = " << dv.norm() << "\n";
}

void kEllipse(const Setup& s) {
  const Vec2 r = s.corner - s.box.position;
  const Mat2 K = pairCollisionMatrix<2>(s.box, r, s.ground, Vec2::Zero());
  const Eigen::SelfAdjointEigenSolver<Mat2> eigen(K);

  Svg svg(740, 480, "The collision matrix K maps unit impulses to an ellipse of velocity changes");
  const double range = 1.15 * std::max(1.0, eigen.eigenvalues()[1]);
  const View v = View::equal(70, 20, 370, 400, -0.75 * range, 0.75 * range, -range, range);
  svg.axes(v, "x component", "y component", 6, 6);
  Points circle, ellipse;
  for (int k = 0; k <= 120; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 120.0;
    const Vec2 j(std::cos(a), std::sin(a));
    const Vec2 u = K * j;
    circle.emplace_back(j.x(), j.y());
    ellipse.emplace_back(u.x(), u.y());
  }
  svg.polyline(v, circle, stroke("#1b7837", 1.5, "5 3"));
  svg.polyline(v, ellipse, stroke("#b2182b", 2.5));
  // The axes of the ellipse: each eigenvector scaled by its eigenvalue, named in the key.
  for (int i = 0; i < 2; ++i) {
    const Vec2 e = eigen.eigenvectors().col(i) * eigen.eigenvalues()[i];
    svg.arrow(v, 0, 0, e.x(), e.y(), "#444", 1.8);
    svg.text(v, e.x(), e.y(), i == 0 ? "a" : "b", "end", -6, i == 0 ? -6 : 14, "#444", 13, true);
  }
  // One unit impulse and its image: K turns it away from itself.
  const Vec2 j(0.0, 1.0);
  const Vec2 u = K * j;
  svg.arrow(v, 0, 0, j.x(), j.y(), "#1b7837", 2.5);
  svg.text(v, j.x(), j.y(), "j = (0, 1)", "start", 6, -4, "#1b7837");
  svg.arrow(v, 0, 0, u.x(), u.y(), "#b2182b", 2.5);
  svg.text(v, u.x(), u.y(), "K j", "start", 6, -2, "#b2182b");
  svg.legend(462, 24, {{stroke("#1b7837", 1.5, "5 3"), "unit impulses j"},
                      {stroke("#b2182b", 2.5), "velocity changes K j"},
                      {stroke("#444", 1.8), "axes a, b: eigenvectors of K"}});
  svg.textPixels(470, 116, "a: eigenvalue " + fmt(eigen.eigenvalues()[0], 3) + " = 1/m, along r", "start",
                 "#444", 12);
  svg.textPixels(470, 136, "b: eigenvalue " + fmt(eigen.eigenvalues()[1], 3) + ", across r", "start",
                 "#444", 12);
  svg.save("ch01_k_ellipse.svg");
  std::cout << "ch01_k_ellipse.svg: eigenvalues " << eigen.eigenvalues().transpose() << "\n";
}

}  // namespace

int main() {
  const Setup s;
  leverArm(s);
  kEllipse(s);
}
