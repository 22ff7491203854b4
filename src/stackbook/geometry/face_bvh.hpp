#pragma once
/// \file
/// \brief A bounding-volume hierarchy over the faces of a `SurfaceMesh<D>`, for the exact
/// unsigned distance from a point to the mesh (\ref ch06). The signed-distance grid asks it
/// for the nearest face at every node; the tree cuts the cost per query from O(F) face
/// tests to roughly O(log F) on well-spread meshes.
///
/// Construction splits the faces at the median of their centroids along the longest axis
/// of the centroid box (deterministic: ties broken by face index). A query descends the
/// nearer child first and skips every box farther away than the best face found so far
/// (branch and bound), so it returns the same face as a brute-force loop (the first face
/// in the loop order on exact ties may differ, the distance does not).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "stackbook/geometry/closest_point.hpp"

namespace stackbook {

/// Result of a nearest-face query.
template <int D>
struct NearestFace {
  int face = -1;                          ///< index into mesh.faces (-1: empty mesh)
  FaceClosestPoint<D> closest;            ///< closest point on that face
  double distance() const { return std::sqrt(closest.squaredDistance); }
};

template <int D>
class FaceBvh {
 public:
  FaceBvh() = default;

  /// Builds the tree over the faces of `mesh`. The tree keeps no reference to the mesh:
  /// queries take the mesh again, which must be the same (checked by face count).
  /// leafSize: most faces a leaf holds (>= 1).
  explicit FaceBvh(const SurfaceMesh<D>& mesh, int leafSize = 4) {
    if (leafSize < 1) throw std::invalid_argument("FaceBvh: leafSize must be at least 1");
    leafSize_ = leafSize;
    const std::size_t n = mesh.faces.size();
    faceCount_ = n;
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0);
    centroids_.resize(n);
    faceBoxes_.resize(n);
    for (std::size_t f = 0; f < n; ++f) {
      Aabb<D> box;
      Vec<D> sum = Vec<D>::Zero();
      for (int k = 0; k < D; ++k) {
        const Vec<D>& v = mesh.vertices[mesh.faces[f][static_cast<std::size_t>(k)]];
        box.extend(v);
        sum += v;
      }
      faceBoxes_[f] = box;
      centroids_[f] = sum / double(D);
    }
    if (n > 0) build(0, n);
  }

  /// Nearest face to x. `hint` (a face index, or -1) seeds the search bound: passing the
  /// answer of a nearby query makes the pruning effective from the first box.
  NearestFace<D> nearest(const SurfaceMesh<D>& mesh, const Vec<D>& x, int hint = -1) const {
    if (mesh.faces.size() != faceCount_) {
      throw std::invalid_argument("FaceBvh::nearest: the mesh is not the one the tree was built on");
    }
    NearestFace<D> best;
    best.closest.squaredDistance = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) return best;
    if (hint >= 0 && static_cast<std::size_t>(hint) < faceCount_) {
      best.face = hint;
      best.closest = closestPointOnFace<D>(mesh, static_cast<std::size_t>(hint), x);
    }
    // Explicit stack of (node, squared box distance); the nearer child is pushed last so
    // that it is popped first.
    struct Entry {
      std::int32_t node;
      double boxDistanceSquared;
    };
    Entry stack[128];
    int top = 0;
    stack[top++] = {0, boxDistanceSquared(nodes_[0].box, x)};
    while (top > 0) {
      const Entry entry = stack[--top];
      if (entry.boxDistanceSquared >= best.closest.squaredDistance) continue;
      const Node& node = nodes_[entry.node];
      ++lastVisits_;
      if (node.count > 0) {
        for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
          const std::size_t f = order_[i];
          if (boxDistanceSquared(faceBoxes_[f], x) >= best.closest.squaredDistance) continue;
          const FaceClosestPoint<D> candidate = closestPointOnFace<D>(mesh, f, x);
          ++lastFaceTests_;
          if (candidate.squaredDistance < best.closest.squaredDistance) {
            best.face = static_cast<int>(f);
            best.closest = candidate;
          }
        }
        continue;
      }
      const std::int32_t left = entry.node + 1, right = node.first;
      const double dl = boxDistanceSquared(nodes_[left].box, x);
      const double dr = boxDistanceSquared(nodes_[right].box, x);
      if (top + 2 > 128) throw std::logic_error("FaceBvh: traversal stack overflow");
      if (dl <= dr) {
        stack[top++] = {right, dr};
        stack[top++] = {left, dl};
      } else {
        stack[top++] = {left, dl};
        stack[top++] = {right, dr};
      }
    }
    return best;
  }

  /// Number of tree nodes.
  std::size_t nodeCount() const { return nodes_.size(); }
  /// Bytes held by the tree (nodes, face order, boxes, centroids).
  std::size_t memoryBytes() const {
    return nodes_.size() * sizeof(Node) + order_.size() * sizeof(std::size_t) +
           faceBoxes_.size() * sizeof(Aabb<D>) + centroids_.size() * sizeof(Vec<D>);
  }
  /// Work counters, accumulated over all queries since the last reset (for the benchmark).
  /// They make a query mutate the tree: do not share one tree between threads.
  std::uint64_t faceTests() const { return lastFaceTests_; }
  std::uint64_t nodeVisits() const { return lastVisits_; }
  void resetCounters() const { lastFaceTests_ = 0; lastVisits_ = 0; }

 private:
  // A node covers order_[first, first + count) if it is a leaf (count > 0). An inner
  // node (count = 0) has its left child at the next index and its right child at `first`.
  struct Node {
    Aabb<D> box;
    std::int32_t first = 0;
    std::int32_t count = 0;
  };

  static double boxDistanceSquared(const Aabb<D>& box, const Vec<D>& x) {
    const Vec<D> excess =
        (box.lower - x).cwiseMax(x - box.upper).cwiseMax(Vec<D>::Zero());
    return excess.squaredNorm();
  }

  // Builds the subtree over order_[begin, end) and returns its node index.
  std::int32_t build(std::size_t begin, std::size_t end) {
    const std::int32_t index = static_cast<std::int32_t>(nodes_.size());
    nodes_.emplace_back();
    Aabb<D> box, centroidBox;
    for (std::size_t i = begin; i < end; ++i) {
      box.extend(faceBoxes_[order_[i]]);
      centroidBox.extend(centroids_[order_[i]]);
    }
    nodes_[index].box = box;
    const std::size_t count = end - begin;
    if (count <= static_cast<std::size_t>(leafSize_)) {
      nodes_[index].first = static_cast<std::int32_t>(begin);
      nodes_[index].count = static_cast<std::int32_t>(count);
      return index;
    }
    Eigen::Index axis = 0;
    centroidBox.extent().maxCoeff(&axis);
    const std::size_t middle = begin + count / 2;
    std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(begin),
                     order_.begin() + static_cast<std::ptrdiff_t>(middle),
                     order_.begin() + static_cast<std::ptrdiff_t>(end),
                     [&](std::size_t p, std::size_t q) {
                       const double cp = centroids_[p][axis], cq = centroids_[q][axis];
                       return cp < cq || (cp == cq && p < q);
                     });
    build(begin, middle);  // the left child is the next node
    const std::int32_t right = build(middle, end);
    nodes_[index].first = right;
    nodes_[index].count = 0;
    return index;
  }

  std::size_t faceCount_ = 0;
  int leafSize_ = 4;
  std::vector<Node> nodes_;
  std::vector<std::size_t> order_;
  std::vector<Aabb<D>> faceBoxes_;
  std::vector<Vec<D>> centroids_;
  mutable std::uint64_t lastFaceTests_ = 0;
  mutable std::uint64_t lastVisits_ = 0;
};

/// Exact unsigned distance from x to the mesh by a loop over every face (the reference
/// the tree is tested against; O(F) per query).
template <int D>
NearestFace<D> nearestFaceBruteForce(const SurfaceMesh<D>& mesh, const Vec<D>& x) {
  NearestFace<D> best;
  best.closest.squaredDistance = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const FaceClosestPoint<D> candidate = closestPointOnFace<D>(mesh, f, x);
    if (candidate.squaredDistance < best.closest.squaredDistance) {
      best.face = static_cast<int>(f);
      best.closest = candidate;
    }
  }
  return best;
}

}  // namespace stackbook
