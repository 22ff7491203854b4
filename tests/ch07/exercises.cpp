// Chapter 7 exercises: suite ch07_exercises, skipped by default. The exercises preset builds
// them into build/exercises/tests/ch07/test_ch07_exercises. It registers one CTest entry per
// exercise, ex07.1 to ex07.3, with the labels exercise and ch07. Run all of them, or one, with
//   ctest --preset exercises -L ch07
//   ctest --preset exercises -R ex07.2
// An entry runs its tests once its stub has no "// TODO(reader)" comment left. The binary
// runs them at any time:
//   build/exercises/tests/ch07/test_ch07_exercises --no-skip -ts=ch07_exercises -tc="Exercise 7.2*"
// They fail until you solve the exercise (the stub returns a neutral value).
// The main build runs them against the reference solutions: ctest --preset solutions -L ch07
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "stackbook/exercises/ex07_1_uniform_grid.hpp"
#include "stackbook/exercises/ex07_2_edge_edge.hpp"
#include "stackbook/exercises/ex07_3_sample_tree.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"
#include "test_shapes.hpp"

using namespace stackbook;
using stackbook::testing::boxBoundary;
using stackbook::testing::boxShape;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;

namespace {

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

/// Unit boxes (half extent 1/2) with centres at k * spacing along `axis`.
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

/// The two crossed bars of chapter 7's edge-on-edge test (3D): the lower bar's top edge
/// along x at z = 0, the upper bar's bottom edge along y at z = -overlap, crossing at
/// (xi, 0). Each bar: half extents (1, 0.25, 0.25), turned 45 degrees about its axis.
struct CrossedBars {
  static constexpr double L = 1.0, a = 0.25, xi = 0.237, eta = 0.311;
  BoxShape<3> bar = boxShape<3>(Vec3(L, a, a));  // corner samples only
  RigidBody<3> lower = makeStaticBody<3>(), upper = makeStaticBody<3>();
  explicit CrossedBars(double overlap) {
    const Eigen::Quaterniond edgeUp(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()));
    lower.position = Vec3(0.0, 0.0, -a * std::sqrt(2.0));
    lower.orientation = edgeUp;
    upper.position = Vec3(xi, eta, a * std::sqrt(2.0) - overlap);
    upper.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())) * edgeUp;
  }
  std::vector<CollisionBody<3>> views() const {
    return {collisionBody<3>(lower, bar), collisionBody<3>(upper, bar)};
  }
};

/// A box on a densely sampled ground (the ground's top face carries a lattice of samples).
/// The box is turned by `boxTurn` relative to the ground, the whole scene by `turn`.
template <int D>
struct BoxOnDenseGround {
  static Vec<D> groundHalf() {
    Vec<D> h = Vec<D>::Constant(5.0);
    h[D - 1] = 0.5;
    return h;
  }
  BoxShape<D> ground = boxShape<D>(groundHalf(), D == 2 ? 64 : 32);
  BoxShape<D> box = boxShape<D>(Vec<D>::Constant(0.5), 2);
  RigidBody<D> groundBody = makeStaticBody<D>();
  RigidBody<D> boxBody = makeStaticBody<D>();
  BoxOnDenseGround(double overlap, const Orientation<D>& turn,
                   const Orientation<D>& boxTurn = identityOrientation<D>()) {
    groundBody.position = turn * Vec<D>(-0.5 * Vec<D>::Unit(D - 1));
    groundBody.orientation = turn;
    boxBody.position = turn * Vec<D>((0.5 - overlap) * Vec<D>::Unit(D - 1));
    boxBody.orientation = turn * boxTurn;
  }
  std::vector<CollisionBody<D>> views() const {
    return {collisionBody<D>(boxBody, box), collisionBody<D>(groundBody, ground)};
  }
};

template <int D>
bool sameSamples(const std::vector<InterferenceSample<D>>& a, const std::vector<InterferenceSample<D>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].owner != b[k].owner || a[k].other != b[k].other ||
        a[k].sampleIndex != b[k].sampleIndex || a[k].depth != b[k].depth ||
        a[k].point != b[k].point || a[k].normal != b[k].normal) {
      return false;
    }
  }
  return true;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER "_exercises" * doctest::skip()) {

// ---- Exercise 7.1: a uniform-grid broad phase -------------------------------------------

TEST_CASE_TEMPLATE("Exercise 7.1: the uniform grid finds the same pairs as sweep and prune", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(7100 + D);
  for (int trial = 0; trial < 10; ++trial) {
    CAPTURE(trial);
    const std::vector<BroadPhaseProxy<D>> proxies = randomProxies<D>(random, 60);
    for (const double cell : {0.25, 1.0, 3.0, 20.0}) {
      for (const double margin : {0.0, 0.1}) {
        CAPTURE(cell);
        CAPTURE(margin);
        const std::vector<BodyPair> expected = sweepAndPrune<D>(proxies, {-1, margin});
        REQUIRE_FALSE(expected.empty());
        CHECK(uniformGridPairs<D>(proxies, {cell, margin}) == expected);
      }
    }
  }
}

TEST_CASE_TEMPLATE("Exercise 7.1: the grid tests only bodies that share a cell", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Touching unit boxes along the last axis, swept by sweep and prune along x: all x
  // intervals overlap, so it tests every pair. Cells of size 1: box k covers cells k-1 and
  // k along that axis, so only neighbours share a cell.
  const int n = 50;
  const std::vector<BroadPhaseProxy<D>> column = rowOfBoxes<D>(n, 1.0, D - 1);
  DetectionCounters sweep, grid;
  const std::vector<BodyPair> expected = sweepAndPrune<D>(column, {0, 0.0}, &sweep);
  CHECK(uniformGridPairs<D>(column, {1.0, 0.0}, &grid) == expected);
  CHECK(expected.size() == static_cast<std::size_t>(n - 1));
  CHECK(sweep.pairsTested == n * (n - 1) / 2);
  CHECK(grid.pairsTested == n - 1);
  CHECK(grid.pairsOverlapping == n - 1);
}

TEST_CASE_TEMPLATE("Exercise 7.1: the grid refuses a bad cell size and a box too large for it", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  std::vector<BroadPhaseProxy<D>> proxies = rowOfBoxes<D>(3, 1.0, 0);
  CHECK_THROWS_AS(uniformGridPairs<D>(proxies, {0.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(uniformGridPairs<D>(proxies, {-1.0, 0.0}), std::invalid_argument);
  proxies[0].box.lower.setConstant(-1e6);  // a ground 2e6 wide in cells of 0.01
  CHECK_THROWS_AS(uniformGridPairs<D>(proxies, {0.01, 0.0}), std::invalid_argument);
}

// ---- Exercise 7.2: edge-edge test ---------------------------------------------------------

TEST_CASE("Exercise 7.2: crossed boxes with corner samples only are found at the exact depth") {
  const double d = 0.05;
  const CrossedBars bars(d);
  const std::vector<CollisionBody<3>> bodies = bars.views();
  const TriangleMesh mesh = boxBoundary<3>(Vec3(CrossedBars::L, CrossedBars::a, CrossedBars::a));
  // The vertex test sees nothing (chapter 7); the edge test finds the crossing.
  REQUIRE(pairInterference<3>(bodies, {0, 1}).empty());
  DetectionCounters counters;
  const std::vector<InterferenceSample<3>> samples =
      edgeEdgeInterference(bodies, {0, 1}, mesh, mesh, &counters);
  REQUIRE_FALSE(samples.empty());
  const double exact = -d / std::sqrt(2.0);  // the crossing point is d below the other edge
  bool lowerFound = false, upperFound = false;
  for (const InterferenceSample<3>& s : samples) {
    CHECK(s.depth >= exact - 1e-12);  // never deeper than the true deepest point
    if (std::abs(s.depth - exact) > 1e-12) continue;
    if (s.owner == 0) {
      lowerFound = true;  // on the lower bar's top edge, inside the upper bar
      CHECK_EIGEN_NEAR(s.point, Vec3(CrossedBars::xi, 0.0, 0.0), 0.0, 1e-12);
      CHECK(s.normal.z() < -0.7);  // out of the upper bar, towards the lower one
    } else {
      upperFound = true;
      CHECK_EIGEN_NEAR(s.point, Vec3(CrossedBars::xi, 0.0, -d), 0.0, 1e-12);
      CHECK(s.normal.z() > 0.7);
    }
  }
  CHECK(lowerFound);
  CHECK(upperFound);
  CHECK(counters.interferenceSamples == static_cast<std::int64_t>(samples.size()));
  // Lift the upper bar clear (a gap of 0.01): no edge sample.
  const CrossedBars apart(-0.01);
  CHECK(edgeEdgeInterference(apart.views(), {0, 1}, mesh, mesh).empty());
}

// ---- Exercise 7.3: a tree over the samples ------------------------------------------------

TEST_CASE_TEMPLATE("Exercise 7.3: a tree query returns exactly the points inside a box", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  RandomSource random(7300 + D);
  std::vector<Vec<D>> points;
  for (int k = 0; k < 500; ++k) points.push_back(random.vector<D>(-1.0, 1.0));
  const SampleTree<D> tree(points, 6);
  int nonEmpty = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const Vec<D> c = random.vector<D>(-1.0, 1.0), h = random.vector<D>(0.01, 0.5);
    const Aabb<D> box{Vec<D>(c - h), Vec<D>(c + h)};
    std::vector<int> expected;
    for (int k = 0; k < static_cast<int>(points.size()); ++k) {
      if (box.contains(points[static_cast<std::size_t>(k)])) expected.push_back(k);
    }
    nonEmpty += expected.empty() ? 0 : 1;
    std::int64_t visited = 0;
    CHECK(tree.query(box, &visited) == expected);
    CHECK(visited >= static_cast<std::int64_t>(expected.size()));
    CHECK(visited <= static_cast<std::int64_t>(points.size()));
  }
  CHECK(nonEmpty > 50);
  for (const auto& node : tree.nodes()) CHECK(node.count <= 6);
}

TEST_CASE_TEMPLATE("Exercise 7.3: the tree gives the plain narrow phase's samples and transforms "
                   "only those near the other body",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const double d = 0.01;
  // Axis-aligned: the ground's candidates are exactly its top-face samples under the box,
  // 7 in 2D (x = -0.46875 .. 0.46875 in steps of 10/64) and 3 x 3 in 3D (steps of 10/32).
  const BoxOnDenseGround<D> scene(d, identityOrientation<D>());
  const std::vector<CollisionBody<D>> bodies = scene.views();
  const SampleTree<D> groundTree(scene.ground.surfaceSamples(), 8);
  std::vector<InterferenceSample<D>> plain, withTree;
  DetectionCounters plainCount, treeCount;
  appendSamplesInside<D>(bodies[1], 1, bodies[0], 0, plain, {}, &plainCount);
  appendSamplesInsideWithTree<D>(bodies[1], groundTree, 1, bodies[0], 0, withTree, {}, &treeCount);
  const std::int64_t underTheBox = D == 2 ? 7 : 9;
  REQUIRE(plain.size() == static_cast<std::size_t>(underTheBox));
  CHECK(sameSamples<D>(plain, withTree));
  CHECK(plainCount.samplesTransformed ==
        static_cast<std::int64_t>(scene.ground.surfaceSamples().size()));
  CHECK(treeCount.samplesTransformed == underTheBox);
  CHECK(treeCount.phiQueries == plainCount.phiQueries);
  CHECK(treeCount.interferenceSamples == underTheBox);

  // The box turned on the ground (3D: 0.3 rad about the up axis; 2D: tilted 0.05 rad and
  // pressed 0.05 deep), the scene turned as a whole: the box seen from the ground is no
  // longer axis-aligned, so its query box takes in a few more samples, yet the answer is
  // the same and the transforms are a small fraction.
  Orientation<D> turn, boxTurn;
  double overlap = d;
  if constexpr (D == 2) {
    turn = Eigen::Rotation2Dd(0.3);
    boxTurn = Eigen::Rotation2Dd(0.05);
    overlap = 0.05;
  } else {
    turn = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3(1.0, 2.0, 3.0).normalized()));
    boxTurn = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
  }
  const BoxOnDenseGround<D> turned(overlap, turn, boxTurn);
  const std::vector<CollisionBody<D>> turnedBodies = turned.views();
  for (const int owner : {0, 1}) {
    CAPTURE(owner);
    const int other = 1 - owner;
    const SampleTree<D> tree(owner == 0 ? turned.box.surfaceSamples() : turned.ground.surfaceSamples(), 8);
    std::vector<InterferenceSample<D>> a, b;
    DetectionCounters ca, cb;
    appendSamplesInside<D>(turnedBodies[owner], owner, turnedBodies[other], other, a, {}, &ca);
    appendSamplesInsideWithTree<D>(turnedBodies[owner], tree, owner, turnedBodies[other], other, b,
                                   {}, &cb);
    REQUIRE_FALSE(a.empty());
    CHECK(sameSamples<D>(a, b));
    if (owner == 1) CHECK(cb.samplesTransformed * 20 < ca.samplesTransformed);
  }
}

}  // TEST_SUITE
