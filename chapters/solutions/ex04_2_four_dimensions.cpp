// Exercise 4.2, reference solution: r* and K in four dimensions.
//
// A rotation of 4D space turns six coordinate planes, so r* maps the 4 components of an
// impulse to the 6 components of an angular impulse: (r ^ b)_ij = r_i b_j - r_j b_i.
// K = delta/m + r*^T I^{-1} r* is Eq. (1.8) unchanged; with one moment I for every plane
// it is delta/m + (|r|^2 delta - r r^T)/I, as in 2D and 3D (Eq. (4.10)).
#include "stackbook/exercises/ex04_2_four_dimensions.hpp"

namespace stackbook::exercises {

CrossMat4 crossMatrix4(const Vec4& r) {
  CrossMat4 rs = CrossMat4::Zero();
  int row = 0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j, ++row) {
      rs(row, j) = r[i];   // r_i b_j
      rs(row, i) = -r[j];  // - r_j b_i
    }
  }
  return rs;
}

Mat4 collisionMatrix4(double inverseMass, const Bivec4& inversePlaneInertia, const Vec4& r) {
  const CrossMat4 rs = crossMatrix4(r);
  return inverseMass * Mat4::Identity() +
         rs.transpose() * inversePlaneInertia.asDiagonal() * rs;  // Eq. (1.8), D = 4
}

}  // namespace stackbook::exercises
