#pragma once
/// \file
/// \brief Which bodies carry the load resting on them (chapter 12, "Freezing only what
/// carries its load", Eqs. (12.1)-(12.4)): the static loads of the contact graph, top down,
/// each body's support region seen along gravity, and the graph with the bodies that cannot
/// carry their load joined to their supporters and to everything above them, so that the
/// pass sweeps them together instead of freezing one under the other.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "stackbook/collision/candidate_list_store.hpp"
#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/contact_levels.hpp"
#include "stackbook/stepping/impulse_stage.hpp"

namespace stackbook {

// [support_region]
/// A set of points seen along gravity (Eq. (12.1)): each point x becomes its coordinates in
/// the plane normal to g, h(x) = (x . t_1, ..., x . t_{D-1}). In 2D the region is the
/// interval [lo, hi] of the points' h; in 3D the convex hull of their h, counter-clockwise.
/// contains() and clamp() answer for the region; an empty region contains nothing.
template <int D>
class SupportRegion {
 public:
  using Flat = Eigen::Matrix<double, D - 1, 1>;

  /// The region of the points `flat` (already projected by SupportFrame::flat()).
  explicit SupportRegion(std::vector<Flat> flat) {
    if (flat.empty()) return;
    if constexpr (D == 2) {
      double lo = flat.front()[0], hi = lo;
      for (const Flat& p : flat) {
        lo = std::min(lo, p[0]);
        hi = std::max(hi, p[0]);
      }
      hull_ = {Flat(lo), Flat(hi)};
    } else {  // Andrew's monotone chain: O(k log k)
      std::sort(flat.begin(), flat.end(), [](const Flat& a, const Flat& b) {
        return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
      });
      const auto turn = [](const Flat& o, const Flat& a, const Flat& b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
      };
      std::vector<Flat> h(2 * flat.size());
      std::size_t k = 0;
      for (std::size_t i = 0; i < flat.size(); ++i) {
        while (k >= 2 && turn(h[k - 2], h[k - 1], flat[i]) <= 0.0) --k;
        h[k++] = flat[i];
      }
      for (std::size_t i = flat.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && turn(h[k - 2], h[k - 1], flat[i]) <= 0.0) --k;
        h[k++] = flat[i];
      }
      h.resize(k > 1 ? k - 1 : k);
      hull_ = std::move(h);
    }
  }

  bool empty() const { return hull_.empty(); }

  /// The point of the region nearest to p (p itself when the region contains it).
  Flat clamp(const Flat& p) const {
    if (hull_.empty()) return p;
    if constexpr (D == 2) {
      return Flat(std::clamp(p[0], hull_[0][0], hull_[1][0]));
    } else {
      if (insidePolygon(p)) return p;
      Flat best = hull_.front();
      double bestDistance = (p - best).squaredNorm();
      for (std::size_t i = 0; i < hull_.size(); ++i) {  // nearest point of each edge
        const Flat& a = hull_[i];
        const Flat& b = hull_[(i + 1) % hull_.size()];
        const Flat ab = b - a;
        const double length = ab.squaredNorm();
        const double s = length > 0.0 ? std::clamp((p - a).dot(ab) / length, 0.0, 1.0) : 0.0;
        const Flat q = a + s * ab;
        if ((p - q).squaredNorm() < bestDistance) {
          bestDistance = (p - q).squaredNorm();
          best = q;
        }
      }
      return best;
    }
  }

  /// True if p lies in the region or within `tolerance` of it.
  bool contains(const Flat& p, double tolerance) const {
    if (hull_.empty()) return false;
    return (clamp(p) - p).norm() <= tolerance;
  }

 private:
  bool insidePolygon(const Flat& p) const {
    if (hull_.size() < 3) return false;
    for (std::size_t i = 0; i < hull_.size(); ++i) {
      const Flat& a = hull_[i];
      const Flat& b = hull_[(i + 1) % hull_.size()];
      if ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) < 0.0) return false;
    }
    return true;
  }

  std::vector<Flat> hull_;
};
// [support_region]

/// The plane normal to gravity: flat(x) are the coordinates of x in it (Eq. (12.1)).
template <int D>
struct SupportFrame {
  Eigen::Matrix<double, D, D - 1> tangents;

  explicit SupportFrame(const Vec<D>& gravity) {
    const Vec<D> down = gravity.normalized();
    if constexpr (D == 2) {
      tangents.col(0) = Vec<D>(-down[1], down[0]);
    } else {
      const Vec<D> seed = std::abs(down[0]) < 0.9 ? Vec<D>::UnitX() : Vec<D>::UnitY();
      const Vec<D> t1 = (seed - seed.dot(down) * down).normalized();
      tangents.col(0) = t1;
      tangents.col(1) = down.cross(t1);
    }
  }
  typename SupportRegion<D>::Flat flat(const Vec<D>& x) const { return tangents.transpose() * x; }
};

// [load_carrying]
/// What loadCarrying() found: per body, whether it carries its load (1; static bodies and
/// bodies with nothing to test count as carrying), its load W and its centre of load x* seen
/// along gravity (Eq. (12.2); zero for a static body), and how many dynamic bodies do not carry.
template <int D>
struct LoadCarrying {
  std::vector<char> carries;
  std::vector<double> weight;
  std::vector<typename SupportRegion<D>::Flat> centre;
  std::int64_t uncarried = 0;
};

/// Eqs. (12.2)-(12.3), top down over `levels`: the static load on each dynamic body c is its
/// own weight m_c at its centre plus, from each child d at a higher level, the share 1/k_d of
/// d's load W_d (k_d: d's supporters at lower levels), applied at the point of the support
/// patch between d and c nearest to d's centre of load. c carries its load when its centre of
/// load x*_c, seen along gravity, lies in the support region of all its contacts with its
/// supporters (within `tolerance`). Patches are the interference samples of each graph edge
/// at the poses the graph was built from (`views`: x + dt v), the upper body advanced by
/// dt^2 g as worldContactGraph() advances it. No gravity: every body carries. O(edges) pair
/// queries; with `kept` (the world's candidate lists, chapter 7) each pair of samples asks
/// through its kept lists, which find the same samples in the same order.
template <int D>
LoadCarrying<D> loadCarrying(const World<D>& world, const ContactGraph& graph, const ContactLevels& levels,
                          double dt, RotationUpdate rotation, const NarrowPhaseSettings& narrow,
                          double tolerance, DetectionCounters* counters = nullptr,
                          const CandidateListStore<D>* kept = nullptr) {
  const std::size_t n = world.bodies.size();
  using Flat = typename SupportRegion<D>::Flat;
  LoadCarrying<D> result;
  result.carries.assign(n, 1);
  result.weight.assign(n, 0.0);
  result.centre.assign(n, Flat::Zero());
  const double g = world.gravity.norm();
  if (!(g > 0.0)) return result;
  const SupportFrame<D> frame(world.gravity);
  std::vector<CollisionBody<D>> views = stageViews<D>(world, Lookahead::Velocity, dt, rotation);
  // The support patch of each edge below -> above, seen along gravity.
  std::vector<InterferenceCandidate<D>> scratch;
  std::vector<InterferenceSample<D>> samples;
  PairCandidateLists<D> lists;
  const auto patch = [&](int below, int above) {
    std::vector<Flat> points;
    const std::size_t k = static_cast<std::size_t>(above);
    RigidBody<D> advanced = world.bodies[k];
    advanceVelocity<D>(advanced, dt, world.loads(above));  // as the graph's test, Eq. (5.7)
    const CollisionBody<D> saved = views[k];
    views[k] = collisionBodyAt<D>(advanced, *world.shapes[k], predictPose<D>(advanced, dt, rotation));
    const BodyPair pair{below, above};
    if (pairAsksDeepestPoint<D>(narrow, *world.shapes[static_cast<std::size_t>(below)], *world.shapes[k])) {
      samples = pairInterference<D>(views, pair, narrow, counters);  // chapter 11's exact points
    } else {
      // A copy: a list remade at the advanced pose stays here, and the pass finds the stage's.
      if (kept == nullptr || !kept->copyFor(below, above, lists)) {
        lists.firstInSecond.made = lists.secondInFirst.made = false;
      }
      pairInterferenceListed<D>(views, pair, narrow, counters, scratch, samples, &lists);
    }
    for (const InterferenceSample<D>& s : samples) points.push_back(frame.flat(s.point));
    views[k] = saved;
    return points;
  };
  std::vector<double> weight(n, 0.0);         // W_c
  std::vector<Flat> moment(n, Flat::Zero());  // sum of W h over c's own weight and its loads
  for (std::size_t k = 0; k < n; ++k) {
    if (world.bodies[k].isStatic()) continue;
    weight[k] = world.bodies[k].mass();
    moment[k] = weight[k] * frame.flat(world.bodies[k].position);
  }
  std::vector<Flat> all;
  for (std::size_t l = levels.levelCount(); l-- > 0;) {  // top down: children before parents
    for (const int c : levels.bodies(l)) {
      const std::size_t kc = static_cast<std::size_t>(c);
      if (world.bodies[kc].isStatic()) continue;
      const Flat centre = moment[kc] / weight[kc];  // x*_c, Eq. (12.2)
      result.weight[kc] = weight[kc];
      result.centre[kc] = centre;
      all.clear();
      int lower = 0;
      for (const int a : graph.parents(c)) {
        if (levels.levelOfBody[static_cast<std::size_t>(a)] < static_cast<int>(l)) ++lower;
      }
      for (const int a : graph.parents(c)) {
        const std::vector<Flat> points = patch(a, c);
        all.insert(all.end(), points.begin(), points.end());
        const std::size_t ka = static_cast<std::size_t>(a);
        if (levels.levelOfBody[ka] >= static_cast<int>(l) || world.bodies[ka].isStatic()) continue;
        // Eq. (12.3): the share of c's load that a carries, where it enters a.
        const double share = weight[kc] / static_cast<double>(lower);
        const Flat at = points.empty() ? centre : SupportRegion<D>(points).clamp(centre);
        weight[ka] += share;
        moment[ka] += share * at;
      }
      if (all.empty()) continue;  // nothing below it to test against
      if (!SupportRegion<D>(all).contains(centre, tolerance)) {  // Eq. (12.4)
        result.carries[kc] = 0;
        ++result.uncarried;
      }
    }
  }
  return result;
}
// [load_carrying]

/// Per body, 1 if it is static (a sleeping body counts: the step made it static).
template <int D>
std::vector<char> staticBodies(const World<D>& world) {
  std::vector<char> out(world.bodies.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = world.bodies[k].isStatic() ? 1 : 0;
  return out;
}

// [join_uncarried]
/// `graph` with every body that does not carry its load (carries[c] == 0) joined to its dynamic
/// supporters and to every body above it (Eq. (12.5)): each edge between two dynamic bodies of
/// one joined group gets its reverse too, so the group is one strongly connected component,
/// one level of topologicalLevels(), swept together and frozen only as a whole. Bodies above a
/// group are joined because the load that tips it comes from them. O(n + m).
inline ContactGraph joinUncarried(const ContactGraph& graph, const std::vector<char>& carries,
                                  const std::vector<char>& isStatic, const ContactLevels& levels) {
  const int n = graph.bodyCount();
  std::vector<int> root(static_cast<std::size_t>(n));
  std::iota(root.begin(), root.end(), 0);
  const auto find = [&root](int k) {
    while (root[static_cast<std::size_t>(k)] != k) {
      root[static_cast<std::size_t>(k)] = root[static_cast<std::size_t>(root[static_cast<std::size_t>(k)])];
      k = root[static_cast<std::size_t>(k)];
    }
    return k;
  };
  const auto join = [&](int a, int b) {
    const int ra = find(a), rb = find(b);
    if (ra != rb) root[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
  };
  std::vector<char> joinsAbove(static_cast<std::size_t>(n), 0);  // its children join its group
  for (std::size_t l = 0; l < levels.levelCount(); ++l) {  // bottom up: parents before children
    for (const int c : levels.bodies(l)) {
      const std::size_t kc = static_cast<std::size_t>(c);
      if (isStatic[kc] != 0) continue;
      if (carries[kc] == 0) joinsAbove[kc] = 1;
      for (const int a : graph.parents(c)) {
        const std::size_t ka = static_cast<std::size_t>(a);
        if (isStatic[ka] != 0) continue;
        if (carries[kc] == 0 || joinsAbove[ka] != 0) {
          join(a, c);
          joinsAbove[kc] = 1;
        }
      }
    }
  }
  ContactGraph joined = graph;
  for (const ContactPair& e : graph.edges()) {
    if (isStatic[static_cast<std::size_t>(e.below)] != 0 || isStatic[static_cast<std::size_t>(e.above)] != 0) continue;
    if (find(e.below) == find(e.above)) joined.addEdge(e.above, e.below);
  }
  return joined;
}
// [join_uncarried]

}  // namespace stackbook
