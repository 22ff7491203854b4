#pragma once
/// \file
/// \brief Closest point on a segment (2D faces) or a triangle (3D faces), by the
/// Voronoi-region case analysis of \ref ch06 (Eqs. (6.3)-(6.5)).
///
/// A face of a `SurfaceMesh<D>` is a (D-1)-simplex with D vertices. The closest point is
/// returned with its barycentric weights and the set of face vertices that carry a
/// positive weight (the "feature": a vertex, an edge or the interior), which the
/// pseudo-normal sign of exercise 6.2 needs.

#include <algorithm>
#include <array>

#include "stackbook/geometry/surface_mesh.hpp"

namespace stackbook {

/// The point of a face nearest to a query point.
template <int D>
struct FaceClosestPoint {
  Vec<D> point = Vec<D>::Zero();          ///< the closest point on the face
  std::array<double, D> weights{};        ///< barycentric weights (sum 1, all >= 0)
  /// Bit k set when face vertex k carries weight > 0: one bit = a vertex region,
  /// two bits = an edge region, all D bits = the interior of the face.
  unsigned feature = 0;
  double squaredDistance = 0.0;           ///< |x - point|^2
};

// [closest_point_segment]
/// The parameter t in [0, 1] of the point a + t (b - a) nearest to x (Eq. (6.3)): the
/// projection (x - a).(b - a) / |b - a|^2 clamped to the segment. 0 for a zero-length one.
template <int D>
double segmentParameter(const Vec<D>& x, const Vec<D>& a, const Vec<D>& b) {
  const Vec<D> ab = b - a;
  const double lengthSquared = ab.squaredNorm();
  const double t = lengthSquared > 0.0 ? (x - a).dot(ab) / lengthSquared : 0.0;  // Eq. (6.3)
  return std::clamp(t, 0.0, 1.0);
}

/// Closest point to x on the segment [a, b] of a 2D boundary.
inline FaceClosestPoint<2> closestPointOnSegment(const Vec2& x, const Vec2& a, const Vec2& b) {
  const double t = segmentParameter<2>(x, a, b);
  FaceClosestPoint<2> result;
  result.point = a + t * (b - a);
  result.weights = {1.0 - t, t};
  result.feature = (t < 1.0 ? 1u : 0u) | (t > 0.0 ? 2u : 0u);
  result.squaredDistance = (x - result.point).squaredNorm();
  return result;
}
// [closest_point_segment]

// [closest_point_triangle]
/// Closest point to x on the triangle (a, b, c), by locating x in one of the seven
/// Voronoi regions of the triangle's features (Eq. (6.4)): three vertex regions, three
/// edge regions and the face region, tested in that order with dot products only.
/// Degenerate (zero-area) triangles fall back to the nearest of the three edges.
inline FaceClosestPoint<3> closestPointOnTriangle(const Vec3& x, const Vec3& a, const Vec3& b,
                                                  const Vec3& c) {
  FaceClosestPoint<3> result;
  const auto finish = [&](double wa, double wb, double wc) {
    result.weights = {wa, wb, wc};
    result.point = wa * a + wb * b + wc * c;
    result.feature = (wa > 0.0 ? 1u : 0u) | (wb > 0.0 ? 2u : 0u) | (wc > 0.0 ? 4u : 0u);
    result.squaredDistance = (x - result.point).squaredNorm();
    return result;
  };
  const Vec3 ab = b - a, ac = c - a;
  // Vertex a: x - a makes an obtuse (or right) angle with both edges leaving a.
  const Vec3 ax = x - a;
  const double d1 = ab.dot(ax), d2 = ac.dot(ax);
  if (d1 <= 0.0 && d2 <= 0.0) return finish(1.0, 0.0, 0.0);
  // Vertex b: the same test with the edges leaving b, (a - b) and (c - b).
  const Vec3 bx = x - b;
  const double d3 = ab.dot(bx), d4 = ac.dot(bx);
  if (d3 >= 0.0 && d4 <= d3) return finish(0.0, 1.0, 0.0);
  // Edge ab: x projects inside [a, b] and lies on the far side of ab from c. The sign
  // of the face-region weight of c, vc = d1 d4 - d3 d2, says which side (Eq. (6.5)).
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return finish(1.0 - t, t, 0.0);
  }
  // Vertex c.
  const Vec3 cx = x - c;
  const double d5 = ab.dot(cx), d6 = ac.dot(cx);
  if (d6 >= 0.0 && d5 <= d6) return finish(0.0, 0.0, 1.0);
  // Edge ac.
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return finish(1.0 - t, 0.0, t);
  }
  // Edge bc.
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish(0.0, 1.0 - t, t);
  }
  // Face region: the barycentric weights are proportional to (va, vb, vc).
  const double sum = va + vb + vc;
  if (sum > 0.0) return finish(va / sum, vb / sum, vc / sum);
  // Degenerate triangle (collinear vertices): the nearest of its three edges.
  const double tab = segmentParameter<3>(x, a, b), tbc = segmentParameter<3>(x, b, c);
  const double tca = segmentParameter<3>(x, c, a);
  const double dab = (x - (a + tab * ab)).squaredNorm();
  const double dbc = (x - (b + tbc * (c - b))).squaredNorm();
  const double dca = (x - (c + tca * (a - c))).squaredNorm();
  if (dab <= dbc && dab <= dca) return finish(1.0 - tab, tab, 0.0);
  if (dbc <= dca) return finish(0.0, 1.0 - tbc, tbc);
  return finish(tca, 0.0, 1.0 - tca);
}
// [closest_point_triangle]

/// Closest point to x on face f of the mesh: a segment in 2D, a triangle in 3D.
template <int D>
FaceClosestPoint<D> closestPointOnFace(const SurfaceMesh<D>& mesh, std::size_t f,
                                       const Vec<D>& x) {
  const std::array<int, D>& face = mesh.faces[f];
  if constexpr (D == 2) {
    return closestPointOnSegment(x, mesh.vertices[face[0]],
                                    mesh.vertices[face[1]]);
  } else {
    return closestPointOnTriangle(x, mesh.vertices[face[0]],
                                  mesh.vertices[face[1]],
                                  mesh.vertices[face[2]]);
  }
}

}  // namespace stackbook
