#pragma once
// Tolerance helpers for Eigen values in doctest.
//
// Eigen's isApprox is purely relative, so it fails against an exact zero. These checks
// use  |a - b| <= abs + rel * max(|a|, |b|)  (max norm), which is what the tolerance
// tiers of the course mean: T1 impulse algebra 1e-12 relative, T2 discrete reference
// 1e-9, T3 continuum analytic about 1 %.

#include <algorithm>
#include <limits>
#include <sstream>
#include <string>

#include <doctest/doctest.h>
#include <Eigen/Core>

namespace stackbook::testing {

/// Tolerance tiers (see docs/conventions.md and validation tier table).
inline constexpr double kEps = std::numeric_limits<double>::epsilon();  ///< machine epsilon
inline constexpr double kTierImpulseAlgebra = 1e-12;   ///< T1: single-impulse algebra
inline constexpr double kTierDiscreteReference = 1e-9; ///< T2: same integrator, exact model

/// True when |a - b|_max <= abs + rel * max(|a|_max, |b|_max).
template <typename A, typename B>
bool near(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b, double rel,
          double abs = 0.0) {
  const double scale = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  return (a - b).cwiseAbs().maxCoeff() <= abs + rel * scale;
}

/// A printable description of a mismatch, for doctest's INFO.
template <typename A, typename B>
std::string describeMismatch(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  std::ostringstream out;
  const Eigen::IOFormat fmt(Eigen::FullPrecision, 0, ", ", "; ", "", "", "[", "]");
  out << "\n  actual:   " << a.format(fmt) << "\n  expected: " << b.format(fmt)
      << "\n  max |diff| = " << (a - b).cwiseAbs().maxCoeff();
  return out.str();
}

}  // namespace stackbook::testing

/// CHECK that two Eigen values agree to a relative tolerance (plus optional absolute one).
#define CHECK_EIGEN_NEAR(actual, expected, ...)                                     \
  do {                                                                              \
    INFO(::stackbook::testing::describeMismatch((actual), (expected)));             \
    CHECK(::stackbook::testing::near((actual), (expected), __VA_ARGS__));           \
  } while (false)

/// REQUIRE version of CHECK_EIGEN_NEAR.
#define REQUIRE_EIGEN_NEAR(actual, expected, ...)                                   \
  do {                                                                              \
    INFO(::stackbook::testing::describeMismatch((actual), (expected)));             \
    REQUIRE(::stackbook::testing::near((actual), (expected), __VA_ARGS__));         \
  } while (false)
