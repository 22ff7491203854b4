// Chapter 9, "The welded pass" (welded_pass.hpp, the preset "weldedPass"): the contact stage's
// impulses carried to lower bodies (Eq. (9.11)), body welds (Eq. (9.12)) with the best subset's
// spin bound (Eq. (9.13)), and the island guard (Eq. (9.14)). Each equation is checked by hand on
// a small case; the step holds stacks and pyramids to round-off, ends exactly as GBF's step
// wherever nothing welds, and is the same bit for bit for any thread count and with a recorder.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../ch08/scene_builders.hpp"
#include "../support/dimensions.hpp"
#include "stack_scenes.hpp"
#include "stackbook/stacking/solver_preset.hpp"
#include "stackbook/stacking/welded_pass.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;

namespace {

/// Kinetic plus potential energy of the dynamic bodies.
template <int D>
double energy(const World<D>& w) {
  double e = 0.0;
  for (const RigidBody<D>& b : w.bodies) {
    if (!b.isStatic()) e += b.kineticEnergy() - b.mass() * w.gravity.dot(b.position);
  }
  return e;
}

struct WeldedRun {
  double moved = 0.0;         ///< largest distance any box moved (m)
  double energyGain = 0.0;    ///< largest rise of the energy over its start (J)
  StepCounters counters;      ///< summed over the steps
  int steps = 0;
};

/// `seconds` of `world` at 60 Hz under `settings` (the welded pass's preset unless given).
template <int D>
WeldedRun runWelded(World<D>& world, double seconds, StepSettings settings = gbfStepWeldedPass()) {
  settings.dt = 1.0 / 60.0;
  const World<D> start = world;
  const double e0 = energy<D>(world);
  WeldedRun run;
  run.steps = static_cast<int>(std::lround(seconds / settings.dt));
  for (int n = 0; n < run.steps; ++n) {
    run.counters += stackingStep<D>(world, settings);
    run.energyGain = std::max(run.energyGain, energy<D>(world) - e0);
  }
  run.moved = stacks::largestDisplacement<D>(start, world);
  return run;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("the welded pass's preset: its fields and presets over presets and the settings it refuses") {
  StepSettings base;
  base.dt = 0.02;
  base.parallel.threads = 3;
  const StepSettings welded = gbfStepWeldedPass(base);
  CHECK(welded.shock.welded.enabled);
  CHECK(welded.dt == base.dt);
  CHECK(welded.parallel.threads == 3);
  // GBF's loops are kept: an island where nothing welds runs GBF's step.
  const StepSettings gbf;
  CHECK(welded.contactPairIterations == gbf.contactPairIterations);
  CHECK(welded.collisionPairIterations == gbf.collisionPairIterations);
  CHECK(welded.pairImpulseTolerance == gbf.pairImpulseTolerance);
  CHECK(welded.shock.sweepsPerLevel == gbf.shock.sweepsPerLevel);
  CHECK_FALSE(welded.shock.replacesContactStage);
  // The welded pass's own loops.
  CHECK(welded.shock.welded.sweepsPerLevel == 20);
  CHECK(welded.shock.welded.pairIterations == 5);
  CHECK(welded.shock.welded.pairImpulseTolerance == 0.2);
  CHECK(welded.shock.welded.levelApproachTolerance == 1e-9);
  CHECK(welded.shock.welded.impulsePoint == ImpulsePointRule::StickingPatch);
  CHECK(welded.shock.welded.weldSpinBound == PatchSpinBound::BestSubset);
  CHECK(welded.shock.welded.bodyWelds);
  CHECK(welded.shock.welded.energyGuard);
  const StepSettings sweeps = weldedPassSweepSettings(welded);
  CHECK(sweeps.shock.replacesContactStage);
  CHECK(sweeps.shock.sweepsPerLevel == 20);
  CHECK(sweeps.shock.restitutionAt(20) == 0.0);
  CHECK(sweeps.frictionCone == FrictionConeRule::StepTotal);
  CHECK(sweeps.impulsePoint.rule == ImpulsePointRule::StickingPatch);
  // By name, and every other preset turns it off.
  CHECK(applySolverPreset(SolverPreset::WeldedPass, base).shock.welded.enabled);
  for (const auto& entry : kSolverPresets) {
    const SolverPreset preset = entry.first;
    const std::string word(entry.second);  // a named copy: clang's CAPTURE cannot take a structured binding
    CAPTURE(word);
    CHECK(applySolverPreset(preset, welded).shock.welded.enabled == (preset == SolverPreset::WeldedPass));
  }
  // It needs the contact stage whose impulses it carries, and loops of at least one.
  StepSettings bad = welded;
  bad.shock.replacesContactStage = true;
  CHECK_THROWS_AS(validateStepSettings(bad), std::invalid_argument);
  bad = welded;
  bad.shock.welded.sweepsPerLevel = 0;
  CHECK_THROWS_AS(validateStepSettings(bad), std::invalid_argument);
  bad = welded;
  bad.shock.welded.pairImpulseTolerance = 1.0;
  CHECK_THROWS_AS(validateStepSettings(bad), std::invalid_argument);
  bad = welded;
  bad.shock.welded.levelApproachTolerance = -1.0;
  CHECK_THROWS_AS(validateStepSettings(bad), std::invalid_argument);
}

// [best_subset_test]
TEST_CASE("Eq. (9.13): the best subset's spin bound by hand") {
  // The four corners of a unit square and its centre, in the plane z = 0.
  const std::vector<Vec3> points = {Vec3(0.5, 0.5, 0.0), Vec3(-0.5, 0.5, 0.0), Vec3(-0.5, -0.5, 0.0),
                                    Vec3(0.5, -0.5, 0.0), Vec3(0.0, 0.0, 0.0)};
  const Vec3 n = Vec3::UnitZ();
  // Pressure at the centre: all five points hold it but the nearest is at distance 0; the
  // corners alone (rho^2 = 0.5) still hold it; fewer than the four corners are at most two.
  CHECK(detail::bestSubsetSpin<3>(points, n, Vec3::Zero(), 1e-12) == doctest::Approx(0.5).epsilon(1e-14));
  // Pressure at (0.3, 0): radii 0.3 (centre), sqrt(0.29) (right corners), sqrt(0.89) (left
  // corners). All five hold it (0.09), the four corners too (0.29), the two left ones cannot.
  CHECK(detail::bestSubsetSpin<3>(points, n, Vec3(0.3, 0.0, 0.0), 1e-12) == doctest::Approx(0.29).epsilon(1e-14));
  // A unit cube (mass 1, I = 1/6 about every axis) sinking at 0.1 m/s onto static ground
  // while it turns about the vertical at w: stopping it takes J = (0, 0, 0.1) through its centre
  // and L = -I w about the patch centre, a spin of w / 6. With mu = 0.5 the corners carry
  // (mu jn) rho^2 / dmax = 0.05 * 0.5 / sqrt(0.5) = 0.0354 of spin; all points carry nothing.
  RigidBody<3> cube = makeDynamicBody<3>(1.0, Vec3::Constant(1.0 / 6.0));
  cube.position = Vec3(0.0, 0.0, 0.5);
  const RigidBody<3> ground;
  const auto stop = [&](double w, PatchSpinBound bound) {
    cube.velocity = Vec3(0.0, 0.0, -0.1);
    cube.angularMomentum = Vec3(0.0, 0.0, w / 6.0);
    cube.syncAngularVelocity();
    return stickingPatchImpulse<3>(cube, cube.position, ground, cube.position, points, n, 0.0, 0.5, bound);
  };
  const auto held = stop(0.12, PatchSpinBound::BestSubset);  // spin 0.02 < 0.0354
  REQUIRE(held.has_value());
  CHECK((held->J - Vec3(0.0, 0.0, 0.1)).norm() < 1e-15);
  CHECK(std::abs(held->L.z() + 0.02) < 1e-15);
  CHECK_FALSE(stop(0.12, PatchSpinBound::AllPoints).has_value());
  CHECK_FALSE(stop(0.3, PatchSpinBound::BestSubset).has_value());  // spin 0.05 > 0.0354
}
// [best_subset_test]

// [carried_loads_test]
TEST_CASE("Eq. (9.11): a body gets back its velocity before the contact stage plus the impulses from above") {
  // Ground 0, box 1 on it, box 2 on box 1, box 3 beside box 2 at its level.
  const Material material{0.0, 0.5, 0.0};
  World<2> world = stacks::groundWorld<2>(material);
  for (const Vec2& centre : {Vec2(0.0, 0.5), Vec2(0.0, 1.5), Vec2(1.0, 1.5)}) {
    stacks::addBox<2>(world, Vec2(1.0, 1.0), 2.0, centre, material);
  }
  std::vector<RigidBody<2>> before = world.bodies;
  before[1].velocity = Vec2(0.1, -0.2);
  before[2].velocity = Vec2(0.0, -0.3);
  const ContactPair edges[] = {{0, 1}, {1, 2}, {2, 3}, {3, 2}};
  const ContactGraph graph(4, edges);
  const ContactLevels levels = levelsFromAssignment(graph, {0, 1, 2, 2});
  ContactRecorder impulses;
  const Vec2 p(0.3, 1.0), j(0.5, 4.0);
  impulses.record<2>(ContactStage::Contact, 2, 1, p, Vec2(0.0, 1.0), j);            // from above: carried to 1
  impulses.record<2>(ContactStage::Contact, 1, 0, Vec2(0.0, 0.0), Vec2(0.0, 1.0), j);  // static partner
  impulses.record<2>(ContactStage::Contact, 2, 3, Vec2(0.5, 1.5), Vec2(1.0, 0.0), j);  // one level
  impulses.record<2>(ContactStage::Collision, 2, 1, p, Vec2(0.0, 1.0), j);           // not the contact stage
  for (RigidBody<2>& b : world.bodies) {
    if (!b.isStatic()) b.velocity = Vec2(7.0, 7.0);  // what the contact stage left: replaced
  }
  CHECK(carryLoads<2>(world, before, impulses, levels) == 1);
  // Box 1 takes -j at p (it is the record's other body): v = v0 - j / m, L = (p - x) x (-j).
  CHECK((world.bodies[1].velocity - Vec2(0.1 - 0.25, -0.2 - 2.0)).norm() < 1e-15);
  const double torque = (p.x() - 0.0) * (-j.y()) - (p.y() - 0.5) * (-j.x());  // 0.3 * -4 - 0.5 * -0.5
  CHECK(world.bodies[1].angularMomentum[0] == doctest::Approx(torque).epsilon(1e-15));
  CHECK(world.bodies[2].velocity == before[2].velocity);  // its partners are below or beside it
  CHECK(world.bodies[3].velocity == before[3].velocity);
}
// [carried_loads_test]

// [body_weld_test]
TEST_CASE("Eq. (9.12): a box sinking onto the ground is stopped whole when its cone holds it") {
  const Material material{0.0, 0.5, 0.0};
  StepSettings settings;
  settings.dt = 0.01;
  const ContactPair edges[] = {{0, 1}};
  const ContactGraph graph(2, edges);
  const ContactLevels levels = topologicalLevels(graph);
  for (const double slide : {0.05, 0.2}) {  // inside the cone (0.05 < 0.5 * 0.2) and outside it
    CAPTURE(slide);
    World<2> world = stacks::groundWorld<2>(material);
    stacks::addBox<2>(world, Vec2(1.0, 1.0), 1.0, Vec2(0.0, 0.5), material);
    world.bodies[1].velocity = Vec2(slide, -0.2);
    world.bodies[1].angularMomentum[0] = 0.01;
    world.bodies[1].syncAngularVelocity();
    WeldedCounters counters;
    const std::vector<char> welded =
        bodyWelds<2>(world, graph, levels, settings, PatchSpinBound::BestSubset, counters, nullptr);
    CHECK(counters.weldTries == 1);
    if (slide < 0.1) {
      CHECK(welded[1] == 1);
      CHECK(world.bodies[1].velocity.norm() < 1e-15);
      CHECK(std::abs(world.bodies[1].angularVelocity[0]) < 1e-15);
    } else {
      CHECK(welded[1] == 0);
      CHECK(world.bodies[1].velocity == Vec2(slide, -0.2));  // untouched: left to the pass
    }
  }
}
// [body_weld_test]

// [welded_stacks_test]
TEST_CASE_TEMPLATE("the welded pass holds a stack of 10 at 60 Hz welding every box every step", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  World<D> world = stacks::boxStack<D>(10, Material{0.0, 0.6, 0.0});
  const WeldedRun run = runWelded<D>(world, 1.0);
  CHECK(run.moved < 1e-9);
  CHECK(run.energyGain < 1e-9);
  CHECK(run.counters.welded.welds == 10 * run.steps);
  CHECK(run.counters.welded.gbfIslands == 0);
}

TEST_CASE("the welded pass holds a 2D pyramid of base 6 and a 3D pyramid of 14 cubes at 60 Hz") {
  // Small and short, so that the sanitizer build runs it in seconds; the slow suite below
  // holds the pyramids GBF's step cannot hold for 10 s.
  const Material material{0.0, 0.6, 0.0};
  World<2> flat = stacks::pyramid2d(6, material);  // 21 boxes
  const WeldedRun a = runWelded<2>(flat, 0.5);
  CHECK(a.moved < 1e-9);
  CHECK(a.energyGain < 1e-9);
  CHECK(a.counters.welded.welds == 21 * a.steps);
  World<3> solid = stacks::pyramid3d(3, material);  // 14 cubes
  const WeldedRun b = runWelded<3>(solid, 0.5);
  CHECK(b.moved < 1e-9);
  CHECK(b.energyGain < 1e-9);
  CHECK(b.counters.welded.welds == 14 * b.steps);
}
// [welded_stacks_test]

// [welded_seesaw_test]
TEST_CASE("Eq. (9.14): where nothing welds the welded pass ends each step as GBF's step does, bit for bit") {
  // GBF's seesaw: the plank turns under the box, so no body is ever at rest on resting
  // supporters and every island keeps GBF's pass. Without the guard the carried loads are all
  // there is, and the seesaw gains energy.
  const World<2> start = stacks::seesaw(Material{0.0, 0.5, 0.0});
  World<2> gbf = start, welded = start, unguarded = start;
  constexpr int kSteps = 400;  // 0.4 s: the plank has tipped, and the unguarded run has gained
  StepSettings unguardedSettings = gbfStepWeldedPass();
  unguardedSettings.shock.welded.energyGuard = false;
  StepCounters counters;
  double gain = 0.0;
  const double e0 = energy<2>(start);
  for (int n = 0; n < kSteps; ++n) {
    stackingStep<2>(gbf, StepSettings{});
    counters += stackingStep<2>(welded, gbfStepWeldedPass());
    stackingStep<2>(unguarded, unguardedSettings);
    gain = std::max(gain, energy<2>(unguarded) - e0);
  }
  CHECK(counters.welded.passes == kSteps);
  CHECK(counters.welded.welds == 0);
  CHECK(counters.welded.gbfIslands == counters.welded.islands);
  CHECK(testing::stateHash<2>(welded) == testing::stateHash<2>(gbf));
  CHECK(stacks::seesawAngle(welded) < -0.05);  // the box's load tipped the plank
  CHECK(energy<2>(welded) <= e0);
  CHECK(gain > 1.0);  // unguarded
}
// [welded_seesaw_test]

TEST_CASE("the welded pass gives the same bits for 1, 2 and 4 threads and with a contact recorder") {
  const Material material{0.0, 0.6, 0.0};
  const auto final = [&](int threads, ContactRecorder* recorder) {
    World<2> world = stacks::pyramid2d(6, material);
    world.bodies[3].velocity = Vec2(0.3, 0.0);  // a nudged box: welds, refusals and GBF islands
    StepSettings settings = gbfStepWeldedPass();
    settings.dt = 1.0 / 60.0;
    settings.parallel.threads = threads;
    settings.parallel.minPairs = 1;
    settings.parallel.graphPairsPerTask = 1;
    settings.contactRecorder = recorder;
    for (int n = 0; n < 30; ++n) stackingStep<2>(world, settings);
    return testing::stateHash<2>(world);
  };
  const std::uint64_t one = final(1, nullptr);
  CHECK(final(2, nullptr) == one);
  CHECK(final(4, nullptr) == one);
  ContactRecorder recorder;
  CHECK(final(1, &recorder) == one);
  std::size_t shock = 0, contact = 0;
  for (const ContactRecord& r : recorder.records()) {
    shock += r.stage == ContactStage::Shock ? 1u : 0u;
    contact += r.stage == ContactStage::Contact ? 1u : 0u;
  }
  CHECK(shock > 0);
  CHECK(contact > 0);
}

}  // TEST_SUITE

// Item 5 of the default (about two minutes in the main build).
TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

// [welded_pyramids_test]
TEST_CASE("the welded pass holds the 2D pyramid of base 20 and the 3D pyramid of 8 levels at 60 Hz for 10 s") {
  // The preset "weldedPass": no box may drift 1 mm.
  const Material material{0.0, 0.6, 0.0};
  const StepSettings settings = applySolverPreset(SolverPreset::WeldedPass, StepSettings{});
  World<2> flat = stacks::pyramid2d(20, material);  // 210 boxes
  const WeldedRun a = runWelded<2>(flat, 10.0, settings);
  CHECK(a.moved < 1e-3);
  CHECK(a.energyGain < 1e-9);
  World<3> solid = stacks::pyramid3d(8, material);  // 204 cubes
  const WeldedRun b = runWelded<3>(solid, 10.0, settings);
  CHECK(b.moved < 1e-3);
  CHECK(b.energyGain < 1e-9);
}
// [welded_pyramids_test]

}  // TEST_SUITE
