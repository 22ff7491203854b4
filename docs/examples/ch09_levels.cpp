// Chapter 9: the contact graphs and levels of the chapter's scenes, found in the worlds
// themselves (worldContactGraph at the start, every body at rest), printed as text.
#include <cstdio>

#include "../../tests/ch09/stack_scenes.hpp"
#include "stackbook/stacking/level_summary.hpp"

using namespace stackbook;

namespace {

template <int D>
void show(const char* title, const World<D>& world, bool withDepth) {
  const ContactGraph graph = worldContactGraph<D>(world, ContactGraphSettings{});
  std::printf("%s\nedges:", title);
  for (const ContactPair& e : graph.edges()) std::printf(" %d->%d", e.below, e.above);
  if (graph.edgeCount() == 0) std::printf(" none");
  std::printf("\n\ntopological levels:\n%s", describeLevels(graph, topologicalLevels(graph)).c_str());
  if (withDepth) std::printf("\nBFS depth:\n%s", describeLevels(graph, bfsDepthLevels(graph)).c_str());
  std::printf("\n");
}

}  // namespace

int main() {
  const Material material{0.0, 0.5, 0.0};
  show<2>("== stack of 4 boxes (2D), ground = body 0 ==", stacks::boxStack<2>(4, material), false);
  show<2>("== plank (7) on a 2-box stack (1 2) and a 4-box stack (3 4 5 6), 2D ==",
          stacks::plankOnTwoStacks<2>(material), true);
  show<2>("== card A-frame at 25 degrees (cards 1 and 2), 2D ==",
          stacks::cardFrame(25.0 * M_PI / 180.0, material), false);
  return 0;
}
