#pragma once
/// \file
/// \brief The sticking patch (\ref ch08, "A whole patch at once", Eqs. (8.16)-(8.19)): one
/// impulse and one angular impulse that stop the whole relative motion of a pair touching
/// along a face, when friction and the patch can carry them.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "stackbook/body/rigid_body.hpp"
#include "stackbook/math/cross.hpp"

namespace stackbook {

/// The impulse pair of a sticking patch: +J at `point` and +L to the owner, -J and -L to
/// the other body.
template <int D>
struct PatchImpulse {
  Vec<D> J = Vec<D>::Zero();         ///< the impulse, applied at `point`
  AngVec<D> L = AngVec<D>::Zero();   ///< the angular impulse about `point`
  Vec<D> point = Vec<D>::Zero();     ///< the patch's reference point p (the mean of its samples)
  Vec<D> pressure = Vec<D>::Zero();  ///< the centre of pressure c, where J's line of action meets the patch plane
};

// [patch_spin_bound]
/// Which spin about n a 3D patch is taken to carry (Eq. (8.19)).
enum class PatchSpinBound {
  /// (mu jn - |J_t|) dmin^2 / dmax over all patch points (the default): carried whatever the
  /// normal shares, but zero when a point lies at the centre of pressure.
  AllPoints,
  /// The largest of that bound over the subsets of points at distance >= rho from the centre
  /// of pressure whose hull still holds it (Eq. (9.13)): shares that put no load on the
  /// nearer points are shares too, so the bound of any such subset is carried. Never smaller
  /// than AllPoints'.
  BestSubset,
};
// [patch_spin_bound]

namespace detail {

/// The change of the relative twist (u at p, relative angular velocity) of the pair when the
/// owner receives (J, L) at p and the other (-J, -L) (Eq. (8.16)): each body adds
/// v += J/m, omega += I^{-1}(r x J + L), so u(p) changes by that v plus omega x r.
template <int D>
Eigen::Matrix<double, D + kAngularDim<D>, 1> patchResponse(const RigidBody<D>& body, const AngMat<D>& inverseInertia,
                                                           const Vec<D>& r, const Vec<D>& J, const AngVec<D>& L) {
  constexpr int A = kAngularDim<D>;
  const AngVec<D> dOmega = inverseInertia * (cross<D>(r, J) + L);
  Eigen::Matrix<double, D + A, 1> out;
  out.template head<D>() = body.inverseMass * J + crossAngular<D>(dOmega, r);
  out.template tail<A>() = dOmega;
  return out;
}

/// True when the point c (in the patch plane) lies in the convex hull of the patch points
/// projected on that plane, grown by `slack` (Eq. (8.19)). 2D: the hull is the segment of the
/// tangent offsets; 3D: the polygon of a monotone-chain hull of the 2D offsets.
template <int D>
bool insidePatch(const std::vector<Vec<D>>& points, const Vec<D>& n, const Vec<D>& c, double slack) {
  if constexpr (D == 2) {
    const Vec<2> t(-n[1], n[0]);
    double lo = t.dot(points.front() - c), hi = lo;
    for (const Vec<2>& p : points) {
      lo = std::min(lo, t.dot(p - c));
      hi = std::max(hi, t.dot(p - c));
    }
    return lo <= slack && hi >= -slack;
  } else {
    // An orthonormal frame (a, b) of the plane.
    const Vec<3> a = (std::abs(n[0]) < 0.9 ? Vec<3>::UnitX() : Vec<3>::UnitY()).cross(n).normalized();
    const Vec<3> b = n.cross(a);
    std::vector<Eigen::Vector2d> q;
    q.reserve(points.size());
    for (const Vec<3>& p : points) q.emplace_back(a.dot(p - c), b.dot(p - c));
    std::sort(q.begin(), q.end(), [](const Eigen::Vector2d& x, const Eigen::Vector2d& y) {
      return x[0] < y[0] || (x[0] == y[0] && x[1] < y[1]);
    });
    const auto turn = [](const Eigen::Vector2d& o, const Eigen::Vector2d& p, const Eigen::Vector2d& r) {
      return (p[0] - o[0]) * (r[1] - o[1]) - (p[1] - o[1]) * (r[0] - o[0]);
    };
    std::vector<Eigen::Vector2d> hull(2 * q.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {  // lower chain
      while (k >= 2 && turn(hull[k - 2], hull[k - 1], q[i]) <= 0.0) --k;
      hull[k++] = q[i];
    }
    for (std::size_t i = q.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
      while (k >= lower && turn(hull[k - 2], hull[k - 1], q[i]) <= 0.0) --k;
      hull[k++] = q[i];
    }
    if (k < 4) return false;  // fewer than three corners: a point or a segment carries no twist
    hull.resize(k - 1);       // counter-clockwise, the first corner not repeated
    // The origin (c) against each edge, grown by `slack`.
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const Eigen::Vector2d& p = hull[i];
      const Eigen::Vector2d& r = hull[(i + 1) % hull.size()];
      const Eigen::Vector2d edge = r - p;
      const double length = edge.norm();
      if (!(length > 0.0)) continue;
      const double cross = edge[0] * (-p[1]) - edge[1] * (-p[0]);  // > 0: origin to the left
      if (cross < -slack * length) return false;
    }
    return true;
  }
}

// [best_subset_spin]
/// Eq. (9.13): the largest rho^2 over the radii rho of the patch points about the centre of
/// pressure c such that the points at distance >= rho still hold c in their hull (grown by
/// `slack`) and number at least three; 0 when no radius qualifies. Times (mu jn - |J_t|) / dmax
/// it is the spin those points carry. O(P^2 log P) for P points (one hull per radius).
template <int D>
double bestSubsetSpin(const std::vector<Vec<D>>& points, const Vec<D>& n, const Vec<D>& c, double slack) {
  std::vector<double> radii;
  radii.reserve(points.size());
  for (const Vec<D>& p : points) radii.push_back((p - c).norm());
  std::vector<double> sorted = radii;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  double best = 0.0;
  std::vector<Vec<D>> subset;
  for (const double rho : sorted) {  // growing rho: fewer points, each farther out
    if (!(rho > 0.0)) continue;
    subset.clear();
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (radii[i] >= rho) subset.push_back(points[i]);
    }
    if (subset.size() < 3 || !insidePatch<D>(subset, n, c, slack)) break;  // smaller subsets lose c too
    best = rho * rho;
  }
  return best;
}
// [best_subset_spin]

}  // namespace detail

// [patch_impulse]
/// The sticking patch (Eqs. (8.16)-(8.19)). `owner` and `other` touch along a patch of
/// samples `points` that share the normal `n` (pointing from the other body to the owner);
/// xo and xb are the bodies' centres at the tested poses. The impulse (J, L) about the
/// patch's mean p that stops the pair's whole relative twist (Eq. (8.16)) is returned when
/// the patch can carry it (a sweep of GBF's ramp, `e` in [-1, 0), gets the whole stop too:
/// it removes only kinetic energy of the relative motion, Eq. (8.17)): J pushes (J . n > 0), its tangential part lies in the friction
/// cone mu (J . n), the centre of pressure lies in the patch, and in 3D the spin about n is
/// one the patch surely carries (Eq. (8.19)).
/// Otherwise, and for a patch of fewer than two samples (three in 3D), empty: the caller
/// then acts at a single point as before. `spinBound` picks the 3D spin test (2D ignores it).
template <int D>
std::optional<PatchImpulse<D>> stickingPatchImpulse(const RigidBody<D>& owner, const Vec<D>& xo,
                                                    const RigidBody<D>& other, const Vec<D>& xb,
                                                    const std::vector<Vec<D>>& points, const Vec<D>& n, double e,
                                                    double mu, PatchSpinBound spinBound = PatchSpinBound::AllPoints) {
  constexpr int A = kAngularDim<D>;
  constexpr int N = D + A;
  if (points.size() < (D == 2 ? 2u : 3u) || !(e <= 0.0 && e >= -1.0) || !(mu >= 0.0)) return std::nullopt;
  PatchImpulse<D> out;
  out.point = Vec<D>::Zero();
  for (const Vec<D>& p : points) out.point += p;
  out.point /= static_cast<double>(points.size());
  const Vec<D> ro = out.point - xo;
  const Vec<D> rb = out.point - xb;
  const AngMat<D> Io = owner.inverseInertiaWorld();
  const AngMat<D> Ib = other.inverseInertiaWorld();
  // The relative twist at p (Eq. (8.16)) and the matrix Y that maps (J, L) to its change.
  Eigen::Matrix<double, N, 1> twist;
  twist.template head<D>() = owner.pointVelocity(ro) - other.pointVelocity(rb);
  twist.template tail<A>() = owner.angularVelocity - other.angularVelocity;
  Eigen::Matrix<double, N, N> Y;
  for (int k = 0; k < N; ++k) {
    Eigen::Matrix<double, N, 1> w = Eigen::Matrix<double, N, 1>::Unit(k);
    const Vec<D> J = w.template head<D>();
    const AngVec<D> L = w.template tail<A>();
    Y.col(k) = detail::patchResponse<D>(owner, Io, ro, J, L) + detail::patchResponse<D>(other, Ib, rb, J, L);
  }
  Y = 0.5 * (Y + Y.transpose());
  const Eigen::LDLT<Eigen::Matrix<double, N, N>> ldlt(Y);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return std::nullopt;
  const Eigen::Matrix<double, N, 1> w = ldlt.solve(-twist);  // Eq. (8.16)
  if (!w.allFinite() || (Y * w + twist).norm() > 1e-9 * (twist.norm() + 1e-300)) {
    return std::nullopt;  // a locked axis: Y is singular along it and the twist cannot be stopped
  }
  out.J = w.template head<D>();
  out.L = w.template tail<A>();
  const double jn = out.J.dot(n);
  if (!(jn > 0.0)) return std::nullopt;  // it would pull
  const Vec<D> jt = out.J - jn * n;
  if (jt.norm() > mu * jn) return std::nullopt;  // Eq. (8.18): outside the cone
  // The centre of pressure c = p + d (Eq. (8.19)): in 2D L = d x J with d along the tangent;
  // in 3D the part of L across n is d x (jn n), and what is left about n is the spin.
  Vec<D> d = Vec<D>::Zero();
  double spin = 0.0;
  if constexpr (D == 2) {
    const Vec<2> t(-n[1], n[0]);
    const double arm = cross<2>(t, out.J)[0];  // t x J = jn (t x n) for J's normal part
    if (!(std::abs(arm) > 0.0)) return std::nullopt;
    d = (out.L[0] / arm) * t;
  } else {
    const Vec<3> across = out.L - out.L.dot(n) * n;
    d = n.cross(across) / jn;
    spin = (out.L - d.cross(out.J)).dot(n);
  }
  out.pressure = out.point + d;
  double scale = 0.0;
  for (const Vec<D>& p : points) scale = std::max(scale, (p - out.point).norm());
  if (!detail::insidePatch<D>(points, n, out.pressure, 1e-9 * (1.0 + scale))) return std::nullopt;
  if constexpr (D == 3) {
    // Eq. (8.19): the spin a patch surely carries. With normal shares f_i >= 0 at the patch
    // points whose f-weighted centre is c, the tangential forces f_i (J_t / jn + k n x d_i)
    // (d_i = p_i - c) add up to J_t and turn about n by k sum f_i |d_i|^2; each stays in its
    // cone while |k| max|d_i| <= mu - |J_t| / jn. So a spin up to (mu jn - |J_t|) dmin^2 / dmax
    // is carried whatever the shares (a round-off allowance of 1e-9 mu jn dmax on top).
    double nearest = std::numeric_limits<double>::infinity(), farthest = 0.0;
    for (const Vec<D>& p : points) {
      const double dist = (p - out.pressure).norm();
      nearest = std::min(nearest, dist);
      farthest = std::max(farthest, dist);
    }
    const double margin = mu * jn - jt.norm();
    double carried = farthest > 0.0 ? margin * nearest * nearest / farthest : 0.0;
    if (spinBound == PatchSpinBound::BestSubset && farthest > 0.0) {
      carried = std::max(carried, detail::bestSubsetSpin<D>(points, n, out.pressure, 1e-9 * (1.0 + scale)) *
                                      margin / farthest);
    }
    if (std::abs(spin) > carried + 1e-9 * mu * jn * farthest) return std::nullopt;
  }
  return out;
}
// [patch_impulse]

}  // namespace stackbook
