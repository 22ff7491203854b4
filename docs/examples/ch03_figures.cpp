// Chapter 3's figures, computed with frictionalImpulse: a 2 x 1 box turned by 20 degrees
// lands on a corner (u_n = -1, e = 0, mu = 0.5) while sliding at a tangential speed u_t.
// For each u_t: the sticking trial j* of Eq. (3.2) and the impulse the library applies,
// drawn in the (j_t, j_n) plane with the friction cone |j_t| <= mu j_n of Eq. (3.3); and the
// tangential velocity left after the impulse, which is zero while the contact sticks.
#include <cmath>
#include <iostream>
#include <numbers>

#include "figure_svg.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"

using namespace stackbook;
using namespace figure_svg;

namespace {

constexpr double kMu = 0.5;
constexpr double kRestitution = 0.0;

struct Landing {
  RigidBody<2> box = makeDynamicBody<2>(1.0, AngVec<2>::Constant(5.0 / 12.0));
  RigidBody<2> ground = makeStaticBody<2>();
  Vec2 r = Vec2::Zero();
  Vec2 n{0.0, 1.0};
  Mat2 K = Mat2::Zero();
  Landing() {
    box.orientation = Eigen::Rotation2Dd(20.0 * std::numbers::pi / 180.0);
    r = box.orientation * Vec2(-1.0, -0.5);  // the lowest corner
    K = pairCollisionMatrix<2>(box, r, ground, Vec2::Zero());
  }
  struct Result {
    Vec2 trial, applied, after;
    ImpulseBranch branch;
  };
  /// The contact slides to the right at ut and approaches at 1.
  Result at(double ut) const {
    const Vec2 u(ut, -1.0);
    Result result;
    result.trial = K.ldlt().solve(Vec2(-kRestitution * u.dot(n) * n - u));  // Eq. (3.2)
    const ContactImpulse<2> j = frictionalImpulse<2>(K, u, n, kRestitution, kMu);
    result.applied = j.j;
    result.branch = j.branch;
    result.after = u + K * j.j;
    return result;
  }
};

void cone(const Landing& s) {
  const double speeds[] = {-1.5, -1.0, -0.5, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5};
  double top = 0.0, bottom = 0.0, right = 0.0, left = 0.0;
  for (double ut : speeds) {
    const Landing::Result r = s.at(ut);
    for (const Vec2& p : {r.trial, r.applied}) {
      top = std::max(top, p.y()), bottom = std::min(bottom, p.y());
      right = std::max(right, p.x()), left = std::min(left, p.x());
    }
  }
  top *= 1.08, right += 0.3, left -= 0.1, bottom -= 0.05;
  Svg svg(620, 420, "Sticking trials and applied impulses in the (j_t, j_n) plane, with the friction cone");
  const View v{80, 20, 510, 330, left, right, bottom, top};
  svg.axes(v, "tangential impulse j_t", "normal impulse j_n", 8, 6);
  // The cone |j_t| <= mu j_n, shaded.
  svg.polygon(v, {{0, 0}, {-kMu * top, top}, {kMu * top, top}}, filled("#d9f0d3", "none", 0, 0.8));
  svg.line(v, 0, 0, -kMu * top, top, stroke("#1b7837", 2));
  svg.line(v, 0, 0, kMu * top, top, stroke("#1b7837", 2));
  for (double ut : speeds) {
    const Landing::Result r = s.at(ut);
    const bool sticks = r.branch == ImpulseBranch::Sticking;
    const std::string colour = sticks ? "#1b7837" : "#d95f02";
    if (!sticks) {
      svg.line(v, r.trial.x(), r.trial.y(), r.applied.x(), r.applied.y(), stroke("#888", 1.2, "4 3"));
      svg.circle(v, r.trial.x(), r.trial.y(), 5, stroke("#d95f02", 1.8));
    }
    svg.circle(v, r.applied.x(), r.applied.y(), 5, filled(colour, colour));
    svg.text(v, r.trial.x(), r.trial.y(), "u_t = " + fmt(ut, 2), "start", 8, 4, "#444", 11);
  }
  svg.legend(90, 28, {{stroke("#1b7837", 2), "cone edge |j_t| = μ j_n"},
                      {stroke("#1b7837", 6), "sticking: trial j* accepted"},
                      {stroke("#d95f02", 1.8), "trial j* outside the cone"},
                      {stroke("#d95f02", 6), "sliding impulse, on the edge"}});
  svg.save("ch03_friction_cone.svg");
}

void afterSlip(const Landing& s) {
  Points slip, ratio;
  double stickFrom = 1e9, stickTo = -1e9;
  for (int k = 0; k <= 240; ++k) {
    const double ut = -2.0 + 4.0 * k / 240.0;
    const Landing::Result r = s.at(ut);
    slip.emplace_back(ut, r.after.x());
    ratio.emplace_back(ut, std::abs(r.applied.x()) / r.applied.y());
    if (r.branch == ImpulseBranch::Sticking) {
      stickFrom = std::min(stickFrom, ut);
      stickTo = std::max(stickTo, ut);
    }
  }
  Svg svg(620, 380, "Tangential velocity after the impulse and the friction used, against the slip before");
  double low = 0.0, high = kMu;
  for (const auto& p : slip) low = std::min(low, p.second), high = std::max(high, p.second);
  const View v{80, 20, 510, 290, -2.0, 2.0, low - 0.1, high + 0.25};
  svg.axes(v, "tangential velocity before the impulse, u_t", "after the impulse", 8, 8);
  svg.cell(v, stickFrom, v.y0, stickTo, v.y1, "#e3f2dc");
  svg.text(v, 0.5 * (stickFrom + stickTo), v.y1, "sticking", "middle", 0, 16, "#1b7837", 13);
  svg.text(v, -1.6, v.y1, "sliding", "middle", 0, 16, "#d95f02", 13);
  svg.text(v, 1.6, v.y1, "sliding", "middle", 0, 16, "#d95f02", 13);
  svg.line(v, -2, kMu, 2, kMu, stroke("#1b7837", 1, "4 3"));
  svg.text(v, 2.0, kMu, "μ", "end", -4, -5, "#1b7837", 13, true);
  svg.polyline(v, slip, stroke("#b2182b", 2.5));
  svg.polyline(v, ratio, stroke("#2166ac", 2.5));
  svg.legend(360, 250, {{stroke("#b2182b", 2.5), "tangential velocity left, u_t'"},
                       {stroke("#2166ac", 2.5), "friction used, |j_t| / j_n"}});
  svg.save("ch03_stick_slide.svg");
  std::cout << "ch03_stick_slide.svg: the contact sticks for u_t in [" << stickFrom << ", " << stickTo
            << "]\n";
}

}  // namespace

int main() {
  const Landing s;
  cone(s);
  afterSlip(s);
}
