#pragma once
/// \file
/// \brief Exercise 7.1: a broad phase on a uniform grid, to set beside sweep and prune
/// (\ref ch07).

#include <vector>

#include "stackbook/collision/broad_phase.hpp"

namespace stackbook {

/// Knobs of the uniform-grid broad phase.
struct UniformGridSettings {
  /// Side of a grid cell (finite, > 0). About the size of a typical body works best.
  double cellSize = 1.0;
  /// Every box is inflated by this much before it is entered, as in BroadPhaseSettings.
  double margin = 0.0;
  /// A box that would cover more cells than this is refused (std::invalid_argument): a
  /// ground plane 1000 cells wide is what a grid handles badly.
  long long maxCellsPerBox = 1'000'000;
};

/// The same pairs as sweepAndPrune(): every (i, j), i < j, whose boxes (inflated by the
/// margin) overlap, static-static pairs skipped, sorted by (i, j). Each box is entered in
/// every cell of the grid it touches (cell index floor(x / cellSize) per axis); two boxes
/// are a candidate pair when they share a cell, and each candidate pair gets one box test
/// however many cells the two share. counters->pairsTested counts those box tests,
/// counters->pairsOverlapping the pairs returned. Deterministic: no unordered containers
/// may decide the output order. Throws std::invalid_argument for a cellSize or margin that
/// is not finite and positive (margin: >= 0), or a box that covers more than
/// maxCellsPerBox cells (an infinite box included).
template <int D>
std::vector<BodyPair> uniformGridPairs(const std::vector<BroadPhaseProxy<D>>& proxies,
                                       const UniformGridSettings& settings = {},
                                       DetectionCounters* counters = nullptr);

}  // namespace stackbook
