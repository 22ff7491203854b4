// Chapter 3, case B12: solving K j = b when K is ill-conditioned. A body with principal
// moments (1, 1, 1e-8) and mass 1, turned at random and touched at a lever arm of 1, so
// that cond(K) is about 1e8. Measures the LDL^T solve with and without one step of
// iterative refinement against a long-double reference. Prints a Markdown table.
#include <cstdio>
#include <limits>

#include <Eigen/Eigenvalues>

#include "../../tests/support/random_bodies.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"

using namespace stackbook;
using LongVec = Eigen::Matrix<long double, 3, 1>;
using LongMat = Eigen::Matrix<long double, 3, 3>;

namespace {

struct Worst {
  double backward = 0.0, residual = 0.0, forward = 0.0;
};

void measure(const Mat3& K, const Vec3& b, const Vec3& j, Worst& worst) {
  const LongMat KL = K.cast<long double>();
  const LongVec bL = b.cast<long double>(), jL = j.cast<long double>();
  const LongVec r = bL - KL * jL;
  const Eigen::LDLT<LongMat> ldlt(KL);
  LongVec exact = ldlt.solve(bL);
  exact += ldlt.solve(LongVec(bL - KL * exact));
  worst.backward = std::max(worst.backward, double(r.norm() / (KL.norm() * jL.norm() + bL.norm())));
  worst.residual = std::max(worst.residual, double(r.norm() / bL.norm()));
  worst.forward = std::max(worst.forward, double((jL - exact).norm() / exact.norm()));
}

}  // namespace

int main() {
  testing::RandomSource random(321);
  FrictionSettings refined, plain;
  plain.refineConditionAbove = std::numeric_limits<double>::infinity();
  Worst withRefinement, without;
  double kappa = 0.0;
  for (int trial = 0; trial < 10000; ++trial) {
    RigidBody<3> body = makeDynamicBody<3>(1.0, Vec3(1.0, 1.0, 1e-8));
    body.orientation = random.orientation<3>();
    const Mat3 K = collisionMatrix<3>(body, random.unitVector<3>());
    const Vec3 b = random.vector<3>(-1.0, 1.0);
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(K);
    kappa = std::max(kappa, eigen.eigenvalues().maxCoeff() / eigen.eigenvalues().minCoeff());
    Vec3 j = Vec3::Zero();
    solveCollisionMatrix<3>(K, b, refined, j);
    measure(K, b, j, withRefinement);
    solveCollisionMatrix<3>(K, b, plain, j);
    measure(K, b, j, without);
  }
  const double eps = std::numeric_limits<double>::epsilon();
  std::printf("<!-- printed by docs/examples/ch03_ill_conditioned.cpp -->\n");
  std::printf("| worst of 10000 random orientations, &kappa;(<b>K</b>) up to %.3g, &kappa;&epsilon; = %.2g "
              "| LDL<sup>T</sup> | LDL<sup>T</sup> + one refinement step |\n|---|---|---|\n", kappa, kappa * eps);
  std::printf("| backward error ‖<b>b</b> - <b>K</b><b>j</b>‖ / (‖<b>K</b>‖ ‖<b>j</b>‖ + ‖<b>b</b>‖) | %.2g | %.2g |\n",
              without.backward, withRefinement.backward);
  std::printf("| residual ‖<b>b</b> - <b>K</b><b>j</b>‖ / ‖<b>b</b>‖ | %.2g | %.2g |\n", without.residual,
              withRefinement.residual);
  std::printf("| forward error ‖<b>j</b> - <b>j</b><sub>exact</sub>‖ / ‖<b>j</b><sub>exact</sub>‖ | %.2g | %.2g |\n",
              without.forward, withRefinement.forward);
}
