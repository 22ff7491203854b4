// Chapter 8: validation cases A4 (tip or slide on an incline) and A10 (rolling without
// slipping down an incline), from the statics and dynamics of a rigid body on a plane:
//   A4: a box of half-width a and half-height b at rest on a slope tips iff tan(theta) > a/b
//       and slides iff tan(theta) > mu; the smaller threshold decides.
//   A10: a body with k = I / (m R^2) rolls without slipping iff mu >= tan(theta) k / (1 + k),
//        with a = g sin(theta) / (1 + k).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "scenes.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// A4's box (width 0.5, depth 0.5 in 3D, height 1, mass 1) resting on a slope; after
/// `seconds`, how far it slid and how far it turned relative to the slope.
template <int D>
struct TipResult {
  double slid = 0.0;    ///< metres down the slope (centre)
  double turned = 0.0;  ///< radians relative to the slope
  /// How far the downhill bottom edge had moved along the slope when the box had first
  /// turned by 0.05 rad (-1 if it never did): a box that tips pivots on that edge.
  double edgeMoveAtTip = -1.0;
};

template <int D>
TipResult<D> tipOrSlide(double thetaDeg, double mu, double seconds) {
  World<D> w;
  w.gravity = -kG * up<D>();
  const double theta = degrees(thetaDeg);
  const Material material{0.0, mu, 0.0};
  addSlab<D>(w, theta, material);
  const Vec<D> size = boxSize<D>(0.5, 1.0);
  AngVec<D> inertia;
  if constexpr (D == 2) {
    inertia[0] = (0.25 + 1.0) / 12.0;
  } else {
    inertia = Vec3((0.25 + 1.0) / 12.0, (0.25 + 1.0) / 12.0, 0.5 / 12.0);
  }
  RigidBody<D> box = makeDynamicBody<D>(1.0, inertia);
  const Orientation<D> q = tilt<D>(theta);
  box.orientation = q;
  box.position = 0.5 * (q * up<D>());
  box.syncAngularVelocity();
  const Vec<D> start = box.position, down = -(q * axis<D>(0));
  const int i = w.addBody(box, std::make_shared<BoxShape<D>>(makeBoxShape<D>(size)), material);
  Vec<D> edge = -0.5 * up<D>();  // body frame: the bottom edge on the downhill side
  edge[0] = -0.25;
  const Vec<D> edgeStart = start + q * edge;
  const auto turnedBy = [&q](const RigidBody<D>& b) {
    const Vec<D> axisNow = b.orientation * up<D>(), axisSlope = q * up<D>();
    return std::acos(std::clamp(axisNow.dot(axisSlope), -1.0, 1.0));
  };
  TipResult<D> r;
  simulate<D>(w, StepSettings{}, seconds, [&](const World<D>& world) {
    const RigidBody<D>& b = world.bodies[static_cast<std::size_t>(i)];
    if (r.edgeMoveAtTip < 0.0 && turnedBy(b) > 0.05) {
      r.edgeMoveAtTip = (b.position + b.orientation * edge - edgeStart).dot(down);
    }
  });
  const RigidBody<D>& b = w.bodies[static_cast<std::size_t>(i)];
  r.slid = (b.position - start).dot(down);
  r.turned = turnedBy(b);
  return r;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

// [test_a4]
TEST_CASE_TEMPLATE("A4: a box with a/b 0.5 stays at 25 and tips at 28 degrees with mu 0.8", Dim,
                   In2D, In3D) {
  // Tip angle atan(0.5) = 26.565 deg is below the slide angle atan(0.8) = 38.66 deg. Just
  // past it the torque about the downhill edge is m g (b sin - a cos) = 0.135 N m on the
  // edge moment 0.417 kg m^2: 0.16 rad after 1 s.
  constexpr int D = Dim::value;
  const TipResult<D> stays = tipOrSlide<D>(25.0, 0.8, 1.0);
  CHECK(std::abs(stays.slid) < 1e-4);
  CHECK(stays.turned < 1e-3);
  const TipResult<D> tips = tipOrSlide<D>(28.0, 0.8, 1.0);
  CHECK(tips.turned > 0.05);
  REQUIRE(tips.edgeMoveAtTip >= 0.0);
  CHECK(tips.edgeMoveAtTip < 1e-3);  // it pivots on its edge rather than sliding
}

TEST_CASE_TEMPLATE("A4: the same box stays at 15 and slides without tipping at 18 degrees with mu 0.3",
                   Dim, In2D, In3D) {
  // Slide angle atan(0.3) = 16.70 deg is below the tip angle; sliding at 18 deg has
  // a = g (sin - mu cos) = 0.232 m/s^2: 0.116 m in 1 s.
  constexpr int D = Dim::value;
  const TipResult<D> stays = tipOrSlide<D>(15.0, 0.3, 1.0);
  CHECK(std::abs(stays.slid) < 1e-4);
  CHECK(stays.turned < 1e-3);
  const TipResult<D> slides = tipOrSlide<D>(18.0, 0.3, 1.0);
  const double a = kG * (std::sin(degrees(18.0)) - 0.3 * std::cos(degrees(18.0)));
  CHECK(slides.slid == within(0.5 * a, 0.02));
  CHECK(slides.turned < 1e-3);
}
// [test_a4]

// [test_a10]
TEST_CASE_TEMPLATE("A10: a ball rolls down a 30 degree incline with a = g sin / (1 + k) and no slip",
                   Dim, In2D, In3D) {
  // Sphere k = 2/5: a = 3.5036 m/s^2, mu_min = 0.1650; disk k = 1/2: a = 3.2700, mu_min
  // 0.1925 (catalogue case A10). mu = 0.5 is above both. The ring of 2000 samples lies in
  // the rolling plane (scenes.hpp), so contact is that of a 2000-gon.
  constexpr int D = Dim::value;
  // The slip is measured after every step. At a switch from one ring vertex to the next
  // the ball can leave the ground for a step, in which gravity adds g sin(theta) dt to v
  // and nothing to omega: a step's slip is bounded by that, and the mean must be small.
  const double theta = degrees(30.0), radius = 0.25, k = D == 3 ? 0.4 : 0.5, seconds = 0.5;
  const double a = kG * std::sin(theta) / (1.0 + k);
  REQUIRE(a == within(D == 3 ? 3.5036 : 3.2700, 1e-4));
  World<D> w;
  w.gravity = -kG * up<D>();
  const Material material{0.0, 0.5, 0.0};
  addSlab<D>(w, theta, material);
  const Orientation<D> q = tilt<D>(theta);
  const Vec<D> normal = q * up<D>(), down = -(q * axis<D>(0));
  RigidBody<D> b = ball<D>(radius);
  b.orientation = q;  // a ring vertex points along -normal
  b.position = radius * normal;
  b.syncAngularVelocity();
  const int i = w.addBody(b, rollingBallShape<D>(radius, 2000), material);
  const auto slipOf = [&](const RigidBody<D>& body) {
    return std::abs(body.velocity.dot(down) - radius * body.angularVelocity.norm());  // |v - omega R|
  };
  double maxSlip = 0.0, sumSlip = 0.0;
  long steps = 0;
  const StepCounters c = simulate<D>(w, StepSettings{}, seconds, [&](const World<D>& world) {
    const double slip = slipOf(world.bodies[static_cast<std::size_t>(i)]);
    maxSlip = std::max(maxSlip, slip);
    sumSlip += slip;
    ++steps;
  });
  const RigidBody<D>& f = w.bodies[static_cast<std::size_t>(i)];
  const double v = f.velocity.dot(down);
  CHECK(v / seconds == within(a, 0.01));
  CAPTURE(maxSlip);
  CHECK(sumSlip / static_cast<double>(steps) < 1e-3);
  CHECK(maxSlip <= kG * std::sin(theta) * 1e-3 * 1.05);
  // The ramp's early sweeps remove only k/N of the approach but ask for all of the
  // tangential velocity, so some of their trials leave the cone and slide; the last
  // sweep (e = 0) sticks. What matters is that the ball ends each step rolling.
  CHECK(c.contact.sticking > 0);
}
// [test_a10]

}  // TEST_SUITE
