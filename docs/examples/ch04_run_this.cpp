// Run this now (chapter 4): the square of the worked example lands on its corner, once in
// the plane (D = 2) and once lifted into space as boxes of several heights (D = 3). The
// impulses agree whatever the height: the in-plane block of K does not depend on it.
#include <cstdio>

#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"
#include "stackbook/impulse/planar_reduction.hpp"

using namespace stackbook;

int main() {
  RigidBody<2> square = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 6.0));
  square.velocity = Vec2(1.0, -2.0);
  const RigidBody<2> floor = makeStaticBody<2>();
  const Vec2 r(0.5, -0.5), n(0.0, 1.0);
  const double mu = 0.5;
  const ContactImpulse<2> j2 = frictionalImpulse<2>(pairCollisionMatrix<2>(square, r, floor, r),
                                                    relativeVelocity<2>(square, r, floor, r), n, 0.0, mu);
  std::printf("plane (D = 2):        j = (%.12f, %.12f)       %s\n", j2.j.x(), j2.j.y(), branchName(j2.branch));
  for (const double h : {0.1, 1.0, 10.0}) {
    const double Ixy = (1.0 + h * h) / 12.0;
    const RigidBody<3> box = liftToSpace(square, Ixy, Ixy);
    const Vec3 r3 = liftToSpace(r);
    const RigidBody<3> floor3 = liftToSpace(floor);
    const ContactImpulse<3> j3 = frictionalImpulse<3>(pairCollisionMatrix<3>(box, r3, floor3, r3),
                                                      relativeVelocity<3>(box, r3, floor3, r3),
                                                      liftToSpace(n), 0.0, mu);
    std::printf("space, height %-5g:  j = (%.12f, %.12f, %g)  %s\n", h, j3.j.x(), j3.j.y(),
                j3.j.z() == 0.0 ? 0.0 : j3.j.z(), branchName(j3.branch));
  }
}
