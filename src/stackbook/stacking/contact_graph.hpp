#pragma once
/// \file
/// \brief The contact graph of chapter 9: a directed graph over body indices in which
/// the edge below -> above means "above rests on below".

// =========================================================================================
// Design note for chapter 9, "The contact graph and shock propagation"
// =========================================================================================
// The chapter page needs the time step of chapter 8 and is written after it. This note is
// its plan: what the page will derive, which code it will show, and the pitfalls it must
// name. It is a plain comment on purpose (Doxygen does not render it). Everything it
// describes is implemented and tested (tests/ch09): the graph algorithms here, and the
// graph of a world, the freeze and the pass in shock_propagation.hpp. Where the chapter
// departs from this plan, the page (chapters/09_shock_propagation.md) is authoritative;
// the notes marked "(as built)" below say where.
//
// Files
//   contact_graph.hpp                  the graph (this file)
//   strongly_connected_components.hpp  iterative Tarjan, canonical component numbers
//   contact_levels.hpp                 topological levels (GBF), BFS depth (the flawed
//                                      variant), and the pairs of each level
//   level_summary.hpp                  counts and a printable summary
//
// 1. Why an order at all. The contact stage of chapter 8 sweeps every contact pair a fixed
//    number of times (GBF: 10, with the restitution ramp e = -0.9 ... 0). In a stack of N
//    boxes the weight of the top box reaches the ground only through N contacts in a row,
//    and a sweep of sequential pair impulses in which every body can still move passes
//    that information down only partly; a fixed number of sweeps leaves a tall stack with
//    residual approach velocities, which the position update turns into sinking (the
//    chapter will measure the residual against N). Shock propagation ends the step with
//    one bottom-up pass: process the bodies that rest on nothing, then freeze them
//    (infinite mass, K = 0 by Eq. (1.9)), then process the bodies resting on them, freeze
//    those, and so on; clear every freeze at the end. Against a frozen supporter a pair
//    impulse changes only the upper body, so settling a level cannot disturb the levels
//    below it, and the pass costs one sweep (GBF: two) per level. It needs an order in
//    which every body comes after all the bodies it rests on. The contact graph supplies it.
//
// 2. The graph. Nodes are all bodies, static ones included. The edge a -> b means "b rests
//    on a" (PhysBAM: nodes "point to objects which are above it"). The direction rule the
//    chapter will implement (PhysBAM, Compute_Contact_Graph): advance body b with its new,
//    gravity-updated velocity while every other body keeps its old one; if b then
//    interferes with a, add a -> b. Gravity picks the direction; no "up" vector is needed,
//    and two boxes side by side usually get no edge. (As built: the hook runs after the
//    contact stage, so "old" is the velocity the contact stage left and "new" adds dt a
//    once more; and the advanced body must also *approach* at an interfering sample, or a
//    resting pair that already overlaps by more than dt^2 g gets both edges: Eq. (9.3).)
//    Both a -> b and b -> a can occur
//    (two leaning planks): mutual support. The graph is built once per step from predicted
//    positions and does not change during the pass (a documented staleness). Static bodies
//    have no parents in practice, but nothing here assumes it; a static body is simply a
//    node that the pass never moves.
//
// 3. Levels, the derivation. Condense each strongly connected component (SCC: bodies that
//    reach each other along edges, a cycle of mutual support) into one node. The condensed
//    graph is acyclic, so it has a topological order; each component becomes one level in
//    that order (PhysBAM Generate_Levels: "collapses all cycles into a single level").
//    The claim the chapter proves and the tests check is, for every edge u -> v,
//        level(u) <= level(v),  with equality if and only if u and v share an SCC,
//    a candidate for Eq. (9.1). Bodies of a cycle share a level and are swept together
//    with nobody frozen among them: freezing any one of them first would be as wrong as
//    freezing a body before its supporters.
//    Pairs of a level (candidate Eq. (9.2)): each body of the level with each of its
//    parents; all of them lie at a lower or the same level. A mutual pair inside a level
//    is listed once. Every edge of the graph then appears in exactly one level's list.
//    Cost: Tarjan visits each node once and each edge once, O(n + m); ordering the
//    condensation with a min-heap costs O(n log n + m); the pairs O(m log d) for d the
//    largest number of children of a body.
//
// 4. Why not BFS depth from the ground (the chapter's worked failure). A plank rests on a
//    stack of 2 boxes of height h and on a stack of 4 boxes of height h/2; both tops are
//    at 2h. Number the bodies ground 0, left boxes 1 2, right boxes 3 4 5 6, plank 7.
//    Edges: 0->1 1->2 2->7 and 0->3 3->4 4->5 5->6 6->7.
//    BFS depth (the shortest path from the ground, OpenTissue's "stack height", Zheng's
//    update_level) is 0 for the ground, 1 for {1, 3}, 2 for {2, 4}, 3 for {5, 7} and 4
//    for {6}: the plank reaches depth 3 through the short stack while box 6, which holds
//    it up, has depth 4. At level 3 the pass sweeps the plank's contacts (2->7 and 6->7)
//    and freezes the plank; at level 4 it stops box 6 against frozen box 5, and the upward
//    correction drives box 6 into the frozen plank, a contact that is never revisited:
//    box 6 is squeezed between two infinite masses. Codes that keep iterating until no
//    contact approaches never finish there (the gamedev.net thread "Contact Graph and
//    Shockpropagation", 2010, reports this "endless loop"). Topological order puts the plank
//    after all 7 of its supporters (level 7 here). A second BFS defect: a cycle that no
//    parentless body reaches gets no depth at all, and a reached cycle is split over
//    several depths, so part of it is frozen before the rest. bfsDepthLevels() keeps this
//    variant callable so that the chapter can run the same scene both ways.
//
// 5. The pass the chapter will add (PhysBAM Shock_Propagation_Using_Graph): for each level
//    bottom to top, sweep the level's pairs twice (e = -0.5, then 0; at most 10 impulses
//    per pair), then mark the level's bodies temporarily static; clear the marks after the
//    last level. Sweeping a level more than once reduces order bias (a one-sweep fixed
//    order walks a tall column sideways).
//
// 6. Pitfalls the page must name, with numbers where the tests measure them.
//    - Recursion. PhysBAM's DIRECTED_GRAPH finds SCCs with recursive depth-first searches
//      (Visit, Visit_Transpose). A chain of 10^5 bodies needs 10^5 nested calls, several
//      megabytes of stack: more than a worker thread usually has, and about the 8 MB that
//      Linux gives the main thread. Everything here is iterative; the test runs a
//      100000-body chain and a 100000-body cycle on a thread with a 256 KiB stack (a
//      recursive search crashes there) and measures the CPU time (5 to 15 ms optimised).
//    - Determinism. Adjacency kept in hash sets or in insertion order makes the level
//      order, and so the simulation, depend on the order in which the broad phase
//      reported the pairs. Here adjacency is sorted, SCCs are numbered by their smallest
//      body, and among condensed nodes that are free to go next the one with the smallest
//      body goes first: the same edge set gives the same levels, bit for bit.
//    - Duplicate edges. A pair detected twice would be swept twice per level (twice the
//      impulses, a different result); the graph stores each edge once.
//    - One level per SCC means as many levels as bodies in a pile of single bodies. The
//      pass still visits each pair once per sweep, so the cost is the same; only the
//      bookkeeping grows. Grouping independent bodies into one level (longest-path
//      layering) keeps the guarantee of point 3 and is a natural exercise.
//    - Physically wrong by construction: a frozen level never feels the bodies above it
//      during the pass. Shock propagation buys visual stability, not correct forces.
//
// 7. Exercises the chapter can set: longest-path layering of the condensation (fewer
//    levels, same order guarantee, same pairs); Kosaraju's two-pass SCC as an
//    independent check of Tarjan; the softened variant (scale a body's inverse mass by its
//    level instead of freezing, as Unreal Chaos does) and its effect on a tall stack.
//
// 8. Loop caps. Every loop in these headers has a proven bound stated at the loop
//    (n = bodies, m = edges), and a LoopCap that throws std::logic_error if the bound is
//    ever exceeded: an internal error is reported, never a hang.
//
// 9. Snippet tags ready for the page. Code: contact_pair, contact_graph (this file);
//    tarjan (strongly_connected_components.hpp); contact_levels, level_pairs,
//    topological_levels, bfs_depth_levels (contact_levels.hpp); level_summary,
//    describe_levels (level_summary.hpp). Tests: graph_duplicates, empty_and_isolated
//    (test_contact_graph.cpp); vertical_stack, plank_topological, plank_bfs_failure,
//    cycle_levels, scc_property, topological_property, pairs_once, determinism,
//    summary_text (test_contact_levels.cpp); deep_chain (test_deep_graphs.cpp).
// =========================================================================================

#include <algorithm>
#include <compare>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace stackbook {

// [contact_pair]
/// One supporting contact of the contact graph: body `above` rests on body `below`
/// (the edge below -> above).
struct ContactPair {
  int below = 0;
  int above = 0;
  friend auto operator<=>(const ContactPair&, const ContactPair&) = default;
};
// [contact_pair]

namespace detail {

/// A hard cap on the number of iterations of one loop. Each loop of chapter 9 states its
/// bound (in terms of the body count n and the edge count m) and calls step() once per
/// iteration; exceeding the bound means the proof at the loop is wrong, which is reported
/// as std::logic_error instead of a hang.
class LoopCap {
 public:
  LoopCap(std::size_t cap, const char* loopName) : cap_(cap), loopName_(loopName) {}
  void step() {
    if (used_ == cap_) {
      throw std::logic_error(std::string(loopName_) + ": more than " + std::to_string(cap_) +
                             " iterations, above the proven bound (internal error)");
    }
    ++used_;
  }

 private:
  std::size_t cap_;
  std::size_t used_ = 0;
  const char* loopName_;
};

}  // namespace detail

// [contact_graph]
/// The contact graph: nodes are the bodies 0..bodyCount()-1, static ones included, and the
/// edge below -> above means "above rests on below". Each edge is stored once, and the
/// children and parents of every body are kept in ascending order, so the graph, and
/// everything computed from it, does not depend on the order in which edges were added.
class ContactGraph {
 public:
  /// A graph over bodyCount bodies and no contacts.
  explicit ContactGraph(int bodyCount = 0) {
    if (bodyCount < 0) {
      throw std::invalid_argument("ContactGraph: bodyCount = " + std::to_string(bodyCount) +
                                  " is negative");
    }
    children_.resize(static_cast<std::size_t>(bodyCount));
    parents_.resize(static_cast<std::size_t>(bodyCount));
  }

  /// The graph of the given contacts, in any order, duplicates allowed (stored once).
  /// Costs O(m log m) for m contacts; prefer it to m calls of addEdge for large graphs.
  ContactGraph(int bodyCount, std::span<const ContactPair> contacts) : ContactGraph(bodyCount) {
    std::vector<ContactPair> sorted(contacts.begin(), contacts.end());
    for (const ContactPair& c : sorted) checkEdge(c.below, c.above, "ContactGraph");
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    // Sorted by (below, above): each children_ list is filled in ascending order, and so is
    // each parents_ list, because the belows arrive in ascending order.
    for (const ContactPair& c : sorted) {
      children_[static_cast<std::size_t>(c.below)].push_back(c.above);
      parents_[static_cast<std::size_t>(c.above)].push_back(c.below);
    }
    edgeCount_ = sorted.size();
  }

  int bodyCount() const { return static_cast<int>(children_.size()); }
  std::size_t edgeCount() const { return edgeCount_; }

  /// Add "above rests on below". Returns false (and changes nothing) if the edge is
  /// already there. Throws std::invalid_argument for an index outside 0..bodyCount()-1 or
  /// for a body resting on itself. Costs O(d) for a body with d children or parents (the
  /// sorted insertion).
  bool addEdge(int below, int above) {
    checkEdge(below, above, "ContactGraph::addEdge");
    std::vector<int>& kids = children_[static_cast<std::size_t>(below)];
    const auto kid = std::lower_bound(kids.begin(), kids.end(), above);
    if (kid != kids.end() && *kid == above) return false;
    kids.insert(kid, above);
    std::vector<int>& ups = parents_[static_cast<std::size_t>(above)];
    ups.insert(std::lower_bound(ups.begin(), ups.end(), below), below);
    ++edgeCount_;
    return true;
  }
  bool addEdge(const ContactPair& contact) { return addEdge(contact.below, contact.above); }

  /// True if `above` rests on `below`. O(log d).
  bool hasEdge(int below, int above) const {
    if (!isBody(below) || !isBody(above)) return false;
    const std::vector<int>& kids = children_[static_cast<std::size_t>(below)];
    return std::binary_search(kids.begin(), kids.end(), above);
  }

  /// The bodies that rest on `body`, ascending.
  std::span<const int> children(int body) const {
    checkBody(body, "ContactGraph::children", "body");
    return children_[static_cast<std::size_t>(body)];
  }
  /// The bodies that `body` rests on, ascending.
  std::span<const int> parents(int body) const {
    checkBody(body, "ContactGraph::parents", "body");
    return parents_[static_cast<std::size_t>(body)];
  }

  /// Every edge, sorted by (below, above).
  std::vector<ContactPair> edges() const {
    std::vector<ContactPair> all;
    all.reserve(edgeCount_);
    for (int below = 0; below < bodyCount(); ++below) {
      for (const int above : children_[static_cast<std::size_t>(below)]) {
        all.push_back(ContactPair{below, above});
      }
    }
    return all;
  }

  friend bool operator==(const ContactGraph&, const ContactGraph&) = default;

 private:
  bool isBody(int body) const { return body >= 0 && body < bodyCount(); }

  void checkBody(int body, const char* where, const char* field) const {
    if (isBody(body)) return;
    const std::string range = bodyCount() == 0
                                  ? std::string("the graph has no bodies")
                                  : "outside the bodies 0.." + std::to_string(bodyCount() - 1);
    throw std::invalid_argument(std::string(where) + ": " + field + " = " + std::to_string(body) +
                                " is " + (bodyCount() == 0 ? "refused, " : "") + range);
  }

  void checkEdge(int below, int above, const char* where) const {
    checkBody(below, where, "below");
    checkBody(above, where, "above");
    if (below == above) {
      throw std::invalid_argument(std::string(where) + ": below = above = " +
                                  std::to_string(below) + ", a body cannot rest on itself");
    }
  }

  std::vector<std::vector<int>> children_;  // children_[b]: bodies resting on b, ascending
  std::vector<std::vector<int>> parents_;   // parents_[b]: bodies b rests on, ascending
  std::size_t edgeCount_ = 0;
};
// [contact_graph]

}  // namespace stackbook
