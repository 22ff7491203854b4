// The accuracy measures of peers_bench (measures.hpp).
#include "stackbook/peers/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Geometry>

namespace peers {

namespace {

/// Half the projection of a box (half sides h, axes the columns of R) on the unit axis n.
double halfProjection(const Eigen::Vector3d& h, const Eigen::Matrix3d& R, const Eigen::Vector3d& n, int dimension) {
  double r = 0.0;
  for (int k = 0; k < dimension; ++k) r += h[k] * std::abs(R.col(k).dot(n));
  return r;
}

/// The separating-axis overlap of two boxes: min over the axes of (r_a + r_b - |d . n|),
/// or 0 when some axis separates them.
double overlap(const BoxSpec& a, const BodyState& sa, const BoxSpec& b, const BodyState& sb, int dimension) {
  const Eigen::Vector3d ha = 0.5 * a.size;
  const Eigen::Vector3d hb = 0.5 * b.size;
  const Eigen::Vector3d d = sb.position - sa.position;
  std::vector<Eigen::Vector3d> axes;
  for (int k = 0; k < dimension; ++k) {
    axes.push_back(sa.rotation.col(k));
    axes.push_back(sb.rotation.col(k));
  }
  if (dimension == 3) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const Eigen::Vector3d c = sa.rotation.col(i).cross(sb.rotation.col(j));
        if (c.norm() > 1e-6) axes.push_back(c.normalized());
      }
    }
  }
  double depth = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& n : axes) {
    const double o = halfProjection(ha, sa.rotation, n, dimension) + halfProjection(hb, sb.rotation, n, dimension) -
                     std::abs(d.dot(n));
    if (o <= 0.0) return 0.0;
    depth = std::min(depth, o);
  }
  return depth;
}

}  // namespace

double boxEnergy(const BoxScene& scene, const std::vector<BodyState>& states) {
  double e = 0.0;
  const Eigen::Vector3d g = scene.gravityVector();
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    const BoxSpec& b = scene.boxes[i];
    if (b.isStatic()) continue;
    const BodyState& s = states[i];
    const Eigen::Vector3d q = b.size.cwiseProduct(b.size);
    Eigen::Vector3d inertia = (b.mass / 12.0) * Eigen::Vector3d(q[1] + q[2], q[0] + q[2], q[0] + q[1]);
    if (scene.dimension == 2) inertia = Eigen::Vector3d(0.0, 0.0, (b.mass / 12.0) * (q[0] + q[1]));
    const Eigen::Vector3d wBody = s.rotation.transpose() * s.angularVelocity;
    e += 0.5 * b.mass * s.velocity.squaredNorm() + 0.5 * wBody.dot(inertia.cwiseProduct(wBody)) +
         -b.mass * g.dot(s.position);  // U = -m g.x
  }
  return e;
}

double boxPenetration(const BoxScene& scene, const std::vector<BodyState>& states) {
  // Candidate pairs by bounding spheres, swept along x.
  const std::size_t n = scene.boxes.size();
  std::vector<double> radius(n);
  for (std::size_t i = 0; i < n; ++i) radius[i] = 0.5 * scene.boxes[i].size.head(scene.dimension).norm();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return states[a].position.x() - radius[a] < states[b].position.x() - radius[b];
  });
  double deepest = 0.0;
  for (std::size_t ia = 0; ia < n; ++ia) {
    const std::size_t a = order[ia];
    const double reach = states[a].position.x() + radius[a];
    for (std::size_t ib = ia + 1; ib < n; ++ib) {
      const std::size_t b = order[ib];
      if (states[b].position.x() - radius[b] > reach) break;
      if (scene.boxes[a].isStatic() && scene.boxes[b].isStatic()) continue;
      if ((states[a].position - states[b].position).norm() > radius[a] + radius[b]) continue;
      deepest = std::max(deepest, overlap(scene.boxes[a], states[a], scene.boxes[b], states[b], scene.dimension));
    }
  }
  return deepest;
}

Accuracy boxAccuracy(const BoxScene& scene, const std::vector<BodyState>& start,
                     const std::vector<BodyState>& end, double seconds) {
  Accuracy a;
  a.drift = 0.0;
  a.maxSpeed = 0.0;
  const int up = scene.dimension - 1;
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    const BodyState& s = end[i];
    if (!s.position.allFinite() || !s.velocity.allFinite() || !s.rotation.allFinite()) a.finite = false;
    if (scene.boxes[i].isStatic()) continue;
    Eigen::Vector3d horizontal = s.position - start[i].position;
    horizontal[up] = 0.0;
    a.drift = std::max(a.drift, horizontal.norm());
    const double halfDiagonal = 0.5 * scene.boxes[i].size.head(scene.dimension).norm();
    a.maxSpeed = std::max(a.maxSpeed, s.velocity.norm() + s.angularVelocity.norm() * halfDiagonal);
  }
  const auto top = static_cast<std::size_t>(scene.top());
  a.sag = start[top].position[up] - end[top].position[up];
  a.penetration = boxPenetration(scene, end);
  a.energyChange = boxEnergy(scene, end) - boxEnergy(scene, start);
  if (scene.tilt != 0.0) {
    a.inclineDistance = scene.inclineDistance(seconds);
    const double slid = end[top].position.x() - start[top].position.x();
    a.inclineError = a.inclineDistance > 0.0 ? slid / a.inclineDistance - 1.0 : slid;
  }
  return a;
}

}  // namespace peers
