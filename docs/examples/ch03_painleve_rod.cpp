// Chapter 3, case A21: the Painleve rod. Prints a Markdown table (\include{doc}).
// A uniform rod (length 1, mass 1, I = 1/12) at theta = atan 2 above the floor, lower end
// on the floor and leading, u = (-1, -0.1), e = 0.
#include <cmath>
#include <cstdio>

#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"

using namespace stackbook;

namespace {
/// Rounding noise (|x| < 1e-12) printed as the 0 it stands for.
double clean(double x) { return std::abs(x) < 1e-12 ? 0.0 : x; }
}  // namespace

int main() {
  const double theta = std::atan(2.0);
  RigidBody<2> rod = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 12.0));
  rod.orientation = Eigen::Rotation2Dd(theta);
  rod.position = Vec2(0.0, 0.5 * std::sin(theta));
  rod.velocity = Vec2(-1.0, -0.1);
  const RigidBody<2> floor = makeStaticBody<2>();
  const Vec2 r = -0.5 * Vec2(std::cos(theta), std::sin(theta));
  const Vec2 p = rod.position + r, n(0.0, 1.0), T(-1.0, 0.0);
  const Mat2 K = pairCollisionMatrix<2>(rod, r, floor, p);
  const Vec2 u = relativeVelocity<2>(rod, r, floor, p);
  Vec2 jStar = Vec2::Zero();
  solveCollisionMatrix<2>(K, Vec2(-u), FrictionSettings{}, jStar);

  std::printf("<!-- printed by docs/examples/ch03_painleve_rod.cpp -->\n");
  std::printf("| quantity | value |\n|---|---|\n");
  std::printf("| <b>K</b><sub>T</sub> | [%.6g, %.6g; %.6g, %.6g] |\n",
              K(0, 0), K(0, 1), K(1, 0), K(1, 1));
  std::printf("| sticking trial <b>j</b>∗ of Eq. (3.2) | (%.6g, %.6g) |\n", jStar.x(), jStar.y());
  std::printf("| switch at &mu; = ‖<b>j</b>∗<sub>t</sub>‖ / j∗<sub>n</sub> | %.6g |\n",
              std::abs(jStar.x()) / jStar.y());
  for (const double mu : {1.0, 1.5}) {
    const double denominator = n.dot(K * Vec2(n - mu * T));
    const ContactImpulse<2> c = frictionalImpulse<2>(K, u, n, 0.0, mu);
    const Vec2 after = u + K * c.j;
    std::printf("| &mu; = %.2g: the notes' denominator <b>n</b><sup>T</sup><b>K</b><sub>T</sub>(<b>n</b> - &mu;<b>T</b>)"
                " and j<sub>n</sub> | %.6g and %.6g |\n",
                mu, denominator, -u.dot(n) / denominator);
    std::printf("| &mu; = %.2g: `frictionalImpulse` | %s, <b>j</b> = (%.6g, %.6g), "
                "<b>u</b>' = (%.6g, %.3g), &Delta;KE = %.6g J |\n",
                mu, branchName(c.branch), c.j.x(), c.j.y(), clean(after.x()), clean(after.y()),
                clean(impulseEnergyChange<2>(K, u, c.j)));
  }
}
