// Chapter 10, "Threads" and "Colours": the islands and the colours of a sweep, and the step
// bit for bit the same for 1, 2 and 4 threads on bundled scenes, in list order and colour by
// colour (exact state bits and every work counter after N steps),
// with GBF's contact stage, with the pass as the contact stage and one cone per step (the
// contact ledger shared by the islands), with the loop tolerances, the implicit midpoint
// rotation, exact deepest points, and with sleeping on.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stepping/pair_colours.hpp"
#include "stackbook/stepping/pair_islands.hpp"
#include "stackbook/stepping/traditional_step.hpp"

using namespace stackbook;

namespace {

std::uint64_t threadsMixDouble(std::uint64_t h, double x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  for (int b = 0; b < 8; ++b) {
    h ^= (bits >> (8 * b)) & 0xffu;
    h *= 1099511628211ull;
  }
  return h;
}

/// FNV-1a over the bits of every body's position, orientation, velocity, angular
/// momentum and angular velocity.
template <int D>
std::uint64_t threadsStateHash(const World<D>& world) {
  std::uint64_t h = 1469598103934665603ull;
  for (const RigidBody<D>& b : world.bodies) {
    for (int k = 0; k < D; ++k) h = threadsMixDouble(threadsMixDouble(h, b.position[k]), b.velocity[k]);
    for (int k = 0; k < b.angularMomentum.size(); ++k) {
      h = threadsMixDouble(threadsMixDouble(h, b.angularMomentum[k]), b.angularVelocity[k]);
    }
    if constexpr (D == 2) {
      h = threadsMixDouble(h, b.orientation.angle());
    } else {
      for (int k = 0; k < 4; ++k) h = threadsMixDouble(h, b.orientation.coeffs()[k]);
    }
  }
  return h;
}

/// What must agree between thread counts: the state bits and the work counted.
struct ThreadsOutcome {
  std::uint64_t hash = 0;
  std::vector<std::int64_t> counts;
  std::int64_t islandSweeps = 0;  // sweeps that ran as islands (differs by thread count)
  std::int64_t fellAsleep = 0;
  std::int64_t pairConvergences = 0;
};

void threadsAddStage(std::vector<std::int64_t>& out, const StageCounters& s) {
  for (const std::int64_t v : {s.sweeps, s.pairVisits, s.impulses, s.frictionless, s.sticking, s.sliding,
                               s.pairIterationCapHits, s.pairConvergences, s.frictionEvaluations, s.elasticImpulses,
                               s.rollingImpulses, s.stepConeSticks, s.detection.pairsTested,
                               s.detection.pairQueries, s.detection.phiQueries,
                               s.detection.interferenceSamples}) {
    out.push_back(v);
  }
}

template <int D>
ThreadsOutcome threadsRun(const Scene& scene, StepSettings settings, int steps) {
  World<D> world = std::get<SceneBodies<D>>(scene.bodies).world;
  const PostContactHook<D> hook = shockPropagationHook<D>();
  StepCounters total;
  // Chapter 8's step with shock propagation: GBF's step, also for a scene whose default is the
  // welded pass, whose thread counts chapter 9's tests and scene_hashes check.
  for (int n = 0; n < steps; ++n) total += step<D>(world, settings, hook);
  ThreadsOutcome out;
  out.hash = threadsStateHash<D>(world);
  threadsAddStage(out.counts, total.collision);
  threadsAddStage(out.counts, total.contact);
  threadsAddStage(out.counts, total.shock);
  out.counts.push_back(total.sleep.sleepingBodySteps);
  out.counts.push_back(total.sleep.fellAsleep);
  out.fellAsleep = total.sleep.fellAsleep;
  out.pairConvergences = total.collision.pairConvergences + total.contact.pairConvergences + total.shock.pairConvergences;
  out.islandSweeps = total.collision.islandSweeps + total.contact.islandSweeps + total.shock.islandSweeps;
  return out;
}

ThreadsOutcome threadsRunScene(const Scene& scene, const StepSettings& settings, int steps) {
  return scene.dimension == 2 ? threadsRun<2>(scene, settings, steps) : threadsRun<3>(scene, settings, steps);
}

/// Calls check(world, pairs) on 200 random lists of pairs, each among a random run of the
/// bodies of one of five worlds of 300, 40, 1200, 7 and 300 bodies (a fifth of them static),
/// as a sweep or a level would have them. The worlds come in turn, so that a per-thread table
/// of the world's size is grown, reused, and used by a smaller world after a larger one.
void threadsForRandomPairLists(unsigned seed,
                               const std::function<void(const World<2>&, const std::vector<BodyPair>&)>& check) {
  const auto shape = std::make_shared<BoxShape<2>>(makeBoxShape<2>(Vec2(1.0, 1.0)));
  std::mt19937 random(seed);
  for (const int n : {300, 40, 1200, 7, 300}) {
    World<2> world;
    for (int i = 0; i < n; ++i) {
      if (random() % 5 == 0) {
        world.addBody(makeStaticBody<2>(Vec2(0.0, 0.0)), shape);
      } else {
        world.addBody(makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0)), shape);
      }
    }
    for (int trial = 0; trial < 40; ++trial) {
      const int span = 1 + static_cast<int>(random() % static_cast<unsigned>(n));
      const int first = static_cast<int>(random() % static_cast<unsigned>(n - span + 1));
      std::vector<BodyPair> pairs;
      const int count = static_cast<int>(random() % 60);
      for (int k = 0; k < count && span > 1; ++k) {
        const int a = first + static_cast<int>(random() % static_cast<unsigned>(span));
        const int b = first + static_cast<int>(random() % static_cast<unsigned>(span));
        if (a != b) pairs.push_back(BodyPair{std::min(a, b), std::max(a, b)});
      }
      check(world, pairs);
    }
  }
}

/// Runs 10 steps of `scene` with a contact recorder on 1 and on 2 threads (sweeps split from
/// two pairs on) and checks that both recorded the same impulses in the same order.
void threadsCheckSameRecords(const Scene& scene) {
  std::vector<ContactRecord> records[2];
  for (const int threads : {1, 2}) {
    ContactRecorder recorder;
    StepSettings settings = scene.settings;
    settings.parallel.threads = threads;
    settings.parallel.minPairs = 2;
    settings.contactRecorder = &recorder;
    threadsRun<2>(scene, settings, 10);
    records[threads - 1] = recorder.records();
  }
  REQUIRE(records[0].size() > 100);
  REQUIRE(records[1].size() == records[0].size());
  bool same = true;
  for (std::size_t k = 0; k < records[0].size(); ++k) {
    const ContactRecord& a = records[0][k];
    const ContactRecord& b = records[1][k];
    same = same && a.stage == b.stage && a.owner == b.owner && a.other == b.other && a.point == b.point &&
           a.normal == b.normal && a.impulse == b.impulse;
  }
  CHECK(same);
}

/// Runs `steps` steps of the bundled scene `name` with 1, 2 and 4 threads (islands split
/// from two pairs on) and checks that the states and counters are identical, and that the
/// runs with several threads did split sweeps into islands.
/// `adjust` sets what no scene field reaches (chapter 8's loop tolerances). Returns the
/// one-thread outcome.
ThreadsOutcome checkThreadCounts(const std::string& name, int steps, const std::vector<std::string>& overrides = {},
                                 const std::function<void(StepSettings&)>& adjust = {}) {
  CAPTURE(name);
  const Scene scene = loadScene(std::string(STACKBOOK_SCENES_DIR) + "/" + name + ".json", overrides);
  StepSettings settings = scene.settings;
  if (adjust) adjust(settings);
  settings.parallel.minPairs = 2;
  settings.parallel.bodiesPerTask = 1;      // the per-body loops split too
  settings.parallel.graphPairsPerTask = 2;  // and the contact graph's tests
  settings.parallel.threads = 1;
  const ThreadsOutcome one = threadsRunScene(scene, settings, steps);
  CHECK(one.islandSweeps == 0);
  for (const int threads : {2, 4}) {
    CAPTURE(threads);
    settings.parallel.threads = threads;
    const ThreadsOutcome many = threadsRunScene(scene, settings, steps);
    CHECK(many.hash == one.hash);
    CHECK(many.counts == one.counts);
    CHECK(many.islandSweeps > 0);
  }
  return one;
}

/// The contact graph of the scene's start (chapter 9) on 1, 2 and 4 threads (blocks from two
/// pairs on): the same edges in the same order, and the same detection work counted.
template <int D>
void checkGraphThreadCounts(const std::string& name) {
  CAPTURE(name);
  const Scene scene = loadScene(std::string(STACKBOOK_SCENES_DIR) + "/" + name + ".json");
  const World<D>& world = std::get<SceneBodies<D>>(scene.bodies).world;
  ContactGraphSettings settings = stepGraphSettings(scene.settings, resolveEffects<D>(world, scene.settings.effects));
  settings.parallel.graphPairsPerTask = 2;
  settings.parallel.threads = 1;
  DetectionCounters one;
  const ContactGraph serial = worldContactGraph<D>(world, settings, &one);
  REQUIRE(serial.edgeCount() > 50);  // enough pairs for every thread to take several blocks
  for (const int threads : {2, 4}) {
    CAPTURE(threads);
    settings.parallel.threads = threads;
    DetectionCounters many;
    const ContactGraph parallel = worldContactGraph<D>(world, settings, &many);
    CHECK(parallel.edges() == serial.edges());
    CHECK(many == one);
  }
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("The islands of a sweep join pairs through dynamic bodies only, in the sweep's order") {
  World<2> world;
  const auto shape = std::make_shared<BoxShape<2>>(makeBoxShape<2>(Vec2(1.0, 1.0)));
  world.addBody(makeStaticBody<2>(Vec2(0.0, 0.0)), shape);  // 0: static ground
  for (int i = 1; i <= 5; ++i) world.addBody(makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0)), shape);
  // Pairs in sweep order: 0-1, 0-3, 1-2, 4-5, 0-2, 3-4.
  const std::vector<BodyPair> pairs{{0, 1}, {0, 3}, {1, 2}, {4, 5}, {0, 2}, {3, 4}};
  const PairIslands islands = pairIslands<2>(world, pairs);
  // Through the static ground nothing joins: {1, 2} holds pairs 0, 2, 4; {3, 4, 5} pairs 1, 3, 5.
  REQUIRE(islands.islandCount() == 2);
  CHECK(std::vector<std::size_t>(islands.pairs.begin(), islands.pairs.begin() + 3) ==
        std::vector<std::size_t>{0, 2, 4});
  CHECK(std::vector<std::size_t>(islands.pairs.begin() + 3, islands.pairs.end()) ==
        std::vector<std::size_t>{1, 3, 5});
  // A body made static (as shock propagation freezes a level) splits its island.
  world.bodies[4].inverseMass = 0.0;
  world.bodies[4].inverseInertia.setZero();
  const PairIslands split = pairIslands<2>(world, pairs);
  CHECK(split.islandCount() == 3);  // {1, 2}: pairs 0, 2, 4; {3}: pairs 1, 5; {5}: pair 3
  CHECK(split.size(0) == 3);
  CHECK(split.size(1) == 2);
  CHECK(split.size(2) == 1);
  CHECK(split.pairs[3] == 1);
  CHECK(split.pairs[4] == 5);
  CHECK(split.pairs[5] == 3);
}

// [test_pair_islands_definition]
TEST_CASE("The islands of a sweep are the connected components of its pairs in any world and any order of calls") {
  // The definition written out: breadth-first search over the dynamic bodies, islands
  // numbered by their first pair in the list, pairs ascending within an island.
  const auto reference = [](const World<2>& world, const std::vector<BodyPair>& pairs) {
    const auto dynamic = [&world](int i) { return !world.bodies[static_cast<std::size_t>(i)].isStatic(); };
    std::vector<int> islandOf(pairs.size(), -1);
    int islands = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      if (islandOf[k] >= 0) continue;
      const int id = islands++;
      islandOf[k] = id;
      std::vector<std::size_t> frontier{k};
      while (!frontier.empty()) {
        const BodyPair p = pairs[frontier.back()];
        frontier.pop_back();
        for (std::size_t m = 0; m < pairs.size(); ++m) {
          if (islandOf[m] >= 0) continue;
          const BodyPair q = pairs[m];
          const bool shares = (dynamic(p.first) && (q.first == p.first || q.second == p.first)) ||
                              (dynamic(p.second) && (q.first == p.second || q.second == p.second));
          if (!shares) continue;
          islandOf[m] = id;
          frontier.push_back(m);
        }
      }
    }
    PairIslands out;
    out.begin.assign(static_cast<std::size_t>(islands) + 1, 0);
    for (int c = 0; c < islands; ++c) {
      for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (islandOf[k] == c) out.pairs.push_back(k);
      }
      out.begin[static_cast<std::size_t>(c) + 1] = out.pairs.size();
    }
    return out;
  };
  int compared = 0, several = 0;
  threadsForRandomPairLists(29, [&](const World<2>& world, const std::vector<BodyPair>& pairs) {
    const PairIslands expected = reference(world, pairs);
    const PairIslands got = pairIslands<2>(world, pairs);
    CHECK(got.begin == expected.begin);
    CHECK(got.pairs == expected.pairs);
    ++compared;
    if (expected.islandCount() > 1) ++several;
  });
  CHECK(compared == 200);
  CHECK(several > 50);  // the trials split into islands, not only one
}
// [test_pair_islands_definition]

// [test_level_waves]
TEST_CASE("The waves of the pass's levels: every level once, after each level it reads, in the first wave it can be") {
  for (const char* name : {"many_pyramids_2d", "pyramid_20_2d", "plank_on_two_stacks_2d"}) {
    CAPTURE(name);
    const Scene scene = loadScene(std::string(STACKBOOK_SCENES_DIR) + "/" + name + ".json");
    const World<2>& world = std::get<SceneBodies<2>>(scene.bodies).world;
    const ContactGraph graph =
        worldContactGraph<2>(world, stepGraphSettings(scene.settings, resolveEffects<2>(world, scene.settings.effects)));
    const ContactLevels levels = topologicalLevels(graph);
    std::vector<char> skipped(levels.levelCount(), 0);
    for (std::size_t l = 0; l < levels.levelCount(); ++l) skipped[l] = isolatedLevel<2>(world, graph, levels, l) ? 1 : 0;
    const std::vector<std::vector<std::size_t>> waves = levelWaves<2>(world, levels, skipped);
    std::vector<int> waveOf(levels.levelCount(), -1);
    std::size_t widest = 0;
    for (std::size_t w = 0; w < waves.size(); ++w) {
      REQUIRE_FALSE(waves[w].empty());
      widest = std::max(widest, waves[w].size());
      for (std::size_t i = 0; i < waves[w].size(); ++i) {
        const std::size_t l = waves[w][i];
        CHECK(waveOf[l] == -1);  // once
        if (i > 0) CHECK(waves[w][i - 1] < l);  // ascending inside a wave
        waveOf[l] = static_cast<int>(w);
      }
    }
    for (std::size_t l = 0; l < levels.levelCount(); ++l) {
      CAPTURE(l);
      CHECK((waveOf[l] == -1) == (skipped[l] != 0));  // every level that is swept, and only those
      if (skipped[l] != 0) continue;
      // The levels whose dynamic bodies l's pairs read: all in earlier waves, one in the wave just before.
      int latest = -1;
      for (const ContactPair& c : levels.pairs(l)) {
        const std::size_t k = static_cast<std::size_t>(levels.levelOfBody[static_cast<std::size_t>(c.below)]);
        if (k == l || world.bodies[static_cast<std::size_t>(c.below)].isStatic()) continue;
        CHECK(waveOf[k] >= 0);
        CHECK(waveOf[k] < waveOf[l]);
        latest = std::max(latest, waveOf[k]);
      }
      CHECK(waveOf[l] == latest + 1);
    }
    CHECK(widest >= 2);  // some wave has levels to sweep at the same time
  }
}
// [test_level_waves]

TEST_CASE("The contact graph is the same for 1, 2 and 4 threads: its edges in order and its work") {
  checkGraphThreadCounts<2>("many_pyramids_2d");
  checkGraphThreadCounts<3>("pyramid_3d");
}

TEST_CASE("A step is bit for bit the same for 1, 2 and 4 threads: many islands (2D)") {
  checkThreadCounts("many_pyramids_2d", 40);
  checkThreadCounts("bouncing_balls_2d", 2500);  // the balls reach the floor after about 1 s
}

TEST_CASE("A step is bit for bit the same for 1, 2 and 4 threads: nonconvex shapes (2D and 3D)") {
  checkThreadCounts("shapes_in_bin_2d", 300);
  checkThreadCounts("rings_on_pegs_3d", 300);
}

TEST_CASE("A step is bit for bit the same for 1, 2 and 4 threads: the pass as the contact stage, "
          "one cone per step") {
  checkThreadCounts("many_pyramids_2d", 30,
                    {"solver.shock.replacesContactStage=true", "solver.shock.sweepsPerLevel=6",
                     "solver.frictionCone=\"step\""});
  // GBF's step (the contact stage, then the pass) with one cone per step, at the scene's
  // former dt; the scene as bundled runs the short pair loops, tested below.
  checkThreadCounts("pyramid_3d", 15, {"solver.preset=gbf", "dt=0.002", "solver.frictionCone=\"step\""});
}

TEST_CASE("A step is bit for bit the same for 1, 2 and 4 threads: the short pair loops of the bundled pyramids") {
  checkThreadCounts("pyramid_3d", 15);  // "preset": "passAsContactShortLoops", dt = 1/60
}

TEST_CASE("A step is bit for bit the same for 1, 2 and 4 threads: the loop tolerances, the implicit "
          "midpoint rotation, exact deepest points, sleeping") {
  // The loop tolerances read the largest approach speed of a sweep, which every island
  // raises; the pair tolerance must have ended some pair loops for the check to mean anything.
  // GBF's step, named: the scene's default (chapter 12) has no contact stage for them to end.
  const ThreadsOutcome tolerant =
      checkThreadCounts("many_pyramids_2d", 30, {"solver.preset=\"gbf\"", "solver.rotation=\"implicitMidpoint\""}, [](StepSettings& s) {
        s.pairImpulseTolerance = 0.05;
        s.stageApproachTolerance = 1e-4;
        s.shock.pairImpulseTolerance = 0.05;
        s.shock.levelApproachTolerance = 1e-4;
      });
  CHECK(tolerant.pairConvergences > 0);
  checkThreadCounts("bouncing_balls_2d", 2500, {"solver.surfaceQuery=\"deepestPoint\""});
  // Four resting pyramids fall asleep after 0.02 s at rest; the sleepers are static to the
  // islands of the later sweeps.
  const ThreadsOutcome sleeping =
      checkThreadCounts("many_pyramids_2d", 60, {"solver.sleep.enabled=true", "solver.sleep.time=0.02"});
  CHECK(sleeping.fellAsleep > 0);
}

TEST_CASE("The scene fields solver.threads and solver.sleep reach the step settings, bad values get one line") {
  const std::string file = std::string(STACKBOOK_SCENES_DIR) + "/box_stack_2d.json";
  const Scene scene = loadScene(file, {"solver.threads=3", "solver.sleep.enabled=true", "solver.sleep.time=0.25",
                                       "solver.sleep.linearSpeed=0.01", "solver.sleep.angularSpeed=0.02",
                                       "solver.sleep.wakeMargin=0.1"});
  CHECK(scene.settings.parallel.threads == 3);
  CHECK(scene.settings.sleep.enabled);
  CHECK(scene.settings.sleep.time == 0.25);
  CHECK(scene.settings.sleep.linearSpeed == 0.01);
  CHECK(scene.settings.sleep.angularSpeed == 0.02);
  CHECK(scene.settings.sleep.wakeMargin == 0.1);
  const Scene plain = loadScene(file);
  CHECK(plain.settings.parallel.threads == 0);  // every hardware thread
  CHECK_FALSE(plain.settings.sleep.enabled);
  CHECK_THROWS_WITH_AS(loadScene(file, {"solver.threads=-1"}), doctest::Contains("/solver/threads: must be an integer in [0, 1024], got -1"),
                       SceneError);
  CHECK_THROWS_WITH_AS(loadScene(file, {"solver.sleep.time=-2"}), doctest::Contains("/solver/sleep/time: must be >= 0"),
                       SceneError);
  CHECK_THROWS_WITH_AS(loadScene(file, {"solver.sleep.sleepy=1"}), doctest::Contains("/solver/sleep/sleepy"),
                       SceneError);
}

TEST_CASE("A contact recorder receives the same impulses in the same order for 1 and 2 threads") {
  const Scene scene = loadScene(std::string(STACKBOOK_SCENES_DIR) + "/many_pyramids_2d.json");
  threadsCheckSameRecords(scene);
}

// [test_pair_colours_definition]
TEST_CASE("The colours of a sweep are the greedy colouring of its pairs in list order in any world") {
  // The definition written out: pair k takes the smallest colour below 64 that no earlier
  // pair sharing one of its dynamic bodies took; none free: the overflow class 64.
  const auto reference = [](const World<2>& world, const std::vector<BodyPair>& pairs) {
    const auto dynamic = [&world](int i) { return !world.bodies[static_cast<std::size_t>(i)].isStatic(); };
    const auto shareDynamic = [&](const BodyPair& p, const BodyPair& q) {
      for (const int b : {p.first, p.second}) {
        if (dynamic(b) && (q.first == b || q.second == b)) return true;
      }
      return false;
    };
    std::vector<std::size_t> colourOf(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      std::vector<bool> taken(65, false);
      for (std::size_t m = 0; m < k; ++m) {
        if (shareDynamic(pairs[k], pairs[m])) taken[colourOf[m]] = true;
      }
      std::size_t c = 0;
      while (c < 64 && taken[c]) ++c;
      colourOf[k] = c;
    }
    PairColours out;
    out.begin.assign(66, 0);
    for (std::size_t c = 0; c <= 64; ++c) {
      for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (colourOf[k] == c) out.pairs.push_back(k);
      }
      out.begin[c + 1] = out.pairs.size();
    }
    return out;
  };
  const auto shape = std::make_shared<BoxShape<2>>(makeBoxShape<2>(Vec2(1.0, 1.0)));
  int compared = 0, coloured = 0;
  threadsForRandomPairLists(31, [&](const World<2>& world, const std::vector<BodyPair>& pairs) {
    const PairColours expected = reference(world, pairs);
    const PairColours got = pairColours<2>(world, pairs);
    CHECK(got.begin == expected.begin);
    CHECK(got.pairs == expected.pairs);
    ++compared;
    if (expected.size(1) > 0) ++coloured;
  });
  CHECK(compared == 200);
  CHECK(coloured > 50);  // the trials needed a second colour, not only one
  // 70 pairs of one dynamic body: 64 colours of one pair each, then the overflow class of 6,
  // whose pairs share that body and are swept in order on one thread.
  World<2> star;
  star.addBody(makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0)), shape);
  std::vector<BodyPair> spokes;
  for (int i = 1; i <= 70; ++i) {
    star.addBody(makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0)), shape);
    spokes.push_back(BodyPair{0, i});
  }
  const PairColours full = pairColours<2>(star, spokes);
  REQUIRE(full.classCount() == 65);
  for (std::size_t c = 0; c < 64; ++c) CHECK(full.size(c) == 1);
  CHECK(full.size(64) == 6);
  CHECK_FALSE(full.independent(64));
  CHECK(full.pairs[64] == 64);
}
// [test_pair_colours_definition]

// [test_colours_sweep_order]
TEST_CASE("A sweep colour by colour is the list-order sweep of its pairs in colour order, on any thread count") {
  // Four boxes in a column on the ground, falling into each other: every pair of the chain
  // shares a dynamic body with the next, so the chain is one island. The colours are
  // {ground-1, 2-3} and {1-2, 3-4}.
  const auto shape = std::make_shared<BoxShape<2>>(makeBoxShape<2>(Vec2(1.0, 1.0)));
  World<2> start;
  start.addBody(makeStaticBody<2>(Vec2(0.0, -0.5)), std::make_shared<BoxShape<2>>(makeBoxShape<2>(Vec2(8.0, 1.0))));
  for (int i = 0; i < 4; ++i) {
    RigidBody<2> box = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 6.0));
    box.position = Vec2(0.05 * i, 0.499 + 0.999 * i);
    box.orientation = Orientation<2>(0.02 * (i % 2 == 0 ? 1 : -1));
    box.velocity = Vec2(0.1 * i, -1.0 - 0.5 * i);
    start.addBody(box, shape);
  }
  const std::vector<BodyPair> chain{{0, 1}, {1, 2}, {2, 3}, {3, 4}};
  const PairColours colours = pairColours<2>(start, chain);
  REQUIRE(colours.size(0) == 2);
  REQUIRE(colours.size(1) == 2);
  std::vector<BodyPair> reordered;
  for (const std::size_t p : colours.pairs) reordered.push_back(chain[p]);
  CHECK(reordered == std::vector<BodyPair>{{0, 1}, {2, 3}, {1, 2}, {3, 4}});
  const auto sweepOnce = [&start](const std::vector<BodyPair>& pairs, PairOrder order, int threads) {
    World<2> world = start;
    StepSettings settings;
    settings.pairOrder = order;
    settings.parallel.threads = threads;
    settings.parallel.minPairs = 2;  // a colour of two pairs splits
    std::vector<CollisionBody<2>> views = stageViews<2>(world, Lookahead::Velocity, settings.dt);
    const StageSpec spec{Lookahead::Velocity, 1, 20, [](int, const PairMaterial&) { return 0.0; }};
    StageCounters counters;
    const int applied = sweepPairs<2>(world, views, pairs, spec, 1, settings.dt, settings, counters);
    return std::make_tuple(threadsStateHash<2>(world), applied, counters.islandSweeps);
  };
  const auto [serial, serialImpulses, serialSplits] = sweepOnce(reordered, PairOrder::List, 1);
  CHECK(serialImpulses > 4);
  CHECK(serialSplits == 0);
  for (const int threads : {1, 2, 4}) {
    CAPTURE(threads);
    const auto [hash, impulses, splits] = sweepOnce(chain, PairOrder::Colours, threads);
    CHECK(hash == serial);
    CHECK(impulses == serialImpulses);
    CHECK((splits > 0) == (threads > 1));
  }
  // The list order itself is another Gauss-Seidel order, with another result.
  CHECK(std::get<0>(sweepOnce(chain, PairOrder::List, 1)) != serial);
}
// [test_colours_sweep_order]

TEST_CASE("A step colour by colour is bit for bit the same for 1, 2 and 4 threads, in one island too") {
  // One island: the bin of shapes and the pyramid of base 20 (the pass's levels), where
  // islands leave one thread all the work; many islands: the four pyramids.
  checkThreadCounts("shapes_in_bin_2d", 300, {"solver.pairOrder=\"colours\""});
  checkThreadCounts("many_pyramids_2d", 30, {"solver.pairOrder=\"colours\""});
  checkThreadCounts("pyramid_20_2d", 10, {"solver.pairOrder=\"colours\""});
  checkThreadCounts("rings_on_pegs_3d", 300, {"solver.pairOrder=\"colours\""});
  // With the loop tolerances (which end some pair loops) and sleeping (whose sleepers are
  // static to the colours of later sweeps), under GBF's step, named: the scene's default
  // (chapter 12) has no contact stage for the tolerances to end.
  const ThreadsOutcome tolerant = checkThreadCounts(
      "many_pyramids_2d", 60,
      {"solver.preset=\"gbf\"", "solver.pairOrder=\"colours\"", "solver.sleep.enabled=true", "solver.sleep.time=0.02"},
      [](StepSettings& s) {
        s.pairImpulseTolerance = 0.05;
        s.stageApproachTolerance = 1e-4;
      });
  CHECK(tolerant.pairConvergences > 0);
  CHECK(tolerant.fellAsleep > 0);
  // A contact recorder gets the impulses in the serial colour order on two threads too.
  const Scene scene = loadScene(std::string(STACKBOOK_SCENES_DIR) + "/many_pyramids_2d.json",
                                {"solver.pairOrder=\"colours\""});
  threadsCheckSameRecords(scene);
}

TEST_CASE("Thread settings outside their ranges are rejected with the field name") {
  const std::pair<void (*)(ParallelSettings&), const char*> bad[] = {
      {[](ParallelSettings& p) { p.threads = -1; }, "parallel.threads must be >= 0"},
      {[](ParallelSettings& p) { p.minPairs = -1; }, "parallel.minPairs must be >= 0"},
      {[](ParallelSettings& p) { p.bodiesPerTask = 0; }, "parallel.bodiesPerTask must be >= 1"},
      {[](ParallelSettings& p) { p.runsPerThread = 0; }, "parallel.runsPerThread must be >= 1, got 0"}};
  for (const auto& entry : bad) {  // not a structured binding: CAPTURE's lambda takes it
    const char* message = entry.second;
    CAPTURE(message);
    StepSettings s;
    entry.first(s.parallel);
    CHECK_THROWS_WITH_AS(validateStepSettings(s, "test"), doctest::Contains(message), std::invalid_argument);
  }
}

TEST_CASE("The scene field solver.pairOrder reaches the step settings and changes the result, bad values get one line") {
  const std::string file = std::string(STACKBOOK_SCENES_DIR) + "/many_pyramids_2d.json";  // in contact from the start
  CHECK(loadScene(file).settings.pairOrder == PairOrder::List);
  CHECK(loadScene(file, {"solver.pairOrder=\"list\""}).settings.pairOrder == PairOrder::List);
  // GBF's step, named: under the scene's default (chapter 12) each resting pyramid's pairs are
  // stopped by whole patches, whose result does not depend on the order of the pairs.
  const Scene coloured = loadScene(file, {"solver.preset=\"gbf\"", "solver.pairOrder=\"colours\""});
  CHECK(coloured.settings.pairOrder == PairOrder::Colours);
  StepSettings one = coloured.settings;
  one.parallel.threads = 1;
  StepSettings list = one;
  list.pairOrder = PairOrder::List;
  CHECK(threadsRun<2>(coloured, one, 10).hash != threadsRun<2>(coloured, list, 10).hash);
  CHECK_THROWS_WITH_AS(loadScene(file, {"solver.pairOrder=\"rainbow\""}),
                       doctest::Contains("/solver/pairOrder: must be \"list\" or \"colours\", got \"rainbow\""),
                       SceneError);
}

}  // TEST_SUITE
