// Exercise 1.1, reference solution: effective masses are reciprocals of Rayleigh quotients
// of K, so their extremes are the reciprocals of K's extreme eigenvalues.
#include "stackbook/exercises/ex01_1_effective_mass.hpp"

#include <limits>

#include <Eigen/Eigenvalues>

namespace stackbook {

namespace {

/// 1/x for x >= 0, with 1/0 = +infinity.
double reciprocal(double x) {
  return x > 0.0 ? 1.0 / x : std::numeric_limits<double>::infinity();
}

}  // namespace

template <int D>
double effectiveMass(const Mat<D>& K, const Vec<D>& d) {
  const Vec<D> unit = d.normalized();
  return reciprocal(unit.dot(K * unit));
}

template <int D>
EffectiveMassExtremes<D> effectiveMassExtremes(const Mat<D>& K) {
  // For unit d, d^T K d ranges over [lambda_min, lambda_max], reached at the
  // eigenvectors. The largest eigenvalue gives the lightest mass and vice versa.
  const Eigen::SelfAdjointEigenSolver<Mat<D>> eigen(K);  // eigenvalues ascending
  EffectiveMassExtremes<D> result;
  result.heaviest = reciprocal(eigen.eigenvalues()[0]);
  result.heaviestDirection = eigen.eigenvectors().col(0);
  result.lightest = reciprocal(eigen.eigenvalues()[D - 1]);
  result.lightestDirection = eigen.eigenvectors().col(D - 1);
  return result;
}

template double effectiveMass<2>(const Mat<2>&, const Vec<2>&);
template double effectiveMass<3>(const Mat<3>&, const Vec<3>&);
template EffectiveMassExtremes<2> effectiveMassExtremes<2>(const Mat<2>&);
template EffectiveMassExtremes<3> effectiveMassExtremes<3>(const Mat<3>&);

}  // namespace stackbook
