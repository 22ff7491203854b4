// Chapter 12, "Run this now": A19's tower (ten unit boxes, each offset 0.2 from the one below) at
// 60 Hz for 3 s, under the pass that freezes every level (the sticking-patch pass, the preset
// "passAsContactPatch") and under the same pass freezing only what carries its load (the
// carrying pass, the default). Prints the top box's height every quarter second and how many
// bodies the carrying pass found not carrying their load, and draws Figure 12.2, the top box's
// height against time under both.
#include <cstdio>
#include <vector>

#include "../../tests/ch09/stack_scenes.hpp"
#include "figure_svg.hpp"
#include "stackbook/stacking/solver_preset.hpp"

using namespace stackbook;
using namespace figure_svg;

int main() {
  StepSettings everyLevel = applySolverPreset(SolverPreset::PassAsContactPatch, StepSettings{});
  everyLevel.dt = 1.0 / 60.0;
  const StepSettings carrying = applySolverPreset(SolverPreset::CarryingPass, everyLevel);
  World<2> frozen = stacks::boxStack<2>(10, Material{0.0, 0.6, 0.0}, 0.2);
  World<2> carried = frozen;
  Points a{{0.0, frozen.bodies[10].position.y()}}, b = a;
  std::printf("  t (s)   top box height (m): every level frozen   only what carries   bodies not carrying\n");
  long uncarried = 0;
  for (int n = 1; n <= 180; ++n) {
    stackingStep<2>(frozen, everyLevel);
    uncarried += stackingStep<2>(carried, carrying).shock.uncarried;
    const double t = n / 60.0;
    a.emplace_back(t, frozen.bodies[10].position.y());
    b.emplace_back(t, carried.bodies[10].position.y());
    if (n % 15 == 0) {
      std::printf("  %5.2f   %34.3f   %17.3f   %19ld\n", t, a.back().second, b.back().second, uncarried);
      uncarried = 0;
    }
  }
  Svg svg(600, 380, "The top box of A19's tower against time: frozen level by level it stays up, freezing only what carries lets it fall");
  const View v{80, 20, 480, 290, 0.0, 3.0, 0.0, 10.0};
  svg.axes(v, "time t (s)", "height of the top box (m)", 6, 5);
  svg.polyline(v, a, stroke("#1f78b4", 2.5));
  svg.polyline(v, b, stroke("#e31a1c", 2.5));
  svg.legend(100, 200, {{stroke("#1f78b4", 2.5), "every level frozen (GBF's rule)"},
                        {stroke("#e31a1c", 2.5), "only what carries (the default)"}});
  svg.save("ch12_tower_heights.svg");
  return 0;
}
