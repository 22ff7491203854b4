#pragma once
/// \file
/// \brief Exercise 7.3: a bounding-volume hierarchy over a body's surface samples, so that
/// the narrow phase transforms only the samples near the other body (\ref ch07).

#include <cstdint>
#include <vector>

#include "stackbook/collision/narrow_phase.hpp"

namespace stackbook {

/// A binary tree of boxes over a set of body-frame points (a shape's surface samples).
/// Node 0 is the root. An inner node has two children; a leaf holds at most `leafSize`
/// points, the entries order[first] .. order[first + count - 1] (indices into the points).
template <int D>
class SampleTree {
 public:
  struct Node {
    Aabb<D> box;     ///< the box around the node's points
    int first = 0;   ///< leaf: first entry in order(); inner node: unused
    int count = 0;   ///< leaf: number of points (>= 1); inner node: 0
    int left = -1;   ///< inner node: child indices; leaf: -1
    int right = -1;
  };

  SampleTree() = default;
  /// Builds the tree: split a node's points at the median along the longest axis of their
  /// box until at most leafSize remain. Throws std::invalid_argument for leafSize < 1.
  explicit SampleTree(const std::vector<Vec<D>>& points, int leafSize = 8);

  /// Indices of the points inside `box` (closed), ascending. *pointsVisited (if given) is
  /// increased by the number of points in the leaves the query reached: the points it
  /// had to look at.
  std::vector<int> query(const Aabb<D>& box, std::int64_t* pointsVisited = nullptr) const;

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<int>& order() const { return order_; }
  const std::vector<Vec<D>>& points() const { return points_; }

 private:
  std::vector<Node> nodes_;
  std::vector<int> order_;
  std::vector<Vec<D>> points_;
};

/// appendSamplesInside() with the owner's samples culled through its tree: the penetrated
/// body's body-frame box (inflated by settings.cullMargin) is carried into the owner's
/// frame (the box around it at the relative pose, as Eq. (7.8) does for the world frame),
/// grown by a hair (1e-9 of its size) so that round-off cannot lose a sample on its
/// boundary; the tree gives the samples in it, and only those candidates are carried into
/// the penetrated frame (Eq. (7.2)), culled exactly (Eq. (7.7)) and tested against phi.
/// The result is the same as appendSamplesInside(): same samples, same order, same values.
/// counters->samplesTransformed counts the candidates, counters->samplesCulled those of
/// them outside the penetrated box; phiQueries and interferenceSamples as before. With
/// settings.cullByBounds false every sample is a candidate, as in appendSamplesInside().
/// `ownerTree` must be built over owner.shape->surfaceSamples().
template <int D>
void appendSamplesInsideWithTree(const CollisionBody<D>& owner, const SampleTree<D>& ownerTree,
                                 int ownerIndex, const CollisionBody<D>& penetrated,
                                 int penetratedIndex, std::vector<InterferenceSample<D>>& out,
                                 const NarrowPhaseSettings& settings = {},
                                 DetectionCounters* counters = nullptr);

}  // namespace stackbook
