// Prints the numbers of chapter 4 as Markdown: the unit square landing on a corner in the
// plane and as prisms of several heights in space, a body whose z axis is not principal,
// and the condition number of K for physical planar bodies touched at their extreme point.
#include <cmath>
#include <cstdio>

#include <Eigen/Eigenvalues>

#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"
#include "stackbook/impulse/planar_reduction.hpp"

namespace {

using namespace stackbook;

// A value as printed, without a "-0".
double shown(double x) { return std::abs(x) < 5e-13 ? 0.0 : x; }

void squareOnCorner() {
  RigidBody<2> square = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 6.0));
  square.velocity = Vec2(1.0, -2.0);
  const RigidBody<2> floor = makeStaticBody<2>();
  const Vec2 r(0.5, -0.5), n(0.0, 1.0);
  const Mat2 K2 = pairCollisionMatrix<2>(square, r, floor, r);
  const Vec2 u2 = relativeVelocity<2>(square, r, floor, r);

  std::printf("**The square in the plane and in space.** `collisionMatrix` of the square "
              "(D = 2) and of boxes of height h over it (D = 3, `liftToSpace` with "
              "I_x = I_y = (1 + h^2)/12):\n\n");
  std::printf("| body | K_xx | K_xy | K_yy | K_xz | K_yz | K_zz | 1 + 6/(1 + h^2) |\n");
  std::printf("|------|------|------|------|------|------|------|-----------------|\n");
  std::printf("| square (D = 2) | %.15g | %.15g | %.15g | | | | |\n", K2(0, 0), K2(0, 1),
              K2(1, 1));
  for (const double h : {0.0, 0.5, 1.0, 4.0}) {
    const double Ixy = (1.0 + h * h) / 12.0;
    const RigidBody<3> prism = liftToSpace(square, Ixy, Ixy);
    const Vec3 r3 = liftToSpace(r);
    const Mat3 K3 = pairCollisionMatrix<3>(prism, r3, liftToSpace(floor), r3);
    std::printf("| box, h = %g | %.15g | %.15g | %.15g | %.3g | %.3g | %.15g | %.15g |\n", h,
                K3(0, 0), K3(0, 1), K3(1, 1), shown(K3(0, 2)), shown(K3(1, 2)), K3(2, 2),
                1.0 + 6.0 / (1.0 + h * h));
  }

  std::printf("\n**The impulses** (e = 0, `frictionalImpulse`), in the plane and for the box "
              "of height 1. The fractions of the derivation are 11/8 = 1.375, 13/8 = 1.625, "
              "4/7 = %.15g, 8/7 = %.15g and 9/7 = %.15g:\n\n",
              4.0 / 7.0, 8.0 / 7.0, 9.0 / 7.0);
  std::printf("| mu | branch | j (D = 2) | j (D = 3, h = 1) | u' = u + K j (D = 2) |\n");
  std::printf("|----|--------|-----------|------------------|----------------------|\n");
  const RigidBody<3> cube = liftToSpace(square, 1.0 / 6.0, 1.0 / 6.0);
  const Vec3 r3 = liftToSpace(r), n3 = liftToSpace(n);
  const Mat3 K3 = pairCollisionMatrix<3>(cube, r3, liftToSpace(floor), r3);
  const Vec3 u3 = relativeVelocity<3>(cube, r3, liftToSpace(floor), r3);
  for (const double mu : {1.0, 0.5}) {
    const ContactImpulse<2> j2 = frictionalImpulse<2>(K2, u2, n, 0.0, mu);
    const ContactImpulse<3> j3 = frictionalImpulse<3>(K3, u3, n3, 0.0, mu);
    const Vec2 after = u2 + K2 * j2.j;
    std::printf("| %g | %s | (%.15g, %.15g) | (%.15g, %.15g, %.3g) | (%.15g, %.3g) |\n", mu,
                branchName(j2.branch), j2.j.x(), j2.j.y(), j3.j.x(), j3.j.y(), shown(j3.j.z()),
                after.x(), shown(after.y()));
  }
  std::printf("\n");
}

void tiltedBody() {
  RigidBody<3> body = makeDynamicBody<3>(1.0, Vec3(1.0, 2.0, 3.0));
  body.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.25 * M_PI, Vec3::UnitX()));
  const Vec3 r(1.0, 2.0, 0.0), j(0.0, 1.0, 0.0);
  const Mat3 invI = body.inverseInertiaWorld();
  const Mat3 K = collisionMatrix<3>(body, r);
  body.applyImpulse(r, j);
  std::printf("**A body whose z axis is not principal.** Principal moments (1, 2, 3) turned "
              "45 degrees about x; in-plane offset r = (1, 2, 0), in-plane impulse "
              "j = (0, 1, 0) on the body at rest:\n\n");
  std::printf("| quantity | value | by hand |\n|----------|-------|---------|\n");
  std::printf("| (I^-1)_yz | %.15g | 1/12 = %.15g |\n", invI(1, 2), 1.0 / 12.0);
  std::printf("| K_xz | %.15g | r_x r_y / 12 = %.15g |\n", K(0, 2), 2.0 / 12.0);
  std::printf("| K_yz | %.15g | -r_x^2 / 12 = %.15g |\n", K(1, 2), -1.0 / 12.0);
  std::printf("| omega after | (%.3g, %.15g, %.15g) | (0, 1/12, (I^-1)_zz) |\n",
              shown(body.angularVelocity.x()), body.angularVelocity.y(),
              body.angularVelocity.z());
  std::printf("| v_z after | %.3g | 0 |\n", shown(body.velocity.z()));
  std::printf("\n");
}

void conditioning() {
  struct Shape {
    const char* name;
    double I;  // moment about the centre, for m = 1
    Vec2 r;    // the point touched
  };
  const double s3 = std::sqrt(3.0);
  const Shape shapes[] = {
      {"thin ring of radius 1, on its rim", 1.0, Vec2(1.0, 0.0)},
      {"disk of radius 1, on its rim", 0.5, Vec2(1.0, 0.0)},
      {"square of side 1, at a corner", 1.0 / 6.0, Vec2(0.5, 0.5)},
      {"rectangle 10 x 0.1, at a corner", (100.0 + 0.01) / 12.0, Vec2(5.0, 0.05)},
      {"rectangle 10 x 0.1, at the middle of an end", (100.0 + 0.01) / 12.0, Vec2(5.0, 0.0)},
      {"equilateral triangle of side 1, at a vertex", 1.0 / 12.0, Vec2(0.0, 1.0 / s3)},
      {"disk of radius 1 with I entered 1000 times too small", 0.5e-3, Vec2(1.0, 0.0)},
  };
  std::printf("**How well conditioned is a planar K?** One body of mass 1, touched at an "
              "extreme point; kappa from the eigenvalues of `collisionMatrix<2>`, against "
              "Eq. (4.4):\n\n");
  std::printf("| body and contact | m r.r / I | kappa(K) | 1 + m r.r / I |\n");
  std::printf("|------------------|-----------|----------|---------------|\n");
  for (const Shape& shape : shapes) {
    const RigidBody<2> body = makeDynamicBody<2>(1.0, AngVec<2>::Constant(shape.I));
    const Mat2 K = collisionMatrix<2>(body, shape.r);
    const Eigen::SelfAdjointEigenSolver<Mat2> eigen(K, Eigen::EigenvaluesOnly);
    const double ratio = shape.r.squaredNorm() / shape.I;
    std::printf("| %s | %.6g | %.6g | %.6g |\n", shape.name, ratio,
                eigen.eigenvalues()[1] / eigen.eigenvalues()[0], 1.0 + ratio);
  }
  std::printf("\n");
}

}  // namespace

int main() {
  squareOnCorner();
  tiltedBody();
  conditioning();
}
