#pragma once
/// \file
/// \brief Strongly connected components of the contact graph (chapter 9): the cycles of
/// mutual support, found by an iterative Tarjan search, so that no graph is too deep.

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "stackbook/stacking/contact_graph.hpp"

namespace stackbook {

/// The strongly connected components (SCCs) of a contact graph: two bodies share a
/// component when each can be reached from the other along edges, i.e. they lie on a
/// common cycle of support. Components are numbered in the order of their smallest body
/// (component 0 holds body 0), so the numbering depends on the edge set alone, not on the
/// algorithm or the order of the edges. Members are stored flat (one array and offsets),
/// so a graph of 10^5 one-body components costs two arrays, not 10^5 small ones.
struct StronglyConnectedComponents {
  /// componentOfBody[b]: the component that holds body b.
  std::vector<int> componentOfBody;
  /// All bodies, ordered by component and ascending inside each component.
  std::vector<int> memberList;
  /// Component c owns memberList[memberStart[c] .. memberStart[c+1]); size componentCount()+1.
  std::vector<std::size_t> memberStart{0};

  std::size_t componentCount() const { return memberStart.size() - 1; }
  /// The bodies of component c, ascending.
  std::span<const int> members(std::size_t c) const {
    return std::span<const int>(memberList).subspan(memberStart[c],
                                                    memberStart[c + 1] - memberStart[c]);
  }
  /// Components of two or more bodies: the cycles of mutual support. (A one-body component
  /// is never a cycle, because the graph refuses a body resting on itself.)
  std::size_t cycleCount() const {
    std::size_t cycles = 0;
    for (std::size_t c = 0; c < componentCount(); ++c) {
      if (memberStart[c + 1] - memberStart[c] > 1) ++cycles;
    }
    return cycles;
  }

  friend bool operator==(const StronglyConnectedComponents&,
                         const StronglyConnectedComponents&) = default;
};

// [tarjan]
/// Tarjan's algorithm with an explicit stack of (body, next child) frames instead of
/// recursion, so a chain of 10^5 bodies needs 10^5 heap-allocated frames, not 10^5 nested
/// calls. A depth-first search numbers the bodies in discovery order; lowLink of a body is
/// the smallest number it can reach through its subtree and one edge to a body still on
/// the Tarjan stack. A finished body whose lowLink equals its own number reaches nothing
/// older that is still open, so it is the first-discovered body of a component, and the
/// component is everything above it on the Tarjan stack. O(n + m) for n bodies, m edges.
inline StronglyConnectedComponents stronglyConnectedComponents(const ContactGraph& graph) {
  const int n = graph.bodyCount();
  const std::size_t nn = static_cast<std::size_t>(n);
  constexpr int kUnvisited = -1;
  std::vector<int> index(nn, kUnvisited);  // discovery number of each body
  std::vector<int> lowLink(nn, 0);         // smallest discovery number seen from the subtree
  std::vector<char> onStack(nn, 0);        // is the body on the Tarjan stack?
  std::vector<int> tarjanStack;            // bodies whose component is not yet complete
  std::vector<int> tarjanComponent(nn, kUnvisited);  // numbered in completion order
  int nextIndex = 0;
  int completed = 0;

  struct Frame {
    int body;
    std::size_t nextChild;  // position in children(body) of the next edge to follow
  };
  std::vector<Frame> callStack;

  // Bound: each iteration of the search loop either follows one edge (each edge is followed
  // once, from the frame of its lower end) or finishes one body (each body is discovered
  // once, so finished once): at most m + n iterations over all roots. The unwinding of the
  // Tarjan stack pops each body once: at most n.
  detail::LoopCap searchCap(nn + graph.edgeCount(), "stronglyConnectedComponents: search");
  detail::LoopCap unwindCap(nn, "stronglyConnectedComponents: component unwinding");

  auto discover = [&](int body) {
    const std::size_t b = static_cast<std::size_t>(body);
    index[b] = lowLink[b] = nextIndex++;
    tarjanStack.push_back(body);
    onStack[b] = 1;
    callStack.push_back(Frame{body, 0});
  };

  for (int root = 0; root < n; ++root) {  // bound: n roots
    if (index[static_cast<std::size_t>(root)] != kUnvisited) continue;
    discover(root);
    while (!callStack.empty()) {
      searchCap.step();
      Frame& frame = callStack.back();
      const std::span<const int> kids = graph.children(frame.body);
      const std::size_t v = static_cast<std::size_t>(frame.body);
      if (frame.nextChild < kids.size()) {
        const int child = kids[frame.nextChild++];
        const std::size_t w = static_cast<std::size_t>(child);
        if (index[w] == kUnvisited) {
          discover(child);  // invalidates `frame`; it is not used again this iteration
        } else if (onStack[w]) {
          lowLink[v] = std::min(lowLink[v], index[w]);
        }
        continue;
      }
      // All children done: the body is finished.
      const int body = frame.body;
      callStack.pop_back();
      if (lowLink[v] == index[v]) {
        // body is the root of a component: everything above it on the Tarjan stack.
        int member = kUnvisited;
        do {
          unwindCap.step();
          member = tarjanStack.back();
          tarjanStack.pop_back();
          onStack[static_cast<std::size_t>(member)] = 0;
          tarjanComponent[static_cast<std::size_t>(member)] = completed;
        } while (member != body);
        ++completed;
      }
      if (!callStack.empty()) {
        const std::size_t parent = static_cast<std::size_t>(callStack.back().body);
        lowLink[parent] = std::min(lowLink[parent], lowLink[v]);
      }
    }
  }

  // Canonical numbering: scan the bodies in ascending order and number each component
  // when its smallest body is met. Then a counting sort lists the members by component,
  // ascending inside each component because the bodies are scanned in ascending order.
  StronglyConnectedComponents result;
  result.componentOfBody.assign(nn, kUnvisited);
  std::vector<int> canonical(static_cast<std::size_t>(completed), kUnvisited);
  std::vector<std::size_t> size;  // size[c]: bodies in canonical component c
  for (std::size_t b = 0; b < nn; ++b) {  // bound: n
    int& c = canonical[static_cast<std::size_t>(tarjanComponent[b])];
    if (c == kUnvisited) {
      c = static_cast<int>(size.size());
      size.push_back(0);
    }
    result.componentOfBody[b] = c;
    ++size[static_cast<std::size_t>(c)];
  }
  result.memberStart.assign(size.size() + 1, 0);
  for (std::size_t c = 0; c < size.size(); ++c) {  // bound: components <= n
    result.memberStart[c + 1] = result.memberStart[c] + size[c];
  }
  result.memberList.resize(nn);
  std::vector<std::size_t> fill(result.memberStart.begin(), result.memberStart.end() - 1);
  for (int body = 0; body < n; ++body) {  // bound: n
    const std::size_t b = static_cast<std::size_t>(body);
    result.memberList[fill[static_cast<std::size_t>(result.componentOfBody[b])]++] = body;
  }
  return result;
}
// [tarjan]

}  // namespace stackbook
