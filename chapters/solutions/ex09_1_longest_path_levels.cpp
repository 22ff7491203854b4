// Exercise 9.1, reference solution: longest-path layering of the condensation (chapter 9).
#include "stackbook/exercises/ex09_1_longest_path_levels.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "stackbook/stacking/strongly_connected_components.hpp"

namespace stackbook {

ContactLevels longestPathLevels(const ContactGraph& graph) {
  const StronglyConnectedComponents scc = stronglyConnectedComponents(graph);
  // The topological levels list the components in a topological order of the condensation.
  const ContactLevels order = topologicalLevels(graph, scc);
  std::vector<int> componentLevel(scc.componentCount(), 0);
  for (std::size_t l = 0; l < order.levelCount(); ++l) {  // components in topological order
    const int first = order.bodies(l).front();
    const std::size_t c = static_cast<std::size_t>(scc.componentOfBody[static_cast<std::size_t>(first)]);
    int level = 0;
    for (const int body : order.bodies(l)) {
      for (const int parent : graph.parents(body)) {
        const std::size_t pc = static_cast<std::size_t>(scc.componentOfBody[static_cast<std::size_t>(parent)]);
        if (pc != c) level = std::max(level, componentLevel[pc] + 1);
      }
    }
    componentLevel[c] = level;
  }
  std::vector<int> levelOfBody(static_cast<std::size_t>(graph.bodyCount()));
  for (std::size_t b = 0; b < levelOfBody.size(); ++b) {
    levelOfBody[b] = componentLevel[static_cast<std::size_t>(scc.componentOfBody[b])];
  }
  return levelsFromAssignment(graph, std::move(levelOfBody));
}

}  // namespace stackbook
