// Exercise 7.2, reference solution: edge-edge interference by closest points of segments
// (chapter 7).
#include "stackbook/exercises/ex07_2_edge_edge.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace stackbook {

namespace {

/// Parameters (s, t) in [0, 1]^2 of the closest points p1 + s (q1 - p1) and
/// p2 + t (q2 - p2) of two segments: minimise |r + s d1 - t d2|^2 with r = p1 - p2, first
/// over the infinite lines, then clamp one parameter and re-solve for the other.
void closestSegmentParameters(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2,
                              double& s, double& t) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r);
  const double tiny = 1e-300;
  if (a <= tiny && e <= tiny) {
    s = t = 0.0;
    return;
  }
  if (a <= tiny) {
    s = 0.0;
    t = std::clamp(f / e, 0.0, 1.0);
    return;
  }
  const double c = d1.dot(r);
  if (e <= tiny) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
    return;
  }
  const double b = d1.dot(d2), denom = a * e - b * b;  // >= 0; 0 for parallel segments
  s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
}

/// Record a sample at the world point x of body `owner` when it is inside `other`.
void recordIfInside(const Vec3& x, int owner, const CollisionBody<3>& otherBody, int other,
                    int edgeIndex, std::vector<InterferenceSample<3>>& out,
                    DetectionCounters* counters) {
  const Vec3 xOther = otherBody.pose.toBody(x);
  const double phi = otherBody.shape->signedDistance(xOther);
  if (counters != nullptr) ++counters->phiQueries;
  if (!(phi < 0.0)) return;
  InterferenceSample<3> sample;
  sample.point = x;
  sample.depth = phi;
  sample.normal = otherBody.pose.directionToWorld(otherBody.shape->normal(xOther));
  sample.owner = owner;
  sample.other = other;
  sample.sampleIndex = edgeIndex;
  out.push_back(sample);
  if (counters != nullptr) ++counters->interferenceSamples;
}

}  // namespace

std::vector<InterferenceSample<3>> edgeEdgeInterference(const std::vector<CollisionBody<3>>& bodies,
                                                        const BodyPair& pair,
                                                        const TriangleMesh& meshFirst,
                                                        const TriangleMesh& meshSecond,
                                                        DetectionCounters* counters) {
  const int n = static_cast<int>(bodies.size());
  if (pair.first < 0 || pair.first >= n || pair.second < 0 || pair.second >= n ||
      pair.first == pair.second) {
    std::ostringstream msg;
    msg << "edgeEdgeInterference: pair (" << pair.first << ", " << pair.second
        << ") must name two different bodies among " << n;
    throw std::invalid_argument(msg.str());
  }
  const CollisionBody<3>& a = bodies[static_cast<std::size_t>(pair.first)];
  const CollisionBody<3>& b = bodies[static_cast<std::size_t>(pair.second)];
  checkCollisionBody<3>(a, pair.first, "edgeEdgeInterference");
  checkCollisionBody<3>(b, pair.second, "edgeEdgeInterference");
  // World positions of both meshes' vertices at the tested poses.
  const auto toWorld = [](const TriangleMesh& mesh, const Pose<3>& pose) {
    std::vector<Vec3> world;
    world.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) world.push_back(pose.toWorld(v));
    return world;
  };
  const std::vector<Vec3> va = toWorld(meshFirst, a.pose), vb = toWorld(meshSecond, b.pose);
  const std::vector<std::array<int, 2>> ea = meshEdges(meshFirst), eb = meshEdges(meshSecond);
  const auto segmentBox = [](const Vec3& p, const Vec3& q) {
    Aabb<3> box;
    box.extend(p);
    box.extend(q);
    return box;
  };
  // Only edges that reach into the other body's world box can have a point inside it.
  const auto nearEdges = [&](const std::vector<std::array<int, 2>>& edges,
                             const std::vector<Vec3>& world, const Aabb<3>& otherBox) {
    std::vector<std::size_t> kept;
    for (std::size_t k = 0; k < edges.size(); ++k) {
      if (segmentBox(world[static_cast<std::size_t>(edges[k][0])],
                     world[static_cast<std::size_t>(edges[k][1])]).overlaps(otherBox)) {
        kept.push_back(k);
      }
    }
    return kept;
  };
  const std::vector<std::size_t> nearA = nearEdges(ea, va, worldBounds<3>(*b.shape, b.pose));
  const std::vector<std::size_t> nearB = nearEdges(eb, vb, worldBounds<3>(*a.shape, a.pose));

  std::vector<InterferenceSample<3>> out;
  for (const std::size_t i : nearA) {
    const Vec3& p1 = va[static_cast<std::size_t>(ea[i][0])];
    const Vec3& q1 = va[static_cast<std::size_t>(ea[i][1])];
    for (const std::size_t j : nearB) {
      const Vec3& p2 = vb[static_cast<std::size_t>(eb[j][0])];
      const Vec3& q2 = vb[static_cast<std::size_t>(eb[j][1])];
      double s = 0.0, t = 0.0;
      closestSegmentParameters(p1, q1, p2, q2, s, t);
      const Vec3 p = p1 + s * (q1 - p1), q = p2 + t * (q2 - p2);
      recordIfInside(p, pair.first, b, pair.second, static_cast<int>(i), out, counters);
      recordIfInside(q, pair.second, a, pair.first, static_cast<int>(j), out, counters);
    }
  }
  return out;
}

}  // namespace stackbook
