#pragma once
/// \file
/// \brief Exercise 9.1: longest-path layering of the condensed contact graph, fewer levels
/// than one level per strongly connected component, with the same order guarantee
/// (\ref ch09).

#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/contact_levels.hpp"

namespace stackbook {

/// Levels in which each strongly connected component (SCC) of `graph` sits at the length
/// of the longest path that reaches it in the condensed graph: components with no parent
/// at level 0, and every other component one above its highest parent component. Several
/// independent components may share a level. Build the result with levelsFromAssignment()
/// so that the pairs of each level follow Eq. (9.2). Must satisfy Eq. (9.1): for every edge
/// u -> v, level(u) <= level(v), with equality if and only if u and v share an SCC.
/// O(n + m) after the SCCs.
ContactLevels longestPathLevels(const ContactGraph& graph);

}  // namespace stackbook
