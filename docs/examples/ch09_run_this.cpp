// Run this now (chapter 9): the plank on two stacks. The program builds the contact graph,
// orders it into levels, and prints them; then it runs two seconds with and without shock
// propagation and prints how far the plank tilted.
#include <cmath>
#include <cstdio>

#include "../../tests/ch09/stack_scenes.hpp"
#include "stackbook/stacking/level_summary.hpp"

using namespace stackbook;

int main() {
  const Material material{0.0, 0.5, 0.0};
  const World<2> start = stacks::plankOnTwoStacks<2>(material);
  const ContactGraph graph = worldContactGraph<2>(start, ContactGraphSettings{});
  std::printf("contacts (below -> above):");
  for (const ContactPair& e : graph.edges()) std::printf(" %d->%d", e.below, e.above);
  std::printf("\nlevels:\n%s", describeLevels(graph, topologicalLevels(graph)).c_str());
  for (const bool shock : {false, true}) {
    World<2> world = start;
    stacks::run<2>(world, StepSettings{}, 2.0, shock);
    std::printf("shock propagation %-3s: plank tilt after 2 s = %.3e rad\n", shock ? "on" : "off",
                stacks::plankTilt<2>(world));
  }
}
