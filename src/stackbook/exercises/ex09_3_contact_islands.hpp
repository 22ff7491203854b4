#pragma once
/// \file
/// \brief Exercise 9.3: contact islands, the groups of bodies that touch each other
/// through dynamic bodies; the unit a simulator puts to sleep or solves on its own
/// (\ref ch09).

#include <vector>

#include "stackbook/stacking/contact_graph.hpp"

namespace stackbook {

/// The islands of `graph`: its edges taken without direction, and static bodies
/// (isStatic[b] true) joining no island and connecting nothing (two stacks on one ground
/// are two islands). Every dynamic body is in exactly one island, a body that touches no
/// dynamic body in an island of its own. Each island lists its bodies ascending; islands
/// are ordered by their smallest body. Throws std::invalid_argument if isStatic does not
/// have one entry per body. O(n + m).
std::vector<std::vector<int>> contactIslands(const ContactGraph& graph, const std::vector<bool>& isStatic);

}  // namespace stackbook
