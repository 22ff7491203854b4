// Chapter 2: what an isolated frictionless impulse conserves and what it dissipates.
// Linear and angular momentum (Eq. (2.5)), the energy change in general (Eq. (2.6)) and
// for the frictionless impulse in closed form (Eq. (2.7)). Every invariant is computed
// from the bodies' state before and after, never from the impulse formula itself.
#include <algorithm>
#include <cmath>

#include <doctest/doctest.h>

#include "pair_fixture.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::kTierImpulseAlgebra;
using stackbook::testing::PairContact;
using stackbook::testing::RandomSource;

namespace {

// Total angular momentum of the pair about o, and the size of the terms it sums.
template <int D>
AngVec<D> totalAngularMomentum(const PairContact<D>& c, const Vec<D>& o) {
  return testing::angularMomentumAbout<D>(c.a, o) + testing::angularMomentumAbout<D>(c.b, o);
}
template <int D>
double angularScale(const PairContact<D>& c, const Vec<D>& o) {
  return testing::angularMomentumScale<D>(c.a, o) + testing::angularMomentumScale<D>(c.b, o);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("linear momentum is conserved by the pair impulse", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(300 + D);
  for (const double e : {0.0, 0.3, 1.0}) {
    for (int trial = 0; trial < 300; ++trial) {
      CAPTURE(e);
      CAPTURE(trial);
      PairContact<D> c = testing::randomApproachingContact<D>(random);
      const Vec<D> before = testing::linearMomentum<D>(c.a, c.b);
      const Vec<D> j = frictionlessImpulse<D>(c.K(), c.relative(), c.n, e).j;
      const double scale = c.a.velocity.norm() / c.a.inverseMass +
                           c.b.velocity.norm() / c.b.inverseMass + j.norm();
      applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, j);
      const Vec<D> after = testing::linearMomentum<D>(c.a, c.b);
      CHECK((after - before).norm() <= kTierImpulseAlgebra * scale);
    }
  }
}

// [test_angular_momentum]
TEST_CASE_TEMPLATE("angular momentum about any fixed point is conserved", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(310 + D);
  for (const double e : {0.0, 0.3, 1.0}) {
    for (int trial = 0; trial < 300; ++trial) {
      CAPTURE(e);
      CAPTURE(trial);
      PairContact<D> c = testing::randomApproachingContact<D>(random);
      const Vec<D> o = random.vector<D>(-5.0, 5.0);  // any fixed point
      const AngVec<D> before = totalAngularMomentum<D>(c, o);
      const Vec<D> j = frictionlessImpulse<D>(c.K(), c.relative(), c.n, e).j;
      const double scaleBefore = angularScale<D>(c, o) + (c.p - o).norm() * j.norm();
      applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, j);
      const double scale = std::max(scaleBefore, angularScale<D>(c, o));
      CHECK((totalAngularMomentum<D>(c, o) - before).norm() <= kTierImpulseAlgebra * scale);
    }
  }
}
// [test_angular_momentum]

TEST_CASE_TEMPLATE("contact points apart along n keep angular momentum but apart sideways do not",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(320 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    for (const bool alongNormal : {true, false}) {
      CAPTURE(alongNormal);
      PairContact<D> c = testing::randomApproachingContact<D>(random);
      // Body a is touched at pa, body b at pb = p: a gap (pa - pb) of length 0.1.
      Vec<D> gap = 0.1 * c.n;
      if (!alongNormal) {
        const Vec<D> w = random.unitVector<D>();
        const Vec<D> t = w - w.dot(c.n) * c.n;
        if (t.norm() < 0.1) continue;
        gap = 0.1 * t.normalized();
      }
      const Vec<D> pa = c.p + gap;
      c.ra = pa - c.a.position;
      if (c.un() >= 0.0) continue;
      const Vec<D> o = random.vector<D>(-5.0, 5.0);
      const AngVec<D> before = totalAngularMomentum<D>(c, o);
      const Vec<D> j = frictionlessImpulse<D>(c.K(), c.relative(), c.n, 0.5).j;
      const double scaleBefore = angularScale<D>(c, o) + (c.p - o).norm() * j.norm();
      applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, j);
      const double scale = std::max(scaleBefore, angularScale<D>(c, o));
      // Eq. (2.5): the change is (pa - pb) x j. Along n it vanishes because j is along n.
      const AngVec<D> change = totalAngularMomentum<D>(c, o) - before;
      CHECK_EIGEN_NEAR(change, cross<D>(gap, j), 0.0, kTierImpulseAlgebra * scale);
      if (alongNormal) {
        CHECK(change.norm() <= kTierImpulseAlgebra * scale);
      } else {
        CHECK(change.norm() >= 0.099 * j.norm());  // |gap x j| = 0.1 |j| since gap is normal to j
      }
    }
  }
}

// [test_energy_closed_form]
TEST_CASE_TEMPLATE("the kinetic energy change equals the closed form", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(330 + D);
  for (const double e : {-0.5, 0.0, 0.3, 1.0}) {
    for (int trial = 0; trial < 300; ++trial) {
      CAPTURE(e);
      CAPTURE(trial);
      PairContact<D> c = testing::randomApproachingContact<D>(random);
      const Mat<D> K = c.K();
      const Vec<D> u = c.relative();
      const double un = u.dot(c.n);
      const double keBefore = c.a.kineticEnergy() + c.b.kineticEnergy();
      const Vec<D> j = frictionlessImpulse<D>(K, u, c.n, e).j;
      applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, j);
      const double measured = c.a.kineticEnergy() + c.b.kineticEnergy() - keBefore;

      const double general = j.dot(u + 0.5 * (K * j));                       // Eq. (2.6)
      const double closed = -(1.0 - e * e) * un * un / (2.0 * c.n.dot(K * c.n));  // Eq. (2.7)
      CHECK(std::abs(measured - general) <= kTierImpulseAlgebra * keBefore);
      CHECK(std::abs(measured - closed) <= kTierImpulseAlgebra * keBefore);
    }
  }
}
// [test_energy_closed_form]

TEST_CASE_TEMPLATE("an elastic impulse keeps kinetic energy and a partly elastic one never gains",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(340 + D);
  for (const double e : {-0.9, 0.0, 0.3, 0.9, 0.999, 1.0}) {
    for (int trial = 0; trial < 300; ++trial) {
      CAPTURE(e);
      CAPTURE(trial);
      PairContact<D> c = testing::randomApproachingContact<D>(random);
      const double keBefore = c.a.kineticEnergy() + c.b.kineticEnergy();
      applyPairImpulse<D>(c.a, c.ra, c.b, c.rb,
                          frictionlessImpulse<D>(c.K(), c.relative(), c.n, e).j);
      const double change = c.a.kineticEnergy() + c.b.kineticEnergy() - keBefore;
      if (e == 1.0) {
        CHECK(std::abs(change) <= kTierImpulseAlgebra * keBefore);
      } else {
        CHECK(change <= kTierImpulseAlgebra * keBefore);
      }
    }
  }
}

}  // TEST_SUITE
