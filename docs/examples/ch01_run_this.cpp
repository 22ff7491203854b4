// Run this now (chapter 1): build K for a box touched at a corner, push the corner with one
// impulse j, and compare the measured change of the corner's velocity with K j (Eq. (1.9)).
// Change the box, the corner or j below, rebuild, and run again.
#include <cstdio>

#include "stackbook/impulse/collision_matrix.hpp"

using namespace stackbook;

int main() {
  RigidBody<3> box = makeDynamicBody<3>(2.0, Vec3(2.0 * (1 + 4) / 12.0, 2.0 * (1 + 4) / 12.0, 2.0 * 2 / 12.0));
  box.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  RigidBody<3> floor = makeStaticBody<3>();
  const Vec3 r = box.orientation * Vec3(0.5, 0.5, -1.0);  // a bottom corner of a 1 x 1 x 2 box
  const Vec3 j(0.1, -0.2, 1.0);

  const Mat3 K = pairCollisionMatrix<3>(box, r, floor, r);
  const Vec3 before = relativeVelocity<3>(box, r, floor, r);
  applyPairImpulse<3>(box, r, floor, r, j);
  const Vec3 measured = relativeVelocity<3>(box, r, floor, r) - before;
  const Vec3 predicted = K * j;

  std::printf("K of a 1 x 1 x 2 box of mass 2 at a bottom corner:\n");
  for (int i = 0; i < 3; ++i) std::printf("  [%9.5f %9.5f %9.5f]\n", K(i, 0), K(i, 1), K(i, 2));
  std::printf("impulse j          = (%.4f, %.4f, %.4f)\n", j.x(), j.y(), j.z());
  std::printf("K j                = (%.6f, %.6f, %.6f)\n", predicted.x(), predicted.y(), predicted.z());
  std::printf("measured change    = (%.6f, %.6f, %.6f)\n", measured.x(), measured.y(), measured.z());
  std::printf("difference |.|     = %.2e\n", (measured - predicted).norm());
}
