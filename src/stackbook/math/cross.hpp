#pragma once
/// \file
/// \brief The cross-product matrix r* and the cross products built from it
/// (\ref ch01, Eqs. (1.3)-(1.5); the 2D form is derived in \ref ch04).

#include "stackbook/math/types.hpp"

namespace stackbook {

// [cross_matrix]
/// The cross-product matrix r*, defined by r x b = r* b (Eq. (1.3)).
/// In 3D it is the skew-symmetric 3 x 3 matrix; in 2D it is the 1 x 2 row
/// [-r_y, r_x] that maps b to the scalar (z) component of r x b (Eq. (4.1)).
template <int D>
CrossMat<D> crossMatrix(const Vec<D>& r);

template <>
inline CrossMat<3> crossMatrix<3>(const Vec<3>& r) {
  CrossMat<3> rs;
  rs << 0.0, -r.z(), r.y(),
        r.z(), 0.0, -r.x(),
        -r.y(), r.x(), 0.0;
  return rs;
}

template <>
inline CrossMat<2> crossMatrix<2>(const Vec<2>& r) {
  CrossMat<2> rs;
  rs << -r.y(), r.x();
  return rs;
}
// [cross_matrix]

// [cross_products]
/// r x b: linear x linear gives an angular quantity (Eq. (1.3)).
template <int D>
AngVec<D> cross(const Vec<D>& r, const Vec<D>& b) {
  return crossMatrix<D>(r) * b;
}

/// w x r: angular x linear gives a linear quantity. With b x r = r*^T b (Eq. (1.4)),
/// w x r = r*^T w. In 2D this is the familiar w (-r_y, r_x).
/// (A separate name, because in 3D AngVec<3> and Vec<3> are the same type.)
template <int D>
Vec<D> crossAngular(const AngVec<D>& w, const Vec<D>& r) {
  return crossMatrix<D>(r).transpose() * w;
}
// [cross_products]

}  // namespace stackbook
