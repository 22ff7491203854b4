// Chapter 3, case B8: a tilted rod landing straight down (u_t = 0). Prints a Markdown
// table (\include{doc}). A uniform rod (length 1, mass 1, I = 1/12) at 60 degrees, lower
// end on the floor, u = (0, -1), e = 0.
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
  const double theta = M_PI / 3.0;
  RigidBody<2> rod = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 12.0));
  rod.orientation = Eigen::Rotation2Dd(theta);
  rod.position = Vec2(0.0, 0.5 * std::sin(theta));
  rod.velocity = Vec2(0.0, -1.0);
  const RigidBody<2> floor = makeStaticBody<2>();
  const Vec2 r = -0.5 * Vec2(std::cos(theta), std::sin(theta));
  const Vec2 p = rod.position + r, n(0.0, 1.0);
  const Mat2 K = pairCollisionMatrix<2>(rod, r, floor, p);
  const Vec2 u = relativeVelocity<2>(rod, r, floor, p);

  std::printf("<!-- printed by docs/examples/ch03_landing_rod.cpp -->\n");
  std::printf("<b>K</b><sub>T</sub> = [%.6g, %.6g; %.6g, %.6g]; "
              "sticking needs &mu; &ge; -K<sub>tn</sub> / K<sub>tt</sub> = %.6g.\n\n",
              K(0, 0), K(0, 1), K(1, 0), K(1, 1), std::abs(K(0, 1)) / K(0, 0));
  std::printf("| &mu; | branch | <b>j</b> | foot velocity after |\n|---|---|---|---|\n");
  for (const double mu : {0.0, 0.1, 0.3, 1.0}) {
    const ContactImpulse<2> c = frictionalImpulse<2>(K, u, n, 0.0, mu);
    const Vec2 after = u + K * c.j;
    std::printf("| %.2g | %s | (%.6g, %.6g) | (%.6g, %.2g) |\n", mu, branchName(c.branch), c.j.x(), c.j.y(),
                clean(after.x()), clean(after.y()));
  }
}
