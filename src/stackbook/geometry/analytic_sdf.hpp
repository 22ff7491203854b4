#pragma once
/// \file
/// \brief Exact signed distances and normals of primitives (\ref ch06, Eqs. (6.16)-(6.19)):
/// sphere (disk in 2D), box (rectangle), torus (annulus: its z = 0 section), capsule and
/// cylinder (a rectangle in 2D). Each is a small value type with distance(x), normal(x),
/// bounds() and describe(); AnalyticShape wraps one into a `Shape<D>` whose surface samples
/// are the vertices of a mesh of the same shape.
///
/// Axis conventions: the capsule and the cylinder lie along the last axis (z in 3D, y in
/// 2D); the torus lies around the z axis, in the xy plane.
///
/// Normals are the exact gradient N = grad(phi) (|N| = 1, Eq. (6.2)) wherever phi is
/// differentiable. On the medial axis (the centre of a sphere, the inner diagonals of a
/// box, the core circle of a torus, the axis of a capsule) phi has a kink and the gradient
/// does not exist; normal() then returns a fixed, documented unit vector (one of the
/// one-sided gradients), so that the result is always a unit vector and deterministic.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/geometry/shape.hpp"

namespace stackbook {

namespace detail {

inline void requirePositiveSize(const char* type, const char* name, double value) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    std::ostringstream msg;
    msg << type << ": " << name << " must be finite and positive, got " << value;
    throw std::invalid_argument(msg.str());
  }
}

/// +1 for x >= 0, -1 otherwise: the side a medial-axis point is assigned to.
inline double sideOf(double x) { return x >= 0.0 ? 1.0 : -1.0; }

/// Unit vector e_k in D dimensions.
template <int D>
Vec<D> unitAxis(int k) {
  Vec<D> e = Vec<D>::Zero();
  e[k] = 1.0;
  return e;
}

}  // namespace detail

// [sphere_sdf]
/// Sphere (3D) or disk (2D) of the given radius about the origin: phi = |x| - r.
template <int D>
struct SphereSdf {
  /// phi is the exact signed Euclidean distance, so |phi(x) - phi(y)| <= |x - y|.
  static constexpr bool exactDistance = true;
  double radius = 1.0;

  explicit SphereSdf(double r = 1.0) : radius(r) {
    detail::requirePositiveSize("SphereSdf", "radius", r);
  }
  double distance(const Vec<D>& x) const { return x.norm() - radius; }
  /// x/|x|; at the centre (the medial axis) the last axis.
  Vec<D> normal(const Vec<D>& x) const {
    const double n = x.norm();
    return n > 0.0 ? Vec<D>(x / n) : detail::unitAxis<D>(D - 1);
  }
  Aabb<D> bounds() const {
    return Aabb<D>{Vec<D>::Constant(-radius), Vec<D>::Constant(radius)};
  }
  /// The surface point farthest along d (chapter 11's deepest-point query): r d/|d|; for
  /// d = 0 the point on the last axis.
  Vec<D> support(const Vec<D>& d) const {
    const double n = d.norm();
    return n > 0.0 ? Vec<D>(radius * d / n) : Vec<D>(radius * detail::unitAxis<D>(D - 1));
  }
  /// Strictly convex: the point farthest along d is unique and is the whole contact.
  static constexpr bool strictlyConvex = true;
  /// Curved all over (SurfaceQuery::RoundShapes).
  static constexpr bool round = true;
  std::string describe() const {
    std::ostringstream out;
    out << (D == 3 ? "sphere" : "disk") << " r = " << radius;
    return out.str();
  }
};
// [sphere_sdf]

// [box_sdf]
/// Axis-aligned box (3D) or rectangle (2D) with the given half extents h about the origin.
/// With q = |x| - h (componentwise), phi = |max(q, 0)| + min(max_k q_k, 0) (Eq. (6.16)):
/// outside, the distance to the nearest point of the box; inside, minus the distance to
/// the nearest face.
template <int D>
struct BoxSdf {
  /// phi is the exact signed Euclidean distance, so |phi(x) - phi(y)| <= |x - y|.
  static constexpr bool exactDistance = true;
  Vec<D> halfExtents = Vec<D>::Constant(0.5);

  explicit BoxSdf(const Vec<D>& h = Vec<D>::Constant(0.5)) : halfExtents(h) {
    for (int k = 0; k < D; ++k) detail::requirePositiveSize("BoxSdf", "half extent", h[k]);
  }
  double distance(const Vec<D>& x) const {
    const Vec<D> q = x.cwiseAbs() - halfExtents;
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);  // Eq. (6.16)
  }
  /// Outside: from the nearest box point to x. Inside: the normal of the nearest face;
  /// on ties (the inner medial axis) the face with the lowest axis index, and on the
  /// mid-plane x_k = 0 the positive side.
  Vec<D> normal(const Vec<D>& x) const {
    const Vec<D> q = x.cwiseAbs() - halfExtents;
    Eigen::Index k = 0;
    const double qmax = q.maxCoeff(&k);
    if (qmax > 0.0) {
      Vec<D> n = q.cwiseMax(0.0);
      for (int i = 0; i < D; ++i) n[i] *= detail::sideOf(x[i]);
      return n.normalized();
    }
    return detail::sideOf(x[k]) * detail::unitAxis<D>(static_cast<int>(k));
  }
  Aabb<D> bounds() const { return Aabb<D>{Vec<D>(-halfExtents), halfExtents}; }
  /// The surface point farthest along d: the corner h * sign(d) (a zero component takes +).
  Vec<D> support(const Vec<D>& d) const {
    Vec<D> p = halfExtents;
    for (int k = 0; k < D; ++k) p[k] *= detail::sideOf(d[k]);
    return p;
  }
  static constexpr bool strictlyConvex = false;
  /// Flat faces only: its samples hold its corners and edges exactly.
  static constexpr bool round = false;
  std::string describe() const {
    std::ostringstream out;
    out << (D == 3 ? "box " : "rectangle ");
    for (int k = 0; k < D; ++k) out << (k ? " x " : "") << 2.0 * halfExtents[k];
    return out.str();
  }
};
// [box_sdf]

// [torus_sdf]
/// Torus about the z axis (3D) with major radius R (the core circle in the xy plane) and
/// minor radius r < R; in 2D its z = 0 section, the annulus R - r <= |x| <= R + r.
/// With rho = |(x, y)| and q = (rho - R, z) (2D: q = rho - R), phi = |q| - r (Eq. (6.17)).
template <int D>
struct TorusSdf {
  /// phi is the exact signed Euclidean distance, so |phi(x) - phi(y)| <= |x - y|.
  static constexpr bool exactDistance = true;
  double majorRadius = 0.5;
  double minorRadius = 0.2;

  explicit TorusSdf(double R = 0.5, double r = 0.2) : majorRadius(R), minorRadius(r) {
    detail::requirePositiveSize("TorusSdf", "majorRadius", R);
    detail::requirePositiveSize("TorusSdf", "minorRadius", r);
    if (!(r < R)) {
      throw std::invalid_argument("TorusSdf: minorRadius must be smaller than majorRadius");
    }
  }
  double distance(const Vec<D>& x) const { return tubeOffset(x).norm() - minorRadius; }
  /// (q / |q|) mapped back to space; on the core circle (q = 0) the direction away from
  /// the axis, and on the axis (rho = 0, outside the body) the +x side.
  Vec<D> normal(const Vec<D>& x) const {
    const Vec2 radial(x[0], x[1]);
    const double rho = radial.norm();
    const Vec2 u = rho > 0.0 ? Vec2(radial / rho) : Vec2(1.0, 0.0);
    Vec<D - 1> q = tubeOffset(x);
    const double length = q.norm();
    if (length > 0.0) {
      q /= length;
    } else {
      q = detail::unitAxis<D - 1>(0);
    }
    Vec<D> n;
    n[0] = q[0] * u.x();
    n[1] = q[0] * u.y();
    if constexpr (D == 3) n[2] = q[1];
    return n;
  }
  Aabb<D> bounds() const {
    Vec<D> h = Vec<D>::Constant(majorRadius + minorRadius);
    if constexpr (D == 3) h[2] = minorRadius;
    return Aabb<D>{Vec<D>(-h), h};
  }
  std::string describe() const {
    std::ostringstream out;
    out << (D == 3 ? "torus" : "annulus") << " R = " << majorRadius << " r = " << minorRadius;
    return out.str();
  }

 private:
  /// q = (rho - R, z) in 3D, (rho - R) in 2D: x relative to the nearest core point.
  Vec<D - 1> tubeOffset(const Vec<D>& x) const {
    Vec<D - 1> q;
    q[0] = Vec2(x[0], x[1]).norm() - majorRadius;
    if constexpr (D == 3) q[1] = x[2];
    return q;
  }
};
// [torus_sdf]

// [capsule_sdf]
/// Capsule: the points within `radius` of the segment from -halfLength to +halfLength on
/// the last axis. phi = |x - c| - r with c the segment point nearest x (Eq. (6.18)).
template <int D>
struct CapsuleSdf {
  /// phi is the exact signed Euclidean distance, so |phi(x) - phi(y)| <= |x - y|.
  static constexpr bool exactDistance = true;
  double halfLength = 0.5;
  double radius = 0.25;

  explicit CapsuleSdf(double h = 0.5, double r = 0.25) : halfLength(h), radius(r) {
    detail::requirePositiveSize("CapsuleSdf", "halfLength", h);
    detail::requirePositiveSize("CapsuleSdf", "radius", r);
  }
  double distance(const Vec<D>& x) const { return offset(x).norm() - radius; }
  /// (x - c)/|x - c|; on the core segment the +x side.
  Vec<D> normal(const Vec<D>& x) const {
    const Vec<D> d = offset(x);
    const double n = d.norm();
    return n > 0.0 ? Vec<D>(d / n) : detail::unitAxis<D>(0);
  }
  Aabb<D> bounds() const {
    Vec<D> h = Vec<D>::Constant(radius);
    h[D - 1] += halfLength;
    return Aabb<D>{Vec<D>(-h), h};
  }
  /// The surface point farthest along d: the end of the core segment on d's side plus
  /// r d/|d|.
  Vec<D> support(const Vec<D>& d) const {
    Vec<D> p = Vec<D>::Zero();
    p[D - 1] = detail::sideOf(d[D - 1]) * halfLength;
    const double n = d.norm();
    return n > 0.0 ? Vec<D>(p + radius * d / n) : p;
  }
  static constexpr bool strictlyConvex = false;
  /// Its caps (and in 3D its side) are curved.
  static constexpr bool round = true;
  std::string describe() const {
    std::ostringstream out;
    out << "capsule half-length " << halfLength << " r = " << radius;
    return out.str();
  }

 private:
  Vec<D> offset(const Vec<D>& x) const {
    Vec<D> d = x;
    d[D - 1] -= std::clamp(x[D - 1], -halfLength, halfLength);
    return d;
  }
};
// [capsule_sdf]

// [cylinder_sdf]
/// Cylinder of the given radius and half height along the last axis (in 2D the
/// rectangle 2r x 2h). With rho the distance from the axis and q = (rho - r, |z| - h),
/// phi is the 2D box distance of q (Eq. (6.19)).
template <int D>
struct CylinderSdf {
  /// phi is the exact signed Euclidean distance, so |phi(x) - phi(y)| <= |x - y|.
  static constexpr bool exactDistance = true;
  double radius = 0.5;
  double halfHeight = 0.5;

  explicit CylinderSdf(double r = 0.5, double h = 0.5) : radius(r), halfHeight(h) {
    detail::requirePositiveSize("CylinderSdf", "radius", r);
    detail::requirePositiveSize("CylinderSdf", "halfHeight", h);
  }
  double distance(const Vec<D>& x) const {
    const Vec2 q(x.template head<D - 1>().norm() - radius, std::abs(x[D - 1]) - halfHeight);
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);  // Eq. (6.19)
  }
  /// As for the box, in the (rho, z) half-plane; on the axis the +x side, and inside on
  /// a tie between side wall and cap the side wall.
  Vec<D> normal(const Vec<D>& x) const {
    const Vec<D - 1> radial = x.template head<D - 1>();
    const double rho = radial.norm();
    const Vec<D - 1> u = rho > 0.0 ? Vec<D - 1>(radial / rho) : detail::unitAxis<D - 1>(0);
    const Vec2 q(rho - radius, std::abs(x[D - 1]) - halfHeight);
    const double side = detail::sideOf(x[D - 1]);
    Vec2 g;  // gradient in the (rho, z) half-plane
    if (q.maxCoeff() > 0.0) {
      g = q.cwiseMax(0.0).normalized();
    } else {
      g = q[0] >= q[1] ? Vec2(1.0, 0.0) : Vec2(0.0, 1.0);
    }
    Vec<D> n;
    n.template head<D - 1>() = g[0] * u;
    n[D - 1] = g[1] * side;
    return n;
  }
  Aabb<D> bounds() const {
    Vec<D> h = Vec<D>::Constant(radius);
    h[D - 1] = halfHeight;
    return Aabb<D>{Vec<D>(-h), h};
  }
  /// The surface point farthest along d: the rim point r d_radial/|d_radial| on the cap of
  /// d's side (the cap's centre when d is along the axis).
  Vec<D> support(const Vec<D>& d) const {
    Vec<D> p = Vec<D>::Zero();
    const Vec<D - 1> radial = d.template head<D - 1>();
    const double rho = radial.norm();
    if (rho > 0.0) p.template head<D - 1>() = radius * radial / rho;
    p[D - 1] = detail::sideOf(d[D - 1]) * halfHeight;
    return p;
  }
  static constexpr bool strictlyConvex = false;
  /// Its side is curved in 3D; in 2D it is a rectangle.
  static constexpr bool round = D == 3;
  std::string describe() const {
    std::ostringstream out;
    out << (D == 3 ? "cylinder" : "rectangle (cylinder section)") << " r = " << radius
        << " h = " << 2.0 * halfHeight;
    return out.str();
  }
};
// [cylinder_sdf]

// [analytic_shape]
/// A `Shape<D>` with an exact signed distance: phi and N come from `Sdf` (one of the
/// primitives above, or any type with the same four members), the surface samples from
/// the vertices of a mesh of the same shape. The constructor checks that every vertex lies
/// on the surface: |phi(v)| <= sampleTolerance x (size of the bounds).
template <int D, class Sdf>
class AnalyticShape final : public Shape<D> {
 public:
  AnalyticShape(Sdf sdf, SurfaceMesh<D> mesh, double sampleTolerance = 1e-9)
      : sdf_(std::move(sdf)), mesh_(std::move(mesh)), chunks_(mesh_.vertices) {
    const double size = sdf_.bounds().extent().norm();
    for (std::size_t v = 0; v < mesh_.vertices.size(); ++v) {
      const double phi = sdf_.distance(mesh_.vertices[v]);
      if (!(std::abs(phi) <= sampleTolerance * size)) {
        std::ostringstream msg;
        msg << "AnalyticShape (" << sdf_.describe() << "): mesh vertex " << v << " ("
            << mesh_.vertices[v].transpose() << ") is at signed distance " << phi
            << " from the surface; samples must lie on it";
        throw std::invalid_argument(msg.str());
      }
    }
  }
  double signedDistance(const Vec<D>& x) const override { return sdf_.distance(x); }
  Vec<D> normal(const Vec<D>& x) const override { return sdf_.normal(x); }
  const std::vector<Vec<D>>& surfaceSamples() const override { return mesh_.vertices; }
  const SampleChunks<D>* sampleChunks() const override { return &chunks_; }
  /// 1 when `Sdf` says it is an exact signed distance (`static constexpr bool exactDistance`):
  /// the distance to a set is 1-Lipschitz. 0 (unknown) for any other `Sdf`.
  double distanceLipschitz() const override {
    if constexpr (requires { Sdf::exactDistance; }) {
      return Sdf::exactDistance ? 1.0 : 0.0;
    } else {
      return 0.0;
    }
  }
  Aabb<D> bounds() const override { return sdf_.bounds(); }
  std::string describe() const override {
    std::ostringstream out;
    out << sdf_.describe() << " (analytic, " << mesh_.vertices.size() << " samples)";
    return out.str();
  }
  const Sdf& sdf() const { return sdf_; }
  const SurfaceMesh<D>& mesh() const { return mesh_; }

  // [analytic_deepest_point]
  /// The exact deepest-point query (chapter 11, Eq. (11.6)) of a convex primitive: the
  /// point of this surface farthest along -N, N the other body's normal, found by the
  /// fixed point p <- support(-M^T N_other(M p + t)) started at the centre. Against a flat
  /// face one iteration is exact (a sphere's point is its centre minus r N); against a
  /// curved body it converges to the point where both normals are opposite. A torus (not
  /// convex) has no such query.
  bool deepestPoint(const Shape<D>& other, const Mat<D>& M, const Vec<D>& t,
                    Vec<D>& point) const override {
    if constexpr (requires(const Sdf& f, const Vec<D>& d) { f.support(d); }) {
      Vec<D> p = sdf_.support(-(M.transpose() * other.normal(t)));
      for (int k = 0; k < 8; ++k) {
        const Vec<D> next = sdf_.support(-(M.transpose() * other.normal(M * p + t)));
        const bool settled = (next - p).norm() <= 1e-14 * sdf_.bounds().extent().norm();
        p = next;
        if (settled) break;
      }
      point = p;
      return true;
    } else {
      (void)other, (void)M, (void)t, (void)point;
      return false;
    }
  }
  bool deepestPointIsWholeContact() const override {
    if constexpr (requires { Sdf::strictlyConvex; }) {
      return Sdf::strictlyConvex;
    } else {
      return false;
    }
  }
  bool roundSurface() const override {
    if constexpr (requires { Sdf::round; }) {
      return Sdf::round;
    } else {
      return false;
    }
  }
  // [analytic_deepest_point]

 private:
  Sdf sdf_;
  SurfaceMesh<D> mesh_;
  SampleChunks<D> chunks_;
};
// [analytic_shape]

template <int D>
using SphereShape = AnalyticShape<D, SphereSdf<D>>;
template <int D>
using BoxShape = AnalyticShape<D, BoxSdf<D>>;
template <int D>
using TorusShape = AnalyticShape<D, TorusSdf<D>>;
template <int D>
using CapsuleShape = AnalyticShape<D, CapsuleSdf<D>>;
template <int D>
using CylinderShape = AnalyticShape<D, CylinderSdf<D>>;

/// How finely the factory functions below tessellate the sample meshes.
struct SampleMeshSettings {
  int sphereLevel = 3;          ///< icosphere subdivision level (3D): 642 vertices
  int circleSegments = 48;      ///< vertices around a circle (2D disk, rings, revolved shapes)
  int tubeSegments = 16;        ///< vertices around the tube of a torus
  int boxSubdivisions = 4;      ///< pieces per box edge
  double profileSpacing = 0.05; ///< longest profile piece of a capsule
};

/// Sphere (icosphere samples) or disk (regular polygon samples).
template <int D>
SphereShape<D> makeSphereShape(double radius, const SampleMeshSettings& mesh = {}) {
  if constexpr (D == 3) {
    return SphereShape<3>(SphereSdf<3>(radius), icosphereMesh(radius, mesh.sphereLevel));
  } else {
    return SphereShape<2>(SphereSdf<2>(radius), regularPolygon(radius, mesh.circleSegments));
  }
}

/// Box or rectangle with the given full side lengths, faces subdivided for samples.
template <int D>
BoxShape<D> makeBoxShape(const Vec<D>& size, const SampleMeshSettings& mesh = {}) {
  if constexpr (D == 3) {
    return BoxShape<3>(BoxSdf<3>(0.5 * size), boxMesh(size, mesh.boxSubdivisions));
  } else {
    return BoxShape<2>(BoxSdf<2>(0.5 * size), rectanglePolygon(size, mesh.boxSubdivisions));
  }
}

/// Torus (3D) or annulus (2D).
template <int D>
TorusShape<D> makeTorusShape(double majorRadius, double minorRadius,
                             const SampleMeshSettings& mesh = {}) {
  return TorusShape<D>(TorusSdf<D>(majorRadius, minorRadius),
                       ringBoundary<D>(majorRadius, minorRadius, mesh.circleSegments,
                                       mesh.tubeSegments));
}

/// Capsule along the last axis.
template <int D>
CapsuleShape<D> makeCapsuleShape(double halfLength, double radius,
                                 const SampleMeshSettings& mesh = {}) {
  return CapsuleShape<D>(CapsuleSdf<D>(halfLength, radius),
                         capsuleBoundary<D>(halfLength, radius, mesh.circleSegments,
                                            mesh.profileSpacing));
}

/// Cylinder along the last axis (a rectangle in 2D).
template <int D>
CylinderShape<D> makeCylinderShape(double radius, double halfHeight,
                                   const SampleMeshSettings& mesh = {}) {
  if constexpr (D == 3) {
    return CylinderShape<3>(CylinderSdf<3>(radius, halfHeight),
                            cylinderMesh(radius, 2.0 * halfHeight, mesh.circleSegments,
                                         mesh.boxSubdivisions, mesh.boxSubdivisions));
  } else {
    return CylinderShape<2>(CylinderSdf<2>(radius, halfHeight),
                            rectanglePolygon(Vec2(2.0 * radius, 2.0 * halfHeight),
                                             mesh.boxSubdivisions));
  }
}

}  // namespace stackbook
