// Exercise 6.2, reference solution: angle-weighted pseudo-normals (Baerentzen and Aanaes,
// "Signed distance computation using the angle weighted pseudonormal", IEEE TVCG 2005).
// For a closed, consistently oriented manifold mesh the sign of (x - q) . N, with N the
// pseudo-normal of the feature containing the nearest point q, is the sign of the distance.
#include <cmath>
#include <stdexcept>

#include "stackbook/exercises/ex06_2_pseudo_normal_sign.hpp"

namespace stackbook::exercises {

PseudoNormalSign::PseudoNormalSign(const TriangleMesh& mesh)
    : mesh_(mesh), tree_(mesh_), vertexNormals_(mesh.vertices.size(), Vec3::Zero()) {
  for (const std::array<int, 3>& f : mesh_.faces) {
    const Vec3& a = mesh_.vertices[f[0]];
    const Vec3& b = mesh_.vertices[f[1]];
    const Vec3& c = mesh_.vertices[f[2]];
    const Vec3 n = (b - a).cross(c - a).normalized();
    faceNormals_.push_back(n);
    for (int k = 0; k < 3; ++k) {
      const int i = f[k], j = f[(k + 1) % 3], l = f[(k + 2) % 3];
      // The angle of the face at vertex i, between the edges to j and to l.
      const Vec3 u = mesh_.vertices[j] - mesh_.vertices[i];
      const Vec3 v = mesh_.vertices[l] - mesh_.vertices[i];
      vertexNormals_[i] += std::atan2(u.cross(v).norm(), u.dot(v)) * n;
      // try_emplace with an explicit zero: Eigen's default constructor leaves a Vec3
      // uninitialised, so map::operator[] would add n to garbage.
      edgeNormals_.try_emplace({std::min(i, j), std::max(i, j)}, Vec3::Zero()).first->second += n;
    }
  }
  for (Vec3& n : vertexNormals_) n.normalize();
  for (auto& [edge, n] : edgeNormals_) n.normalize();
}

Vec3 PseudoNormalSign::vertexPseudoNormal(int vertex) const { return vertexNormals_.at(vertex); }

Vec3 PseudoNormalSign::edgePseudoNormal(int a, int b) const {
  const auto found = edgeNormals_.find({std::min(a, b), std::max(a, b)});
  if (found == edgeNormals_.end()) throw std::invalid_argument("PseudoNormalSign: no such edge");
  return found->second;
}

bool PseudoNormalSign::inside(const Vec3& x) const {
  const NearestFace<3> nearest = tree_.nearest(mesh_, x);
  const std::array<int, 3>& f = mesh_.faces[nearest.face];
  const unsigned feature = nearest.closest.feature;
  Vec3 N;
  if (feature == 7u) {
    N = faceNormals_[nearest.face];
  } else if (feature == 1u || feature == 2u || feature == 4u) {
    N = vertexNormals_[f[feature == 1u ? 0 : feature == 2u ? 1 : 2]];
  } else {
    // Two bits: the edge between the two vertices that carry weight.
    const int missing = feature == 3u ? 2 : feature == 6u ? 0 : 1;
    N = edgePseudoNormal(f[(missing + 1) % 3], f[(missing + 2) % 3]);
  }
  return (x - nearest.closest.point).dot(N) < 0.0;
}

}  // namespace stackbook::exercises
