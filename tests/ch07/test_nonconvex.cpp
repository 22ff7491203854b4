// Chapter 7: nonconvex bodies. The interference test needs only phi < 0, so it works for
// a ring threaded on a peg and a ball lying in a cup, where a convex hull reports contact
// that is not there. Exact (analytic) phi first, then chapter 6's signed-distance grids.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "stackbook/collision/narrow_phase.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "test_shapes.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

constexpr double kRingRadius = 1.0;  // centre circle of the tube
constexpr double kTubeRadius = 0.2;  // so the hole has radius 0.8
constexpr double kPegHalf = 0.1;     // the peg's half width

/// A peg: a box of half width 0.1 (3D: 3 long, along z) whose edges are cut into 8
/// pieces, so that samples lie on every face: the middle of each side and, in 3D, a
/// ring of 32 samples in the plane z = 0 of the ring.
template <int D>
BoxShape<D> makePeg() {
  Vec<D> h = Vec<D>::Constant(kPegHalf);
  if constexpr (D == 3) h[2] = 1.5;
  return boxShape<D>(h, 8);
}

/// Interference of a ring (or its hull) centred at `offset` along x with a static peg at
/// the origin; body 0 is the ring, body 1 the peg.
template <int D>
std::vector<InterferenceSample<D>> ringOnPeg(const Shape<D>& ring, const Shape<D>& peg,
                                             double offset) {
  const RigidBody<D> pegBody = makeStaticBody<D>();
  const RigidBody<D> ringBody = makeStaticBody<D>(Vec<D>(offset * Vec<D>::Unit(0)));
  const std::vector<CollisionBody<D>> bodies = {collisionBody<D>(ringBody, ring),
                                                collisionBody<D>(pegBody, peg)};
  return pairInterference<D>(bodies, {0, 1});
}

template <int D>
double deepestOf(const std::vector<InterferenceSample<D>>& samples) {
  double deepest = 0.0;
  for (const InterferenceSample<D>& s : samples) deepest = std::min(deepest, s.depth);
  return deepest;
}

/// The hole (radius 0.8) first reaches the peg's corners, sqrt(2) 0.1 from the axis, when
/// the ring is off centre by sqrt(0.8^2 - 0.1^2) - 0.1 = 0.6937.
const double kFirstTouch = std::sqrt(0.8 * 0.8 - kPegHalf * kPegHalf) - kPegHalf;

/// Chapter 6's grid of the ring mesh, coarse (16 cells across) so that the test is fast;
/// built once per dimension.
template <int D>
const GridShape<D>& gridRing() {
  static const GridShape<D> ring = [] {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = 16;
    return GridShape<D>(ringBoundary<D>(kRingRadius, kTubeRadius, 48, 24), "ring", settings);
  }();
  return ring;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_ring_on_peg]
TEST_CASE_TEMPLATE("a ring threaded on a peg touches it only where the hole meets the peg", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  const TorusShape<D> ring = ringShape<D>(kRingRadius, kTubeRadius, 48);
  const HullShape<D, RingHullSdf<D>> hull({kRingRadius, kTubeRadius}, ring.surfaceSamples());
  const BoxShape<D> peg = makePeg<D>();
  for (const double offset : {0.0, 0.3, 0.6, kFirstTouch - 1e-3}) {
    CAPTURE(offset);
    CHECK(ringOnPeg<D>(ring, peg, offset).empty());  // the peg passes through the hole
    // The convex hull fills the hole: it reports the peg deep inside.
    const std::vector<InterferenceSample<D>> hullSamples = ringOnPeg<D>(hull, peg, offset);
    CHECK_FALSE(hullSamples.empty());
    CHECK(deepestOf<D>(hullSamples) < -0.19);
  }
  // Centred, the hull's answer is known in closed form. 3D: the 32 peg samples in the
  // ring's plane are 0.2 inside the hull's flat faces. 2D: all 32 peg samples are inside
  // the disk of radius 1.2, the deepest (mid-sides, 0.1 from the centre) by 1.1.
  const std::vector<InterferenceSample<D>> centred = ringOnPeg<D>(hull, peg, 0.0);
  CHECK(centred.size() == 32);
  CHECK(std::abs(deepestOf<D>(centred) - (D == 3 ? -0.2 : -1.1)) <= 1e-12);

  // Slid by 0.7 + d, the hole's edge is d inside the peg's side x = -0.1: the ring's
  // sample on the inner edge (angle pi, in the plane z = 0) is at depth -d exactly, with
  // the peg's normal -x; every sample found is at that side of the peg.
  const double d = 0.01;
  const std::vector<InterferenceSample<D>> touching = ringOnPeg<D>(ring, peg, 0.7 + d);
  REQUIRE_FALSE(touching.empty());
  int innerEdge = 0;
  for (const InterferenceSample<D>& s : touching) {
    CHECK(s.point[0] <= -kPegHalf + d + 1e-12);
    CHECK(s.point[0] >= -kPegHalf - 1e-12);
    if (s.owner == 0 && s.point.template tail<D - 1>().norm() < 1e-9) {
      ++innerEdge;
      CHECK(std::abs(s.depth + d) <= 1e-12);
      CHECK_EIGEN_NEAR(s.normal, Vec<D>(-Vec<D>::Unit(0)), 0.0, 1e-12);
    }
  }
  CHECK(innerEdge == 1);
}
// [test_ring_on_peg]

TEST_CASE_TEMPLATE("a ring with a grid signed distance threads on a peg as the exact ring does", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  const GridShape<D>& ring = gridRing<D>();
  const TorusSdf<D> exact(kRingRadius, kTubeRadius);
  const BoxShape<D> peg = makePeg<D>();
  // The grid's error near the surface, measured against the exact torus on 2000 points
  // within 0.1 of it (chapter 6's tools). It must be below the hole's clearance at 0.6.
  const std::vector<Vec<D>> band = sampleBand<D>(
      [&](const Vec<D>& x) { return exact.distance(x); }, exact.bounds().inflated(0.1), -0.1, 0.1,
      2000, 7);
  double eps = 0.0;
  for (const Vec<D>& x : band) eps = std::max(eps, std::abs(ring.signedDistance(x) - exact.distance(x)));
  CAPTURE(eps);
  const double clearanceAt06 = 0.8 - std::sqrt(0.7 * 0.7 + kPegHalf * kPegHalf);
  REQUIRE(eps < clearanceAt06);
  for (const double offset : {0.0, 0.3, 0.6}) {
    CAPTURE(offset);
    CHECK(ringOnPeg<D>(ring, peg, offset).empty());
  }
  // Touching by d = 0.05: the ring's own samples are mesh vertices, exactly on the torus,
  // tested against the peg's exact phi, so the inner-edge sample is at -d to round-off;
  // the peg's samples are tested against the grid, so their depths carry its error.
  const double d = 0.05;
  const std::vector<InterferenceSample<D>> touching = ringOnPeg<D>(ring, peg, 0.7 + d);
  REQUIRE_FALSE(touching.empty());
  bool innerEdge = false;
  for (const InterferenceSample<D>& s : touching) {
    if (s.owner == 0) {
      CHECK(s.point[0] <= -kPegHalf + d + 1e-12);
      if (s.point.template tail<D - 1>().norm() < 1e-9) {
        innerEdge = true;
        CHECK(std::abs(s.depth + d) <= 1e-12);
      }
    } else {
      const Vec<D> inRing = s.point - (0.7 + d) * Vec<D>::Unit(0);
      CHECK(std::abs(s.depth - exact.distance(inRing)) <= eps);
      CHECK(s.point[0] <= -kPegHalf + d + eps);  // where the tube can reach
    }
  }
  CHECK(innerEdge);
}

// [test_cup_and_ball]
TEST_CASE_TEMPLATE("a ball in a cup touches the bottom and not the walls while the hull swallows it",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Chapter 6's cup (U in 2D) with a grid phi: outer radius 1, height 1.5, wall 0.2,
  // bottom 0.3, centred on its box, so the inner floor is at up = -0.75 + 0.3. A ball of
  // radius 0.5 rests on the floor with overlap d, turned so that a sample points down.
  const CupDimensions dims{1.0, 1.5, 0.2, 0.3};
  SdfGridSettings coarse;
  coarse.cellsAcrossLargestExtent = 16;
  static const GridShape<D> cup(cupBoundary<D>(dims, 24, 0.1), "cup", coarse);
  const HullShape<D, CylinderSdf<D>> hull(CylinderSdf<D>(1.0, 0.75), cup.surfaceSamples());
  const double floor = -0.75 + 0.3, radius = 0.5, d = 0.02;
  const SphereShape<D> ball = ballShape<D>(radius, D == 2 ? 64 : 2);
  RigidBody<D> ballBody = makeStaticBody<D>();
  if constexpr (D == 2) {
    ballBody.orientation = Eigen::Rotation2Dd(-M_PI / 2);  // vertex (r, 0) points down
  } else {
    ballBody.orientation =
        Eigen::Quaterniond::FromTwoVectors(ball.surfaceSamples()[0], -Vec3::UnitZ());
  }
  ballBody.position = (floor + radius - d) * Vec<D>::Unit(D - 1);
  const RigidBody<D> cupBody = makeStaticBody<D>();
  const auto detect = [&](const Shape<D>& cupShape) {
    const std::vector<CollisionBody<D>> bodies = {collisionBody<D>(ballBody, ball),
                                                  collisionBody<D>(cupBody, cupShape)};
    return pairInterference<D>(bodies, {0, 1});
  };

  const std::vector<InterferenceSample<D>> samples = detect(cup);
  REQUIRE_FALSE(samples.empty());
  const double capRadius = std::sqrt(2.0 * radius * d);  // the ball's part below the floor
  int ballOwned = 0, cupOwned = 0;
  for (const InterferenceSample<D>& s : samples) {
    const double rho = s.point.template head<D - 1>().norm();
    CHECK(rho <= capRadius + 1e-12);  // at the bottom, nowhere near the walls at 0.8
    CHECK(s.point[D - 1] >= floor - d - 1e-12);
    CHECK(s.point[D - 1] <= floor + 1e-12);
    CHECK(s.depth >= -d - 1e-9);
    if (s.owner == 0) {
      ++ballOwned;
      CHECK_EIGEN_NEAR(s.normal, Vec<D>(Vec<D>::Unit(D - 1)), 0.0, 1e-9);  // the floor's up
    } else {
      ++cupOwned;  // floor samples inside the ball, with the ball's normal: down-ish
      CHECK(s.normal[D - 1] < -0.97);
    }
  }
  CHECK(ballOwned >= 1);
  CHECK(cupOwned >= 1);
  // The lowest ball sample is d below the floor. The grid is exact there: phi is linear
  // (the distance to the flat floor) at every node of the cells around it.
  CHECK(std::abs(deepestOf<D>(samples) + d) <= 1e-9);

  // The convex hull (the solid outer cylinder) has the whole ball inside, about 0.5 deep.
  const std::vector<InterferenceSample<D>> hullSamples = detect(hull);
  const auto ballInHull = std::count_if(hullSamples.begin(), hullSamples.end(),
                                        [](const InterferenceSample<D>& s) { return s.owner == 0; });
  CHECK(ballInHull == static_cast<long>(ball.surfaceSamples().size()));
  CHECK(deepestOf<D>(hullSamples) < -0.45);
}
// [test_cup_and_ball]

}  // TEST_SUITE
