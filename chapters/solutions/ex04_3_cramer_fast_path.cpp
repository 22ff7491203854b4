// Exercise 4.3, reference solution: Cramer's rule for the 2D sticking solve, and a fast
// path that uses it only where it is accurate.
//
// For a symmetric positive definite 2 x 2 K with eigenvalues l1 >= l2 > 0,
//   trace^2 / det = (l1 + l2)^2 / (l1 l2) = kappa + 2 + 1/kappa,   kappa = l1 / l2,
// so the bound costs three products and never underestimates the condition number.
// Cramer's rule computes j as accurately as LDL^T (both have forward error ~ kappa eps),
// but its residual K j - rhs, the velocity error the sticking impulse leaves behind, grows
// like kappa eps |rhs| when rhs lies along the stiff eigenvector: the adjugate product
// cancels. LDL^T keeps the residual at eps |rhs|. So: Cramer only below maxCondition.
#include "stackbook/exercises/ex04_3_cramer_fast_path.hpp"

#include <cmath>

#include "stackbook/impulse/frictional_impulse.hpp"

namespace stackbook::exercises {

bool solveCramer2(const Mat2& K, const Vec2& rhs, Vec2& j) {
  const double det = K(0, 0) * K(1, 1) - K(0, 1) * K(1, 0);
  if (!(det > 0.0) || !std::isfinite(det)) return false;
  j = Vec2(K(1, 1) * rhs[0] - K(0, 1) * rhs[1], K(0, 0) * rhs[1] - K(1, 0) * rhs[0]) / det;
  return j.allFinite();
}

bool solveCollisionMatrix2D(const Mat2& K, const Vec2& rhs, const FrictionSettings& settings,
                            Vec2& j, double maxCondition) {
  const double det = K(0, 0) * K(1, 1) - K(0, 1) * K(1, 0);
  const double trace = K.trace();
  if (det > 0.0 && trace * trace <= maxCondition * det) return solveCramer2(K, rhs, j);
  return solveCollisionMatrix<2>(K, rhs, settings, j);
}

}  // namespace stackbook::exercises
