// Chapter 3, case B9: a 3D Painleve configuration. Searches, with a fixed seed, for the
// corner of a 0.2 x 0.2 x 2 box (mass 1) hitting a static floor where the sticking trial
// is rejected and the notes' kinetic denominator along u_t is not positive, then shows
// what each slip-direction rule does there. Prints Markdown (\include{doc}).
#include <cstdio>

#include "../../tests/support/random_bodies.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"

using namespace stackbook;

int main() {
  testing::RandomSource random(371);
  const double a = 0.2, L = 2.0;
  int tried = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    RigidBody<3> box = makeDynamicBody<3>(1.0, Vec3((a * a + L * L) / 12.0, (a * a + L * L) / 12.0, a * a / 6.0));
    box.orientation = random.orientation<3>();
    const Mat3 R = box.orientation.toRotationMatrix();
    Vec3 r = Vec3::Zero();
    double lowest = 1e9;
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 p((corner & 1 ? 0.5 : -0.5) * a, (corner & 2 ? 0.5 : -0.5) * a, (corner & 4 ? 0.5 : -0.5) * L);
      if ((R * p).z() < lowest) {
        lowest = (R * p).z();
        r = R * p;
      }
    }
    box.velocity = random.vector<3>(-1.0, 1.0);
    box.velocity.z() = -std::abs(box.velocity.z()) - 0.1;
    box.setAngularVelocity(random.vector<3>(-2.0, 2.0));
    const double mu = random.uniform(2.5, 5.0);
    const Mat3 K = collisionMatrix<3>(box, r);
    const Vec3 u = box.pointVelocity(r), n = Vec3::UnitZ();
    if (!(u.dot(n) < 0.0)) continue;
    ++tried;
    Vec3 jStar = Vec3::Zero();
    solveCollisionMatrix<3>(K, Vec3(-u), FrictionSettings{}, jStar);
    const double jn = jStar.dot(n);
    const Vec3 jt = jStar - jn * n;
    if (jn > 0.0 && jt.norm() <= mu * jn) continue;
    const Vec3 slip = (u - u.dot(n) * n).normalized();
    const double raw = n.dot(K * Vec3(n - mu * slip));
    if (raw > 0.0) continue;
    std::printf("<!-- printed by docs/examples/ch03_painleve_3d.cpp -->\n");
    std::printf("The first such hit among %d approaching corners: &mu; = %.4g, sticking trial "
                "j∗<sub>n</sub> = %.4g with ‖<b>j</b>∗<sub>t</sub>‖ = %.4g (so &mu; = %.4g would be needed), "
                "‖<b>u</b><sub>t</sub>‖ / (-u<sub>n</sub>) = %.3g. The notes' denominator along "
                "<b>u</b><sub>t</sub> is **%.4g**: their j<sub>n</sub> would be %.4g, a pull.\n\n",
                tried, mu, jn, jt.norm(), jt.norm() / jn, (u - u.dot(n) * n).norm() / std::abs(u.dot(n)), raw,
                -u.dot(n) / raw);
    std::printf("| rule | slips along | denominator | j<sub>n</sub> | &mu; used | u<sub>n</sub>' | &Delta;KE |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    const SlipDirectionRule rules[3] = {SlipDirectionRule::Blended, SlipDirectionRule::RelativeVelocity,
                                        SlipDirectionRule::StickingImpulse};
    const char* names[3] = {"`Blended`", "`RelativeVelocity`", "`StickingImpulse`"};
    for (int i = 0; i < 3; ++i) {
      FrictionSettings settings;
      settings.slipDirection = rules[i];
      const ContactImpulse<3> c = frictionalImpulse<3>(K, u, n, 0.0, mu, settings);
      const double jnUsed = c.j.dot(n);
      std::printf("| %s | %s | %.4g | %.4g | %.4g | %.2g | %.4g J |\n", names[i],
                  c.slipFromImpulse ? "<b>T</b>∗" : "the blend", -u.dot(n) / jnUsed, jnUsed, c.friction,
                  std::abs(Vec3(u + K * c.j).dot(n)) < 1e-12 ? 0.0 : Vec3(u + K * c.j).dot(n),
                  impulseEnergyChange<3>(K, u, c.j));
    }
    return 0;
  }
  std::printf("no Painleve configuration found\n");
  return 1;
}
