// Exercise 6.2 (your answer goes here): see ex06_2_pseudo_normal_sign.hpp and chapter 6.
// Implement: PseudoNormalSign (the pseudo-normals and inside). Delete every TODO(reader) comment
// once your code is in: while one is left, the exercise counts as not solved and its tests do
// not run.
#include "stackbook/exercises/ex06_2_pseudo_normal_sign.hpp"

namespace stackbook::exercises {

PseudoNormalSign::PseudoNormalSign(const TriangleMesh& mesh) : mesh_(mesh), tree_(mesh_) {
  // TODO(reader): compute faceNormals_, edgeNormals_ and the angle-weighted vertexNormals_.
}

Vec3 PseudoNormalSign::vertexPseudoNormal(int vertex) const {
  // TODO(reader): return the angle-weighted pseudo-normal of the vertex.
  (void)vertex;
  return Vec3::Zero();
}

Vec3 PseudoNormalSign::edgePseudoNormal(int a, int b) const {
  // TODO(reader): return the pseudo-normal of the edge a-b.
  (void)a;
  (void)b;
  return Vec3::Zero();
}

bool PseudoNormalSign::inside(const Vec3& x) const {
  // TODO(reader): find the nearest point q and its feature (tree_.nearest), pick the
  // feature's pseudo-normal N and return (x - q) . N < 0.
  (void)x;
  return false;
}

}  // namespace stackbook::exercises
