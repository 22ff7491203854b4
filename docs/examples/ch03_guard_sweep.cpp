// Chapter 3: how often each branch and safeguard of frictionalImpulse is taken on random
// contacts (the sweep of validation case A20, made larger), for each slip-direction rule.
// Prints a Markdown table (\include{doc}).
#include <array>
#include <cstdio>

#include "../../tests/support/random_bodies.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"

using namespace stackbook;
using stackbook::testing::RandomSource;

namespace {

struct Counts {
  int contacts = 0, sticking = 0, sliding = 0, eLowered = 0, impactSlip = 0, painleveSwitch = 0,
      muLowered = 0, noFriction = 0;
};

/// Random body against a static or a dynamic partner, random normal, u_n in [-2, -0.1],
/// |u_t| / |u_n| log-uniform in [1e-3, 10], e in {0, 0.3, 1}, mu in {0.3, 1}.
template <int D>
Counts sweep(SlipDirectionRule rule, int samples) {
  RandomSource random(7000 + D);
  FrictionSettings settings;
  settings.slipDirection = rule;
  Counts c;
  const std::array<double, 3> restitutions{0.0, 0.3, 1.0};
  const std::array<double, 2> frictions{0.3, 1.0};
  for (int k = 0; k < samples; ++k) {
    const RigidBody<D> a = random.dynamicBody<D>();
    const RigidBody<D> b = k % 2 == 0 ? makeStaticBody<D>() : random.dynamicBody<D>();
    const Vec<D> ra = random.vector<D>(-1.0, 1.0), rb = random.vector<D>(-1.0, 1.0);
    const Mat<D> K = pairCollisionMatrix<D>(a, ra, b, rb);
    const Vec<D> n = random.unitVector<D>();
    Vec<D> t;
    do {
      const Vec<D> v = random.unitVector<D>();
      t = v - v.dot(n) * n;
    } while (t.norm() < 0.1);
    const double un = -random.uniform(0.1, 2.0);
    const Vec<D> u = un * n + random.logUniform(1e-3, 10.0) * std::abs(un) * t.normalized();
    const double e = restitutions[k % 3], mu = frictions[(k / 3) % 2];
    const ContactImpulse<D> r = frictionalImpulse<D>(K, u, n, e, mu, settings);
    ++c.contacts;
    c.sticking += r.branch == ImpulseBranch::Sticking;
    c.sliding += r.branch == ImpulseBranch::Sliding;
    c.eLowered += r.restitutionLowered;
    c.impactSlip += r.branch == ImpulseBranch::Sliding && r.slipFromImpulse;
    c.muLowered += r.frictionLowered;
    c.noFriction += r.branch == ImpulseBranch::Frictionless;
    // Did the Painleve guard replace the rule's direction? (T* taken although the rule
    // would not take it: u_t is not ~0 and, for the blend, the slip is not reversed.)
    if (r.branch == ImpulseBranch::Sliding && r.slipFromImpulse && rule != SlipDirectionRule::StickingImpulse) {
      Vec<D> jStar = Vec<D>::Zero();
      solveCollisionMatrix<D>(K, Vec<D>(-e * un * n - u), settings, jStar);
      const Vec<D> ut = u - un * n, jt = jStar - jStar.dot(n) * n;
      const bool ruleTakesImpact = ut.norm() <= settings.slipTolerance * u.norm() ||
                                   (rule == SlipDirectionRule::Blended && jt.dot(ut) >= 0.0);
      c.painleveSwitch += !ruleTakesImpact;
    }
  }
  return c;
}

double percent(int part, int whole) { return 100.0 * part / whole; }

}  // namespace

int main() {
  constexpr int kSamples = 20000;
  std::printf("<!-- printed by docs/examples/ch03_guard_sweep.cpp -->\n");
  std::printf("| rule | D | sticking | sliding | e lowered (Eq. (3.9)) | slides along <b>T</b>∗ "
              "| of which the Painleve switch (Eq. (3.7)) | &mu; lowered (Eq. (3.10)) | friction dropped |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  const std::array<SlipDirectionRule, 3> rules{SlipDirectionRule::Blended, SlipDirectionRule::RelativeVelocity,
                                               SlipDirectionRule::StickingImpulse};
  const std::array<const char*, 3> names{"`Blended`", "`RelativeVelocity`", "`StickingImpulse`"};
  for (int i = 0; i < 3; ++i) {
    for (const int D : {2, 3}) {
      const Counts c = D == 2 ? sweep<2>(rules[i], kSamples) : sweep<3>(rules[i], kSamples);
      std::printf("| %s | %d | %.1f %% | %.1f %% | %.2f %% | %.2f %% | %.3f %% | %.2f %% | %.2f %% |\n", names[i], D,
                  percent(c.sticking, c.contacts), percent(c.sliding, c.contacts), percent(c.eLowered, c.contacts),
                  percent(c.impactSlip, c.contacts), percent(c.painleveSwitch, c.contacts),
                  percent(c.muLowered, c.contacts), percent(c.noFriction, c.contacts));
    }
  }
  std::printf("\n%d random contacts per row: a random body against a static or a random dynamic partner, "
              "u<sub>n</sub> in [-2, -0.1], ‖<b>u</b><sub>t</sub>‖ / (-u<sub>n</sub>) log-uniform in "
              "[10<sup>-3</sup>, 10], e in {0, 0.3, 1}, &mu; in {0.3, 1}.\n",
              kSamples);
}
