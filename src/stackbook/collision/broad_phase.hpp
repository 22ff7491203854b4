#pragma once
/// \file
/// \brief Broad phase: the pairs of bodies whose world boxes overlap, by sweep and prune
/// along one axis, with the all-pairs test kept beside it as the reference (\ref ch07).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <compare>
#include <utility>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "stackbook/collision/collision_body.hpp"
#include "stackbook/collision/detection_counters.hpp"

namespace stackbook {

/// Two body indices, first < second. Pairs compare lexicographically, which is the order
/// the broad phase reports them in.
struct BodyPair {
  int first = 0;
  int second = 0;
  friend auto operator<=>(const BodyPair&, const BodyPair&) = default;
};

/// What the broad phase needs of a body: its world box and whether it is static.
template <int D>
struct BroadPhaseProxy {
  Aabb<D> box;
  bool isStatic = false;
};

/// Broad-phase knobs. \ref ch07
struct BroadPhaseSettings {
  /// Sweep axis 0..D-1, or -1: the axis along which the box centres spread most
  /// (largest variance), which keeps the sweep's candidate list short.
  int axis = -1;
  /// Every box is inflated by this much on every side before the test, so pairs whose
  /// boxes are within 2 * margin of each other are reported too. Must be >= 0.
  double margin = 0.0;
  /// KeptBroadPhase (a stage's sweeps): each body's box is grown by this fraction of its
  /// largest extent when the kept pairs are found, which then answer until a box moves by
  /// half that. Changes the work, never the pairs. 0: sweep and prune at every sweep.
  /// Must be finite and >= 0.
  double keepSlack = 0.05;
};

/// One proxy per collision view: worldBounds() at the view's pose (with the view's kept
/// rotation matrix, the same bits) and its static flag.
/// Throws std::invalid_argument when a view has no shape. \ref ch07
template <int D>
std::vector<BroadPhaseProxy<D>> broadPhaseProxies(const std::vector<CollisionBody<D>>& bodies) {
  std::vector<BroadPhaseProxy<D>> proxies;
  proxies.reserve(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].shape == nullptr) {
      std::ostringstream msg;
      msg << "broadPhaseProxies: body " << i << " has no Shape (shape is null)";
      throw std::invalid_argument(msg.str());
    }
    proxies.push_back({detail::worldBoundsWithMatrix<D>(*bodies[i].shape, bodies[i].pose, bodies[i].poseRotation()),
                       bodies[i].isStatic});
  }
  return proxies;
}

namespace detail {

template <int D>
void checkBroadPhaseInput(const std::vector<BroadPhaseProxy<D>>& proxies,
                          const BroadPhaseSettings& settings, const char* caller) {
  std::ostringstream msg;
  if (settings.axis < -1 || settings.axis >= D) {
    msg << caller << ": settings.axis must be -1 (automatic) or in 0.." << D - 1 << ", got "
        << settings.axis;
  } else if (!std::isfinite(settings.margin) || settings.margin < 0.0) {
    msg << caller << ": settings.margin must be finite and >= 0, got " << settings.margin;
  } else if (!std::isfinite(settings.keepSlack) || settings.keepSlack < 0.0) {
    msg << caller << ": settings.keepSlack must be finite and >= 0, got " << settings.keepSlack;
  } else {
    for (std::size_t i = 0; i < proxies.size(); ++i) {
      const Aabb<D>& b = proxies[i].box;
      if (b.lower.hasNaN() || b.upper.hasNaN()) {
        msg << caller << ": proxy " << i << " has a NaN in its box";
        break;
      }
    }
  }
  if (!msg.str().empty()) throw std::invalid_argument(msg.str());
}

}  // namespace detail

/// The sweep axis the settings ask for: settings.axis, or for -1 the axis with the largest
/// variance of the (finite) box centres; ties go to the lower axis. \ref ch07
template <int D>
int sweepAxis(const std::vector<BroadPhaseProxy<D>>& proxies,
              const BroadPhaseSettings& settings = {}) {
  if (settings.axis >= 0) return settings.axis;
  Vec<D> sum = Vec<D>::Zero(), sumSq = Vec<D>::Zero();
  double count = 0.0;
  for (const BroadPhaseProxy<D>& p : proxies) {
    if (p.box.isEmpty()) continue;
    const Vec<D> c = p.box.center();
    if (!c.allFinite()) continue;  // an infinite ground plane says nothing about spread
    sum += c;
    sumSq += c.cwiseProduct(c);
    count += 1.0;
  }
  if (count == 0.0) return 0;
  const Vec<D> variance = sumSq / count - (sum / count).cwiseProduct(sum / count);
  int best = 0;
  for (int a = 1; a < D; ++a) {
    if (variance[a] > variance[best]) best = a;
  }
  return best;
}

// [sweep_and_prune]
/// All pairs (i, j), i < j, whose boxes (inflated by settings.margin) overlap, skipping
/// pairs of two static bodies, sorted by (i, j). Sweep and prune: sort the boxes by their
/// lower bound on one axis (equal bounds in index order), then walk
/// the sorted list; a box can only overlap the boxes that start before it ends on that
/// axis. Cost: the sort, O(n log n), plus one full box test per pair whose intervals
/// overlap on the sweep axis (Eq. (7.9)). counters->pairsTested counts those box tests,
/// which is the same number whatever order the bodies come in. \ref ch07
template <int D>
std::vector<BodyPair> sweepAndPrune(const std::vector<BroadPhaseProxy<D>>& proxies,
                                    const BroadPhaseSettings& settings = {},
                                    DetectionCounters* counters = nullptr) {
  detail::checkBroadPhaseInput<D>(proxies, settings, "sweepAndPrune");
  const int axis = sweepAxis<D>(proxies, settings);
  const int n = static_cast<int>(proxies.size());
  std::vector<Aabb<D>> boxes;
  boxes.reserve(proxies.size());
  for (const BroadPhaseProxy<D>& p : proxies) boxes.push_back(p.box.inflated(settings.margin));

  // The sort by lower bound, equal bounds in index order: the keys (lower bound, index) are
  // all different, so sorting them gives the one order a stable sort of the indices would.
  std::vector<std::pair<double, int>> keys(proxies.size());
  for (int i = 0; i < n; ++i) keys[static_cast<std::size_t>(i)] = {boxes[static_cast<std::size_t>(i)].lower[axis], i};
  std::sort(keys.begin(), keys.end());
  // The boxes in sweep order, side by side, so that the walk below reads memory in order.
  struct Swept {
    Aabb<D> box;
    int index;
    bool isStatic;
  };
  std::vector<Swept> sorted;
  sorted.reserve(proxies.size());
  for (const auto& [lower, i] : keys) {
    sorted.push_back({boxes[static_cast<std::size_t>(i)], i, proxies[static_cast<std::size_t>(i)].isStatic});
  }

  std::vector<BodyPair> pairs;
  std::int64_t tested = 0;
  for (int s = 0; s < n; ++s) {
    const Swept& a = sorted[static_cast<std::size_t>(s)];
    if (a.box.isEmpty()) continue;
    const double end = a.box.upper[axis];
    for (int t = s + 1; t < n; ++t) {
      const Swept& b = sorted[static_cast<std::size_t>(t)];
      if (b.box.lower[axis] > end) break;  // sorted: no later box can overlap
      if (a.isStatic && b.isStatic) continue;
      ++tested;
      if (a.box.overlaps(b.box)) pairs.push_back({std::min(a.index, b.index), std::max(a.index, b.index)});
    }
  }
  std::sort(pairs.begin(), pairs.end());
  if (counters != nullptr) {
    counters->pairsTested += tested;
    counters->pairsOverlapping += static_cast<std::int64_t>(pairs.size());
  }
  return pairs;
}
// [sweep_and_prune]

/// Sweep and prune over collision views: broadPhaseProxies() then sweepAndPrune(). \ref ch07
template <int D>
std::vector<BodyPair> sweepAndPrune(const std::vector<CollisionBody<D>>& bodies,
                                    const BroadPhaseSettings& settings = {},
                                    DetectionCounters* counters = nullptr) {
  return sweepAndPrune<D>(broadPhaseProxies<D>(bodies), settings, counters);
}

// [kept_broad_phase]
/// The broad phase of one stage's sweeps (chapter 8), found once and kept while it answers:
/// pairs() returns exactly the list sweepAndPrune() would, sweep after sweep. When the pairs
/// are found, each body's box is grown by settings.keepSlack times its largest extent (a
/// static body's not at all: it does not move) and swept once. At a later sweep, if every
/// box still lies within half its growth of the box it had then, two boxes that overlap now
/// overlapped grown, so the kept pairs hold every pair that overlaps now; testing their boxes
/// as they are now, in the kept (i, j) order, gives sweepAndPrune()'s list. Otherwise the pairs
/// are found again. counters->pairsTested counts the boxes compared (the kept pairs', plus
/// the sweep's when they are found again) and pairsOverlapping the pairs returned.
template <int D>
class KeptBroadPhase {
 public:
  std::vector<BodyPair> pairs(const std::vector<CollisionBody<D>>& bodies, const BroadPhaseSettings& settings,
                              DetectionCounters* counters = nullptr) {
    std::vector<BroadPhaseProxy<D>> proxies = broadPhaseProxies<D>(bodies);
    bool anyEmpty = false;
    for (const BroadPhaseProxy<D>& p : proxies) anyEmpty = anyEmpty || p.box.isEmpty();
    // Without slack (or with a bad one, which sweepAndPrune() reports) sweep and prune itself.
    if (!(settings.keepSlack > 0.0) || anyEmpty) return sweepAndPrune<D>(proxies, settings, counters);
    detail::checkBroadPhaseInput<D>(proxies, settings, "KeptBroadPhase");
    std::int64_t tested = 0;
    if (!covers(proxies)) {
      made_ = proxies;
      slack_.resize(proxies.size());
      std::vector<BroadPhaseProxy<D>> grown = proxies;
      for (std::size_t i = 0; i < proxies.size(); ++i) {
        const Aabb<D>& box = proxies[i].box;
        const double extent = (box.upper - box.lower).maxCoeff();
        // No growth for a static body, an unbounded box, or one too small to move within
        // round-off: such a box must stay exactly where it was.
        double slack = proxies[i].isStatic ? 0.0 : settings.keepSlack * extent;
        const double scale = box.lower.cwiseAbs().maxCoeff() + box.upper.cwiseAbs().maxCoeff();
        if (!std::isfinite(slack) || !(slack > 1e-9 * scale)) slack = 0.0;
        slack_[i] = slack;
        grown[i].box = box.inflated(slack);
      }
      DetectionCounters sweep;
      kept_ = sweepAndPrune<D>(grown, settings, &sweep);
      tested += sweep.pairsTested;
    }
    // Each box as sweepAndPrune() tests it, inflated by the margin, once per body.
    std::vector<Aabb<D>> boxes;
    boxes.reserve(proxies.size());
    for (const BroadPhaseProxy<D>& p : proxies) boxes.push_back(p.box.inflated(settings.margin));
    std::vector<BodyPair> out;
    for (const BodyPair& p : kept_) {  // sorted by (i, j), as sweepAndPrune() reports
      ++tested;
      if (boxes[static_cast<std::size_t>(p.first)].overlaps(boxes[static_cast<std::size_t>(p.second)])) out.push_back(p);
    }
    if (counters != nullptr) {
      counters->pairsTested += tested;
      counters->pairsOverlapping += static_cast<std::int64_t>(out.size());
    }
    return out;
  }

 private:
  /// True when the kept pairs answer for these boxes: the same bodies, static as they were,
  /// each box within half its growth of the box it had when the pairs were found.
  bool covers(const std::vector<BroadPhaseProxy<D>>& proxies) const {
    if (made_.size() != proxies.size()) return false;
    for (std::size_t i = 0; i < proxies.size(); ++i) {
      if (proxies[i].isStatic != made_[i].isStatic) return false;
      const double half = 0.5 * slack_[i];
      if (!(proxies[i].box.lower.array() >= made_[i].box.lower.array() - half).all()) return false;
      if (!(proxies[i].box.upper.array() <= made_[i].box.upper.array() + half).all()) return false;
    }
    return true;
  }

  std::vector<BroadPhaseProxy<D>> made_;  ///< each body's box and static flag when the pairs were found
  std::vector<double> slack_;             ///< each box's growth then
  std::vector<BodyPair> kept_;            ///< the pairs of the grown boxes, sorted by (i, j)
};
// [kept_broad_phase]

// [all_pairs]
/// The same pairs as sweepAndPrune() by testing every pair that is not static-static:
/// n(n-1)/2 box tests. The reference the sweep is checked against, and the cost it
/// saves (counters->pairsTested). \ref ch07
template <int D>
std::vector<BodyPair> allPairs(const std::vector<BroadPhaseProxy<D>>& proxies,
                               const BroadPhaseSettings& settings = {},
                               DetectionCounters* counters = nullptr) {
  detail::checkBroadPhaseInput<D>(proxies, settings, "allPairs");
  const int n = static_cast<int>(proxies.size());
  std::vector<BodyPair> pairs;
  std::int64_t tested = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (proxies[i].isStatic && proxies[j].isStatic) continue;
      ++tested;
      if (proxies[i].box.inflated(settings.margin).overlaps(proxies[j].box.inflated(settings.margin))) {
        pairs.push_back({i, j});
      }
    }
  }
  if (counters != nullptr) {
    counters->pairsTested += tested;
    counters->pairsOverlapping += static_cast<std::int64_t>(pairs.size());
  }
  return pairs;
}
// [all_pairs]

}  // namespace stackbook
