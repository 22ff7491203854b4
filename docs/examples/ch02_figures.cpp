// Chapter 2's figures, computed with the chapter's functions on the off-centre impact of
// the worked example (a disk hits a box's face above its centre, e = 1): the bodies before
// and after, with where the free motion takes them, and a sweep of the restitution e.
#include <cmath>
#include <iostream>
#include <numbers>

#include "figure_svg.hpp"
#include "stackbook/body/integrate.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"

using namespace stackbook;
using namespace figure_svg;

namespace {

struct OffCentre {
  RigidBody<2> box = makeDynamicBody<2>(2.0, AngVec<2>::Constant(1.0 / 3.0));
  RigidBody<2> disk = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.125));
  Vec2 p{-0.5, 0.3};
  Vec2 n{1.0, 0.0};
  OffCentre() {
    disk.position = Vec2(-1.0, 0.3);
    disk.velocity = Vec2(2.0, 0.0);
  }
  Vec2 ra() const { return p - box.position; }
  Vec2 rb() const { return p - disk.position; }
  /// Apply the frictionless impulse with restitution e; returns j_n.
  double collide(double e) {
    const Mat2 K = pairCollisionMatrix<2>(box, ra(), disk, rb());
    const Vec2 u = relativeVelocity<2>(box, ra(), disk, rb());
    const ContactImpulse<2> impulse = frictionlessImpulse<2>(K, u, n, e);
    applyPairImpulse<2>(box, ra(), disk, rb(), impulse.j);
    return impulse.normal(n);
  }
};

Points boxOutline(const RigidBody<2>& b) {
  Points p;
  for (const Vec2& c : {Vec2(-0.5, -0.5), Vec2(0.5, -0.5), Vec2(0.5, 0.5), Vec2(-0.5, 0.5)}) {
    const Vec2 q = b.position + b.orientation * c;
    p.emplace_back(q.x(), q.y());
  }
  return p;
}

void drawBodies(Svg& svg, const View& v, const RigidBody<2>& box, const RigidBody<2>& disk,
                double opacity, bool marks) {
  const std::string edge = opacity < 1.0 ? "#99a" : "#345";
  svg.polygon(v, boxOutline(box), filled("#e8eef7", edge, 1.2, opacity));
  svg.circle(v, disk.position.x(), disk.position.y(), 0.5 * v.width / (v.x1 - v.x0),
             filled("#f7e8e0", opacity < 1.0 ? "#b99" : "#743", 1.2, opacity));
  if (marks) {  // a line through each body shows its rotation
    const Vec2 a = box.position + box.orientation * Vec2(0.0, 0.5);
    svg.line(v, box.position.x(), box.position.y(), a.x(), a.y(), stroke(edge, 1.2));
    const Vec2 d = disk.position + disk.orientation * Vec2(0.0, 0.5);
    svg.line(v, disk.position.x(), disk.position.y(), d.x(), d.y(), stroke("#743", 1.2));
  }
}

void beforeAfter() {
  OffCentre at;
  const OffCentre before = at;
  const double jn = at.collide(1.0);
  const double dt = 0.2;

  Svg svg(760, 330, "The off-centre impact: before and after, with the free motion either side");
  const View left = View::equal(10, 40, 360, 250, -2.3, 0.9, -0.9, 1.3);
  const View right = View::equal(390, 40, 360, 250, -1.9, 1.3, -0.9, 1.3);
  svg.textPixels(190, 24, "before: approaching (every 0.2 s)", "middle", "#222", 14);
  svg.textPixels(570, 24, "after: e = 1, j_n = " + fmt(jn, 3) + " (every 0.2 s)", "middle", "#222", 14);
  // Before: where the bodies were 0.4 s and 0.2 s earlier (they move freely, no gravity).
  for (int k = 2; k >= 1; --k) {
    RigidBody<2> box = before.box, disk = before.disk;
    disk.position -= k * dt * disk.velocity;
    drawBodies(svg, left, box, disk, 0.35, false);
  }
  drawBodies(svg, left, before.box, before.disk, 1.0, true);
  svg.arrow(left, before.disk.position.x(), before.disk.position.y(),
            before.disk.position.x() + 0.4 * before.disk.velocity.x(), before.disk.position.y(),
            "#b2182b", 2.5);
  svg.text(left, before.disk.position.x(), before.disk.position.y(), "v = (2, 0)", "middle", 10, 36,
           "#b2182b");
  svg.text(left, before.box.position.x(), before.box.position.y(), "at rest", "middle", 0, 36,
           "#345");
  // After: the state right after the impulse, then the free motion for 0.2 s and 0.4 s.
  for (int k = 1; k <= 2; ++k) {
    RigidBody<2> box = at.box, disk = at.disk;
    for (int s = 0; s < 20 * k; ++s) {
      advanceFreeBody<2>(box, dt / 20.0);
      advanceFreeBody<2>(disk, dt / 20.0);
    }
    drawBodies(svg, right, box, disk, 0.35, true);
  }
  drawBodies(svg, right, at.box, at.disk, 1.0, true);
  svg.arrow(right, at.p.x(), at.p.y(), at.p.x() + 0.35 * jn / 2.0, at.p.y(), "#1b7837", 3);
  svg.text(right, at.p.x(), at.p.y(), "j on the box", "start", 4, -28, "#1b7837", 12);
  svg.arrow(right, at.box.position.x(), at.box.position.y(),
            at.box.position.x() + 0.4 * at.box.velocity.x(), at.box.position.y(), "#2166ac", 2.5);
  svg.arrow(right, at.disk.position.x(), at.disk.position.y(),
            at.disk.position.x() + 0.4 * at.disk.velocity.x(), at.disk.position.y(), "#b2182b", 2.5);
  svg.text(right, at.box.position.x(), at.box.position.y(),
           "v = " + fmt(at.box.velocity.x(), 3) + ", ω = " + fmt(at.box.angularVelocity[0], 3),
           "middle", 0, 78, "#2166ac", 12);
  svg.text(right, at.disk.position.x(), at.disk.position.y(), "v = " + fmt(at.disk.velocity.x(), 3),
           "middle", 0, 40, "#b2182b", 12);
  svg.save("ch02_off_centre_impact.svg");
  std::cout << "ch02_off_centre_impact.svg: j_n = " << jn << "\n";
}

void restitutionSweep() {
  const OffCentre start;
  const double keBefore = start.box.kineticEnergy() + start.disk.kineticEnergy();
  const double unBefore = relativeVelocity<2>(start.box, start.ra(), start.disk, start.rb()).dot(start.n);
  Points speed, energy;
  for (int k = 0; k <= 60; ++k) {
    const double e = -0.5 + 1.5 * k / 60.0;
    OffCentre s = start;
    s.collide(e);
    const double un = relativeVelocity<2>(s.box, s.ra(), s.disk, s.rb()).dot(s.n);
    speed.emplace_back(e, un / -unBefore);
    energy.emplace_back(e, (s.box.kineticEnergy() + s.disk.kineticEnergy()) / keBefore);
  }
  Svg svg(600, 440, "Normal velocity and kinetic energy after the impact against the restitution e");
  const View v{80, 20, 490, 300, -0.5, 1.0, -0.6, 1.05};
  svg.axes(v, "restitution e", "after the impact", 6, 8);
  svg.line(v, -0.5, 0, 1, 0, stroke("#888", 1));
  svg.polyline(v, speed, stroke("#b2182b", 2.5));
  svg.polyline(v, energy, stroke("#2166ac", 2.5));
  // The key below the plot, where it covers no curve.
  svg.legend(90, 370, {{stroke("#b2182b", 2.5), "normal velocity u_n' / |u_n|  (= e)"},
                        {stroke("#2166ac", 2.5), "kinetic energy after / before"}});
  svg.save("ch02_restitution_sweep.svg");
  std::cout << "ch02_restitution_sweep.svg: energy kept at e = 0: " << energy[20].second << "\n";
}

}  // namespace

int main() {
  beforeAfter();
  restitutionSweep();
}
