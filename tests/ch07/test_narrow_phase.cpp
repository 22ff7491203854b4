// Chapter 7: the narrow phase (samples against phi, both ways), the deepest approaching
// sample, what vertex sampling misses, and the cost counters.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "stackbook/body/integrate.hpp"
#include "stackbook/collision/narrow_phase.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"
#include "support/tilt.hpp"
#include "test_shapes.hpp"

using namespace stackbook;
using stackbook::testing::boxShape;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;
using stackbook::testing::tilt;

namespace {

/// The unit vector along axis k.
template <int D>
Vec<D> unit(int k) {
  return Vec<D>::Unit(k);
}

/// Half extents with `side` along every axis but the last, `up` along the last (up) axis.
template <int D>
Vec<D> flatHalfExtents(double side, double up) {
  Vec<D> h = Vec<D>::Constant(side);
  h[D - 1] = up;
  return h;
}

/// Ground: a static box 10 wide, 1 thick, whose top face is the plane up = 0; and a unit
/// box (corner samples only) whose bottom face is at up = -overlap. The whole scene is
/// turned by `sceneTurn` about the origin, so "up" is the ground's rotated up axis.
template <int D>
struct BoxOnGround {
  BoxShape<D> groundShape = boxShape<D>(flatHalfExtents<D>(5.0, 0.5));
  BoxShape<D> cubeShape = boxShape<D>(Vec<D>::Constant(0.5));
  RigidBody<D> ground = makeStaticBody<D>();
  RigidBody<D> box = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0 / 6.0));
  Orientation<D> turn;

  BoxOnGround(double overlap, const Orientation<D>& sceneTurn) : turn(sceneTurn) {
    ground.position = turn * Vec<D>(-0.5 * unit<D>(D - 1));
    ground.orientation = turn;
    box.position = turn * Vec<D>((0.5 - overlap) * unit<D>(D - 1));
    box.orientation = turn;
  }
  Vec<D> up() const { return turn * unit<D>(D - 1); }
  /// {box, ground} or {ground, box}.
  std::vector<CollisionBody<D>> views(bool boxFirst) const {
    if (boxFirst) return {collisionBody<D>(box, cubeShape), collisionBody<D>(ground, groundShape)};
    return {collisionBody<D>(ground, groundShape), collisionBody<D>(box, cubeShape)};
  }
};

template <int D>
Orientation<D> someTurn() {
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(0.3);
  } else {
    return Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3(1.0, 2.0, 3.0).normalized()));
  }
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("separated bodies give no broad-phase pair and no interference sample", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  {
    const BoxOnGround<D> scene(-0.01, identityOrientation<D>());  // 0.01 above the ground
    const std::vector<CollisionBody<D>> bodies = scene.views(true);
    CHECK(sweepAndPrune<D>(bodies).empty());
    CHECK(pairInterference<D>(bodies, {0, 1}).empty());
  }
  {
    // Turned, the world boxes (axis-aligned) overlap although the bodies do not: the
    // broad phase reports the pair and the narrow phase finds nothing, without a single
    // phi query, because each body-frame box test already sees the gap.
    const BoxOnGround<D> scene(-0.01, someTurn<D>());
    const std::vector<CollisionBody<D>> bodies = scene.views(true);
    CHECK(sweepAndPrune<D>(bodies) == std::vector<BodyPair>{{0, 1}});
    DetectionCounters counters;
    CHECK(pairInterference<D>(bodies, {0, 1}, {}, &counters).empty());
    CHECK(counters.phiQueries == 0);
  }
}

// [test_box_on_ground]
TEST_CASE_TEMPLATE("a box resting on the ground with overlap d gives its bottom corners at depth -d",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  for (const double d : {1e-3, 0.01, 0.1}) {
    CAPTURE(d);
    const BoxOnGround<D> scene(d, someTurn<D>());
    const std::vector<CollisionBody<D>> bodies = scene.views(true);  // 0 = box, 1 = ground
    const std::vector<InterferenceSample<D>> samples = pairInterference<D>(bodies, {0, 1});
    REQUIRE(samples.size() == std::size_t{1} << (D - 1));  // 2 corners in 2D, 4 in 3D
    for (const InterferenceSample<D>& s : samples) {
      CHECK(s.owner == 0);
      CHECK(s.other == 1);
      const Vec<D> corner = scene.cubeShape.surfaceSamples()[s.sampleIndex];
      CHECK(corner[D - 1] == -0.5);  // a bottom corner
      CHECK(std::abs(s.depth + d) <= 1e-12);
      CHECK_EIGEN_NEAR(s.normal, scene.up(), 0.0, 1e-12);  // the ground's up vector
      CHECK_EIGEN_NEAR(s.point, Vec<D>(scene.box.position + scene.turn * corner), 0.0, 1e-12);
    }
  }
}
// [test_box_on_ground]

TEST_CASE_TEMPLATE("the same contact found with the bodies in the other order gives the same samples",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const double d = 0.01;
  const BoxOnGround<D> scene(d, someTurn<D>());
  const std::vector<CollisionBody<D>> boxFirst = scene.views(true);
  const std::vector<CollisionBody<D>> groundFirst = scene.views(false);
  const std::vector<InterferenceSample<D>> a = pairInterference<D>(boxFirst, {0, 1});
  const std::vector<InterferenceSample<D>> b = pairInterference<D>(groundFirst, {0, 1});
  REQUIRE(a.size() == b.size());
  REQUIRE(b.size() == std::size_t{1} << (D - 1));
  for (std::size_t k = 0; k < a.size(); ++k) {
    CHECK(b[k].owner == 1);  // still the box: the owner is whoever's sample it is
    CHECK(b[k].other == 0);
    CHECK(b[k].sampleIndex == a[k].sampleIndex);
    CHECK(std::abs(b[k].depth + d) <= 1e-12);
    CHECK_EIGEN_NEAR(b[k].normal, scene.up(), 0.0, 1e-12);
    CHECK_EIGEN_NEAR(b[k].point, a[k].point, 0.0, 1e-15);
  }
}

// [test_predicted_pose]
TEST_CASE_TEMPLATE("a view at the predicted pose finds the overlap the step is about to make", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  // The cube hovers 0.01 above the ground, falling at 1 m/s under gravity. GBF tests it
  // where the step would take it, x' = x + dt (v + dt g) (chapter 5's predictPose), and
  // judges approach with the current velocity.
  const double gap = 0.01, dt = 0.02, g = -9.81, v = -1.0;
  BoxOnGround<D> scene(-gap, someTurn<D>());
  scene.box.velocity = v * scene.up();
  const ExternalLoads<D> loads = gravityLoads<D>(Vec<D>(g * scene.up()));
  const std::vector<CollisionBody<D>> now = scene.views(true);
  CHECK(pairInterference<D>(now, {0, 1}).empty());
  const std::vector<CollisionBody<D>> ahead = {
      collisionBodyAt<D>(scene.box, scene.cubeShape, predictPose<D>(scene.box, dt, loads)),
      now[1]};
  const std::vector<InterferenceSample<D>> samples = pairInterference<D>(ahead, {0, 1});
  REQUIRE(samples.size() == std::size_t{1} << (D - 1));
  const double depth = gap + dt * (v + dt * g);  // the predicted bottom face, below 0
  for (const InterferenceSample<D>& s : samples) {
    CHECK(std::abs(s.depth - depth) <= 1e-12);
    CHECK(std::abs(normalRelativeVelocity<D>(s, ahead) - v) <= 1e-12);  // current v, not v + dt g
  }
}
// [test_predicted_pose]

// [test_both_directions]
TEST_CASE_TEMPLATE("a corner pushed into a face is found only by testing the samples of both bodies",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const double d = 0.02;
  // Body 0: a big static box whose top face is up = 0. Body 1: a small box standing on a
  // corner, pressed d into that face. The big box's samples (its corners) are all far
  // from the small box, and no face has samples in its interior.
  const BoxShape<D> bigShape = boxShape<D>(flatHalfExtents<D>(2.0, 0.5));
  const BoxShape<D> smallShape = boxShape<D>(Vec<D>::Constant(0.25));
  Orientation<D> cornerDown;  // turns the corner (-1, ..., -1)/sqrt(D) to point straight down
  if constexpr (D == 2) {
    cornerDown = Eigen::Rotation2Dd(M_PI / 4);
  } else {
    cornerDown = Eigen::Quaterniond::FromTwoVectors(Vec3(-1.0, -1.0, -1.0), Vec3(0.0, 0.0, -1.0));
  }
  const double reach = 0.25 * std::sqrt(double(D));  // centre-to-corner distance
  const RigidBody<D> big = makeStaticBody<D>(Vec<D>(-0.5 * unit<D>(D - 1)));
  const RigidBody<D> small =
      makeStaticBody<D>(Vec<D>((reach - d) * unit<D>(D - 1)), cornerDown);
  const std::vector<CollisionBody<D>> bodies = {collisionBody<D>(big, bigShape),
                                                collisionBody<D>(small, smallShape)};
  std::vector<InterferenceSample<D>> bigInSmall, smallInBig;
  appendSamplesInside<D>(bodies[0], 0, bodies[1], 1, bigInSmall);
  appendSamplesInside<D>(bodies[1], 1, bodies[0], 0, smallInBig);
  CHECK(bigInSmall.empty());  // one direction alone misses the contact
  REQUIRE(smallInBig.size() == 1);
  CHECK(std::abs(smallInBig[0].depth + d) <= 1e-12);
  CHECK_EIGEN_NEAR(smallInBig[0].normal, unit<D>(D - 1), 0.0, 1e-12);
  CHECK_EIGEN_NEAR(smallInBig[0].point, Vec<D>(-d * unit<D>(D - 1)), 0.0, 1e-12);
  // The pair query runs both directions, so it finds the corner whichever body is first.
  CHECK(pairInterference<D>(bodies, {0, 1}).size() == 1);
}
// [test_both_directions]

// [test_edge_on_edge]
TEST_CASE_TEMPLATE("crossed boxes touching edge on edge are missed by corner samples and found by "
                   "subdivided faces",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Two bars, half length L and half thickness a, crossed at 90 degrees. 2D: a plus sign,
  // the edges of each bar cutting through the other, no corner inside. 3D: each bar
  // turned 45 degrees about its axis so that an edge faces the other; the lower bar's top
  // edge (along x, at up = 0) and the upper bar's bottom edge (along y, at up = -d) cross
  // at (xi, 0) and overlap by d there. The crossing is off the bars' centres by (xi, eta).
  const double L = 1.0, a = 0.25, d = 0.05, xi = 0.237, eta = 0.311;
  Vec<D> half = Vec<D>::Constant(a);
  half[0] = L;
  RigidBody<D> lower = makeStaticBody<D>(), upper = makeStaticBody<D>();
  if constexpr (D == 2) {
    upper.position = Vec2(xi, eta);
    upper.orientation = Eigen::Rotation2Dd(M_PI / 2);
  } else {
    const Eigen::Quaterniond edgeUp(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()));
    lower.position = Vec3(0.0, 0.0, -a * std::sqrt(2.0));
    lower.orientation = edgeUp;
    upper.position = Vec3(xi, eta, a * std::sqrt(2.0) - d);
    upper.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())) * edgeUp;
  }
  // The deepest point of either bar's surface inside the other, in closed form:
  // 2D: -a (the middle of an edge, a from both sides of the other bar);
  // 3D: -d / sqrt(2) (the crossing point, d below the other edge, whose faces are at 45 degrees).
  const double exact = D == 2 ? -a : -d / std::sqrt(2.0);
  const double reach = D == 2 ? a : d;  // an edge sample within `reach` of the crossing is inside
  const double slope = D == 2 ? 1.0 : 1.0 / std::sqrt(2.0);
  for (const int n : {1, 2, 4, 8, 16, 32, 64}) {
    CAPTURE(n);
    const BoxShape<D> bar = boxShape<D>(half, n);  // n segments per edge: spacing h = 2L/n along the bars
    const std::vector<CollisionBody<D>> bodies = {collisionBody<D>(lower, bar),
                                                  collisionBody<D>(upper, bar)};
    const std::vector<InterferenceSample<D>> samples = pairInterference<D>(bodies, {0, 1});
    // Edge samples sit at x_k = -L + 2Lk/n along each bar; the nearest to the crossing is
    // delta away (xi along the lower bar, -eta along the upper one).
    double delta = 1e300;
    for (int k = 0; k <= n; ++k) {
      const double xk = -L + 2.0 * L * k / n;
      delta = std::min({delta, std::abs(xk - xi), std::abs(xk + eta)});
    }
    if (delta >= reach) {
      CHECK(samples.empty());
      continue;
    }
    REQUIRE_FALSE(samples.empty());
    double deepest = 0.0;
    for (const InterferenceSample<D>& s : samples) deepest = std::min(deepest, s.depth);
    CHECK(std::abs(deepest - (-slope * (reach - delta))) <= 1e-12);
    CHECK(deepest - exact <= slope * L / n + 1e-12);  // error at most slope * h/2
  }
}
// [test_edge_on_edge]

// [test_deepest_approaching]
TEST_CASE_TEMPLATE("the deepest approaching sample ignores deeper samples that separate", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  // A box 1 x 0.5 tilted by theta on a static ground (top face up = 0): its left bottom
  // corner is 0.15 deep, its right bottom corner 0.15 - sin(theta) deep.
  const double theta = 0.1;
  const BoxShape<D> groundShape = boxShape<D>(flatHalfExtents<D>(5.0, 0.5));
  Vec<D> h = Vec<D>::Constant(0.25);
  h[0] = 0.5;
  const BoxShape<D> plankShape = boxShape<D>(h);
  const RigidBody<D> ground = makeStaticBody<D>(Vec<D>(-0.5 * unit<D>(D - 1)));
  RigidBody<D> box = makeDynamicBody<D>(1.0, AngVec<D>::Constant(0.1));
  box.orientation = tilt<D>(theta);
  const double height = -0.15 + 0.5 * std::sin(theta) + 0.25 * std::cos(theta);
  box.position = height * unit<D>(D - 1);
  const double leftDepth = -0.15, rightDepth = -0.15 + std::sin(theta);
  // Horizontal offsets of the bottom corners from the centre: the up-velocity of a
  // corner turning at w in the tilt plane is w times that offset.
  const double leftArm = -0.5 * std::cos(theta) + 0.25 * std::sin(theta);
  const double rightArm = 0.5 * std::cos(theta) + 0.25 * std::sin(theta);
  AngVec<D> spinAxis = AngVec<D>::Zero();  // the tilt plane's rotation axis
  spinAxis[D == 2 ? 0 : 1] = D == 2 ? 1.0 : -1.0;

  struct Case {
    double w, up;          // angular speed in the tilt plane, upward speed
    int expected;          // -1 none, 0 left corner, 1 right corner
  };
  for (const Case c : {Case{1.0, 0.0, 0}, Case{-1.0, 0.0, 1}, Case{0.0, 0.1, -1},
                       Case{0.0, 0.0, -1}, Case{0.2, -0.5, 0}}) {
    CAPTURE(c.w);
    CAPTURE(c.up);
    box.velocity = c.up * unit<D>(D - 1);
    box.setAngularVelocity(c.w * spinAxis);
    const std::vector<CollisionBody<D>> bodies = {collisionBody<D>(box, plankShape),
                                                  collisionBody<D>(ground, groundShape)};
    const std::vector<InterferenceSample<D>> samples = pairInterference<D>(bodies, {0, 1});
    REQUIRE(samples.size() == std::size_t{1} << (D - 1));
    const std::optional<InterferenceSample<D>> best = deepestApproachingSample<D>(samples, bodies);
    if (c.expected < 0) {
      CHECK_FALSE(best.has_value());
      continue;
    }
    REQUIRE(best.has_value());
    const bool left = plankShape.surfaceSamples()[best->sampleIndex][0] < 0.0;
    CHECK(left == (c.expected == 0));
    CHECK(std::abs(best->depth - (left ? leftDepth : rightDepth)) <= 1e-12);
    CHECK(std::abs(normalRelativeVelocity<D>(*best, bodies) -
                   (c.up + c.w * (left ? leftArm : rightArm))) <= 1e-12);
  }
}
// [test_deepest_approaching]

TEST_CASE_TEMPLATE("a penetrated body moving into a resting owner counts as approaching", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  // A resting box (the owner) 0.01 into a big box that moves up into it or down away.
  const BoxOnGround<D> scene(0.01, identityOrientation<D>());
  RigidBody<D> mover = makeDynamicBody<D>(10.0, AngVec<D>::Constant(1.0));
  mover.position = scene.ground.position;
  const RigidBody<D> resting = scene.box;
  for (const double v : {1.0, -1.0}) {
    mover.velocity = v * unit<D>(D - 1);
    const std::vector<CollisionBody<D>> bodies = {collisionBody<D>(resting, scene.cubeShape),
                                                  collisionBody<D>(mover, scene.groundShape)};
    const std::vector<InterferenceSample<D>> samples = pairInterference<D>(bodies, {0, 1});
    REQUIRE(samples.size() == std::size_t{1} << (D - 1));
    for (const InterferenceSample<D>& s : samples) {
      CHECK(normalRelativeVelocity<D>(s, bodies) == doctest::Approx(-v).epsilon(1e-12));
    }
    CHECK(deepestApproachingSample<D>(samples, bodies).has_value() == (v > 0.0));
  }
}

// [test_counters]
TEST_CASE_TEMPLATE("the counters count the work of detecting a box on the ground exactly", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  const std::int64_t corners = 1 << D;
  const BoxOnGround<D> scene(0.01, someTurn<D>());
  const std::vector<CollisionBody<D>> bodies = scene.views(true);
  DetectionCounters counters;
  const std::vector<PairInterference<D>> found = detectInterference<D>(bodies, {}, &counters);
  REQUIRE(found.size() == 1);
  CHECK(found[0].samples.size() == static_cast<std::size_t>(corners / 2));
  CHECK(counters.pairsTested == 1);
  CHECK(counters.pairsOverlapping == 1);
  CHECK(counters.pairQueries == 1);
  CHECK(counters.samplesTransformed == 2 * corners);  // every corner of both boxes
  // The box's top corners are above the ground's box; the ground's corners are 5 away.
  CHECK(counters.samplesCulled == corners / 2 + corners);
  CHECK(counters.phiQueries == corners / 2);  // only the bottom corners reach phi
  CHECK(counters.interferenceSamples == corners / 2);
  // Without the box test every sample costs a phi query, and the answer is the same.
  DetectionCounters unculled;
  DetectionSettings noCull;
  noCull.narrow.cullByBounds = false;
  CHECK(detectInterference<D>(bodies, noCull, &unculled)[0].samples.size() == found[0].samples.size());
  CHECK(unculled.samplesCulled == 0);
  CHECK(unculled.phiQueries == 2 * corners);
  CHECK(unculled.interferenceSamples == corners / 2);
  // Counts add up across calls, print, and reset.
  DetectionCounters total = counters;
  total += unculled;
  CHECK(total.phiQueries == corners / 2 + 2 * corners);
  CHECK(counters.summary().find("tested 1, overlapping 1") != std::string::npos);
  total.reset();
  CHECK(total == DetectionCounters{});
}
// [test_counters]

TEST_CASE_TEMPLATE("skipping far runs of samples finds the samples the plain loop finds, bit for bit, for turned "
                   "bodies", Dim, In2D, In3D) {
  // Two densely sampled boxes (a lattice of samples on every face: more than four runs, so
  // the runs are used) at random turned poses that overlap: with and without culling, the
  // same samples in the same order with the same bits, and culling transforms fewer.
  constexpr int D = Dim::value;
  const BoxShape<D> a = boxShape<D>(Vec<D>(flatHalfExtents<D>(1.0, 0.25)), 12);
  const BoxShape<D> b = boxShape<D>(Vec<D>::Constant(0.5), 12);
  REQUIRE(a.surfaceSamples().size() > 32);
  RandomSource rng(707);
  DetectionSettings noCull;
  noCull.narrow.cullByBounds = false;
  std::int64_t culledByRuns = 0;
  int overlapping = 0;
  for (int trial = 0; trial < 200; ++trial) {
    RigidBody<D> bodyA = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
    RigidBody<D> bodyB = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
    bodyA.position = rng.vector<D>(-0.2, 0.2);
    bodyA.orientation = rng.orientation<D>();
    bodyB.position = rng.vector<D>(-1.2, 1.2);
    bodyB.orientation = rng.orientation<D>();
    const std::vector<CollisionBody<D>> bodies{collisionBody<D>(bodyA, a), collisionBody<D>(bodyB, b)};
    DetectionCounters culled, plain;
    const std::vector<PairInterference<D>> withRuns = detectInterference<D>(bodies, {}, &culled);
    const std::vector<PairInterference<D>> without = detectInterference<D>(bodies, noCull, &plain);
    REQUIRE(withRuns.size() == without.size());
    for (std::size_t p = 0; p < withRuns.size(); ++p) {
      ++overlapping;
      const auto& x = withRuns[p].samples;
      const auto& y = without[p].samples;
      REQUIRE(x.size() == y.size());
      for (std::size_t k = 0; k < x.size(); ++k) {
        CHECK(x[k].sampleIndex == y[k].sampleIndex);
        CHECK(x[k].owner == y[k].owner);
        CHECK(x[k].depth == y[k].depth);  // the same operations: the same bits
        CHECK(x[k].point == y[k].point);
        CHECK(x[k].normal == y[k].normal);
      }
    }
    CHECK(culled.interferenceSamples == plain.interferenceSamples);
    CHECK(culled.samplesTransformed == plain.samplesTransformed);  // a skipped sample counts as culled
    culledByRuns += culled.samplesCulled;
  }
  CHECK(overlapping > 50);     // most trials overlap, so the comparison is not empty
  CHECK(culledByRuns > 0);
}

TEST_CASE_TEMPLATE("equal boxes sampled at their corners only miss a square stack's contact, two pieces per edge "
                   "find it", Dim, In2D, In3D) {
  // A unit box sunk 0.01 into an equal box below it, squarely: each corner of either box lies
  // on a side face of the other, where phi = 0 is not inside (Eq. (7.1)), so corner samples
  // find nothing (the scene format's warning for "samples": 1); with the edges cut in two the
  // face midpoints lie inside and the contact is found, 0.01 deep.
  constexpr int D = Dim::value;
  const Vec<D> half = Vec<D>::Constant(0.5);
  RigidBody<D> lower = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0 / 6.0));
  RigidBody<D> upper = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0 / 6.0));
  upper.position = Vec<D>(0.99 * unit<D>(D - 1));
  for (const int pieces : {1, 2}) {
    const BoxShape<D> box = boxShape<D>(half, pieces);
    const std::vector<CollisionBody<D>> bodies{collisionBody<D>(lower, box), collisionBody<D>(upper, box)};
    const std::vector<InterferenceSample<D>> found = pairInterference<D>(bodies, BodyPair{0, 1});
    if (pieces == 1) {
      CHECK(found.empty());
    } else {
      REQUIRE_FALSE(found.empty());
      double deepest = 0.0;
      for (const InterferenceSample<D>& s : found) deepest = std::min(deepest, s.depth);
      CHECK(deepest == doctest::Approx(-0.01).epsilon(1e-12));
    }
  }
}

TEST_CASE_TEMPLATE("the narrow phase rejects missing shapes bad margins bad poses and bad pairs", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  const BoxOnGround<D> scene(0.01, someTurn<D>());
  std::vector<CollisionBody<D>> bodies = scene.views(true);
  CHECK_THROWS_AS(pairInterference<D>(bodies, {0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(pairInterference<D>(bodies, {0, 2}), std::invalid_argument);
  NarrowPhaseSettings bad;
  bad.cullMargin = -1.0;
  CHECK_THROWS_WITH_AS(pairInterference<D>(bodies, {0, 1}, bad), doctest::Contains("cullMargin"),
                       std::invalid_argument);
  std::vector<CollisionBody<D>> nanPose = bodies;
  nanPose[1].pose.position[0] = std::nan("");
  CHECK_THROWS_WITH_AS(pairInterference<D>(nanPose, {0, 1}), doctest::Contains("body 1"),
                       std::invalid_argument);
  bodies[1].shape = nullptr;
  CHECK_THROWS_WITH_AS(pairInterference<D>(bodies, {0, 1}), doctest::Contains("no Shape"),
                       std::invalid_argument);
}

namespace {

/// True when two matrices hold the same bits (a -0.0 is not a +0.0 here).
template <int D>
bool rotationBitsEqual(const Mat<D>& a, const Mat<D>& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * D * D) == 0;
}

/// An orientation from three numbers: the angle in 2D, a normalised quaternion in 3D.
template <int D>
Orientation<D> orientationFrom(double a, double b, double c) {
  if constexpr (D == 2) {
    (void)b;
    (void)c;
    return Eigen::Rotation2Dd(a);
  } else {
    return Eigen::Quaterniond(std::cos(a), b, c, 0.5 * a).normalized();
  }
}

}  // namespace

// [test_rotation_cache]
TEST_CASE_TEMPLATE("the rotation matrix of a view is the one its pose gives bit for bit however the pose was set",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const RigidBody<D> body = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0 / 6.0));
  const BoxShape<D> shape = boxShape<D>(Vec<D>::Constant(0.5));
  RandomSource random(71);
  for (int trial = 0; trial < 200; ++trial) {
    const double scale = trial < 100 ? 3.0 : 1e4;  // angles of many turns too
    Pose<D> kept{random.vector<D>(-1.0, 1.0),
                 orientationFrom<D>(random.uniform(-scale, scale), random.uniform(-1, 1), random.uniform(-1, 1))};
    CollisionBody<D> view = collisionBodyAt<D>(body, shape, kept);
    CHECK(rotationBitsEqual<D>(view.poseRotation(), rotationMatrix<D>(kept.orientation)));
    // Moved by setPose(): the new matrix is kept.
    const Pose<D> moved{kept.position,
                        orientationFrom<D>(random.uniform(-scale, scale), random.uniform(-1, 1), random.uniform(-1, 1))};
    view.setPose(moved);
    CHECK(rotationBitsEqual<D>(view.poseRotation(), rotationMatrix<D>(moved.orientation)));
    // Moved by writing the pose directly: the kept matrix is stale and must not be used.
    view.pose = kept;
    CHECK(rotationBitsEqual<D>(view.poseRotation(), rotationMatrix<D>(kept.orientation)));
  }
  if constexpr (D == 2) {
    // +0 and -0 compare equal as numbers but give matrices with different bits (the sign of
    // sin 0), so a cache keyed by == would hand back the wrong one.
    const Mat<2> plus = rotationMatrix<2>(Eigen::Rotation2Dd(0.0));
    const Mat<2> minus = rotationMatrix<2>(Eigen::Rotation2Dd(-0.0));
    REQUIRE_FALSE(rotationBitsEqual<2>(plus, minus));
    CollisionBody<2> view = collisionBodyAt<2>(body, shape, Pose<2>{Vec<2>::Zero(), Eigen::Rotation2Dd(0.0)});
    view.pose.orientation = Eigen::Rotation2Dd(-0.0);
    CHECK(rotationBitsEqual<2>(view.poseRotation(), minus));
    view.setPose(Pose<2>{Vec<2>::Zero(), Eigen::Rotation2Dd(-0.0)});
    view.pose.orientation = Eigen::Rotation2Dd(0.0);
    CHECK(rotationBitsEqual<2>(view.poseRotation(), plus));
  }
}
// [test_rotation_cache]

}  // TEST_SUITE
