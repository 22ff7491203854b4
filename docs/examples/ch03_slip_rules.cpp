// Chapter 3: how good is each slip-direction rule? Compares the one-shot impulse of
// frictionalImpulse with the impact integrated through time (tests/ch03/impact_reference.hpp:
// exact in 2D, small steps in 3D) on random sliding contacts, and measures the jump of the
// impulse at the stick/slide switch. Prints Markdown tables (\include{doc}).
#include <algorithm>
#include <cstdio>
#include <vector>

#include "../../tests/ch03/impact_reference.hpp"
#include "../../tests/support/random_bodies.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"

using namespace stackbook;
using stackbook::testing::RandomSource;

namespace {

constexpr SlipDirectionRule kRules[3] = {SlipDirectionRule::Blended,
                                         SlipDirectionRule::RelativeVelocity,
                                         SlipDirectionRule::StickingImpulse};
constexpr const char* kRuleNames[3] = {"`Blended` (default)",
                                       "`RelativeVelocity` (GBF, the notes)", "`StickingImpulse`"};

struct Contact {
  Mat3 K3;
  Vec3 u3, n3;
};

template <int D>
struct RandomContact {
  Mat<D> K;
  Vec<D> u, n;
};

/// A random body touched at a random point by a static partner; u_n in [-1, -0.2] and
/// |u_t| / |u_n| = ratio.
template <int D>
RandomContact<D> randomContact(RandomSource& random, double ratio) {
  const RigidBody<D> body = random.dynamicBody<D>();
  RandomContact<D> c;
  c.K = collisionMatrix<D>(body, random.vector<D>(-1.0, 1.0));
  c.n = random.unitVector<D>();
  Vec<D> t;
  do {
    const Vec<D> v = random.unitVector<D>();
    t = v - v.dot(c.n) * c.n;
  } while (t.norm() < 0.1);
  const double un = -random.uniform(0.2, 1.0);
  c.u = un * c.n + ratio * std::abs(un) * t.normalized();
  return c;
}

template <int D>
testing::IntegratedImpact<D> integrate(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n, double e,
                                       double mu) {
  if constexpr (D == 2) {
    return testing::integrateImpact2D(K, u, n, e, mu);
  } else {
    return testing::integrateImpact3D(K, u, n, e, mu, 1000);
  }
}

template <int D>
void accuracyTable(int perBin) {
  const double bins[4] = {1e-3, 0.1, 1.0, 10.0};
  std::printf("\n| %dD, ‖<b>u</b><sub>t</sub>‖ / (-u<sub>n</sub>) | sliding contacts |", D);
  for (const char* name : kRuleNames) std::printf(" %s |", name);
  std::printf("\n|---|---|---|---|---|\n");
  RandomSource random(9000 + D);
  for (int bin = 0; bin < 3; ++bin) {
    double error[3] = {0.0, 0.0, 0.0};
    int guarded[3] = {0, 0, 0};
    int count = 0;
    while (count < perBin) {
      const RandomContact<D> c = randomContact<D>(random, random.logUniform(bins[bin], bins[bin + 1]));
      const double e = random.uniform(0.0, 1.0), mu = random.uniform(0.05, 1.5);
      const ContactImpulse<D> first = frictionalImpulse<D>(c.K, c.u, c.n, e, mu);
      if (first.branch != ImpulseBranch::Sliding) continue;
      const testing::IntegratedImpact<D> reference = integrate<D>(c.K, c.u, c.n, e, mu);
      if (reference.history == testing::SlipHistory::Jammed) continue;
      ++count;
      for (int rule = 0; rule < 3; ++rule) {
        FrictionSettings settings;
        settings.slipDirection = kRules[rule];
        const ContactImpulse<D> r = frictionalImpulse<D>(c.K, c.u, c.n, e, mu, settings);
        error[rule] += (r.j - reference.j).norm() / reference.j.norm();
        guarded[rule] += r.frictionLowered;
      }
    }
    std::printf("| %g to %g | %d |", bins[bin], bins[bin + 1], count);
    for (int rule = 0; rule < 3; ++rule) {
      std::printf(" %.1f %% (%.0f %% guarded) |", 100.0 * error[rule] / count, 100.0 * guarded[rule] / count);
    }
    std::printf("\n");
  }
}

/// Relative jump |j(mu_c (1 - 1e-9)) - j*| / |j*| at the switch, median and maximum.
template <int D>
void continuityRow(int samples) {
  RandomSource random(9100 + D);
  std::vector<double> jumps[3];
  while (int(jumps[0].size()) < samples) {
    const RandomContact<D> c = randomContact<D>(random, random.logUniform(1e-2, 10.0));
    Vec<D> jStar = Vec<D>::Zero();
    if (!solveCollisionMatrix<D>(c.K, Vec<D>(-c.u), FrictionSettings{}, jStar)) continue;
    const double jn = jStar.dot(c.n);
    if (!(jn > 0.0)) continue;
    const double threshold = (jStar - jn * c.n).norm() / jn;
    std::vector<double> row;
    for (int rule = 0; rule < 3; ++rule) {
      FrictionSettings settings;
      settings.slipDirection = kRules[rule];
      const ContactImpulse<D> r = frictionalImpulse<D>(c.K, c.u, c.n, 0.0, threshold * (1.0 - 1e-9), settings);
      row.push_back((r.j - jStar).norm() / jStar.norm());
    }
    for (int rule = 0; rule < 3; ++rule) jumps[rule].push_back(row[rule]);
  }
  std::printf("| %dD |", D);
  for (auto& v : jumps) {
    std::sort(v.begin(), v.end());
    std::printf(" %.2g / %.2g |", v[v.size() / 2], v.back());
  }
  std::printf("\n");
}

/// A unit cube (m = 1, I = 1/6 per axis) sliding along x at 1 m/s on its corner
/// (-1/2, -1/2, -1/2) over a static floor and approaching at eps (e = 0, mu = 0.3): the
/// angle between the friction and -u_t for each rule as eps -> 0, as in a time step's
/// contact stage where eps = g dt.
void fastSlideTable() {
  RigidBody<3> cube = makeDynamicBody<3>(1.0, Vec3::Constant(1.0 / 6.0));
  const Mat3 K = collisionMatrix<3>(cube, Vec3(-0.5, -0.5, -0.5));
  const Vec3 n = Vec3::UnitZ();
  std::printf("\nA cube sliding at 1 m/s on a corner and approaching at &epsilon;: angle (degrees) "
              "between the friction and -<b>u</b><sub>t</sub>:\n\n| &epsilon; |");
  for (const char* name : kRuleNames) std::printf(" %s |", name);
  std::printf("\n|---|---|---|---|\n");
  for (const double eps : {1e-1, 1e-2, 1e-3, 1e-4}) {
    std::printf("| %g |", eps);
    for (int rule = 0; rule < 3; ++rule) {
      FrictionSettings settings;
      settings.slipDirection = kRules[rule];
      const ContactImpulse<3> r = frictionalImpulse<3>(K, Vec3(1.0, 0.0, -eps), n, 0.0, 0.3, settings);
      const Vec3 friction = r.j - r.j.dot(n) * n;
      std::printf(" %.3g |", std::atan2(friction.cross(Vec3::UnitX()).norm(), -friction.x()) * 180.0 / M_PI);
    }
    std::printf("\n");
  }
}

}  // namespace

int main() {
  std::printf("<!-- printed by docs/examples/ch03_slip_rules.cpp -->\n");
  std::printf("Mean relative error ‖<b>j</b> - <b>j</b><sub>ref</sub>‖ / ‖<b>j</b><sub>ref</sub>‖ "
              "against the impact integrated through time, and how often a guard had to lower "
              "&mu;; random bodies, e in [0, 1], &mu; in [0.05, 1.5], contacts that slide.\n");
  accuracyTable<2>(400);
  accuracyTable<3>(150);
  std::printf("\nJump of the impulse at the stick/slide switch, ‖<b>j</b>(&mu;<sub>c</sub>(1 - 10<sup>-9</sup>)) - "
              "<b>j</b>∗‖ / ‖<b>j</b>∗‖, median / maximum over 2000 random contacts (e = 0):\n\n");
  std::printf("| dimension |");
  for (const char* name : kRuleNames) std::printf(" %s |", name);
  std::printf("\n|---|---|---|---|\n");
  continuityRow<2>(2000);
  continuityRow<3>(2000);
  fastSlideTable();
}
