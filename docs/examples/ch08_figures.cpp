// Chapter 8's figures, computed with step(): the unit box on a 20-degree incline
// (mu = 0.5, e = 1: friction holds it) under GBF's order and the traditional order, its
// height above the slope over one second; and a box sliding down a 30-degree incline
// (mu = 0.3) under both orders against the closed form s = a t^2 / 2.
#include <cmath>
#include <iostream>
#include <numbers>

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

}  // namespace

int main() {
  hop();
  slide();
}
