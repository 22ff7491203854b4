#pragma once
/// \file
/// \brief Exercise 4.3 (chapter 4): a 2D-only fast path for the sticking solve K j = rhs
/// by Cramer's rule, and where it loses accuracy against the LDL^T solve of chapter 3.

#include "stackbook/impulse/friction_settings.hpp"
#include "stackbook/math/types.hpp"

namespace stackbook::exercises {

/// Solve K j = rhs for a symmetric positive definite 2 x 2 matrix K by Cramer's rule
/// (the explicit 2 x 2 inverse, adj(K) / det(K)). Returns false, leaving j unchanged,
/// when det(K) is not positive and finite.
bool solveCramer2(const Mat2& K, const Vec2& rhs, Vec2& j);

/// The 2D fast path: Cramer's rule when the cheap bound trace(K)^2 / det(K), which is at
/// least the condition number of K, is at most maxCondition; otherwise the LDL^T solve
/// `solveCollisionMatrix<2>` of chapter 3 with the given settings. Returns false when the
/// solve it used fails.
bool solveCollisionMatrix2D(const Mat2& K, const Vec2& rhs, const FrictionSettings& settings,
                            Vec2& j, double maxCondition = 1e4);

}  // namespace stackbook::exercises
