// Prints the worked examples of chapter 2 as Markdown tables: the off-centre impact of
// validation case A7, the head-on collisions of case A6, and a sweep of the restitution e
// over the A7 configuration. Each "by hand" column is the exact fraction derived in the
// chapter; the "stackbook" column is what the library computes; the last column is their
// difference.
#include <cmath>
#include <cstdio>
#include <string>

#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"

namespace {

using namespace stackbook;

void header(const char* title) {
  std::printf("%s\n\n", title);
  std::printf("| quantity | by hand | exact value | stackbook | difference |\n");
  std::printf("|----------|---------|-------------|-----------|------------|\n");
}

void row(const char* quantity, const char* fraction, double exact, double computed) {
  std::printf("| %s | %s | %.12g | %.12g | %.1e |\n", quantity, fraction, exact, computed,
              computed - exact);
}

// A value rounded to the 6 decimals printed, without a "-0.000000".
double shown(double x) { return std::abs(x) < 5e-7 ? 0.0 : x; }

// The total angular momentum about the origin (z component) and the kinetic energy.
double angularMomentumZ(const RigidBody<2>& a, const RigidBody<2>& b) {
  double lz = 0.0;
  for (const RigidBody<2>* body : {&a, &b}) {
    lz += body->angularMomentum[0] +
          cross<2>(body->position, Vec2(body->velocity / body->inverseMass))[0];
  }
  return lz;
}

struct OffCentre {
  RigidBody<2> box = makeDynamicBody<2>(2.0, AngVec<2>::Constant(1.0 / 3.0));
  RigidBody<2> disk = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.125));
  Vec2 p{-0.5, 0.3};
  Vec2 n{1.0, 0.0};
  Vec2 ra() const { return p - box.position; }
  Vec2 rb() const { return p - disk.position; }
  OffCentre() {
    disk.position = Vec2(-1.0, 0.3);
    disk.velocity = Vec2(2.0, 0.0);
  }
};

void offCentreImpact() {
  OffCentre s;
  const Mat2 K = pairCollisionMatrix<2>(s.box, s.ra(), s.disk, s.rb());
  const Vec2 u = relativeVelocity<2>(s.box, s.ra(), s.disk, s.rb());
  const double lzBefore = angularMomentumZ(s.box, s.disk);
  const double keBefore = s.box.kineticEnergy() + s.disk.kineticEnergy();
  const ContactImpulse<2> impulse = frictionlessImpulse<2>(K, u, s.n, 1.0);
  applyPairImpulse<2>(s.box, s.ra(), s.disk, s.rb(), impulse.j);
  const Vec2 uAfter = relativeVelocity<2>(s.box, s.ra(), s.disk, s.rb());

  header("<b>Case \\ref case_A7 \"A7\", an off-centre elastic impact (e = 1).</b> Body a is the box, body b the disk, "
         "<b>n</b> = (1, 0).");
  row("(<b>r</b><sub>a</sub> × <b>n</b>)<sub>z</sub>", "-3/10", -0.3, cross<2>(s.ra(), s.n)[0]);
  row("u<sub>n</sub>", "-2", -2.0, u.dot(s.n));
  row("<b>n</b><sup>T</sup><b>K</b><sub>T</sub><b>n</b>", "177/100", 1.77, s.n.dot(K * s.n));
  row("j<sub>n</sub>", "400/177", 400.0 / 177.0, impulse.normal(s.n));
  row("box v<sub>x</sub>′", "200/177", 200.0 / 177.0, s.box.velocity.x());
  row("box ω<sub>z</sub>′", "-120/59", -120.0 / 59.0, s.box.angularVelocity[0]);
  row("disk v<sub>x</sub>′", "-46/177", -46.0 / 177.0, s.disk.velocity.x());
  row("u<sub>n</sub>′", "2", 2.0, uAfter.dot(s.n));
  row("u<sub>t</sub>′ (was 0)", "180/177", 180.0 / 177.0, uAfter.y());
  row("L<sub>z</sub> about the origin, before", "-3/5", -0.6, lzBefore);
  row("L<sub>z</sub> about the origin, after", "-3/5", -0.6, angularMomentumZ(s.box, s.disk));
  row("kinetic energy, before", "2", 2.0, keBefore);
  row("kinetic energy, after", "2", 2.0, s.box.kineticEnergy() + s.disk.kineticEnergy());
  std::printf("\n");
}

void headOn(double m1, double m2, double v1, double e, const char* title, const char* v1Hand,
            double v1Exact, const char* v2Hand, double v2Exact, const char* keBeforeHand,
            const char* keHand, double keExact) {
  // Two balls on the x axis, body a (mass m1) at -1 moving at v1, body b (mass m2) at rest
  // at +1, touching at the origin. n = -x points from b toward a.
  RigidBody<2> a = makeDynamicBody<2>(m1, AngVec<2>::Constant(0.4 * m1));
  RigidBody<2> b = makeDynamicBody<2>(m2, AngVec<2>::Constant(0.4 * m2));
  a.position = Vec2(-1.0, 0.0);
  b.position = Vec2(1.0, 0.0);
  a.velocity = Vec2(v1, 0.0);
  const Vec2 n(-1.0, 0.0), ra = -a.position, rb = -b.position;
  const Mat2 K = pairCollisionMatrix<2>(a, ra, b, rb);
  const double keBefore = a.kineticEnergy() + b.kineticEnergy();
  const Vec2 u = relativeVelocity<2>(a, ra, b, rb);
  applyPairImpulse<2>(a, ra, b, rb, frictionlessImpulse<2>(K, u, n, e).j);
  header(title);
  row("effective mass 1/(<b>n</b><sup>T</sup><b>K</b><sub>T</sub><b>n</b>)", "m<sub>1</sub>m<sub>2</sub>/(m<sub>1</sub> + m<sub>2</sub>)",
      m1 * m2 / (m1 + m2), 1.0 / n.dot(K * n));
  row("v<sub>1</sub>′", v1Hand, v1Exact, a.velocity.x());
  row("v<sub>2</sub>′", v2Hand, v2Exact, b.velocity.x());
  row("kinetic energy, before", keBeforeHand, 0.5 * m1 * v1 * v1, keBefore);
  row("kinetic energy, after", keHand, keExact, a.kineticEnergy() + b.kineticEnergy());
  std::printf("\n");
}

void restitutionSweep() {
  std::printf("<b>The \\ref case_A7 \"A7\" impact for several e.</b> ΔKE is measured from the bodies; the fifth "
              "column divides it by the kinetic energy of the normal approach, "
              "½ u<sub>n</sub><sup>2</sup>/(<b>n</b><sup>T</sup><b>K</b><sub>T</sub><b>n</b>), "
              "which Eq. (2.7) predicts to be −(1 − e<sup>2</sup>).\n\n");
  std::printf("| e | j<sub>n</sub> | u<sub>n</sub>′ | ΔKE | ΔKE / normal KE | −(1 − e<sup>2</sup>) |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const double e : {-1.0, -0.5, 0.0, 0.5, 0.8, 1.0}) {
    OffCentre s;
    const Mat2 K = pairCollisionMatrix<2>(s.box, s.ra(), s.disk, s.rb());
    const Vec2 u = relativeVelocity<2>(s.box, s.ra(), s.disk, s.rb());
    const double keBefore = s.box.kineticEnergy() + s.disk.kineticEnergy();
    const ContactImpulse<2> impulse = frictionlessImpulse<2>(K, u, s.n, e);
    applyPairImpulse<2>(s.box, s.ra(), s.disk, s.rb(), impulse.j);
    const double un = u.dot(s.n);
    const double dke = s.box.kineticEnergy() + s.disk.kineticEnergy() - keBefore;
    const double normalKe = 0.5 * un * un / s.n.dot(K * s.n);
    std::printf("| %g | %.6f | %.6f | %.6f | %.6f | %.6f |\n", e, shown(impulse.normal(s.n)),
                shown(relativeVelocity<2>(s.box, s.ra(), s.disk, s.rb()).dot(s.n)), shown(dke),
                shown(dke / normalKe), shown(-(1.0 - e * e)));
  }
  std::printf("\n");
}

}  // namespace

int main() {
  offCentreImpact();
  headOn(1.0, 3.0, 4.0, 0.5, "<b>Case \\ref case_A6 \"A6\", head-on: masses 1 and 3, v = 4 and 0, e = 0.5.</b>",
         "-1/2", -0.5, "3/2", 1.5, "8", "7/2", 3.5);
  headOn(1.0, 1000.0, 1.0, 1.0, "<b>Case \\ref case_A6 \"A6\", head-on: masses 1 and 1000, v = 1 and 0, e = 1.</b>",
         "-999/1001", -999.0 / 1001.0, "2/1001", 2.0 / 1001.0, "1/2", "1/2", 0.5);
  restitutionSweep();
}
