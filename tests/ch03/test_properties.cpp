// Chapter 3: properties every frictional impulse has, whatever its branch (validation
// cases A20, B1-B3, B7, B10), and the input checks.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "ch03/friction_fixtures.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::Partner;
using stackbook::testing::RandomSource;

namespace {

/// How often each branch and safeguard was seen in a sweep.
struct SweepCounts {
  int sticking = 0, sliding = 0, frictionless = 0;
  int restitutionLowered = 0, painleve = 0, energy = 0, impactSlip = 0;
};

/// True when two vectors are the same bits.
template <int D>
bool sameBits(const Vec<D>& a, const Vec<D>& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * D) == 0;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_a20_sweep]
TEST_CASE_TEMPLATE("every impulse of the A20 sweep keeps its branch's promise", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(401 + D);
  const FrictionSettings settings;
  SweepCounts seen;
  const std::array<double, 3> restitutions{0.0, 0.3, 1.0}, frictions{0.0, 0.3, 1.0};
  const std::array<double, 4> slipRatios{0.0, 0.01, 0.3, 3.0};
  for (int partner = 0; partner < 3; ++partner) {
    for (const double e : restitutions) {
      for (const double mu : frictions) {
        for (const double slipRatio : slipRatios) {
          for (int trial = 0; trial < 12; ++trial) {
            CAPTURE(partner);
            CAPTURE(e);
            CAPTURE(mu);
            CAPTURE(slipRatio);
            CAPTURE(trial);
            const auto c = testing::randomContact<D>(random, Partner(partner), slipRatio);
            const Mat<D> K = c.K();
            const Vec<D> u = c.u(), n = c.n;
            const double un = u.dot(n);
            const ContactImpulse<D> r = frictionalImpulse<D>(K, u, n, e, mu, settings);
            REQUIRE(r.j.allFinite());
            const auto after = c.after(r.j);
            const Vec<D> uAfter = after.u();
            const double scale = u.norm() + (K * r.j).norm();
            // K is SPD with eigenvalues >= sum 1/m, so |j| sum(1/m) <= |K j| = |u' - u|.
            CHECK(r.j.norm() * c.inverseMassSum() <= (uAfter - u).norm() * (1.0 + 1e-12) + 1e-15);
            // Eq. (3.8) is the kinetic-energy change of the bodies (a kinematic partner's
            // energy is prescribed, so there only the formula is checked)...
            const double dKE = impulseEnergyChange<D>(K, u, r.j);
            if (Partner(partner) != Partner::Kinematic) {
              const double before = c.kineticEnergy();
              CHECK(after.kineticEnergy() - before ==
                    doctest::Approx(dKE).epsilon(1e-12).scale(before));
            }
            // ...and no impulse adds energy.
            CHECK(dKE <= 1e-12 * (u.squaredNorm() / K.trace()) + 1e-15);
            CHECK(r.j.dot(n) >= 0.0);
            switch (r.branch) {
              case ImpulseBranch::Frictionless:
                // mu = 0, or the energy guard found that any friction would add energy.
                ++seen.frictionless;
                CHECK((mu == 0.0 || r.frictionLowered));
                CHECK(sameBits<D>(r.j, frictionlessImpulse<D>(K, u, n, e).j));
                seen.energy += r.frictionLowered;
                break;
              case ImpulseBranch::Sticking: {
                ++seen.sticking;
                seen.restitutionLowered += r.restitutionLowered;
                // u' = -e u_n n exactly (Eq. (3.1)), e lowered only to the e_max of Eq. (3.9).
                CHECK_EIGEN_NEAR(uAfter, Vec<D>(-r.restitution * un * n), 0.0, 1e-12 * scale);
                if (r.restitutionLowered) {
                  CHECK(r.restitution ==
                        doctest::Approx(std::min(e, testing::eMaxReference<D>(K, u, n))).epsilon(1e-10));
                } else {
                  CHECK(r.restitution == e);
                }
                const double jn = r.j.dot(n);
                CHECK(testing::tangentialPart<D>(r.j, n).norm() <= mu * jn * (1.0 + 1e-12));
                break;
              }
              case ImpulseBranch::Sliding: {
                ++seen.sliding;
                seen.impactSlip += r.slipFromImpulse;
                // u_n' = -e u_n and |j_t| = mu j_n, with the mu actually used.
                CHECK(uAfter.dot(n) == doctest::Approx(-e * un).epsilon(1e-12).scale(scale));
                const double jn = r.j.dot(n);
                CHECK(testing::tangentialPart<D>(r.j, n).norm() ==
                      doctest::Approx(r.friction * jn).epsilon(1e-12).scale(jn));
                if (!r.frictionLowered) {
                  CHECK(r.friction == mu);
                  break;
                }
                // A guard fired: check its own claim. Painleve (Eq. (3.7)): the denominator
                // sits on the margin. Energy (Eq. (3.10)): Delta KE is zero, not negative.
                CHECK(r.friction < mu);
                const double knn = n.dot(K * n);
                const double denominator = -(1.0 + e) * un / jn;  // n^T K (n - mu' T)
                const bool onMargin =
                    std::abs(denominator - settings.painleveMargin * knn) <= 1e-9 * knn;
                const bool energyRoot = std::abs(dKE) <= 1e-12 * scale * scale / K.trace();
                CHECK((onMargin || energyRoot));
                seen.painleve += onMargin;
                seen.energy += energyRoot && !onMargin;
                break;
              }
              default:
                FAIL("approaching contacts with a dynamic body get an impulse");
            }
          }
        }
      }
    }
  }
  MESSAGE("A20 ", D, "D: sticking ", seen.sticking, ", sliding ", seen.sliding, ", frictionless ",
          seen.frictionless, "; e lowered ", seen.restitutionLowered, ", mu lowered by Painleve ",
          seen.painleve, " and by energy ", seen.energy, ", slip from the impact ", seen.impactSlip);
  CHECK(seen.sticking > 150);
  CHECK(seen.sliding > 150);
  CHECK(seen.restitutionLowered > 0);
  CHECK(seen.energy > 0);
  CHECK(seen.impactSlip > 0);
}
// [test_a20_sweep]

TEST_CASE_TEMPLATE("a static partner and a partner of mass 1e12 give the same impulse (B1)", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(411 + D);
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    auto c = testing::randomContact<D>(random, Partner::Static, random.logUniform(1e-3, 3.0));
    auto heavy = c;
    heavy.b = makeDynamicBody<D>(1e12, AngVec<D>::Constant(1e12));
    heavy.b.position = c.b.position;
    heavy.b.orientation = c.b.orientation;
    const double e = 0.5, mu = random.uniform(0.1, 1.0);
    const ContactImpulse<D> light = frictionalImpulse<D>(c.K(), c.u(), c.n, e, mu);
    const ContactImpulse<D> massive = frictionalImpulse<D>(heavy.K(), heavy.u(), heavy.n, e, mu);
    // K differs by about 1e-12 of itself; skip the few contacts that sit on the switch.
    const Vec<D> jStar = testing::stickingReference<D>(c.K(), c.u(), c.n, e);
    const double margin = std::abs(testing::tangentialPart<D>(jStar, c.n).norm() - mu * jStar.dot(c.n));
    if (margin <= 1e-6 * jStar.norm()) continue;
    CHECK(light.branch == massive.branch);
    CHECK_EIGEN_NEAR(massive.j, light.j, 1e-9);
    // The static body is not moved by its -j.
    const auto after = c.after(light.j);
    CHECK(sameBits<D>(after.b.velocity, c.b.velocity));
    CHECK(after.b.angularMomentum == c.b.angularMomentum);
    ++compared;
  }
  CHECK(compared > 250);
}

TEST_CASE_TEMPLATE("two immovable bodies get no impulse and no NaN (B2)", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(421 + D);
  for (int trial = 0; trial < 50; ++trial) {
    auto c = testing::randomContact<D>(random, Partner::Kinematic, 0.5);
    c.a = makeStaticBody<D>(c.a.position, c.a.orientation);
    c.a.velocity = random.vector<D>(-1.0, 1.0);
    const Vec<D> u = Vec<D>(-c.n + 0.3 * testing::randomTangent<D>(random, c.n));
    const Mat<D> K = c.K();
    CHECK(K == Mat<D>::Zero());
    const ContactImpulse<D> r = frictionalImpulse<D>(K, u, c.n, 0.5, 0.7);
    CHECK(r.branch == ImpulseBranch::Immovable);
    CHECK(r.j == Vec<D>::Zero());
  }
}

// [test_locked_dofs]
TEST_CASE("a body that can only spin about the normal gets no impulse (B3)") {
  // Translation locked and rotation only about the vertical y axis: K = r*^T I^{-1} r* has
  // n^T K n = 0 for n = y, so no normal impulse can stop the approach. The contact is
  // skipped (as Jolt does), and the spin is not touched.
  RigidBody<3> spinner;
  spinner.inverseMass = 0.0;
  spinner.inertia = Vec3(1.0, 1.0, 1.0);
  spinner.inverseInertia = Vec3(0.0, 1.0, 0.0);
  spinner.setAngularVelocity(Vec3(0.0, 3.0, 0.0));
  const Vec3 r(0.5, -0.5, 0.5), n = Vec3::UnitY();
  const Mat3 K = collisionMatrix<3>(spinner, r);
  CHECK(n.dot(K * n) == 0.0);
  const Vec3 u = spinner.pointVelocity(r) - Vec3(0.0, 1.0, 0.0);  // the floor rises under it
  const ContactImpulse<3> result = frictionalImpulse<3>(K, u, n, 0.5, 1.0);
  CHECK(result.branch == ImpulseBranch::Immovable);
  CHECK(result.j == Vec3::Zero());
  spinner.applyImpulse(r, result.j);
  CHECK(spinner.angularVelocity.y() == 3.0);
}

TEST_CASE("a body pinned at its centre of mass slides with friction when K is singular (B3)") {
  // Translation locked, rotation free: K = r*^T I^{-1} r* is singular along r, the
  // sticking solve fails its pivot test, and the impulse slides along u_t, meeting the
  // normal target (n^T K n > 0) without adding energy.
  RandomSource random(431);
  int sliding = 0;
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    testing::PairContact<3> c;
    c.a.inverseMass = 0.0;
    c.a.inertia = random.principalInertia<3>(1.0);
    c.a.inverseInertia = c.a.inertia.cwiseInverse();
    c.a.orientation = random.orientation<3>();
    c.a.setAngularVelocity(random.vector<3>(-2.0, 2.0));
    c.b = makeStaticBody<3>();
    c.ra = random.unitVector<3>();
    c.rb = c.ra;
    c.n = -c.ra.normalized();
    c.n = (c.n + 0.5 * testing::randomTangent<3>(random, c.n)).normalized();  // not along r
    const Vec3 u = c.u();
    if (!(u.dot(c.n) < -0.05 * u.norm())) continue;
    const Mat3 K = c.K();
    const double e = 0.5;
    const ContactImpulse<3> r = frictionalImpulse<3>(K, u, c.n, e, 0.5);
    REQUIRE(r.j.allFinite());
    CHECK(r.singularK);
    const auto after = c.after(r.j);
    CHECK(after.u().dot(c.n) == doctest::Approx(-e * u.dot(c.n)).epsilon(1e-12).scale(u.norm()));
    CHECK(after.kineticEnergy() <= c.kineticEnergy() * (1.0 + 1e-12));
    CHECK(after.a.velocity == Vec3::Zero());
    sliding += r.branch == ImpulseBranch::Sliding;
    if (r.branch == ImpulseBranch::Sliding && !r.frictionLowered) {
      CHECK(testing::tangentialPart<3>(r.j, c.n).norm() == doctest::Approx(0.5 * r.j.dot(c.n)));
    }
  }
  CHECK(sliding > 50);
}
// [test_locked_dofs]

// [test_mu_zero]
TEST_CASE_TEMPLATE("mu = 0 gives chapter 2's impulse bit for bit (B7)", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(441 + D);
  for (int trial = 0; trial < 500; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 3), random.logUniform(1e-3, 10.0));
    const double e = random.uniform(-1.0, 1.0);
    const ContactImpulse<D> with = frictionalImpulse<D>(c.K(), c.u(), c.n, e, 0.0);
    const ContactImpulse<D> without = frictionlessImpulse<D>(c.K(), c.u(), c.n, e);
    CHECK(sameBits<D>(with.j, without.j));
    CHECK(with.branch == without.branch);
    CHECK(with.restitution == without.restitution);
    CHECK(with.friction == 0.0);
    CHECK(!with.restitutionLowered);
  }
}

TEST_CASE_TEMPLATE("with mu = 0 a ball's tangential contact velocity is unchanged and e = 1 keeps its energy",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(451 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    // A ball: the contact offset is along the normal, so K n is along n.
    testing::PairContact<D> c;
    c.a = random.dynamicBody<D>();
    c.b = makeStaticBody<D>();
    c.n = random.unitVector<D>();
    c.ra = -random.uniform(0.1, 1.0) * c.n;
    c.rb = c.a.position + c.ra;
    c.setRelativeVelocity(Vec<D>(-random.uniform(0.1, 2.0) * c.n +
                                 random.uniform(0.0, 3.0) * testing::randomTangent<D>(random, c.n)));
    const Vec<D> u = c.u();
    const ContactImpulse<D> r = frictionalImpulse<D>(c.K(), u, c.n, 1.0, 0.0);
    const auto after = c.after(r.j);
    CHECK_EIGEN_NEAR(testing::tangentialPart<D>(after.u(), c.n), testing::tangentialPart<D>(u, c.n),
                     0.0, 1e-12 * u.norm());
    CHECK(after.kineticEnergy() == doctest::Approx(c.kineticEnergy()).epsilon(1e-12));
  }
}
// [test_mu_zero]

TEST_CASE_TEMPLATE("with e = 0 every branch leaves zero normal velocity (B10)", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(461 + D);
  std::array<int, 3> branches{};
  for (int trial = 0; trial < 600; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 3), random.logUniform(1e-3, 10.0));
    const double mu = std::array<double, 3>{0.0, 0.4, 2.0}[trial % 3];
    const Vec<D> u = c.u();
    const ContactImpulse<D> r = frictionalImpulse<D>(c.K(), u, c.n, 0.0, mu);
    CHECK(std::abs(c.after(r.j).u().dot(c.n)) <= 1e-12 * (u.norm() + (c.K() * r.j).norm()));
    branches[r.branch == ImpulseBranch::Frictionless ? 0 : r.branch == ImpulseBranch::Sticking ? 1 : 2]++;
  }
  CHECK(branches[0] > 100);
  CHECK(branches[1] > 100);
  CHECK(branches[2] > 100);
}

// [test_bad_input]
TEST_CASE("bad input is rejected with a message that names it") {
  const Mat3 K = Mat3::Identity();
  const Vec3 u(0.3, 0.0, -1.0), n = Vec3::UnitZ();
  const auto rejects = [&](const char* field, const auto& call) {
    CAPTURE(field);
    try {
      call();
      FAIL("no exception");
    } catch (const std::invalid_argument& error) {
      CHECK(std::string(error.what()).find(field) != std::string::npos);
    }
  };
  rejects("friction mu", [&] { frictionalImpulse<3>(K, u, n, 0.5, -0.1); });
  rejects("friction mu", [&] { frictionalImpulse<3>(K, u, n, 0.5, std::nan("")); });
  rejects("friction mu", [&] { frictionalImpulse<3>(K, u, n, 0.5, HUGE_VAL); });
  rejects("restitution e", [&] { frictionalImpulse<3>(K, u, n, 1.5, 0.5); });
  rejects("normal n", [&] { frictionalImpulse<3>(K, u, Vec3(0.0, 0.0, 2.0), 0.5, 0.5); });
  rejects("relative velocity u", [&] { frictionalImpulse<3>(K, Vec3(0.0, std::nan(""), -1.0), n, 0.5, 0.5); });
  rejects("collision matrix K", [&] { frictionalImpulse<3>(Mat3(HUGE_VAL * K), u, n, 0.5, 0.5); });
  FrictionSettings settings;
  settings.painleveMargin = 0.0;
  rejects("painleveMargin", [&] { frictionalImpulse<3>(K, u, n, 0.5, 0.5, settings); });
  settings = FrictionSettings{};
  settings.energyBisectionSteps = 0;
  rejects("energyBisectionSteps", [&] { frictionalImpulse<3>(K, u, n, 0.5, 0.5, settings); });
}
// [test_bad_input]

}  // TEST_SUITE
