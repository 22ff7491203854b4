// Chapter 12, "Freezing only what carries its load": A19's tower (ten unit boxes, each offset 0.2
// from the one below) at rest, as the carrying pass sees it at its first step. loadCarrying()
// gives each box's load W (Eq. (12.2)), its centre of load x* seen along gravity, the end of its
// support region (the patch on the box below, or the ground) and whether it carries its load
// (Eq. (12.4)); joinUncarried() and topologicalLevels() give the levels the pass then sweeps
// (Eq. (12.5)). Prints the table and draws Figure 12.1: the tower, each box coloured by whether
// it carries, its centre of load as a dot and its support region as a bar under it.
#include <algorithm>
#include <cstdio>
#include <string>

#include "../../tests/ch09/stack_scenes.hpp"
#include "figure_svg.hpp"
#include "stackbook/stacking/load_carrying.hpp"

using namespace stackbook;
using namespace figure_svg;

int main() {
  const World<2> world = stacks::boxStack<2>(10, Material{0.0, 0.6, 0.0}, 0.2);
  ContactGraphSettings g;
  g.dt = 1.0 / 60.0;
  const ContactGraph graph = worldContactGraph<2>(world, g);
  const ContactLevels gbfLevels = topologicalLevels(graph);
  const LoadCarrying<2> loads = loadCarrying<2>(world, graph, gbfLevels, g.dt, g.rotation, g.narrow, 0.0);
  const ContactLevels joined = topologicalLevels(joinUncarried(graph, loads.carries, staticBodies<2>(world), gbfLevels));
  // The support region of box k: from its lower edge's overlap with the body below.
  const auto supportEnds = [&](int k) {
    const double x = world.bodies[static_cast<std::size_t>(k)].position.x();
    const double below = k == 1 ? 0.0 : world.bodies[static_cast<std::size_t>(k - 1)].position.x();
    const double half = k == 1 ? 100.0 : 0.5;
    return std::pair<double, double>(std::max(x - 0.5, below - half), std::min(x + 0.5, below + half));
  };
  std::printf("| box | centre x (m) | load W (boxes) | centre of load x* (m) | support region (m) | carries | level: GBF / joined |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (int k = 10; k >= 1; --k) {
    const std::size_t i = static_cast<std::size_t>(k);
    const auto [lo, hi] = supportEnds(k);
    std::printf("| %d | %.2f | %.0f | %.3f | [%.2f, %.2f] | %s | %d / %d |\n", k, world.bodies[i].position.x(), loads.weight[i],
                loads.centre[i][0], lo, hi, loads.carries[i] != 0 ? "yes" : "**no**", gbfLevels.levelOfBody[i],
                joined.levelOfBody[i]);
  }
  std::printf("\nTable: the leaning tower at rest under the carrying pass's test, box 10 at the top; box 1 stands on the ground.\n");

  Svg svg(560, 560, "A19's tower: each box's centre of load and support region, green where it carries its load");
  const View v = View::equal(20, 20, 520, 520, -1.2, 3.0, -0.3, 10.3);
  svg.line(v, -1.2, 0.0, 3.0, 0.0, stroke("#555", 2.0));
  for (int k = 1; k <= 10; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    const Vec2 c = world.bodies[i].position;
    const bool carries = loads.carries[i] != 0;
    svg.polygon(v, {{c.x() - 0.5, c.y() - 0.5}, {c.x() + 0.5, c.y() - 0.5}, {c.x() + 0.5, c.y() + 0.5}, {c.x() - 0.5, c.y() + 0.5}},
                filled(carries ? "#b2df8a" : "#fb9a99", "#333", 1.2));
    const auto [lo, hi] = supportEnds(k);
    const double bar = c.y() - 0.5 + 0.06;
    svg.line(v, std::max(lo, -1.2), bar, hi, bar, stroke("#1f78b4", 4.0));
    svg.circle(v, loads.centre[i][0], c.y(), 5.0, filled("#222", "#222", 1.0));
    svg.text(v, c.x() - 0.5, c.y(), std::to_string(k), "end", -6, 5, "#111", 13);
  }
  // The legend: a swatch, a bar and a dot, each with its meaning.
  const double lx = 330, ly = 380;
  svg.raw("<rect x=\"" + fmt(lx) + "\" y=\"" + fmt(ly) + "\" width=\"200\" height=\"92\" fill=\"white\" stroke=\"#bbb\"/>\n");
  const char* swatches[2][2] = {{"#b2df8a", "carries its load"}, {"#fb9a99", "does not: joined"}};
  for (int i = 0; i < 2; ++i) {
    const double y = ly + 10 + 20 * i;
    svg.raw("<rect x=\"" + fmt(lx + 10) + "\" y=\"" + fmt(y) + "\" width=\"22\" height=\"14\" fill=\"" + swatches[i][0] +
            "\" stroke=\"#333\"/>\n");
    svg.textPixels(lx + 40, y + 12, swatches[i][1], "start", "#222", 12);
  }
  svg.raw("<line x1=\"" + fmt(lx + 10) + "\" y1=\"" + fmt(ly + 57) + "\" x2=\"" + fmt(lx + 32) + "\" y2=\"" + fmt(ly + 57) +
          "\" stroke=\"#1f78b4\" stroke-width=\"4\"/>\n");
  svg.textPixels(lx + 40, ly + 61, "support region", "start", "#222", 12);
  svg.raw("<circle cx=\"" + fmt(lx + 21) + "\" cy=\"" + fmt(ly + 77) + "\" r=\"5\" fill=\"#222\"/>\n");
  svg.textPixels(lx + 40, ly + 81, "centre of load x*", "start", "#222", 12);
  svg.save("ch12_tower_loads.svg");
  return 0;
}
