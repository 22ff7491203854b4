// Chapter 3, case B11: a sticking impulse with e = 1 that would add energy. Prints a
// Markdown table (\include{doc}). A uniform rod (length 1, mass 1, I = 1/12) at 45
// degrees, lower end on the floor, u = (0.5, -1), e = 1, mu = 1.
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
  const double theta = 0.25 * M_PI;
  RigidBody<2> rod = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 12.0));
  rod.orientation = Eigen::Rotation2Dd(theta);
  rod.position = Vec2(0.0, 0.5 * std::sin(theta));
  rod.velocity = Vec2(0.5, -1.0);
  const RigidBody<2> floor = makeStaticBody<2>();
  const Vec2 r = -0.5 * Vec2(std::cos(theta), std::sin(theta));
  const Vec2 p = rod.position + r, n(0.0, 1.0);
  const Mat2 K = pairCollisionMatrix<2>(rod, r, floor, p);
  const Vec2 u = relativeVelocity<2>(rod, r, floor, p);
  Vec2 greedy = Vec2::Zero();
  solveCollisionMatrix<2>(K, Vec2(-1.0 * u.dot(n) * n - u), FrictionSettings{}, greedy);
  const ContactImpulse<2> c = frictionalImpulse<2>(K, u, n, 1.0, 1.0);
  const Vec2 after = u + K * c.j;

  std::printf("<!-- printed by docs/examples/ch03_energy_rod.cpp -->\n");
  std::printf("| quantity | value |\n|---|---|\n");
  std::printf("| <b>K</b><sub>T</sub> | [%.6g, %.6g; %.6g, %.6g] |\n",
              K(0, 0), K(0, 1), K(1, 0), K(1, 1));
  std::printf("| kinetic energy before | %.6g J |\n", rod.kineticEnergy());
  std::printf("| sticking trial with e = 1 and its &Delta;KE (Eq. (3.8)) | (%.6g, %.6g), **%+.6g J** |\n",
              greedy.x(), greedy.y(), impulseEnergyChange<2>(K, u, greedy));
  std::printf("| e<sub>max</sub> of Eq. (3.9), the restitution used | %.6g |\n", c.restitution);
  std::printf("| `frictionalImpulse`: branch and <b>j</b> | %s, (%.6g, %.6g) |\n",
              branchName(c.branch), c.j.x(), c.j.y());
  std::printf("| contact velocity after | (%.3g, %.6g) |\n", clean(after.x()), clean(after.y()));
  std::printf("| &Delta;KE | %.3g J |\n", clean(impulseEnergyChange<2>(K, u, c.j)));
}
