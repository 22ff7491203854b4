#pragma once
/// \file
/// \brief Exercise 11.2 (\ref ch11_exercises): a new error measure, the apex heights of a
/// bouncing ball read from its recorded heights, against the closed form h_k = e^{2k} h_0.

#include <vector>

namespace stackbook {

/// The apexes of a bouncing body: the heights at the frames that are strictly higher than
/// both neighbours (a local maximum of the recorded height), in time order. The first and
/// the last frame are never apexes.
std::vector<double> apexHeights(const std::vector<double>& heights);

/// The largest relative error of the first `count` apexes after a drop from h0 against
/// e^{2k} h0, k = 1..count (a ball dropped at rest from h0 with restitution e). Throws
/// std::invalid_argument if fewer than `count` apexes were found or h0 <= 0.
double apexError(const std::vector<double>& heights, double h0, double e, int count);

}  // namespace stackbook
