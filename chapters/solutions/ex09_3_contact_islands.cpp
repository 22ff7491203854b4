// Exercise 9.3, reference solution: contact islands (chapter 9).
#include "stackbook/exercises/ex09_3_contact_islands.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace stackbook {

std::vector<std::vector<int>> contactIslands(const ContactGraph& graph, const std::vector<bool>& isStatic) {
  const int n = graph.bodyCount();
  if (isStatic.size() != static_cast<std::size_t>(n)) {
    throw std::invalid_argument("contactIslands: isStatic has " + std::to_string(isStatic.size()) +
                                " entries, the graph has " + std::to_string(n) + " bodies");
  }
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  std::vector<std::vector<int>> islands;
  std::vector<int> stack;
  for (int start = 0; start < n; ++start) {  // ascending: islands ordered by smallest body
    const std::size_t s = static_cast<std::size_t>(start);
    if (isStatic[s] || seen[s] != 0) continue;
    std::vector<int> island;
    seen[s] = 1;
    stack.assign(1, start);
    while (!stack.empty()) {  // each dynamic body pushed once: bound n
      const int b = stack.back();
      stack.pop_back();
      island.push_back(b);
      for (const auto& neighbours : {graph.children(b), graph.parents(b)}) {
        for (const int k : neighbours) {
          const std::size_t kk = static_cast<std::size_t>(k);
          if (isStatic[kk] || seen[kk] != 0) continue;
          seen[kk] = 1;
          stack.push_back(k);
        }
      }
    }
    std::sort(island.begin(), island.end());
    islands.push_back(std::move(island));
  }
  return islands;
}

}  // namespace stackbook
