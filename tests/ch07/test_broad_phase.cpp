// Chapter 7: world bounding boxes and the broad phase (sweep and prune).
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "stackbook/collision/broad_phase.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"
#include "test_shapes.hpp"

using namespace stackbook;
using stackbook::testing::OffsetShape;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;

namespace {

/// The box around the 2^D transformed corners, visited one by one.
template <int D>
Aabb<D> boxOfTransformedCorners(const Aabb<D>& local, const Pose<D>& pose) {
  Aabb<D> box;
  for (int mask = 0; mask < (1 << D); ++mask) {
    Vec<D> corner;
    for (int i = 0; i < D; ++i) corner[i] = (mask >> i) & 1 ? local.upper[i] : local.lower[i];
    box.extend(pose.toWorld(corner));
  }
  return box;
}

/// n random proxies: centres in [-5, 5]^D, half extents in [0.05, 1.5], about one in
/// eight static.
template <int D>
std::vector<BroadPhaseProxy<D>> randomProxies(RandomSource& random, int n) {
  std::vector<BroadPhaseProxy<D>> proxies;
  for (int i = 0; i < n; ++i) {
    const Vec<D> c = random.vector<D>(-5.0, 5.0);
    const Vec<D> h = random.vector<D>(0.05, 1.5);
    proxies.push_back({Aabb<D>{Vec<D>(c - h), Vec<D>(c + h)}, random.uniform(0.0, 1.0) < 0.125});
  }
  return proxies;
}

/// The pairs by the definition, written out independently of the library.
template <int D>
std::vector<BodyPair> pairsByDefinition(const std::vector<BroadPhaseProxy<D>>& p, double margin) {
  std::vector<BodyPair> pairs;
  const int n = static_cast<int>(p.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (p[i].isStatic && p[j].isStatic) continue;
      bool overlap = true;
      for (int a = 0; a < D; ++a) {
        overlap = overlap && p[i].box.lower[a] - margin <= p[j].box.upper[a] + margin &&
                  p[j].box.lower[a] - margin <= p[i].box.upper[a] + margin;
      }
      if (overlap) pairs.push_back({i, j});
    }
  }
  return pairs;
}

/// Unit boxes (half extent 1/2) with centres at k * spacing along `axis`, dynamic.
template <int D>
std::vector<BroadPhaseProxy<D>> rowOfBoxes(int n, double spacing, int axis) {
  std::vector<BroadPhaseProxy<D>> proxies;
  for (int k = 0; k < n; ++k) {
    Vec<D> c = Vec<D>::Zero();
    c[axis] = k * spacing;
    proxies.push_back({Aabb<D>{Vec<D>(c.array() - 0.5), Vec<D>(c.array() + 0.5)}, false});
  }
  return proxies;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("worldBounds equals the box around the transformed corners of the body box",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(700 + D);
  // A box whose body origin is off its centre (as a body's centre of mass can be), so
  // that the centre term of Eq. (7.8) matters.
  const Vec<D> half = Vec<D>::LinSpaced(0.3, 0.9);
  const OffsetShape<D, BoxSdf<D>> body(BoxSdf<D>(half), stackbook::testing::boxBoundary<D>(half, 2),
                                      Vec<D>::LinSpaced(0.2, -0.4));
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const Pose<D> pose{random.vector<D>(-3.0, 3.0), random.orientation<D>()};
    const Aabb<D> fast = worldBounds<D>(body, pose);
    const Aabb<D> slow = boxOfTransformedCorners<D>(body.bounds(), pose);
    CHECK_EIGEN_NEAR(fast.lower, slow.lower, 1e-12, 1e-12);
    CHECK_EIGEN_NEAR(fast.upper, slow.upper, 1e-12, 1e-12);
    for (const Vec<D>& s : body.surfaceSamples()) CHECK(fast.inflated(1e-12).contains(pose.toWorld(s)));
  }
}

TEST_CASE("a ball's world box from its body box is loose by sqrt 2 at 45 degrees and its samples "
          "do not bound it") {
  const SphereShape<3> ball = stackbook::testing::ballShape<3>(1.0, 3);
  const Pose<3> pose{Vec3::Zero(), Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()))};
  const Aabb<3> box = worldBounds<3>(ball, pose);
  CHECK_EIGEN_NEAR(box.upper, Vec3(std::sqrt(2.0), std::sqrt(2.0), 1.0), 1e-12);
  // The tight box of the inscribed icosphere's vertices misses the sphere's extreme point
  // (1, 0, 0), which is no vertex: a sample box bounds a mesh, not a smooth body.
  const Aabb<3> tight = worldBoundsOfSamples<3>(ball, pose);
  CHECK(tight.upper.x() < 1.0);
  CHECK(tight.upper.x() > 0.98);
  CHECK_FALSE(tight.contains(Vec3(1.0, 0.0, 0.0)));
}

TEST_CASE_TEMPLATE("sweep and prune finds exactly the overlapping pairs once each in index order",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(710 + D);
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    const std::vector<BroadPhaseProxy<D>> proxies = randomProxies<D>(random, 60);
    for (const double margin : {0.0, 0.1}) {
      const std::vector<BodyPair> expected = pairsByDefinition<D>(proxies, margin);
      for (int axis = -1; axis < D; ++axis) {
        CAPTURE(axis);
        const std::vector<BodyPair> pairs = sweepAndPrune<D>(proxies, {axis, margin});
        CHECK(pairs == expected);  // same pairs, i < j, sorted by (i, j), no duplicates
      }
      CHECK(allPairs<D>(proxies, {-1, margin}) == expected);
    }
  }
}

TEST_CASE_TEMPLATE("the broad phase skips pairs of two static bodies", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Two overlapping static grounds and one dynamic box touching both.
  const Vec<D> one = Vec<D>::Ones();
  std::vector<BroadPhaseProxy<D>> proxies = {
      {Aabb<D>{Vec<D>(-2.0 * one), Vec<D>::Zero()}, true},
      {Aabb<D>{Vec<D>(-one), Vec<D>(one)}, true},
      {Aabb<D>{Vec<D>(-0.5 * one), Vec<D>(0.5 * one)}, false}};
  DetectionCounters counters;
  const std::vector<BodyPair> pairs = sweepAndPrune<D>(proxies, {}, &counters);
  CHECK(pairs == std::vector<BodyPair>{{0, 2}, {1, 2}});
  CHECK(counters.pairsTested == 2);  // the static-static pair is not even compared
  CHECK(counters.pairsOverlapping == 2);
  proxies[2].isStatic = true;
  CHECK(sweepAndPrune<D>(proxies).empty());
}

TEST_CASE_TEMPLATE("sweep and prune output and cost do not depend on the order of the bodies", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(720 + D);
  const std::vector<BroadPhaseProxy<D>> proxies = randomProxies<D>(random, 80);
  const int n = static_cast<int>(proxies.size());
  DetectionCounters reference;
  const std::vector<BodyPair> base = sweepAndPrune<D>(proxies, {0, 0.0}, &reference);
  std::vector<int> perm(proxies.size());
  std::iota(perm.begin(), perm.end(), 0);
  for (int trial = 0; trial < 10; ++trial) {
    CAPTURE(trial);
    // New position of old body k is perm[k]; shuffle with the seeded source.
    for (int k = n - 1; k > 0; --k) {
      std::swap(perm[k], perm[static_cast<int>(random.uniform(0.0, k + 1.0 - 1e-9))]);
    }
    std::vector<BroadPhaseProxy<D>> shuffled(proxies.size());
    for (int k = 0; k < n; ++k) shuffled[perm[k]] = proxies[k];
    DetectionCounters counters;
    const std::vector<BodyPair> pairs = sweepAndPrune<D>(shuffled, {0, 0.0}, &counters);
    // Invariant: the set of pairs (relabelled), reported sorted in the new labels, and the
    // number of box tests (the pairs whose x intervals overlap).
    std::vector<BodyPair> relabelled;
    for (const BodyPair& p : base) {
      relabelled.push_back({std::min(perm[p.first], perm[p.second]),
                            std::max(perm[p.first], perm[p.second])});
    }
    std::sort(relabelled.begin(), relabelled.end());
    CHECK(pairs == relabelled);
    CHECK(counters.pairsTested == reference.pairsTested);
    CHECK(counters.pairsOverlapping == reference.pairsOverlapping);
  }
}

TEST_CASE_TEMPLATE("sweep and prune tests only pairs that overlap on the sweep axis", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  const int n = 100;
  // Unit boxes 2 apart along x: no two x intervals overlap, so no box test at all,
  // where testing every pair costs n(n-1)/2 = 4950.
  {
    DetectionCounters sweep, brute;
    CHECK(sweepAndPrune<D>(rowOfBoxes<D>(n, 2.0, 0), {0, 0.0}, &sweep).empty());
    CHECK(allPairs<D>(rowOfBoxes<D>(n, 2.0, 0), {}, &brute).empty());
    CHECK(sweep.pairsTested == 0);
    CHECK(brute.pairsTested == n * (n - 1) / 2);
  }
  // Touching boxes (spacing 1): each overlaps its neighbours only; n - 1 tests, n - 1 pairs.
  {
    DetectionCounters sweep;
    const std::vector<BodyPair> pairs = sweepAndPrune<D>(rowOfBoxes<D>(n, 1.0, 0), {0, 0.0}, &sweep);
    CHECK(pairs.size() == static_cast<std::size_t>(n - 1));
    CHECK(sweep.pairsTested == n - 1);
  }
  // The same row swept across its length (axis 1): every interval overlaps, n(n-1)/2 tests.
  {
    DetectionCounters sweep;
    sweepAndPrune<D>(rowOfBoxes<D>(n, 2.0, 0), {1, 0.0}, &sweep);
    CHECK(sweep.pairsTested == n * (n - 1) / 2);
  }
}

TEST_CASE_TEMPLATE("the automatic sweep axis is the one along which the bodies spread", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  for (int axis = 0; axis < D; ++axis) {
    CAPTURE(axis);
    const std::vector<BroadPhaseProxy<D>> column = rowOfBoxes<D>(20, 2.0, axis);
    CHECK(sweepAxis<D>(column) == axis);
    DetectionCounters counters;
    sweepAndPrune<D>(column, {}, &counters);
    CHECK(counters.pairsTested == 0);
  }
}

TEST_CASE_TEMPLATE("a broad-phase margin reports boxes within twice the margin", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  std::vector<BroadPhaseProxy<D>> proxies = rowOfBoxes<D>(2, 1.25, 0);  // gap 0.25 on x
  CHECK(sweepAndPrune<D>(proxies, {-1, 0.0}).empty());
  CHECK(sweepAndPrune<D>(proxies, {-1, 0.124}).empty());
  CHECK(sweepAndPrune<D>(proxies, {-1, 0.125}) == std::vector<BodyPair>{{0, 1}});
}

TEST_CASE_TEMPLATE("the broad phase rejects a bad axis or margin with a message", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const std::vector<BroadPhaseProxy<D>> proxies = rowOfBoxes<D>(3, 1.0, 0);
  CHECK_THROWS_WITH_AS(sweepAndPrune<D>(proxies, {D, 0.0}),
                       doctest::Contains("settings.axis"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(sweepAndPrune<D>(proxies, {0, -0.1}),
                       doctest::Contains("settings.margin"), std::invalid_argument);
  std::vector<BroadPhaseProxy<D>> bad = proxies;
  bad[1].box.lower[0] = std::nan("");
  CHECK_THROWS_WITH_AS(sweepAndPrune<D>(bad), doctest::Contains("proxy 1"), std::invalid_argument);
}

// [test_kept_broad_phase]
TEST_CASE_TEMPLATE("the kept broad phase of a stage reports sweep and prune's pairs at every sweep with fewer box tests",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(900 + D);
  const auto shape = stackbook::testing::boxShape<D>(Vec<D>::Constant(0.5));
  constexpr int n = 60;
  std::vector<RigidBody<D>> bodies;
  std::vector<Pose<D>> poses;
  for (int i = 0; i < n; ++i) {
    const Vec<D> at = random.vector<D>(-4.0, 4.0);
    bodies.push_back(i % 8 == 0 ? makeStaticBody<D>(at) : makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0)));
    poses.push_back(Pose<D>{at, random.orientation<D>()});
  }
  const auto viewsNow = [&] {
    std::vector<CollisionBody<D>> views;
    for (int i = 0; i < n; ++i) views.push_back(collisionBodyAt<D>(bodies[i], shape, poses[i]));
    return views;
  };
  KeptBroadPhase<D> kept, off;
  BroadPhaseSettings noSlack;
  noSlack.keepSlack = 0.0;
  DetectionCounters keptWork, offWork, sweepWork;
  for (int sweep = 0; sweep < 40; ++sweep) {
    CAPTURE(sweep);
    // The dynamic bodies move a little at most sweeps (as in a stage) and far at every tenth,
    // which the kept pairs no longer cover.
    const double step = sweep % 10 == 9 ? 0.4 : 1e-3;
    for (int i = 0; i < n; ++i) {
      if (bodies[static_cast<std::size_t>(i)].isStatic()) continue;
      poses[static_cast<std::size_t>(i)].position += random.vector<D>(-step, step);
    }
    const std::vector<CollisionBody<D>> views = viewsNow();
    const std::vector<BodyPair> expected = sweepAndPrune<D>(views, {}, &sweepWork);
    REQUIRE_FALSE(expected.empty());
    CHECK(kept.pairs(views, {}, &keptWork) == expected);
    CHECK(off.pairs(views, noSlack, &offWork) == expected);
  }
  CHECK(keptWork.pairsOverlapping == sweepWork.pairsOverlapping);
  CHECK(keptWork.pairsTested < sweepWork.pairsTested / 2);  // the kept pairs answered most sweeps
  CHECK(offWork == sweepWork);  // no slack: sweep and prune at every sweep, the same work
  BroadPhaseSettings bad;
  bad.keepSlack = -0.1;
  CHECK_THROWS_WITH_AS(kept.pairs(viewsNow(), bad), doctest::Contains("settings.keepSlack"), std::invalid_argument);
}
// [test_kept_broad_phase]

}  // TEST_SUITE
