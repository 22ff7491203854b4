#pragma once
/// \file
/// \brief The generalised winding number of a closed boundary around a point: the signed
/// angle (2D) or solid angle (3D) that the boundary subtends, divided by that of the full
/// circle or sphere (\ref ch06, Eqs. (6.6)-(6.8)). It is 1 inside, 0 outside, and it
/// degrades gracefully (to a value near 1 or 0) when the mesh has small cracks.

#include <cmath>

#include "stackbook/geometry/surface_mesh.hpp"

namespace stackbook {

// [winding_contribution]
/// The signed angle (2D, radians) or solid angle (3D, steradians) that face f of the mesh
/// subtends at x, positive when x sees the face from its inner (body) side.
///   2D: atan2(a x b, a . b) with a, b the segment's ends relative to x (Eq. (6.6)).
///   3D: 2 atan2(a . (b x c), |a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|), the formula
///       of Van Oosterom and Strackee (Eq. (6.7)).
/// Both use atan2, which stays accurate for nearly flat and nearly full angles.
template <int D>
double faceSubtendedAngle(const SurfaceMesh<D>& mesh, std::size_t f, const Vec<D>& x) {
  const auto& face = mesh.faces[f];
  if constexpr (D == 2) {
    const Vec2 a = mesh.vertices[face[0]] - x;
    const Vec2 b = mesh.vertices[face[1]] - x;
    return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));  // Eq. (6.6)
  } else {
    const Vec3 a = mesh.vertices[face[0]] - x;
    const Vec3 b = mesh.vertices[face[1]] - x;
    const Vec3 c = mesh.vertices[face[2]] - x;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    return 2.0 * std::atan2(numerator, denominator);  // Eq. (6.7)
  }
}
// [winding_contribution]

// [winding_number]
/// Generalised winding number w(x) = (sum of subtended angles) / (2 pi in 2D, 4 pi in 3D),
/// Eq. (6.8). For a closed, outward-oriented boundary it is 1 inside, 0 outside (an
/// integer count for overlapping closed components), and undefined on the boundary.
template <int D>
double windingNumber(const SurfaceMesh<D>& mesh, const Vec<D>& x) {
  double total = 0.0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) total += faceSubtendedAngle<D>(mesh, f, x);
  const double fullAngle = D == 2 ? 2.0 * M_PI : 4.0 * M_PI;
  return total / fullAngle;  // Eq. (6.8)
}
// [winding_number]

/// Inside test by winding number: w(x) > 1/2 (Eq. (6.9)).
template <int D>
bool insideByWindingNumber(const SurfaceMesh<D>& mesh, const Vec<D>& x) {
  return windingNumber<D>(mesh, x) > 0.5;
}

}  // namespace stackbook
