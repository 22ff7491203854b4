// Exercise 7.3, reference solution: a bounding-volume hierarchy over surface samples
// (chapter 7).
#include "stackbook/exercises/ex07_3_sample_tree.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace stackbook {

template <int D>
SampleTree<D>::SampleTree(const std::vector<Vec<D>>& points, int leafSize) : points_(points) {
  if (leafSize < 1) {
    std::ostringstream msg;
    msg << "SampleTree: leafSize must be at least 1, got " << leafSize;
    throw std::invalid_argument(msg.str());
  }
  order_.resize(points_.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (points_.empty()) return;
  // Build top-down with an explicit stack of (node, first, count); children are appended.
  struct Task {
    int node, first, count;
  };
  nodes_.push_back(Node{});
  std::vector<Task> stack = {{0, 0, static_cast<int>(points_.size())}};
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    Aabb<D> box;
    for (int k = task.first; k < task.first + task.count; ++k) {
      box.extend(points_[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])]);
    }
    nodes_[static_cast<std::size_t>(task.node)].box = box;
    if (task.count <= leafSize) {
      nodes_[static_cast<std::size_t>(task.node)].first = task.first;
      nodes_[static_cast<std::size_t>(task.node)].count = task.count;
      continue;
    }
    Eigen::Index axis = 0;
    box.extent().maxCoeff(&axis);
    const int half = task.count / 2;
    const auto begin = order_.begin() + task.first;
    // Median split; ties broken by index, so the tree does not depend on the library.
    std::nth_element(begin, begin + half, begin + task.count, [&](int i, int j) {
      const double xi = points_[static_cast<std::size_t>(i)][axis];
      const double xj = points_[static_cast<std::size_t>(j)][axis];
      return xi < xj || (xi == xj && i < j);
    });
    const int left = static_cast<int>(nodes_.size());
    nodes_.push_back(Node{});
    nodes_.push_back(Node{});
    nodes_[static_cast<std::size_t>(task.node)].left = left;
    nodes_[static_cast<std::size_t>(task.node)].right = left + 1;
    stack.push_back({left, task.first, half});
    stack.push_back({left + 1, task.first + half, task.count - half});
  }
}

template <int D>
std::vector<int> SampleTree<D>::query(const Aabb<D>& box, std::int64_t* pointsVisited) const {
  std::vector<int> found;
  if (nodes_.empty()) return found;
  std::vector<int> stack = {0};
  while (!stack.empty()) {
    const Node& node = nodes_[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    if (!node.box.overlaps(box)) continue;
    if (node.left < 0) {
      if (pointsVisited != nullptr) *pointsVisited += node.count;
      for (int k = node.first; k < node.first + node.count; ++k) {
        const int i = order_[static_cast<std::size_t>(k)];
        if (box.contains(points_[static_cast<std::size_t>(i)])) found.push_back(i);
      }
    } else {
      stack.push_back(node.left);
      stack.push_back(node.right);
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

template <int D>
void appendSamplesInsideWithTree(const CollisionBody<D>& owner, const SampleTree<D>& ownerTree,
                                 int ownerIndex, const CollisionBody<D>& penetrated,
                                 int penetratedIndex, std::vector<InterferenceSample<D>>& out,
                                 const NarrowPhaseSettings& settings, DetectionCounters* counters) {
  checkCollisionBody<D>(owner, ownerIndex, "appendSamplesInsideWithTree");
  checkCollisionBody<D>(penetrated, penetratedIndex, "appendSamplesInsideWithTree");
  const std::vector<Vec<D>>& samples = owner.shape->surfaceSamples();
  if (ownerTree.points().size() != samples.size()) {
    throw std::invalid_argument(
        "appendSamplesInsideWithTree: the tree was not built over the owner's samples");
  }
  const Shape<D>& shapeB = *penetrated.shape;
  const Aabb<D> boxB = shapeB.bounds().inflated(settings.cullMargin);
  const Mat<D> RA = rotationMatrix<D>(owner.pose.orientation);
  const Mat<D> RB = rotationMatrix<D>(penetrated.pose.orientation);
  // Owner frame -> penetrated frame (Eq. (7.2)), exactly as appendSamplesInside does it.
  const Mat<D> M = RB.transpose() * RA;
  const Vec<D> t = RB.transpose() * Vec<D>(owner.pose.position - penetrated.pose.position);

  std::vector<int> candidates;
  if (settings.cullByBounds) {
    if (boxB.isEmpty()) return;
    // The penetrated box seen from the owner: x_A = M^T (x_B - t); its box by Eq. (7.8).
    const Vec<D> centre = M.transpose() * Vec<D>(boxB.center() - t);
    const Vec<D> half = M.transpose().cwiseAbs() * Vec<D>(0.5 * boxB.extent());
    const double hair = 1e-9 * (1.0 + half.maxCoeff() + centre.cwiseAbs().maxCoeff());
    const Aabb<D> query{Vec<D>(centre.array() - half.array() - hair),
                        Vec<D>(centre.array() + half.array() + hair)};
    candidates = ownerTree.query(query);
  } else {
    candidates.resize(samples.size());
    std::iota(candidates.begin(), candidates.end(), 0);
  }

  std::int64_t culled = 0, queries = 0, found = 0;
  for (const int k : candidates) {
    const Vec<D>& s = samples[static_cast<std::size_t>(k)];
    const Vec<D> xB = M * s + t;
    if (settings.cullByBounds && !boxB.contains(xB)) {
      ++culled;
      continue;
    }
    ++queries;
    const double phi = shapeB.signedDistance(xB);
    if (!(phi < 0.0)) continue;
    ++found;
    InterferenceSample<D> sample;
    sample.point = owner.pose.toWorld(s);
    sample.depth = phi;
    sample.normal = penetrated.pose.directionToWorld(shapeB.normal(xB));
    sample.owner = ownerIndex;
    sample.other = penetratedIndex;
    sample.sampleIndex = k;
    out.push_back(sample);
  }
  if (counters != nullptr) {
    counters->samplesTransformed += static_cast<std::int64_t>(candidates.size());
    counters->samplesCulled += culled;
    counters->phiQueries += queries;
    counters->interferenceSamples += found;
  }
}

template class SampleTree<2>;
template class SampleTree<3>;
template void appendSamplesInsideWithTree<2>(const CollisionBody<2>&, const SampleTree<2>&, int,
                                             const CollisionBody<2>&, int,
                                             std::vector<InterferenceSample<2>>&,
                                             const NarrowPhaseSettings&, DetectionCounters*);
template void appendSamplesInsideWithTree<3>(const CollisionBody<3>&, const SampleTree<3>&, int,
                                             const CollisionBody<3>&, int,
                                             std::vector<InterferenceSample<3>>&,
                                             const NarrowPhaseSettings&, DetectionCounters*);

}  // namespace stackbook
