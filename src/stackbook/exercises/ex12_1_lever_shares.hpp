#pragma once
/// \file
/// \brief Exercise 12.1: the lever rule for a load resting on several supporters (\ref ch12).

#include <vector>

namespace stackbook {

/// How a load whose centre lies at `centre` (a coordinate along the ground, 2D) divides among the
/// supporters it enters at `entries` (one coordinate each, at least one). The shares are >= 0,
/// add up to 1 and put the load's centre where it is: sum s_i x_i = centre, with the load
/// carried by the two entries nearest on either side of the centre (the lever rule,
/// Eq. (12.8)). A centre outside all entries goes wholly to the nearest one; entries at one
/// place share equally. Throws std::invalid_argument for no entries or a non-finite value.
std::vector<double> leverShares(double centre, const std::vector<double>& entries);

}  // namespace stackbook
