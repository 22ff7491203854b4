// Chapter 3: the kinetic impulse and its slip direction, the Painleve configuration,
// the energy guard, and continuity across the stick/slide switch (Eqs. (3.4)-(3.10)).
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "ch03/friction_fixtures.hpp"
#include "ch03/impact_reference.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::Partner;
using stackbook::testing::RandomSource;

namespace {

/// The Painleve rod of case A21: theta = atan 2, u = (-1, -0.1), lower end leading.
testing::PairContact<2> painleveRod() { return testing::rodOnFloor(std::atan(2.0), Vec2(-1.0, -0.1)); }

/// The slip direction T a sliding impulse used, read back from j = j_n (n - mu T).
template <int D>
Vec<D> slipDirectionOf(const ContactImpulse<D>& r, const Vec<D>& n) {
  return -testing::tangentialPart<D>(r.j, n) / (r.friction * r.j.dot(n));
}

FrictionSettings withRule(SlipDirectionRule rule) {
  FrictionSettings s;
  s.slipDirection = rule;
  return s;
}

/// A corner of a 0.2 x 0.2 x 2 box (mass 1) at a random orientation, hitting a static
/// floor (normal +z) with a random velocity: the elongated body of hard case B9.
testing::PairContact<3> boxCornerOnFloor(RandomSource& random) {
  const double a = 0.2, L = 2.0;
  testing::PairContact<3> c;
  c.a = makeDynamicBody<3>(1.0, Vec3((a * a + L * L) / 12.0, (a * a + L * L) / 12.0, a * a / 6.0));
  c.a.orientation = random.orientation<3>();
  const Mat3 R = c.a.orientation.toRotationMatrix();
  double lowest = 1e9;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1 ? 0.5 : -0.5) * a, (corner & 2 ? 0.5 : -0.5) * a,
                 (corner & 4 ? 0.5 : -0.5) * L);
    const Vec3 r = R * p;
    if (r.z() < lowest) {
      lowest = r.z();
      c.ra = r;
    }
  }
  c.a.position = Vec3(0.0, 0.0, -lowest);
  c.b = makeStaticBody<3>();
  c.rb = c.a.position + c.ra;
  c.n = Vec3::UnitZ();
  c.a.velocity = random.vector<3>(-1.0, 1.0);
  c.a.velocity.z() = -std::abs(c.a.velocity.z()) - 0.1;
  c.a.setAngularVelocity(random.vector<3>(-2.0, 2.0));
  return c;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_painleve_rod_slides]
TEST_CASE("the Painleve rod at mu = 1 slides with denominator 0.4 and j_n = 0.25 (A21)") {
  const auto c = painleveRod();
  // theta = atan 2: cos = 1/sqrt 5, sin = 2/sqrt 5, r = -(cos, sin)/2, and with
  // K = delta/m + r*^T r* / I:  K = [1 + 3 sin^2, -3 sin cos; -3 sin cos, 1 + 3 cos^2].
  Mat2 expectedK;
  expectedK << 17.0 / 5.0, -6.0 / 5.0, -6.0 / 5.0, 8.0 / 5.0;
  const Mat2 K = c.K();
  CHECK_EIGEN_NEAR(K, expectedK, 1e-15);
  const Vec2 u = c.u();
  CHECK_EIGEN_NEAR(u, Vec2(-1.0, -0.1), 1e-15);
  // Sticking trial (e = 0): K^{-1} = [2/5 3/10; 3/10 17/20], j* = K^{-1}(1, 0.1) = (0.43, 0.385).
  CHECK_EIGEN_NEAR(testing::stickingReference<2>(K, u, c.n, 0.0), Vec2(0.43, 0.385), 1e-15);
  // 0.43 > 1.0 * 0.385: outside the cone. T = u_t/|u_t| = (-1, 0); the denominator of
  // Eq. (3.5) is 8/5 - 1.0 * 6/5 = 0.4 and j_n = 0.1 / 0.4 = 0.25.
  const ContactImpulse<2> r = frictionalImpulse<2>(K, u, c.n, 0.0, 1.0);
  CHECK(r.branch == ImpulseBranch::Sliding);
  CHECK(!r.frictionLowered);
  CHECK(!r.slipFromImpulse);
  CHECK(c.n.dot(K * Vec2(c.n - 1.0 * Vec2(-1.0, 0.0))) == doctest::Approx(0.4).epsilon(1e-15));
  CHECK_EIGEN_NEAR(r.j, Vec2(0.25, 0.25), 1e-15);
  // On the bodies: the end stops falling and keeps sliding at 0.45, losing 0.19375 J.
  const auto after = c.after(r.j);
  CHECK_EIGEN_NEAR(after.u(), Vec2(-0.45, 0.0), 0.0, 1e-15);
  CHECK(after.kineticEnergy() - c.kineticEnergy() == doctest::Approx(-0.19375).epsilon(1e-13));
}
// [test_painleve_rod_slides]

// [test_painleve_rod_sticks]
TEST_CASE("the Painleve rod at mu = 1.5 sticks where the raw kinetic formula would pull (A21)") {
  const auto c = painleveRod();
  const Mat2 K = c.K();
  const Vec2 u = c.u(), T(-1.0, 0.0);
  // The notes' kinetic impulse at mu = 1.5: denominator 8/5 - 1.5 * 6/5 = -0.2, j_n = -0.5.
  const double rawDenominator = c.n.dot(K * Vec2(c.n - 1.5 * T));
  CHECK(rawDenominator == doctest::Approx(-0.2).epsilon(1e-14));
  CHECK(testing::kineticNormalReference<2>(K, u, c.n, T, 0.0, 1.5) ==
        doctest::Approx(-0.5).epsilon(1e-14));
  // The chapter never applies it: sticking is tried first, and 0.43 <= 1.5 * 0.385.
  const ContactImpulse<2> r = frictionalImpulse<2>(K, u, c.n, 0.0, 1.5);
  CHECK(r.branch == ImpulseBranch::Sticking);
  CHECK_EIGEN_NEAR(r.j, Vec2(0.43, 0.385), 1e-15);
  CHECK_EIGEN_NEAR(c.after(r.j).u(), Vec2(0.0, 0.0), 0.0, 1e-15);
  // And the kinetic formula itself refuses to pull: a non-positive denominator gives 0.
  CHECK(detail::slidingImpulse<2>(K, u.dot(c.n), c.n, T, 0.0, 1.5) == Vec2::Zero());
}
// [test_painleve_rod_sticks]

TEST_CASE("the Painleve rod is never pulled and never gains energy for any mu") {
  const auto c = painleveRod();
  const Mat2 K = c.K();
  const Vec2 u = c.u();
  // The switch is at mu = 0.43 / 0.385 = 86/77; the rod sticks above it.
  for (int step = 0; step <= 300; ++step) {
    const double mu = 0.01 * step;
    CAPTURE(mu);
    const ContactImpulse<2> r = frictionalImpulse<2>(K, u, c.n, 0.0, mu);
    CHECK(r.j.dot(c.n) > 0.0);
    CHECK(std::abs(c.after(r.j).u().dot(c.n)) <= 1e-15);
    CHECK(impulseEnergyChange<2>(K, u, r.j) < 0.0);
    CHECK((r.branch == ImpulseBranch::Sticking) == (mu >= 86.0 / 77.0));
  }
}

// [test_sliding_promise]
TEST_CASE_TEMPLATE("a sliding impulse meets the normal target and lies on the friction cone", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(351 + D);
  int sliding = 0, fromVelocity = 0, fromImpact = 0;
  for (int trial = 0; trial < 900; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 3), random.logUniform(1e-3, 10.0));
    const double e = (trial % 3) * 0.5, mu = random.uniform(0.05, 1.0);
    const Vec<D> u = c.u();
    const ContactImpulse<D> r = frictionalImpulse<D>(c.K(), u, c.n, e, mu);
    if (r.branch != ImpulseBranch::Sliding) continue;
    ++sliding;
    const double jn = r.j.dot(c.n);
    CHECK(jn > 0.0);
    // Normal target of Eq. (3.5), measured on the bodies.
    CHECK(c.after(r.j).u().dot(c.n) == doctest::Approx(-e * u.dot(c.n)).epsilon(1e-12).scale(u.norm()));
    // On the cone with the mu actually used, which is mu unless a guard lowered it.
    CHECK(testing::tangentialPart<D>(r.j, c.n).norm() == doctest::Approx(r.friction * jn).epsilon(1e-12));
    CHECK(r.friction <= mu);
    if (!r.frictionLowered) CHECK(r.friction == mu);
    // Friction opposes the slip direction of Eq. (3.4): the impact's (u_t = 0, a reversed
    // slip, or the Painleve fallback), or the blend of u_t's and the impact's.
    if (r.friction > 1e-9) {
      const Vec<D> T = slipDirectionOf<D>(r, c.n);
      const double eTrial = std::min(e, testing::eMaxReference<D>(c.K(), u, c.n));
      const Vec<D> jStar = testing::stickingReference<D>(c.K(), u, c.n, eTrial);
      const Vec<D> impact = -testing::tangentialPart<D>(jStar, c.n).normalized();
      if (r.slipFromImpulse) {
        CHECK_EIGEN_NEAR(T, impact, 1e-9);
        ++fromImpact;
      } else {
        CHECK_EIGEN_NEAR(T, testing::blendedSlipReference<D>(c.K(), u, c.n, e, eTrial, mu), 1e-9);
        CHECK(impact.dot(testing::tangentialPart<D>(u, c.n)) > 0.0);  // not reversed
        ++fromVelocity;
      }
    }
  }
  CHECK(sliding > 300);
  CHECK(fromVelocity > 100);
  CHECK(fromImpact > 20);
}
// [test_sliding_promise]

// [test_positive_denominator]
TEST_CASE_TEMPLATE("with the impact's slip direction the kinetic denominator is positive", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  RandomSource random(361 + D);
  const FrictionSettings impact = withRule(SlipDirectionRule::StickingImpulse);
  int sliding = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 3), random.logUniform(1e-3, 10.0));
    const double mu = random.logUniform(0.01, 10.0);
    const Mat<D> K = c.K();
    const Vec<D> u = c.u();
    const ContactImpulse<D> r = frictionalImpulse<D>(K, u, c.n, 0.0, mu, impact);
    if (r.branch != ImpulseBranch::Sliding) continue;
    ++sliding;
    // Eq. (3.6): n - mu T is a positive combination of n and j*, so the denominator is
    // n^T K n (1 - mu a/b) + mu (n^T K j*) / b > 0, for the mu asked for.
    const Vec<D> jStar = testing::stickingReference<D>(K, u, c.n, 0.0);
    const Vec<D> T = -testing::tangentialPart<D>(jStar, c.n).normalized();
    CHECK(c.n.dot(K * Vec<D>(c.n - mu * T)) > 0.0);
    CHECK(r.slipFromImpulse);
    // Hence the Painleve guard never has to lower mu here; only the energy guard may.
    if (r.frictionLowered) {
      CHECK(std::abs(impulseEnergyChange<D>(K, u, r.j)) <= 1e-12 * c.kineticEnergy() + 1e-15);
    }
  }
  CHECK(sliding > 500);
}
// [test_positive_denominator]

// [test_painleve_3d]
TEST_CASE("a 3D Painleve configuration never gets a pulling impulse (B9)") {
  // Search for elongated-box corner hits where sticking is rejected and the notes'
  // kinetic denominator along u_t is not positive: n^T K (n - mu u_t/|u_t|) <= 0.
  RandomSource random(371);
  int found = 0;
  for (int trial = 0; trial < 40000 && found < 4; ++trial) {
    const auto c = boxCornerOnFloor(random);
    const double mu = random.uniform(2.5, 5.0);
    const Mat3 K = c.K();
    const Vec3 u = c.u(), n = c.n;
    if (!(u.dot(n) < 0.0)) continue;  // the corner must be approaching the floor
    const Vec3 jStar = testing::stickingReference<3>(K, u, n, 0.0);
    const double jn = jStar.dot(n);
    if (jn > 0.0 && testing::tangentialPart<3>(jStar, n).norm() <= mu * jn) continue;
    const Vec3 slip = testing::tangentialPart<3>(u, n).normalized();
    const double rawDenominator = n.dot(K * Vec3(n - mu * slip));
    if (rawDenominator > 0.0) continue;
    ++found;
    CAPTURE(trial);
    CAPTURE(rawDenominator);
    for (const SlipDirectionRule rule :
         {SlipDirectionRule::Blended, SlipDirectionRule::RelativeVelocity,
          SlipDirectionRule::StickingImpulse}) {
      for (const double e : {0.0, 0.5}) {
        const ContactImpulse<3> r = frictionalImpulse<3>(K, u, n, e, mu, withRule(rule));
        REQUIRE(r.j.allFinite());
        CHECK(r.j.dot(n) > 0.0);
        const auto after = c.after(r.j);
        CHECK(after.u().dot(n) == doctest::Approx(-r.restitution * u.dot(n)).epsilon(1e-12));
        CHECK(after.kineticEnergy() <= c.kineticEnergy() * (1.0 + 1e-12));
        // e = 0 is the case searched for: it slides. Along u_t the denominator is not
        // positive, so the velocity rule falls back to the impact's direction T*, whose
        // denominator is (Eq. (3.6)); any other direction keeps the margin of Eq. (3.7).
        if (e == 0.0) CHECK(r.branch == ImpulseBranch::Sliding);
        if (r.branch != ImpulseBranch::Sliding) continue;
        if (rule == SlipDirectionRule::RelativeVelocity) CHECK(r.slipFromImpulse);
        const double denominator = -(1.0 + e) * u.dot(n) / r.j.dot(n);
        CHECK(denominator > 0.0);
        if (!r.slipFromImpulse) {
          CHECK(denominator >= FrictionSettings{}.painleveMargin * n.dot(K * n) * (1.0 - 1e-12));
        }
      }
    }
  }
  CHECK(found == 4);
}
// [test_painleve_3d]

// [test_tilted_rod]
TEST_CASE("a tilted rod landing straight down slides the way the impact pushes it (B8)") {
  // u_t = 0, so the notes' T = u_t/|u_t| is 0/0. The rod at 60 degrees needs
  // mu >= |K_tn| / K_tt = 3 sin cos / (1 + 3 sin^2) = 0.3997 to stick; with mu = 0.1 it slides.
  for (const double e : {0.0, 0.5}) {
    CAPTURE(e);
    const auto c = testing::rodOnFloor(M_PI / 3.0, Vec2(0.0, -1.0));
    const Mat2 K = c.K();
    const Vec2 u = c.u();
    CHECK(testing::tangentialPart<2>(u, c.n).norm() == 0.0);
    const ContactImpulse<2> r = frictionalImpulse<2>(K, u, c.n, e, 0.1);
    REQUIRE(r.j.allFinite());
    CHECK(r.branch == ImpulseBranch::Sliding);
    CHECK(r.slipFromImpulse);
    // A normal impulse alone would move the foot along (K n)_t = -3 sin cos < 0: outward.
    // Friction opposes that slip: T = (-1, 0) and j_t = +mu j_n.
    CHECK_EIGEN_NEAR(slipDirectionOf<2>(r, c.n), Vec2(-1.0, 0.0), 1e-15);
    const auto after = c.after(r.j);
    CHECK(after.u().dot(c.n) == doctest::Approx(-e * u.dot(c.n)).epsilon(1e-14));
    CHECK(after.u().x() < 0.0);  // the foot does slide outward, along T
    // Friction took slip away: less than the frictionless impulse would leave.
    const auto frictionless = c.after(frictionlessImpulse<2>(K, u, c.n, e).j);
    CHECK(std::abs(after.u().x()) < std::abs(frictionless.u().x()));
    // Exactly what the impact integrated through time gives (one sliding phase).
    const auto reference = testing::integrateImpact2D(K, u, c.n, e, 0.1);
    CHECK(reference.history == testing::SlipHistory::Slid);
    CHECK_EIGEN_NEAR(r.j, reference.j, 1e-14);
  }
  // The same rod in 3D: the impulse stays in the rod's vertical plane.
  const auto c3 = testing::rodOnFloor3(M_PI / 3.0, Vec3(0.0, 0.0, -1.0));
  const ContactImpulse<3> r3 = frictionalImpulse<3>(c3.K(), c3.u(), c3.n, 0.0, 0.1);
  CHECK(r3.branch == ImpulseBranch::Sliding);
  CHECK(r3.slipFromImpulse);
  CHECK(std::abs(r3.j.y()) <= 1e-15);
  CHECK_EIGEN_NEAR(slipDirectionOf<3>(r3, c3.n), Vec3(-1.0, 0.0, 0.0), 1e-14);
  CHECK(std::abs(c3.after(r3.j).u().z()) <= 1e-14);
}
// [test_tilted_rod]

// [test_routh_2d]
TEST_CASE("in 2D the impulse equals the impact integrated through time unless the slip reverses") {
  RandomSource random(381);
  int slid = 0, stuck = 0, reversed = 0, jammed = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    CAPTURE(trial);
    const double ratio = trial % 5 == 0 ? 0.0 : random.logUniform(1e-3, 10.0);
    const auto c = testing::randomContact<2>(random, Partner(trial % 3), ratio);
    const double e = random.uniform(0.0, 1.0), mu = random.uniform(0.05, 1.5);
    const Mat2 K = c.K();
    const Vec2 u = c.u();
    const auto reference = testing::integrateImpact2D(K, u, c.n, e, mu);
    const ContactImpulse<2> r = frictionalImpulse<2>(K, u, c.n, e, mu);
    if (reference.history == testing::SlipHistory::Jammed) {
      // Sliding along u_t would make u_n fall (Painleve): the rigid contact stops slipping
      // at once, and in 2D the sticking trial is then inside the cone (see the chapter).
      CHECK(r.branch == ImpulseBranch::Sticking);
      ++jammed;
      continue;
    }
    if (reference.history == testing::SlipHistory::Reversed) {
      ++reversed;  // one-shot impulse with one slip direction: differs by design
      continue;
    }
    if (r.restitutionLowered || r.frictionLowered) continue;  // a guard changed the answer
    CHECK_EIGEN_NEAR(r.j, reference.j, 1e-11);
    CHECK((r.branch == ImpulseBranch::Sticking) == (reference.history == testing::SlipHistory::Stuck));
    slid += reference.history == testing::SlipHistory::Slid;
    stuck += reference.history == testing::SlipHistory::Stuck;
  }
  MESSAGE("Routh 2D: slid ", slid, ", stuck ", stuck, ", reversed ", reversed, ", jammed ", jammed);
  CHECK(slid > 300);
  CHECK(stuck > 300);
  CHECK(reversed > 10);
  CHECK(jammed > 0);
}
// [test_routh_2d]

// [test_fast_slide]
TEST_CASE("a fast slide's friction turns to -u_t as the approach speed vanishes") {
  // A unit cube (m = 1, I = 1/6) sliding along x at 1 m/s on its corner (-1/2, -1/2, -1/2)
  // over a static floor, approaching at eps: the contact stage of a time step sees
  // eps = g dt. K is anisotropic in the tangent plane, so -j*_t is not along -u_t. The
  // friction of Eq. (3.4) turns to GBF's direction linearly in eps; along T* it does not.
  testing::PairContact<3> c;
  c.a = makeDynamicBody<3>(1.0, Vec3::Constant(1.0 / 6.0));
  c.b = makeStaticBody<3>();
  c.ra = Vec3(-0.5, -0.5, -0.5);
  c.rb = c.a.position + c.ra;
  c.n = Vec3::UnitZ();
  double previous = 0.0;
  for (const double eps : {1e-2, 1e-3, 1e-4}) {
    CAPTURE(eps);
    c.setRelativeVelocity(Vec3(1.0, 0.0, -eps));
    const ContactImpulse<3> r = frictionalImpulse<3>(c.K(), c.u(), c.n, 0.0, 0.3);
    const ContactImpulse<3> impact =
        frictionalImpulse<3>(c.K(), c.u(), c.n, 0.0, 0.3, withRule(SlipDirectionRule::StickingImpulse));
    REQUIRE(r.branch == ImpulseBranch::Sliding);
    REQUIRE(impact.branch == ImpulseBranch::Sliding);
    const auto angleToX = [&](const ContactImpulse<3>& x) {
      const Vec3 T = slipDirectionOf<3>(x, c.n);
      return std::atan2(T.cross(Vec3::UnitX()).norm(), T.x());
    };
    CHECK(angleToX(r) <= 0.1 * eps);
    if (previous > 0.0) CHECK(angleToX(r) <= 0.2 * previous);  // linear in eps
    previous = angleToX(r);
    CHECK(angleToX(impact) >= 0.3);  // T* stays about 30 degrees off
  }
}
// [test_fast_slide]

// [test_continuity_2d]
TEST_CASE("in 2D the impulse is continuous across the stick slide switch") {
  RandomSource random(391);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<2>(random, Partner(trial % 3), random.logUniform(1e-3, 10.0));
    const double e = 0.3;
    const Mat2 K = c.K();
    const Vec2 u = c.u();
    if (testing::eMaxReference<2>(K, u, c.n) <= e) continue;  // e lowered: see Pitfalls
    const Vec2 jStar = testing::stickingReference<2>(K, u, c.n, e);
    if (!(jStar.dot(c.n) > 0.0)) continue;
    const double threshold = testing::tangentialPart<2>(jStar, c.n).norm() / jStar.dot(c.n);
    double jump[2] = {0.0, 0.0};
    bool guarded = false;
    for (int k = 0; k < 2; ++k) {
      const double delta = k == 0 ? 1e-5 : 1e-8;
      const ContactImpulse<2> below = frictionalImpulse<2>(K, u, c.n, e, threshold * (1.0 - delta));
      const ContactImpulse<2> above = frictionalImpulse<2>(K, u, c.n, e, threshold * (1.0 + delta));
      REQUIRE(below.branch == ImpulseBranch::Sliding);
      REQUIRE(above.branch == ImpulseBranch::Sticking);
      guarded = guarded || below.frictionLowered;
      jump[k] = (below.j - above.j).norm() / jStar.norm();
    }
    if (guarded) continue;
    // The jump shrinks in proportion to delta: continuity, not a step.
    CHECK(jump[1] <= 2e-3 * jump[0] + 1e-12);
    CHECK(jump[1] <= 1e-5);
    ++checked;
  }
  CHECK(checked > 200);
}
// [test_continuity_2d]

// [test_continuity_3d]
TEST_CASE("in 3D the impulse is continuous across the switch except with the velocity rule") {
  RandomSource random(392);
  int checked = 0, velocityRuleJumps = 0;
  for (int trial = 0; trial < 400; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<3>(random, Partner(trial % 3), random.logUniform(1e-2, 10.0));
    const double e = 0.3;
    const Mat3 K = c.K();
    const Vec3 u = c.u();
    if (testing::eMaxReference<3>(K, u, c.n) <= e) continue;
    const Vec3 jStar = testing::stickingReference<3>(K, u, c.n, e);
    if (!(jStar.dot(c.n) > 0.0)) continue;
    const double threshold = testing::tangentialPart<3>(jStar, c.n).norm() / jStar.dot(c.n);
    const ContactImpulse<3> above = frictionalImpulse<3>(K, u, c.n, e, threshold * (1.0 + 1e-8));
    REQUIRE(above.branch == ImpulseBranch::Sticking);
    // Relative jumps |j(mu_c (1 - delta)) - j*| / |j*| at delta = 1e-5 and 1e-8.
    double blendedJump[2], impactJump[2];
    bool guarded = false;
    ContactImpulse<3> velocity;
    for (int k = 0; k < 2; ++k) {
      const double below = threshold * (1.0 - (k == 0 ? 1e-5 : 1e-8));
      const ContactImpulse<3> blended = frictionalImpulse<3>(K, u, c.n, e, below);
      const ContactImpulse<3> impact =
          frictionalImpulse<3>(K, u, c.n, e, below, withRule(SlipDirectionRule::StickingImpulse));
      velocity = frictionalImpulse<3>(K, u, c.n, e, below, withRule(SlipDirectionRule::RelativeVelocity));
      guarded = guarded || blended.frictionLowered || impact.frictionLowered || velocity.frictionLowered;
      blendedJump[k] = (blended.j - above.j).norm() / jStar.norm();
      impactJump[k] = (impact.j - above.j).norm() / jStar.norm();
    }
    if (guarded) continue;
    // Both end at j* (Eq. (3.6), and rho -> 1 in Eq. (3.4)): the jump shrinks with delta.
    CHECK(blendedJump[1] <= 2e-3 * blendedJump[0] + 1e-12);
    CHECK(impactJump[1] <= 2e-3 * impactJump[0] + 1e-12);
    CHECK(blendedJump[1] <= 1e-4);
    CHECK(impactJump[1] <= 1e-5);
    // The velocity rule slides along u_t, which j*_t is not parallel to unless K is
    // isotropic in the tangent plane: a jump of order |j*|.
    velocityRuleJumps += (velocity.j - above.j).norm() > 1e-3 * jStar.norm();
    ++checked;
  }
  CHECK(checked > 150);
  CHECK(velocityRuleJumps > checked / 2);
}
// [test_continuity_3d]

TEST_CASE("at the threshold mu the kinetic impulse along the impact's slip equals the sticking impulse") {
  // Eq. (3.5) with T = -j*_t/|j*_t| and mu = |j*_t| / j*_n gives k = j* / j*_n, and the
  // normal target then fixes j_n = j*_n: j = j* (the algebra of the continuity claim).
  RandomSource random(393);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<3>(random, Partner(trial % 3), random.logUniform(1e-2, 10.0));
    const Mat3 K = c.K();
    const Vec3 u = c.u();
    const Vec3 jStar = testing::stickingReference<3>(K, u, c.n, 0.0);
    if (!(jStar.dot(c.n) > 0.0)) continue;
    const Vec3 jt = testing::tangentialPart<3>(jStar, c.n);
    const double threshold = jt.norm() / jStar.dot(c.n);
    const Vec3 kinetic = detail::slidingImpulse<3>(K, u.dot(c.n), c.n, Vec3(-jt.normalized()), 0.0, threshold);
    CHECK_EIGEN_NEAR(kinetic, jStar, 1e-11);
  }
}

TEST_CASE("the velocity rule jumps at the switch when the impact reverses a 2D slip") {
  // The rod of B11 at 45 degrees with a small inward slip u = (0.05, -1): the impact
  // pushes the foot outward far more than 0.05, so sticking needs friction along +u_t
  // (j*_t . u_t > 0). GBF's T = u_t/|u_t| then slides on the wrong edge of the cone.
  const auto c = testing::rodOnFloor(0.25 * M_PI, Vec2(0.05, -1.0));
  const Mat2 K = c.K();
  const Vec2 u = c.u();
  const Vec2 jStar = testing::stickingReference<2>(K, u, c.n, 0.0);
  REQUIRE(jStar.dot(c.n) > 0.0);
  CHECK(testing::tangentialPart<2>(jStar, c.n).dot(testing::tangentialPart<2>(u, c.n)) > 0.0);
  const double threshold = std::abs(jStar.x()) / jStar.y();
  const double below = threshold * (1.0 - 1e-9);
  const ContactImpulse<2> velocity =
      frictionalImpulse<2>(K, u, c.n, 0.0, below, withRule(SlipDirectionRule::RelativeVelocity));
  const ContactImpulse<2> standard = frictionalImpulse<2>(K, u, c.n, 0.0, below);
  CHECK(!velocity.slipFromImpulse);
  CHECK(standard.slipFromImpulse);
  CHECK((standard.j - jStar).norm() <= 1e-6 * jStar.norm());
  CHECK((velocity.j - jStar).norm() >= 0.5 * jStar.norm());
}

TEST_CASE_TEMPLATE("a friction coefficient of 1e10 gives finite impulses that never pull or add energy",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(395 + D);
  int sticking = 0;
  for (int trial = 0; trial < 600; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 3), random.logUniform(1e-3, 10.0));
    const double e = (trial % 3) * 0.5;
    const Vec<D> u = c.u();
    const ContactImpulse<D> r = frictionalImpulse<D>(c.K(), u, c.n, e, 1e10);
    REQUIRE(r.j.allFinite());
    CHECK(r.j.dot(c.n) >= 0.0);
    CHECK(c.after(r.j).u().dot(c.n) ==
          doctest::Approx(-r.restitution * u.dot(c.n)).epsilon(1e-12).scale(u.norm()));
    CHECK(impulseEnergyChange<D>(c.K(), u, r.j) <= 1e-12 * c.kineticEnergy() + 1e-15);
    sticking += r.branch == ImpulseBranch::Sticking;
  }
  CHECK(sticking > 500);
}

// [test_energy_guard]
TEST_CASE_TEMPLATE("with e = 1 and friction no impulse adds energy", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(397 + D);
  int lowered = 0, guarded = 0, checkedRoots = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    CAPTURE(trial);
    const auto c = testing::randomContact<D>(random, Partner(trial % 2 == 0 ? 0 : 2),
                                             random.logUniform(1e-3, 3.0));
    const double mu = std::array<double, 3>{0.3, 1.0, 3.0}[trial % 3];
    const Mat<D> K = c.K();
    const Vec<D> u = c.u();
    const ContactImpulse<D> r = frictionalImpulse<D>(K, u, c.n, 1.0, mu);
    // Measured on the bodies: kinetic energy after <= before.
    const double before = c.kineticEnergy();
    CHECK(c.after(r.j).kineticEnergy() <= before + 1e-12 * before);
    lowered += r.restitutionLowered;
    if (r.branch == ImpulseBranch::Frictionless) {
      // The guard found that any friction along T would add energy (mu lowered to 0).
      CHECK(r.frictionLowered);
      ++guarded;
    }
    if (r.branch != ImpulseBranch::Sliding || !r.frictionLowered) continue;
    ++guarded;
    CHECK(std::abs(impulseEnergyChange<D>(K, u, r.j)) <= 1e-12 * before + 1e-15);
    if (r.friction < 1e-6 * mu) continue;  // lowered to ~0: T cannot be read back from j
    // The energy guard's mu is the smallest positive root of Eq. (3.10),
    // Q(mu) = A mu^2 + B mu + C with A = 2 K_nT u_T + c K_TT, B = -2 (K_nn u_T - e u_n K_nT),
    // C = K_nn (1 - e) u_n and c = -(1 + e) u_n: here e = 1, so C = 0 and mu = -B / A.
    const Vec<D> T = slipDirectionOf<D>(r, c.n);
    const double un = u.dot(c.n), uT = u.dot(T), cc = -2.0 * un;
    const double Knn = c.n.dot(K * c.n), KnT = c.n.dot(K * T), KTT = T.dot(K * T);
    const double A = 2.0 * KnT * uT + cc * KTT, B = -2.0 * (Knn * uT - un * KnT);
    if (A > 0.0 && B < 0.0 && std::abs(B) > 1e-6 * (std::abs(A) + Knn * std::abs(un))) {
      CHECK(r.friction == doctest::Approx(-B / A).epsilon(1e-9));
      ++checkedRoots;
    }
  }
  MESSAGE("e = 1 sweep ", D, "D: e lowered ", lowered, ", mu lowered ", guarded, ", roots checked ",
          checkedRoots);
  CHECK(lowered > 20);
  CHECK(guarded > 5);
  CHECK(checkedRoots > 3);
}
// [test_energy_guard]

}  // TEST_SUITE
