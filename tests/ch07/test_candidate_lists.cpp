// Chapter 7: candidate lists. A pair asked again and again while its bodies move a little
// gets the same answer, bit for bit, from its lists as from the loop over every sample;
// the grid's Lipschitz bound that makes this safe holds; bad settings are refused.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "stackbook/collision/candidate_list_store.hpp"
#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/stepping/impulse_stage.hpp"
#include "support/dimensions.hpp"
#include "support/random_bodies.hpp"
#include "test_shapes.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// `q` turned a little more, by `angle` about a random axis.
template <int D>
Orientation<D> nudgedBy(const Orientation<D>& q, double angle, RandomSource& rng) {
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(q.angle() + angle);
  } else {
    return (Eigen::Quaterniond(Eigen::AngleAxisd(angle, rng.unitVector<3>())) * q).normalized();
  }
}

/// Chapter 6's grid of a ring (16 cells across), built once per dimension.
template <int D>
const GridShape<D>& ringForLists() {
  static const GridShape<D> ring = [] {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = 16;
    return GridShape<D>(ringBoundary<D>(1.0, 0.2, 48, 24), "ring", settings);
  }();
  return ring;
}

/// Asks the pair (0, 1) of two moving bodies `asks` times, once with candidate lists kept
/// from ask to ask and once with none, and checks that every answer and every candidate is
/// the same, bit for bit. Between asks body 1 moves by a small step (at most `step`), and
/// every 7th ask by a large one (10 times the list's reach), which forces the lists to be
/// remade. The pair's whole interference is compared too: pairInterferenceListed() with
/// lists of its own, kept likewise, against pairInterference(), sample for sample (its
/// counters go to `whole`). Returns the counters of the deepest-sample asks with lists.
template <int D>
DetectionCounters compareAsks(const Shape<D>& shapeA, const Shape<D>& shapeB, RigidBody<D> a, RigidBody<D> b,
                              int asks, double step, RandomSource& rng, DetectionCounters& whole) {
  NarrowPhaseSettings plain;
  plain.candidateReach = 0.0;
  const NarrowPhaseSettings listed;  // the default reach
  PairCandidateLists<D> lists, wholeLists;
  std::vector<InterferenceCandidate<D>> withLists, without, wholeScratch;
  std::vector<InterferenceSample<D>> wholeListed;
  DetectionCounters counters;
  const Vec<D> centre = b.position;
  for (int ask = 0; ask < asks; ++ask) {
    const double size = ask % 7 == 6 ? 10.0 * listed.candidateReach : step;
    b.position = centre + rng.vector<D>(-size, size);
    b.orientation = nudgedBy<D>(b.orientation, rng.uniform(-size, size), rng);
    b.velocity = rng.vector<D>(-1.0, 1.0);
    const std::vector<CollisionBody<D>> bodies{collisionBody<D>(a, shapeA), collisionBody<D>(b, shapeB)};
    const std::optional<InterferenceSample<D>> x =
        deepestApproachingInPair<D>(bodies, BodyPair{0, 1}, listed, &counters, withLists, &lists);
    const std::optional<InterferenceSample<D>> y =
        deepestApproachingInPair<D>(bodies, BodyPair{0, 1}, plain, nullptr, without);
    REQUIRE(x.has_value() == y.has_value());
    if (x) {
      CHECK(x->sampleIndex == y->sampleIndex);
      CHECK(x->owner == y->owner);
      CHECK(x->depth == y->depth);  // the same operations: the same bits
      CHECK(x->point == y->point);
      CHECK(x->normal == y->normal);
    }
    REQUIRE(withLists.size() == without.size());
    for (std::size_t k = 0; k < withLists.size(); ++k) {
      CHECK(withLists[k].sampleIndex == without[k].sampleIndex);
      CHECK(withLists[k].firstOwns == without[k].firstOwns);
      CHECK(withLists[k].depth == without[k].depth);
      CHECK(withLists[k].inPenetrated == without[k].inPenetrated);
    }
    pairInterferenceListed<D>(bodies, BodyPair{0, 1}, listed, &whole, wholeScratch, wholeListed, &wholeLists);
    const std::vector<InterferenceSample<D>> full = pairInterference<D>(bodies, BodyPair{0, 1}, plain);
    REQUIRE(wholeListed.size() == full.size());
    for (std::size_t k = 0; k < full.size(); ++k) {
      CHECK(wholeListed[k].sampleIndex == full[k].sampleIndex);
      CHECK(wholeListed[k].owner == full[k].owner);
      CHECK(wholeListed[k].other == full[k].other);
      CHECK(wholeListed[k].depth == full[k].depth);  // the same operations: the same bits
      CHECK(wholeListed[k].point == full[k].point);
      CHECK(wholeListed[k].normal == full[k].normal);
    }
  }
  return counters;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_candidate_lists]
TEST_CASE_TEMPLATE("candidate lists answer a moving pair as the loop over every sample does, bit for bit", Dim,
                   In2D, In3D) {
  // Two densely sampled boxes, one on the other and turned, and a grid ring threaded on a
  // densely sampled peg: 30 trials of 42 asks each, the upper body moved between asks.
  constexpr int D = Dim::value;
  const BoxShape<D> slab = boxShape<D>(Vec<D>(Vec<D>::Constant(1.0) - 0.75 * Vec<D>::Unit(D - 1)), 12);
  const BoxShape<D> cube = boxShape<D>(Vec<D>::Constant(0.5), 12);
  Vec<D> pegHalf = Vec<D>::Constant(0.1);
  if constexpr (D == 3) pegHalf[2] = 1.5;
  const BoxShape<D> peg = boxShape<D>(pegHalf, 8);
  const GridShape<D>& ring = ringForLists<D>();
  RandomSource rng(1207);
  // Small moves are a twenty-fifth of the default reach fraction (in metres and radians).
  const double smallStep = 0.04 * NarrowPhaseSettings{}.candidateReach;
  DetectionCounters boxes, rings, boxesWhole, ringsWhole;
  for (int trial = 0; trial < 30; ++trial) {
    RigidBody<D> lower = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
    RigidBody<D> upper = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
    upper.position = Vec<D>((0.73 - rng.uniform(0.0, 0.03)) * Vec<D>::Unit(D - 1));
    upper.orientation = nudgedBy<D>(Orientation<D>::Identity(), rng.uniform(-0.3, 0.3), rng);
    lower.velocity = rng.vector<D>(-1.0, 1.0);
    boxes += compareAsks<D>(slab, cube, lower, upper, 42, smallStep, rng, boxesWhole);
    RigidBody<D> pegBody = makeStaticBody<D>();
    RigidBody<D> ringBody = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
    ringBody.position = Vec<D>(rng.uniform(0.7, 0.8) * Vec<D>::Unit(0));  // the hole's rim on the peg
    rings += compareAsks<D>(peg, ring, pegBody, ringBody, 42, smallStep, rng, ringsWhole);
  }
  // The lists answered most asks and were remade after the large moves, so the
  // comparison above covers both paths; they ask far fewer samples than the loop.
  for (const DetectionCounters* c : {&boxes, &rings, &boxesWhole, &ringsWhole}) {
    CHECK(c->listedQueries > c->candidateListsMade);
    CHECK(c->candidateListsMade >= 2 * 30 * 5);  // both directions, remade after (nearly) every large move
    CHECK(c->interferenceSamples > 0);
  }
}

TEST_CASE_TEMPLATE("a grid's Lipschitz bound holds between any two points, inside and outside the grid", Dim, In2D,
                   In3D) {
  // |phi(x) - phi(y)| <= L |x - y| for random pairs, near each other and far apart, in and
  // around the grid's box; L is near 1 + 1 for a grid of a true distance (its node
  // differences are at most about h per cell, and 1 more for the extension outside).
  constexpr int D = Dim::value;
  const GridShape<D>& ring = ringForLists<D>();
  const double L = ring.distanceLipschitz();
  CHECK(L >= 1.0);
  CHECK(L <= 1.0 + std::sqrt(static_cast<double>(D)) + 1e-9);
  const Aabb<D> around = ring.grid().box().inflated(0.5);
  RandomSource rng(33);
  int tested = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec<D> x = around.lower + rng.vector<D>(0.0, 1.0).cwiseProduct(around.extent());
    const double reach = k % 2 == 0 ? 0.05 : 2.0;
    const Vec<D> y = x + rng.vector<D>(-reach, reach);
    const double lhs = std::abs(ring.signedDistance(x) - ring.signedDistance(y));
    CHECK(lhs <= L * (x - y).norm() * (1.0 + 1e-12) + 1e-14);
    ++tested;
  }
  CHECK(tested == 20000);
  // Exact distances report 1; a shape that knows no bound reports 0 and keeps no lists.
  CHECK(boxShape<D>(Vec<D>::Constant(0.5)).distanceLipschitz() == 1.0);
  const HullShape<D, SphereSdf<D>> hull(SphereSdf<D>(1.0), {Vec<D>::Unit(0)});
  CHECK(hull.distanceLipschitz() == 0.0);
}

TEST_CASE_TEMPLATE("a pair against a shape with no Lipschitz bound is asked without lists", Dim, In2D, In3D) {
  // A densely sampled box pressed into a hull (a Shape that reports no bound and has no
  // sample chunks): neither direction may keep a list, and the answer is still found.
  constexpr int D = Dim::value;
  const BoxShape<D> box = boxShape<D>(Vec<D>::Constant(0.5), 8);
  std::vector<Vec<D>> samples;
  for (int k = 0; k < 64; ++k) samples.push_back(Vec<D>::Unit(k % D) * (k % 2 == 0 ? 1.0 : -1.0));
  const HullShape<D, SphereSdf<D>> hull(SphereSdf<D>(1.0), samples);
  RigidBody<D> a = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
  RigidBody<D> b = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
  b.position = Vec<D>(1.4 * Vec<D>::Unit(0));
  b.velocity = Vec<D>(-Vec<D>::Unit(0));
  const std::vector<CollisionBody<D>> bodies{collisionBody<D>(a, box), collisionBody<D>(b, hull)};
  PairCandidateLists<D> lists;
  std::vector<InterferenceCandidate<D>> scratch;
  DetectionCounters counters;
  CHECK(deepestApproachingInPair<D>(bodies, BodyPair{0, 1}, {}, &counters, scratch, &lists).has_value());
  CHECK(counters.candidateListsMade == 0);
  CHECK(counters.listedQueries == 0);
  CHECK_FALSE(lists.firstInSecond.made);
  CHECK_FALSE(lists.secondInFirst.made);
}

TEST_CASE_TEMPLATE("a candidate list answers only for the shapes it was made for", Dim, In2D, In3D) {
  // Lists made for two small boxes, then asked at the same relative pose by two larger boxes:
  // remade, with the plain loop's answer. Then asked by another pair of the larger boxes at
  // the same relative pose elsewhere: answered from the lists (the answer depends on the
  // shapes and their relative pose only).
  constexpr int D = Dim::value;
  const BoxShape<D> small = boxShape<D>(Vec<D>::Constant(0.5), 4);
  const BoxShape<D> large = boxShape<D>(Vec<D>::Constant(0.6), 4);
  RigidBody<D> a = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
  RigidBody<D> b = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
  b.position = Vec<D>(0.95 * Vec<D>::Unit(D - 1));
  b.velocity = Vec<D>(-Vec<D>::Unit(D - 1));
  PairCandidateLists<D> lists;
  std::vector<InterferenceCandidate<D>> scratch, plain;
  DetectionCounters counters;
  NarrowPhaseSettings off;
  off.candidateReach = 0.0;
  const std::vector<CollisionBody<D>> smallPair{collisionBody<D>(a, small), collisionBody<D>(b, small)};
  CHECK(deepestApproachingInPair<D>(smallPair, BodyPair{0, 1}, {}, &counters, scratch, &lists).has_value());
  CHECK(counters.candidateListsMade == 2);
  const std::vector<CollisionBody<D>> largePair{collisionBody<D>(a, large), collisionBody<D>(b, large)};
  const std::optional<InterferenceSample<D>> x =
      deepestApproachingInPair<D>(largePair, BodyPair{0, 1}, {}, &counters, scratch, &lists);
  const std::optional<InterferenceSample<D>> y = deepestApproachingInPair<D>(largePair, BodyPair{0, 1}, off, nullptr, plain);
  CHECK(counters.candidateListsMade == 4);
  CHECK(counters.listedQueries == 0);
  REQUIRE(x.has_value());
  REQUIRE(y.has_value());
  CHECK(x->sampleIndex == y->sampleIndex);
  CHECK(x->depth == y->depth);
  CHECK(scratch.size() == plain.size());
  RigidBody<D> c = a, d = b;
  c.position += Vec<D>(5.0 * Vec<D>::Unit(0));
  d.position += Vec<D>(5.0 * Vec<D>::Unit(0));
  const std::vector<CollisionBody<D>> elsewhere{collisionBody<D>(c, large), collisionBody<D>(d, large)};
  const std::optional<InterferenceSample<D>> z =
      deepestApproachingInPair<D>(elsewhere, BodyPair{0, 1}, {}, &counters, scratch, &lists);
  CHECK(counters.candidateListsMade == 4);
  CHECK(counters.listedQueries == 2);
  REQUIRE(z.has_value());
  CHECK(z->sampleIndex == y->sampleIndex);
  CHECK(z->depth == y->depth);
}

TEST_CASE_TEMPLATE("the narrow phase refuses a candidate reach that is negative or not finite", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const BoxShape<D> box = boxShape<D>(Vec<D>::Constant(0.5));
  const RigidBody<D> a = makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0));
  const std::vector<CollisionBody<D>> bodies{collisionBody<D>(a, box), collisionBody<D>(a, box)};
  std::vector<InterferenceCandidate<D>> scratch;
  for (const double reach : {-0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    NarrowPhaseSettings settings;
    settings.candidateReach = reach;
    CHECK_THROWS_WITH_AS(deepestApproachingInPair<D>(bodies, BodyPair{0, 1}, settings, nullptr, scratch),
                         doctest::Contains("candidateReach must be finite and >= 0"), std::invalid_argument);
  }
}
// [test_candidate_lists]

TEST_CASE("a pair takes its kept lists in either body order and gives them back") {
  CandidateListStore<2> store;
  store.pairs = {{0, 1}, {1, 4}, {2, 3}};
  store.lists.resize(3);
  for (std::size_t k = 0; k < 3; ++k) {  // mark each list by its owner and penetrated body
    store.lists[k].firstInSecond.t = Vec2(store.pairs[k].first, store.pairs[k].second);
    store.lists[k].secondInFirst.t = Vec2(store.pairs[k].second, store.pairs[k].first);
  }
  PairCandidateLists<2> taken;
  // As pair (4, 1), below before above as the pass names it: firstInSecond is 4's samples in 1.
  REQUIRE(store.swapFor(4, 1, taken));
  CHECK(taken.firstInSecond.t == Vec2(4.0, 1.0));
  CHECK(taken.secondInFirst.t == Vec2(1.0, 4.0));
  REQUIRE(store.swapFor(4, 1, taken));  // given back
  CHECK(store.lists[1].firstInSecond.t == Vec2(1.0, 4.0));
  CHECK(store.lists[1].secondInFirst.t == Vec2(4.0, 1.0));
  REQUIRE(store.swapFor(2, 3, taken));
  CHECK(taken.firstInSecond.t == Vec2(2.0, 3.0));
  CHECK(taken.secondInFirst.t == Vec2(3.0, 2.0));
  // A pair the store does not hold: nothing moves.
  PairCandidateLists<2> other;
  other.firstInSecond.t = Vec2(9.0, 9.0);
  CHECK_FALSE(store.swapFor(0, 2, other));
  CHECK_FALSE(store.swapFor(3, 4, other));
  CHECK(other.firstInSecond.t == Vec2(9.0, 9.0));
}

TEST_CASE("a sweep's candidate lists are carried to the pairs of the next sweep by pair, new pairs start without") {
  // Each pair's lists are marked by their translation t = (first, second): a list that
  // reaches pair (i, j) from the last sweep carries (i, j), a new pair's lists are unmade.
  const auto listsOf = [](const std::vector<BodyPair>& pairs) {
    std::vector<PairCandidateLists<2>> lists(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      lists[k].firstInSecond.made = lists[k].secondInFirst.made = true;
      lists[k].firstInSecond.t = Vec2(pairs[k].first, pairs[k].second);
      lists[k].firstInSecond.samples = {pairs[k].first, pairs[k].second};
    }
    return lists;
  };
  const std::vector<BodyPair> previous{{0, 1}, {0, 2}, {1, 3}, {2, 5}};
  const std::vector<BodyPair> next{{0, 2}, {1, 2}, {1, 3}, {4, 5}, {4, 6}};
  std::vector<PairCandidateLists<2>> lists = listsOf(previous), spare;
  carryCandidateLists<2>(previous, next, lists, spare);
  REQUIRE(lists.size() == next.size());
  for (std::size_t k = 0; k < next.size(); ++k) {
    CAPTURE(k);
    const bool carried = k == 0 || k == 2;  // (0, 2) and (1, 3) were in the last sweep
    CHECK(lists[k].firstInSecond.made == carried);
    CHECK(lists[k].secondInFirst.made == carried);
    if (carried) {
      CHECK(lists[k].firstInSecond.t == Vec2(next[k].first, next[k].second));
      CHECK(lists[k].firstInSecond.samples == std::vector<int>{next[k].first, next[k].second});
    }
  }
  // The same pairs again: every list stays where it is. Fewer pairs: the spare storage,
  // grown above, is used again and the result is still by pair.
  const std::vector<PairCandidateLists<2>> before = lists;
  carryCandidateLists<2>(next, next, lists, spare);
  for (std::size_t k = 0; k < next.size(); ++k) CHECK(lists[k].firstInSecond.t == before[k].firstInSecond.t);
  const std::vector<BodyPair> fewer{{1, 3}};
  carryCandidateLists<2>(next, fewer, lists, spare);
  REQUIRE(lists.size() == 1);
  CHECK(lists[0].firstInSecond.made);
  CHECK(lists[0].firstInSecond.t == Vec2(1.0, 3.0));
  // No pairs last time (a stage's first sweep): nothing is carried.
  carryCandidateLists<2>({}, previous, lists, spare);
  REQUIRE(lists.size() == previous.size());
  for (const PairCandidateLists<2>& l : lists) CHECK_FALSE(l.firstInSecond.made);
}

}  // TEST_SUITE
