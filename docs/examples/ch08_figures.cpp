// Chapter 8's figures, computed with step(): the unit box on a 20-degree incline
// (mu = 0.5, e = 1: friction holds it) under GBF's order and the traditional order, its
// height above the slope over one second; and a box sliding down a 30-degree incline
// (mu = 0.3) under both orders against the closed form s = a t^2 / 2.
#include <cmath>
#include <iostream>
#include <numbers>

#include "../../tests/ch08/rocking_block.hpp"    // the rocking block of the tests
#include "../../tests/ch08/scene_builders.hpp"  // the incline of the chapter's tests
#include "figure_svg.hpp"

using namespace stackbook;
using namespace figure_svg;
using stackbook::testing::kG;

namespace {

const char* orderName(StepOrder order) { return order == StepOrder::Gbf ? "GBF's order" : "traditional order"; }

void hop() {
  const char* colours[2] = {"#1b7837", "#b2182b"};
  Points lift[2], slid[2];
  int c = 0;
  for (const StepOrder order : {StepOrder::Gbf, StepOrder::Traditional}) {
    testing::InclineScene<2> scene = testing::makeIncline<2>(20.0 * std::numbers::pi / 180.0, 0.5, 1.0);
    StepSettings settings;
    settings.order = order;
    lift[c].emplace_back(0.0, 1e3 * scene.lift());
    slid[c].emplace_back(0.0, 1e3 * scene.travelled());
    const long steps = std::lround(1.0 / settings.dt);
    for (long n = 1; n <= steps; ++n) {
      step<2>(scene.world, settings);
      lift[c].emplace_back(static_cast<double>(n) * settings.dt, 1e3 * scene.lift());
      slid[c].emplace_back(static_cast<double>(n) * settings.dt, 1e3 * scene.travelled());
    }
    ++c;
  }
  auto range = [](const Points (&p)[2]) {
    double lo = 0.0, hi = 0.0;
    for (const Points& q : p) {
      for (const auto& [t, y] : q) lo = std::min(lo, y), hi = std::max(hi, y);
    }
    const double pad = 0.08 * std::max(hi - lo, 1e-3);
    return std::pair{lo - pad, hi + pad};
  };
  Svg svg(660, 590, "A box on a 20-degree incline under both step orders: distance slid and height");
  const auto [s0, s1] = range(slid);
  const View top{90, 20, 540, 190, 0.0, 1.0, s0, s1};
  svg.axes(top, "time (s)", "slid down the slope (mm)", 5, 5);
  const auto [l0, l1] = range(lift);
  const View bottom{90, 290, 540, 190, 0.0, 1.0, l0, l1};
  svg.axes(bottom, "time (s)", "height above resting (mm)", 5, 5);
  for (int k = 0; k < 2; ++k) {
    svg.polyline(top, slid[k], stroke(colours[k], 2.2));
    svg.polyline(bottom, lift[k], stroke(colours[k], 2.2));
  }
  svg.legend(100, 532, {{stroke(colours[0], 2.2), "GBF's order: the box stays where it was put"},
                        {stroke(colours[1], 2.2), "traditional order: it sinks into the slope and creeps down"}});
  svg.save("ch08_incline_hop.svg");
  std::cout << "ch08_incline_hop.svg: after 1 s, traditional order slid " << slid[1].back().second
            << " mm, height " << lift[1].back().second << " mm\n";
}

void slide() {
  const double theta = 30.0 * std::numbers::pi / 180.0, mu = 0.3, duration = 1.0;
  const double a = kG * (std::sin(theta) - mu * std::cos(theta));
  Svg svg(660, 380, "Distance slid down a 30-degree incline against the closed form, both step orders");
  const View v{80, 20, 550, 290, 0.0, duration, 0.0, 0.5 * a * duration * duration * 1.05};
  svg.axes(v, "time (s)", "distance down the slope (m)", 5, 6);
  Points exact;
  for (int k = 0; k <= 100; ++k) {
    const double t = duration * k / 100.0;
    exact.emplace_back(t, 0.5 * a * t * t);
  }
  svg.polyline(v, exact, stroke("#999", 6));
  const char* colours[2] = {"#1b7837", "#b2182b"};
  const char* dashes[2] = {"", "6 4"};
  int c = 0;
  std::vector<std::pair<Style, std::string>> legend{{stroke("#999", 6), "closed form a t²/2"}};
  for (const StepOrder order : {StepOrder::Gbf, StepOrder::Traditional}) {
    testing::InclineScene<2> scene = testing::makeIncline<2>(theta, mu, 0.0);
    StepSettings settings;
    settings.order = order;
    Points s{{0.0, 0.0}};
    const long steps = std::lround(duration / settings.dt);
    for (long n = 1; n <= steps; ++n) {
      step<2>(scene.world, settings);
      if (n % 10 == 0) s.emplace_back(static_cast<double>(n) * settings.dt, scene.travelled());
    }
    svg.polyline(v, s, stroke(colours[c], 2, dashes[c]));
    legend.push_back({stroke(colours[c], 2, dashes[c]),
                      std::string(orderName(order)) + ": " + fmt(scene.travelled(), 4) + " m at 1 s"});
    ++c;
  }
  legend.push_back({stroke("#fff", 0), "closed form: " + fmt(0.5 * a * duration * duration, 4) + " m"});
  svg.legend(90, 30, legend);
  svg.save("ch08_incline_slide.svg");
}

/// Figure 8.2: a block rocking about corner A lands on corner B (Eq. (8.20)). Left: just
/// before the landing, turning about A at omega, its centre moving on the circle about A.
/// Right: just after, turning about B at r omega; the impulse J acts at B.
void rocking() {
  const double b = 0.1, h = 0.3, r = stackbook::testing::housnerRatio(b, h);
  Svg svg(700, 360, "A rocking block lands on its other corner: before and after the impulse at B");
  const std::string ink = "#2a6f97", impulse = "#c0392b", floorInk = "#555";
  const auto panel = [&](double left, double tilt, bool after) {
    const View v = View::equal(left, 40, 330, 280, -0.22, 0.42, -0.06, 0.68);
    svg.line(v, -0.2, 0.0, 0.4, 0.0, stroke(floorInk, 2.0));
    for (double x = -0.19; x < 0.4; x += 0.04) svg.line(v, x, 0.0, x - 0.03, -0.03, stroke(floorInk, 1.0));
    // The block on its pivot: before, on A at the origin with B above the floor; after, on B.
    const double c = std::cos(tilt), s = std::sin(tilt);
    const double px = after ? 2.0 * b : 0.0;  // the pivot
    const double sx = after ? -2.0 * b : 0.0; // the pivot's offset from A in the block's frame
    const auto at = [&](double x, double y) {  // block frame, A at (0, 0), to world
      const double X = x + sx, Y = y;
      return std::make_pair(px + c * X - s * Y, s * X + c * Y);
    };
    Points block = {at(0, 0), at(2 * b, 0), at(2 * b, 2 * h), at(0, 2 * h)};
    svg.polygon(v, block, filled("#dbe9f3", ink, 1.8));
    const auto [cx, cy] = at(b, h);
    svg.circle(v, cx, cy, 3.5, filled(ink, ink));
    svg.text(v, cx, cy, "C", "start", 7, -6, ink);
    const auto [ax, ay] = at(0, 0);
    const auto [bx, by] = at(2 * b, 0);
    svg.text(v, ax, ay, "A", "end", -6, 16);
    svg.text(v, bx, by, "B", "start", 6, 16);
    // Turning about the pivot: an arc and the centre's velocity, perpendicular to C - pivot.
    const double pivotX = after ? bx : ax, pivotY = after ? by : ay;
    const double dx = cx - pivotX, dy = cy - pivotY;
    const double speed = (after ? r : 1.0) * 0.18;
    svg.arrow(v, cx, cy, cx + speed * dy / std::hypot(dx, dy), cy - speed * dx / std::hypot(dx, dy), ink, 2.2);
    svg.text(v, cx + speed * dy / std::hypot(dx, dy), cy - speed * dx / std::hypot(dx, dy),
             after ? "r ω" : "ω", "start", 6, 4, ink, 14, true);
    svg.circle(v, pivotX, pivotY, 5, filled("white", ink, 2.0));
    if (after) svg.arrow(v, bx + 0.035, by - 0.05, bx + 0.005, by - 0.004, impulse, 2.6);
    if (after) svg.text(v, bx + 0.035, by - 0.05, "J", "start", 4, 6, impulse, 14, true);
    svg.text(v, 0.1, 0.66, after ? "just after: about B" : "just before: about A", "middle", 0, 0, "#222", 14);
  };
  panel(10, 0.06, false);
  panel(360, -0.06, true);
  svg.save("ch08_rocking.svg");
  std::cout << "ch08_rocking.svg: b/h = " << b / h << ", Housner's ratio r = " << r << "\n";
}

}  // namespace

int main() {
  hop();
  slide();
  rocking();
}
