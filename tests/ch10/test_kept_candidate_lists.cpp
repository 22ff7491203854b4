// Chapter 7's store of candidate lists ("Keeping lists between stages") on whole steps and
// bundled scenes: lists kept from stage to stage and step to step change no bit of the
// state, whatever lists the store holds (even another world's), and they save list making;
// a store kept with other shapes is dropped.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "stackbook/collision/candidate_list_store.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

TEST_SUITE(STACKBOOK_CHAPTER) {

namespace {

/// True when every body of `a` and `b` has the same bits of position, orientation, velocity
/// and angular momentum.
template <int D>
bool storeSameBits(const World<D>& a, const World<D>& b) {
  if (a.bodies.size() != b.bodies.size()) return false;
  const auto same = [](const auto& x, const auto& y) {
    return std::memcmp(x.data(), y.data(), sizeof(double) * static_cast<std::size_t>(x.size())) == 0;
  };
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const RigidBody<D>& p = a.bodies[i];
    const RigidBody<D>& q = b.bodies[i];
    if (!same(p.position, q.position) || !same(p.velocity, q.velocity) ||
        !same(p.angularMomentum, q.angularMomentum)) {
      return false;
    }
    if constexpr (D == 2) {
      const double u = p.orientation.angle(), v = q.orientation.angle();
      if (std::memcmp(&u, &v, sizeof u) != 0) return false;
    } else {
      if (!same(p.orientation.coeffs(), q.orientation.coeffs())) return false;
    }
  }
  return true;
}

/// Lists made in all stages of `steps` steps of `world` (which is stepped).
template <int D>
std::int64_t storeListsMade(World<D>& world, const StepSettings& settings, int steps, bool forgetEachStep) {
  const PostContactHook<D> hook = shockPropagationHook<D>();
  std::int64_t made = 0;
  for (int n = 0; n < steps; ++n) {
    if (forgetEachStep) world.candidateLists = CandidateListStore<D>{};
    const StepCounters c = step<D>(world, settings, hook);
    made += c.collision.detection.candidateListsMade + c.contact.detection.candidateListsMade +
            c.shock.detection.candidateListsMade;
  }
  return made;
}

}  // namespace

TEST_CASE_TEMPLATE("lists kept between stages and steps change no bit and save list making", Dim, In2D, In3D) {
  // One bundled nonconvex scene per dimension, with its own settings, run three ways: lists
  // kept from stage to stage and step to step; forgotten before every step; and a store
  // swapped before every step for the one of another run of the scene (different poses,
  // the same shapes), whose lists are made for poses this world does not have.
  constexpr int D = Dim::value;
  const std::string name = D == 2 ? "shapes_in_bin_2d" : "rings_on_pegs_3d";
  const Scene scene = loadScene(std::string(STACKBOOK_SCENES_DIR) + "/" + name + ".json");
  // From the first step that makes lists (bodies in contact), so that there is something to keep.
  World<D> start = std::get<SceneBodies<D>>(scene.bodies).world;
  int settle = 0;
  for (World<D> probe = start; settle < 5000 && storeListsMade<D>(probe, scene.settings, 1, false) == 0; ++settle) {
    start = probe;
  }
  REQUIRE(settle < 5000);
  const int steps = 100;
  World<D> kept = start, forgotten = start, foreign = start, ahead = start;
  const std::int64_t madeKept = storeListsMade<D>(kept, scene.settings, steps, false);
  const std::int64_t madeForgotten = storeListsMade<D>(forgotten, scene.settings, steps, true);
  storeListsMade<D>(ahead, scene.settings, 2 * steps, false);  // a store of later poses
  const PostContactHook<D> hook = shockPropagationHook<D>();
  for (int n = 0; n < steps; ++n) {
    foreign.candidateLists = ahead.candidateLists;
    step<D>(foreign, scene.settings, hook);
  }
  CHECK(storeSameBits<D>(kept, forgotten));
  CHECK(storeSameBits<D>(kept, foreign));
  // Pairs that met in one step meet again in the next: their kept lists are not made again.
  CAPTURE(madeKept);
  CAPTURE(madeForgotten);
  CHECK(madeKept > 0);
  CHECK(madeKept < madeForgotten);
}

TEST_CASE_TEMPLATE("the centre rule asks through the candidate lists and changes no bit", Dim, In2D, In3D) {
  // Chapter 8's impulse point at the depth-weighted centre needs every interfering sample of
  // a pair, not only the deepest. The same bundled scenes, from their first impulse, run 100
  // steps under that rule with the default reach (lists kept) and with reach 0 (every
  // sample carried into the other body's frame): the same bits, with fewer samples carried.
  constexpr int D = Dim::value;
  const std::string name = D == 2 ? "shapes_in_bin_2d" : "rings_on_pegs_3d";
  const Scene scene = loadScene(std::string(STACKBOOK_SCENES_DIR) + "/" + name + ".json");
  StepSettings listed = scene.settings;
  listed.impulsePoint.rule = ImpulsePointRule::DepthWeightedCentre;
  // Samples everywhere: the scene's default (chapter 12) asks the pegs, cylinders, for their exact
  // deepest point, which pairInterference() finds without the lists this test is about.
  listed.detection.narrow.surfaceQuery = SurfaceQuery::Samples;
  REQUIRE(listed.detection.narrow.candidateReach > 0.0);
  StepSettings everySample = listed;
  everySample.detection.narrow.candidateReach = 0.0;
  // From the step before the first impulse, so that every one of the 100 steps has contact.
  const PostContactHook<D> hook = shockPropagationHook<D>();
  const auto impulses = [](const StepCounters& c) {
    return c.collision.impulses + c.contact.impulses + c.shock.impulses;
  };
  World<D> start = std::get<SceneBodies<D>>(scene.bodies).world;
  int settle = 0;
  for (World<D> probe = start; settle < 5000 && impulses(step<D>(probe, listed, hook)) == 0; ++settle) {
    start = probe;
  }
  REQUIRE(settle < 5000);
  World<D> a = start, b = start;
  std::int64_t samplesListed = 0, samplesEvery = 0, centres = 0;
  for (int n = 0; n < 100; ++n) {
    const StepCounters x = step<D>(a, listed, hook);
    const StepCounters y = step<D>(b, everySample, hook);
    samplesListed += x.collision.detection.samplesTransformed + x.contact.detection.samplesTransformed +
                     x.shock.detection.samplesTransformed;
    samplesEvery += y.collision.detection.samplesTransformed + y.contact.detection.samplesTransformed +
                    y.shock.detection.samplesTransformed;
    centres += impulses(x);
  }
  CHECK(storeSameBits<D>(a, b));
  CAPTURE(samplesListed);
  CAPTURE(samplesEvery);
  CHECK(centres > 0);
  CHECK(samplesListed < samplesEvery);  // 2D: 51k against 1.2M; 3D, with rings landing at speed: 0.69M against 1.1M
}

TEST_CASE("a store kept with other shapes is dropped, and the step goes on with the new shapes") {
  // A box resting on the ground; between two steps the box's shape is replaced by a larger
  // one. The store, kept with the old shapes, must not answer for the new one.
  World<2> world;
  world.gravity = Vec2(0.0, -9.81);
  world.addBody(makeStaticBody<2>(Vec2(0.0, -0.5)), std::make_shared<BoxShape<2>>(makeBoxShape<2>(Vec2(10.0, 1.0))));
  RigidBody<2> box = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 6.0));
  box.position = Vec2(0.0, 0.499);
  world.addBody(box, std::make_shared<BoxShape<2>>(makeBoxShape<2>(Vec2(1.0, 1.0))));
  StepSettings settings;
  settings.dt = 1e-3;
  for (int n = 0; n < 5; ++n) stackingStep<2>(world, settings);
  REQUIRE_FALSE(world.candidateLists.pairs.empty());
  CHECK(world.candidateLists.shapes == world.shapes);
  world.shapes[1] = std::make_shared<BoxShape<2>>(makeBoxShape<2>(Vec2(1.2, 1.2)));
  World<2> fresh = world;
  fresh.candidateLists = CandidateListStore<2>{};
  for (int n = 0; n < 5; ++n) {
    stackingStep<2>(world, settings);
    stackingStep<2>(fresh, settings);
  }
  CHECK(world.candidateLists.shapes == world.shapes);
  CHECK(storeSameBits<2>(world, fresh));
  for (const RigidBody<2>& b : world.bodies) CHECK(b.position.allFinite());
}

}  // TEST_SUITE
