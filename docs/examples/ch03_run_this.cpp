// Run this now (chapter 3): a 2 x 1 box turned by 20 degrees lands on a corner (u_n = -1,
// e = 0, mu = 0.5) while its corner slides at u_t. For each u_t, frictionalImpulse picks
// sticking or sliding (Eq. (3.3)); the program prints the branch, the impulse and the
// tangential velocity left. Try another mu or restitution below.
#include <cstdio>
#include <numbers>

#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"

using namespace stackbook;

int main() {
  const double mu = 0.5, e = 0.0;
  RigidBody<2> box = makeDynamicBody<2>(1.0, AngVec<2>::Constant(5.0 / 12.0));
  box.orientation = Eigen::Rotation2Dd(20.0 * std::numbers::pi / 180.0);
  const Vec2 r = box.orientation * Vec2(-1.0, -0.5), n(0.0, 1.0);
  const Mat2 K = pairCollisionMatrix<2>(box, r, makeStaticBody<2>(), Vec2::Zero());
  std::printf("  u_t   branch      j_t       j_n    |j_t|/j_n   u_t after\n");
  for (const double ut : {-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5}) {
    const Vec2 u(ut, -1.0);
    const ContactImpulse<2> j = frictionalImpulse<2>(K, u, n, e, mu);
    const Vec2 after = u + K * j.j;
    std::printf("%5.1f   %-9s %8.5f  %8.5f  %8.5f  %10.5f\n", ut, branchName(j.branch), j.j.x(), j.j.y(),
                std::abs(j.j.x()) / j.j.y(), after.x());
  }
}
