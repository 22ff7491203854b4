// Chapter 8: rolling and spinning friction (Eqs. (8.6)-(8.8)). The impulse pair of one
// contact is checked against its defining equations on random bodies (T1), and a ball
// rolling on level ground against the closed-form deceleration of a rolling-resistance
// couple mu_r m g: about the contact point, (I + m R^2) dw/dt = -mu_r m g, so
//   a = mu_r g / (R (1 + k)),  k = I / (m R^2)   (5 mu_r g / (7 R) for a ball, 2 mu_r g / (3 R) for a disk).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "scenes.hpp"
#include "stackbook/impulse/rolling_friction.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// k = I / (m R^2) of a uniform ball (3D) or disk (2D).
constexpr double inertiaRatio(int d) { return d == 3 ? 0.4 : 0.5; }

/// Eq. (8.8): the deceleration of a ball rolling on level ground under rolling friction.
double rollingDeceleration(int d, double muRolling, double radius) {
  return muRolling * kG / (radius * (1.0 + inertiaRatio(d)));
}

template <int D>
double pairKineticEnergy(const RigidBody<D>& a, const RigidBody<D>& b) {
  return a.kineticEnergy() + b.kineticEnergy();
}

template <int D>
RigidBody<D> randomBody(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.2, 2.0);
  AngVec<D> inertia;
  for (int k = 0; k < inertia.size(); ++k) inertia[k] = pos(rng);
  if constexpr (D == 3) {
    // keep the triangle inequality of a real body: each moment below the sum of the others
    inertia = AngVec<D>::Constant(inertia.mean()) + 0.3 * (inertia - AngVec<D>::Constant(inertia.mean()));
  }
  RigidBody<D> b = makeDynamicBody<D>(pos(rng), inertia);
  for (int k = 0; k < D; ++k) b.velocity[k] = u(rng);
  if constexpr (D == 3) {
    // one draw per statement, in a fixed order (argument order is unspecified)
    const double z = u(rng), y = u(rng), x = u(rng), w = u(rng);
    b.orientation = Eigen::Quaterniond(w, x, y, z).normalized();
  } else {
    b.orientation = Eigen::Rotation2Dd(3.0 * u(rng));
  }
  AngVec<D> w;
  for (int k = 0; k < w.size(); ++k) w[k] = 3.0 * u(rng);
  b.setAngularVelocity(w);
  return b;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_rolling_algebra]
TEST_CASE_TEMPLATE("Rolling friction keeps the contact point still and brakes w by the bounded couple",
                   Dim, In2D, In3D) {
  // Random pairs (half of them with a static partner) whose contact point has just been
  // stopped by a sticking impulse with e = 0, as after the contact stage's last sweep.
  // Checked: Delta u = 0, w' = (1 - s) w with 0 <= s <= 1 (braked, never reversed), the
  // couple's rolling and spinning parts within mu_r j_n, s = 1 only when that bound is not
  // reached, and no gain of kinetic energy. Tier T1.
  constexpr int D = Dim::value;
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0), mu(0.01, 3.0);
  int limited = 0, stopped = 0;
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    RigidBody<D> a = randomBody<D>(rng);
    RigidBody<D> b = trial % 2 == 0 ? makeStaticBody<D>() : randomBody<D>(rng);
    Vec<D> n, ra, rb;
    for (int k = 0; k < D; ++k) {
      n[k] = u(rng);
      ra[k] = u(rng);
      rb[k] = u(rng);
    }
    n.normalize();
    // the sticking impulse of Eq. (3.2) with e = 0: u' = 0
    const Mat<D> K = pairCollisionMatrix<D>(a, ra, b, rb);
    const Vec<D> stick = K.ldlt().solve(-relativeVelocity<D>(a, ra, b, rb));
    applyPairImpulse<D>(a, ra, b, rb, stick);
    const double jn = std::abs(stick.dot(n)) + 0.01;  // any positive normal impulse
    const double muR = mu(rng);
    const AngVec<D> w0 = a.angularVelocity - b.angularVelocity;
    const double e0 = pairKineticEnergy<D>(a, b);

    const RollingFrictionImpulse<D> r = rollingFrictionImpulse<D>(a, ra, b, rb, n, jn, muR);
    REQUIRE_FALSE(r.singular);
    applyRollingFriction<D>(a, ra, b, rb, r);
    const AngVec<D> w1 = a.angularVelocity - b.angularVelocity;
    CHECK(relativeVelocity<D>(a, ra, b, rb).norm() <= 1e-12 * (1.0 + w0.norm()));
    CHECK(r.scale >= 0.0);
    CHECK(r.scale <= 1.0);
    CHECK((w1 - (1.0 - r.scale) * w0).norm() <= 1e-12 * (1.0 + w0.norm()));
    const double bound = muR * jn;
    const double roll = rollingPart<D>(r.tau, n).norm(), spin = spinningPart<D>(r.tau, n).norm();
    CHECK(roll <= bound * (1.0 + 1e-12));
    CHECK(spin <= bound * (1.0 + 1e-12));
    if (r.scale < 1.0) {
      ++limited;  // the bound acted: one of the two parts is on it
      CHECK(std::max(roll, spin) == doctest::Approx(bound).epsilon(1e-12));
    } else {
      ++stopped;
    }
    CHECK(pairKineticEnergy<D>(a, b) <= e0 * (1.0 + 1e-12));
  }
  CHECK(limited > 20);  // both outcomes occurred
  CHECK(stopped > 20);
}
// [test_rolling_algebra]

TEST_CASE_TEMPLATE("Rolling friction of a coefficient 0 or a non-rotating pair is exactly nothing",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  std::mt19937 rng(3);
  RigidBody<D> a = randomBody<D>(rng);
  const RigidBody<D> b = makeStaticBody<D>();
  const Vec<D> n = up<D>(), ra = -0.5 * up<D>(), rb = Vec<D>::Zero();
  CHECK(rollingFrictionImpulse<D>(a, ra, b, rb, n, 1.0, 0.0).isZero());
  CHECK(rollingFrictionImpulse<D>(a, ra, b, rb, n, 0.0, 0.1).isZero());
  a.setAngularVelocity(AngVec<D>::Zero());
  CHECK(rollingFrictionImpulse<D>(a, ra, b, rb, n, 1.0, 0.1).isZero());
}

TEST_CASE_TEMPLATE("A ball rolling on level ground keeps rolling without rolling friction", Dim,
                   In2D, In3D) {
  // Without rolling friction only the discretisation brakes it: the ring rolls as a
  // 2000-gon, and each step turns the contact by omega dt = 4e-3 rad, a plastic "vertex
  // switch" of the same kind. Both losses are second order in the angle per switch and
  // first order per unit time: ch08_rolling prints them (0.16 % of v0 per 0.1 s at
  // dt = 1e-3, 2D, 2000-gon). Rolling friction of 0.05 m costs 13 % in the same 0.1 s.
  constexpr int D = Dim::value;
  const double v0 = 1.0, radius = 0.25;
  const Material ground{0.0, 0.5, 0.1};
  RollingScene<D> scene = makeRollingBall<D>(radius, v0, ground, Material{0.0, 0.5, 0.0}, 1000);
  const StepCounters c = simulate<D>(scene.world, StepSettings{}, 0.1);
  CHECK(c.effects.rollingFriction == false);  // the ball's mu_r = 0 makes the pair's 0
  CHECK(scene.speed() > 0.995 * v0);
  CHECK(scene.slip() < 1e-3);
  CHECK(c.contact.rollingImpulses == 0);
}

// [test_rolling_deceleration]
TEST_CASE_TEMPLATE("A ball rolling on level ground decelerates at mu_r g / (R (1 + k))", Dim, In2D,
                   In3D) {
  // Per step the contact stage's normal impulses add up to m g dt (they remove gravity's
  // approach), each allows a couple mu_r j_n, and none is enough to stop the rolling: so
  // the couple per step is mu_r m g dt and Eq. (8.8) holds step by step. The polygon's
  // The discretisation's own loss (test above) grows as v^2; from v0 = 0.5 it is a few
  // tenths of a percent of the speed change.
  constexpr int D = Dim::value;
  const double v0 = 0.5, radius = 0.25, muR = 0.05, seconds = 0.1;
  const double a = rollingDeceleration(D, muR, radius);
  const Material both{0.0, 0.5, muR};
  RollingScene<D> scene = makeRollingBall<D>(radius, v0, both, both, 1000);
  const StepCounters c = simulate<D>(scene.world, StepSettings{}, seconds);
  CHECK(c.effects.rollingFriction);
  CHECK(c.contact.rollingImpulses > 0);
  CHECK((v0 - scene.speed()) / seconds == within(a, 0.01));
  CHECK(scene.slip() < 1e-3);  // it still rolls
}
// [test_rolling_deceleration]

}  // TEST_SUITE

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

// [test_rolling_stop]
TEST_CASE_TEMPLATE("A rolling ball stops after v0^2 / (2 a) and stays stopped", Dim, In2D, In3D) {
  // Semi-implicit Euler at constant deceleration covers v0^2 / (2 a) - v0 dt / 2 + O(dt^2)
  // before the step in which it stops: the error is first order in dt.
  constexpr int D = Dim::value;
  const double v0 = 0.5, radius = 0.25, muR = 0.05;
  const double a = rollingDeceleration(D, muR, radius), distance = v0 * v0 / (2.0 * a);
  double error[2] = {0.0, 0.0};
  for (int halving = 0; halving < 2; ++halving) {
    StepSettings settings;
    settings.dt = 1e-3 / (1 << halving);
    const Material both{0.0, 0.5, muR};
    RollingScene<D> scene = makeRollingBall<D>(radius, v0, both, both, 4000);
    const Vec<D> start = scene.ball().position;
    double stoppedAt = -1.0, minSpeed = v0;
    long n = 0;
    simulate<D>(scene.world, settings, v0 / a + 0.1, [&](const World<D>&) {
      ++n;
      minSpeed = std::min(minSpeed, scene.speed());
      if (stoppedAt < 0.0 && scene.ball().velocity.norm() < 1e-9) {
        stoppedAt = static_cast<double>(n) * settings.dt;
      }
    });
    const double travelled = scene.ball().position[0] - start[0];
    error[halving] = std::abs(travelled - distance) / distance;
    CAPTURE(travelled);
    CHECK(travelled == within(distance, 0.01));
    REQUIRE(stoppedAt > 0.0);
    CHECK(stoppedAt == within(v0 / a, 0.01));
    CHECK(minSpeed > -1e-9);  // never rolls back
    CHECK(scene.ball().angularVelocity.norm() < 1e-9);
  }
  CAPTURE(error[0]);
  CAPTURE(error[1]);
  CHECK(error[0] > 1.5 * error[1]);
}
// [test_rolling_stop]

}  // TEST_SUITE
