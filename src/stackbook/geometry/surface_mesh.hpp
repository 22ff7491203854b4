#pragma once
/// \file
/// \brief The closed boundary of a body: a polygon (2D) or a triangle mesh (3D), as one
/// dimension-generic type.
///
/// A face is a (D-1)-simplex given by D vertex indices: a segment (2 indices) in 2D, a
/// triangle (3 indices) in 3D. Faces are oriented so that the normal points out of the
/// body: in 2D a segment (a, b) has the body on its left (counterclockwise boundary); in
/// 3D a triangle (a, b, c) has outward normal (b - a) x (c - a).

#include <array>
#include <vector>

#include "stackbook/geometry/aabb.hpp"

namespace stackbook {

// [surface_mesh]
template <int D>
struct SurfaceMesh {
  std::vector<Vec<D>> vertices;
  std::vector<std::array<int, D>> faces;

  Aabb<D> bounds() const {
    Aabb<D> box;
    for (const Vec<D>& v : vertices) box.extend(v);
    return box;
  }
};
// [surface_mesh]

using Polygon = SurfaceMesh<2>;
using TriangleMesh = SurfaceMesh<3>;

}  // namespace stackbook
