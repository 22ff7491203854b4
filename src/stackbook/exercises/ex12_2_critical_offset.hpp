#pragma once
/// \file
/// \brief Exercise 12.2: the largest offset at which a leaning tower carries its loads (\ref ch12).

namespace stackbook {

/// A tower of n >= 2 unit boxes (side 1, equal masses) stands on the ground, each box offset by
/// s along x from the one below. The largest s >= 0 at which every box carries its load
/// (Eq. (12.4) with the loads of Eq. (12.2), where each box's load enters the box below at its
/// centre of load). Throws std::invalid_argument for n < 2.
double criticalOffset(int n);

}  // namespace stackbook
