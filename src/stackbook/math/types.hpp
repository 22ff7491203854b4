#pragma once
/// \file
/// \brief Dimension-generic vector and matrix types (chapter 1, \ref ch01 "Notation").
///
/// Everything in stackbook is written once as `template <int D>` and instantiated for
/// D = 2 (the plane) and D = 3 (space). Linear quantities (positions, velocities,
/// impulses) have D components. Angular quantities (angular velocity, angular
/// momentum, torque) have D(D-1)/2 components: one in the plane, three in space.
/// \see \ref ch01 and \ref ch04 for why this is the right count.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace stackbook {

// [angular_dimension]
/// Number of components of an angular quantity in D dimensions: D(D-1)/2.
template <int D>
inline constexpr int kAngularDim = D * (D - 1) / 2;
// [angular_dimension]

/// Linear vector: position, velocity, impulse (D components).
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

/// Linear D x D matrix, e.g. the collision matrix K.
template <int D>
using Mat = Eigen::Matrix<double, D, D>;

/// Angular vector: angular velocity, angular momentum, torque (D(D-1)/2 components).
template <int D>
using AngVec = Eigen::Matrix<double, kAngularDim<D>, 1>;

/// Angular matrix: inertia tensor and its inverse (1 x 1 in 2D, 3 x 3 in 3D).
template <int D>
using AngMat = Eigen::Matrix<double, kAngularDim<D>, kAngularDim<D>>;

/// The cross-product matrix r* that maps a linear vector to an angular one,
/// r x j = r* j (a 1 x 2 row in 2D, the 3 x 3 skew matrix in 3D).
template <int D>
using CrossMat = Eigen::Matrix<double, kAngularDim<D>, D>;

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;
using Mat2 = Mat<2>;
using Mat3 = Mat<3>;

}  // namespace stackbook
