#pragma once
/// \file
/// \brief Exercise 6.2: inside/outside by the angle-weighted pseudo-normal of the nearest
/// feature (Baerentzen and Aanaes, 2005), the O(log F) alternative to the winding number
/// (\ref ch06).

#include <map>
#include <utility>
#include <vector>

#include "stackbook/geometry/face_bvh.hpp"

namespace stackbook::exercises {

/// The sign of the distance to a triangle mesh from the pseudo-normal of the feature
/// (face, edge or vertex) that holds the nearest point q: x is inside when
/// (x - q) . N < 0. The pseudo-normals are
/// - face: the unit normal (b - a) x (c - a) / |...|;
/// - edge: the normalised sum of the normals of its two faces (of its one face on the
///   rim of an open mesh);
/// - vertex: the normalised sum over the incident faces of the face normal times the
///   face's angle at the vertex (angle weights make it independent of how the faces
///   around the vertex are triangulated).
class PseudoNormalSign {
 public:
  /// Precomputes the pseudo-normals. The mesh needs consistent orientation but need not
  /// be closed (an open sheet has an "inside" below its normals).
  explicit PseudoNormalSign(const TriangleMesh& mesh);
  /// The unit pseudo-normal of a vertex.
  Vec3 vertexPseudoNormal(int vertex) const;
  /// The unit pseudo-normal of the edge between vertices a and b (either order); throws
  /// std::invalid_argument if no face has that edge.
  Vec3 edgePseudoNormal(int a, int b) const;
  /// True when x is inside by the pseudo-normal test (false on the surface itself).
  bool inside(const Vec3& x) const;

 private:
  TriangleMesh mesh_;
  FaceBvh<3> tree_;                             ///< for the nearest face
  std::vector<Vec3> faceNormals_;               ///< per face
  std::vector<Vec3> vertexNormals_;             ///< per vertex
  std::map<std::pair<int, int>, Vec3> edgeNormals_;  ///< key (min, max) vertex index
};

}  // namespace stackbook::exercises
