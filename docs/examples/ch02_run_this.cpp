// Run this now (chapter 2): the off-centre impact of the chapter (a disk of mass 1 hits a
// 1 x 1 box of mass 2 at (-0.5, 0.3)), once for each restitution e. It prints the normal
// impulse (Eq. (2.3)), the velocities after, and the kinetic energy kept.
#include <cstdio>

#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"

using namespace stackbook;

int main() {
  std::printf("   e      j_n   box v_x  box omega   disk v_x  energy kept\n");
  for (const double e : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    RigidBody<2> box = makeDynamicBody<2>(2.0, AngVec<2>::Constant(1.0 / 3.0));
    RigidBody<2> disk = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.125));
    disk.position = Vec2(-1.0, 0.3);
    disk.velocity = Vec2(2.0, 0.0);
    const Vec2 p(-0.5, 0.3), n(1.0, 0.0);
    const Vec2 ra = p - box.position, rb = p - disk.position;
    const double before = box.kineticEnergy() + disk.kineticEnergy();
    const Mat2 K = pairCollisionMatrix<2>(box, ra, disk, rb);
    const ContactImpulse<2> j = frictionlessImpulse<2>(K, relativeVelocity<2>(box, ra, disk, rb), n, e);
    applyPairImpulse<2>(box, ra, disk, rb, j.j);
    std::printf("%5.2f %8.5f %8.5f %10.5f %10.5f %12.5f\n", e, j.normal(n), box.velocity.x(),
                box.angularVelocity[0], disk.velocity.x(), (box.kineticEnergy() + disk.kineticEnergy()) / before);
  }
}
