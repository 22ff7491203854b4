// Exercise 7.1, reference solution: a uniform-grid broad phase (chapter 7).
#include "stackbook/exercises/ex07_1_uniform_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace stackbook {

template <int D>
std::vector<BodyPair> uniformGridPairs(const std::vector<BroadPhaseProxy<D>>& proxies,
                                       const UniformGridSettings& settings,
                                       DetectionCounters* counters) {
  if (!std::isfinite(settings.cellSize) || !(settings.cellSize > 0.0)) {
    std::ostringstream msg;
    msg << "uniformGridPairs: settings.cellSize must be finite and > 0, got " << settings.cellSize;
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(settings.margin) || settings.margin < 0.0) {
    std::ostringstream msg;
    msg << "uniformGridPairs: settings.margin must be finite and >= 0, got " << settings.margin;
    throw std::invalid_argument(msg.str());
  }
  using Cell = std::array<long long, D>;
  const int n = static_cast<int>(proxies.size());
  std::vector<Aabb<D>> boxes;
  boxes.reserve(proxies.size());
  // (cell, body) for every cell every box touches; sorted, equal cells are adjacent.
  std::vector<std::pair<Cell, int>> entries;
  for (int i = 0; i < n; ++i) {
    const Aabb<D> box = proxies[static_cast<std::size_t>(i)].box.inflated(settings.margin);
    boxes.push_back(box);
    if (box.isEmpty()) continue;
    Cell lo{}, hi{};
    long long cells = 1;
    for (int a = 0; a < D; ++a) {
      const double l = std::floor(box.lower[a] / settings.cellSize);
      const double u = std::floor(box.upper[a] / settings.cellSize);
      if (!(std::abs(l) < 1e15 && std::abs(u) < 1e15) ||
          (u - l + 1.0) * static_cast<double>(cells) > static_cast<double>(settings.maxCellsPerBox)) {
        std::ostringstream msg;
        msg << "uniformGridPairs: the box of proxy " << i << " covers more than "
            << settings.maxCellsPerBox << " cells of size " << settings.cellSize;
        throw std::invalid_argument(msg.str());
      }
      lo[static_cast<std::size_t>(a)] = static_cast<long long>(l);
      hi[static_cast<std::size_t>(a)] = static_cast<long long>(u);
      cells *= hi[static_cast<std::size_t>(a)] - lo[static_cast<std::size_t>(a)] + 1;
    }
    Cell c = lo;
    for (;;) {  // odometer over the cells lo..hi
      entries.push_back({c, i});
      int a = 0;
      for (; a < D; ++a) {
        const std::size_t k = static_cast<std::size_t>(a);
        if (++c[k] <= hi[k]) break;
        c[k] = lo[k];
      }
      if (a == D) break;
    }
  }
  std::sort(entries.begin(), entries.end());

  // Candidate pairs: bodies that share a cell, each pair once.
  std::vector<BodyPair> candidates;
  for (std::size_t start = 0; start < entries.size();) {
    std::size_t end = start + 1;
    while (end < entries.size() && entries[end].first == entries[start].first) ++end;
    for (std::size_t s = start; s < end; ++s) {
      for (std::size_t t = s + 1; t < end; ++t) {
        const int i = entries[s].second, j = entries[t].second;  // i < j: sorted by body
        if (proxies[static_cast<std::size_t>(i)].isStatic &&
            proxies[static_cast<std::size_t>(j)].isStatic) {
          continue;
        }
        candidates.push_back({i, j});
      }
    }
    start = end;
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

  std::vector<BodyPair> pairs;
  for (const BodyPair& p : candidates) {
    if (boxes[static_cast<std::size_t>(p.first)].overlaps(boxes[static_cast<std::size_t>(p.second)])) {
      pairs.push_back(p);
    }
  }
  if (counters != nullptr) {
    counters->pairsTested += static_cast<std::int64_t>(candidates.size());
    counters->pairsOverlapping += static_cast<std::int64_t>(pairs.size());
  }
  return pairs;
}

template std::vector<BodyPair> uniformGridPairs<2>(const std::vector<BroadPhaseProxy<2>>&,
                                                   const UniformGridSettings&, DetectionCounters*);
template std::vector<BodyPair> uniformGridPairs<3>(const std::vector<BroadPhaseProxy<3>>&,
                                                   const UniformGridSettings&, DetectionCounters*);

}  // namespace stackbook
