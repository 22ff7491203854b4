// Chapter 9: the pass as the contact stage (Eq. (9.9)). GBF's contact stage leaves
// velocities that the pass cannot touch (Eq. (9.8)); with ShockSettings::replacesContactStage
// the pass does all contact processing: piles stand still to round-off, the single-body
// cases of chapter 8 keep their answers, and loads no longer reach lower bodies (a seesaw
// is glued). The longest runs (the 20-box-base pyramid) are in test_stacks.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "../ch08/scene_builders.hpp"
#include "../support/dimensions.hpp"
#include "stack_scenes.hpp"
#include "stackbook/stacking/solver_preset.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;

namespace {

/// The chapter's settings (passAsContactStage()) with `sweepsPerLevel` sweeps per level.
StepSettings passOnly(int sweepsPerLevel = 20) { return passAsContactStage(StepSettings{}, sweepsPerLevel); }

/// The short pair loops (passAsContactStageShortLoops()) with `sweepsPerLevel` sweeps per level.
StepSettings shortLoops(int sweepsPerLevel = 20) {
  return passAsContactStageShortLoops(StepSettings{}, sweepsPerLevel);  // the ramp follows: it is left empty
}

/// Run `steps` steps of stackingStep (with whatever effects the settings leave inferred).
template <int D>
StepCounters runSteps(World<D>& world, const StepSettings& settings, int steps) {
  StepCounters total;
  for (int n = 0; n < steps; ++n) total += stackingStep<D>(world, settings);
  return total;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_pass_single_body]
TEST_CASE_TEMPLATE("with the pass as the contact stage a box alone on the ground rests and the pass reports it ran",
                   Dim, In2D, In3D) {
  // One dynamic body: shock propagation is inferred off, and the flag turns it on, since
  // the pass is now the only contact processing. Its level is swept, not skipped.
  constexpr int D = Dim::value;
  const World<D> start = stacks::boxStack<D>(1, Material{0.0, 0.5, 0.0});
  World<D> world = start;
  const StepCounters c = runSteps<D>(world, passOnly(), 500);
  CHECK(c.effects.contact);
  CHECK(c.effects.shockPropagation);
  CHECK(c.contact.impulses == 0);  // the contact stage never ran
  CHECK(c.shock.impulses > 0);     // the pass did its work
  CHECK(stacks::measureStack<D>(start, world, 1, 1).maxSpeed < 1e-12);
  CHECK(std::abs(world.bodies[1].position[D - 1] - 0.5) < 1e-12);
}
// [test_pass_single_body]

// [test_pass_seesaw]
TEST_CASE("with the pass as the contact stage the seesaw is glued: the box's load never reaches the plank") {
  // GBF's step: the contact stage carries the box's weight into the plank, which turns
  // about the post's corner. The pass alone settles the plank on the post before it
  // visits the box (the plank's own centre is over the post): the plank stays level.
  const World<2> start = stacks::seesaw(Material{0.0, 0.5, 0.0});
  World<2> gbf = start;
  World<2> pass = start;
  StepSettings settings;
  settings.effects.shockPropagation = true;
  runSteps<2>(gbf, settings, 300);
  runSteps<2>(pass, passOnly(), 300);
  CHECK(stacks::seesawAngle(gbf) < -0.05);  // tipped towards the box by more than 3 degrees in 0.3 s
  CHECK(std::abs(stacks::seesawAngle(pass)) < 1e-9);
}
// [test_pass_seesaw]

TEST_CASE("forcing shock propagation off keeps the contact stage even when the pass would replace it") {
  const World<2> start = stacks::boxStack<2>(2, Material{0.0, 0.5, 0.0});
  World<2> world = start;
  StepSettings settings = passOnly();
  settings.effects.shockPropagation = false;
  const StepCounters c = runSteps<2>(world, settings, 50);
  CHECK_FALSE(c.effects.shockPropagation);
  CHECK(c.contact.impulses > 0);
  CHECK(c.shock.impulses == 0);
  CHECK(stacks::measureStack<2>(start, world, 1, 2).sag < 1e-3);
}

TEST_CASE("chapter 8's step without a hook ignores the flag and runs its contact stage") {
  World<2> world = stacks::boxStack<2>(2, Material{0.0, 0.5, 0.0});
  const StepCounters c = gbfStep<2>(world, passOnly());
  CHECK(c.contact.impulses > 0);
  CHECK_FALSE(c.effects.shockPropagation);
}

// [test_unpressed_contacts]
TEST_CASE("a contact nothing presses gets both edges between dynamic bodies and one from a static body") {
  // Without gravity, two boxes at rest side by side, overlapping by 1 mm, and a static wall
  // overlapping the right one by 1 mm: no body approaches another, so the graph is empty
  // (Eq. (9.3)); the completed graph joins the boxes in a cycle (one level) and puts the
  // wall below the right box.
  const Material material{0.0, 0.5, 0.0};
  World<2> world;
  stacks::addBox<2>(world, Vec2(1.0, 1.0), 1.0, Vec2(-0.4995, 0.0), material);     // body 0
  stacks::addBox<2>(world, Vec2(1.0, 1.0), 1.0, Vec2(0.4995, 0.0), material);      // body 1
  world.addBody(makeStaticBody<2>(Vec2(1.4985, 0.0), Orientation<2>::Identity()),  // body 2
                stacks::boxShape<2>(Vec2(1.0, 2.0)), material);
  const ContactGraphSettings settings;
  const ContactGraph pressed = worldContactGraph<2>(world, settings);
  CHECK(pressed.edgeCount() == 0);
  const ContactGraph completed = withUnpressedContacts<2>(world, pressed, settings);
  CHECK(completed.edges() == std::vector<ContactPair>{{0, 1}, {1, 0}, {2, 1}});
  const ContactLevels levels = topologicalLevels(completed);
  CHECK(levels.levelOfBody[0] == levels.levelOfBody[1]);
  CHECK(levels.levelOfBody[2] < levels.levelOfBody[1]);
}
// [test_unpressed_contacts]

// [test_pass_early_exit]
TEST_CASE("a level sweep that applies no impulse ends its level") {
  // Restitution only scales an impulse, so a sweep that finds no approaching sample is
  // followed by sweeps that find none: stopping changes nothing and saves the rest.
  World<2> world = stacks::boxStack<2>(3, Material{0.0, 0.5, 0.0});
  const StepCounters c = runSteps<2>(world, passOnly(50), 100);
  // 3 levels per step, 50 sweeps allowed per level: far fewer are used.
  CHECK(c.shock.sweeps < 100 * 3 * 50 / 2);
  CHECK(c.shock.sweeps >= 100 * 3);
}
// [test_pass_early_exit]

// [test_short_loops_early_exit]
TEST_CASE("with short pair loops a level sweep that applies no impulse still ends its level") {
  // The same claim and bound as with PhysBAM's caps: a visit cut short leaves what it did
  // not finish to the level's next sweep, and the level must still settle in fewer than
  // half the sweeps it is allowed.
  World<2> world = stacks::boxStack<2>(3, Material{0.0, 0.5, 0.0});
  const StepCounters c = runSteps<2>(world, shortLoops(50), 100);
  CHECK(c.shock.sweeps < 100 * 3 * 50 / 2);
  CHECK(c.shock.sweeps >= 100 * 3);
  CHECK(c.shock.pairConvergences > 0);  // the tolerance ended some visits before the cap
}
// [test_short_loops_early_exit]

TEST_CASE("the short pair loops are the pass as the contact stage with caps of 5 and a tolerance of 0.2") {
  const StepSettings s = passAsContactStageShortLoops();
  const StepSettings pass = passAsContactStage();
  CHECK(s.shock.replacesContactStage);
  CHECK(s.shock.sweepsPerLevel == pass.shock.sweepsPerLevel);
  CHECK(s.frictionCone == FrictionConeRule::StepTotal);
  CHECK(s.shock.pairIterations == 5);
  CHECK(s.collisionPairIterations == 5);
  CHECK(s.shock.pairImpulseTolerance == 0.2);
  CHECK(s.pairImpulseTolerance == 0.2);
  StepSettings base;
  base.dt = 1.0 / 60.0;
  CHECK(passAsContactStageShortLoops(base).dt == base.dt);  // the rest of base is kept
  CHECK_NOTHROW(validateStepSettings(s));
}

TEST_CASE("the short pair loops take their sweeps, cap and tolerance as parameters") {
  const StepSettings s = passAsContactStageShortLoops(StepSettings{}, 12, 4, 0.1);
  CHECK(s.shock.replacesContactStage);
  CHECK(s.shock.sweepsPerLevel == 12);
  CHECK(s.shock.restitution.empty());  // GBF's ramp over the 12 sweeps
  CHECK(s.shock.pairIterations == 4);
  CHECK(s.collisionPairIterations == 4);
  CHECK(s.shock.pairImpulseTolerance == 0.1);
  CHECK(s.pairImpulseTolerance == 0.1);
  CHECK_NOTHROW(validateStepSettings(s));
  // A cap below one impulse, or a tolerance outside [0, 1], is not a short loop: refused.
  CHECK_THROWS_AS(passAsContactStageShortLoops(StepSettings{}, 20, 0), std::invalid_argument);
  CHECK_THROWS_AS(passAsContactStageShortLoops(StepSettings{}, 20, 5, -0.1), std::invalid_argument);
  CHECK_THROWS_AS(passAsContactStageShortLoops(StepSettings{}, 20, 5, 1.5), std::invalid_argument);
  CHECK_THROWS_AS(passAsContactStageShortLoops(StepSettings{}, 20, 5, std::nan("")), std::invalid_argument);
}

TEST_CASE("each solver preset is the settings function it names, and its word names it back") {
  StepSettings base;
  base.dt = 1.0 / 60.0;
  base.parallel.threads = 3;
  const StepSettings gbf = applySolverPreset(SolverPreset::Gbf, base);
  CHECK_FALSE(gbf.shock.replacesContactStage);
  CHECK(gbf.contactIterations == base.contactIterations);
  CHECK(gbf.frictionCone == base.frictionCone);
  const StepSettings pass = applySolverPreset(SolverPreset::PassAsContact, base);
  const StepSettings passByHand = passAsContactStage(base);
  CHECK(pass.shock.replacesContactStage);
  CHECK(pass.shock.sweepsPerLevel == passByHand.shock.sweepsPerLevel);
  CHECK(pass.shock.pairIterations == passByHand.shock.pairIterations);
  CHECK(pass.frictionCone == FrictionConeRule::StepTotal);
  const StepSettings loops = applySolverPreset(SolverPreset::PassAsContactShortLoops, base);
  CHECK(loops.shock.pairIterations == 5);
  CHECK(loops.collisionPairIterations == 5);
  CHECK(loops.pairImpulseTolerance == 0.2);
  CHECK(loops.impulsePoint.rule == ImpulsePointRule::Deepest);
  const StepSettings patch = applySolverPreset(SolverPreset::PassAsContactPatch, base);
  CHECK(patch.shock.replacesContactStage);
  CHECK(patch.shock.pairIterations == 5);
  CHECK(patch.impulsePoint.rule == ImpulsePointRule::StickingPatch);
  CHECK(patch.shock.levelApproachTolerance == 1e-9);
  // A preset means the same settings whatever base came from: the patch preset's own fields
  // are put back when another preset is applied to its settings.
  const StepSettings back = applySolverPreset(SolverPreset::PassAsContactShortLoops, patch);
  CHECK(back.impulsePoint.rule == ImpulsePointRule::Deepest);
  CHECK(back.shock.levelApproachTolerance == 0.0);
  CHECK_THROWS_AS(passAsContactStagePatch(StepSettings{}, -1.0), std::invalid_argument);
  for (const StepSettings* s : {&gbf, &pass, &loops, &patch}) {  // base's other fields are kept
    CHECK(s->dt == base.dt);
    CHECK(s->parallel.threads == 3);
  }
  for (const auto& [preset, word] : kSolverPresets) {
    REQUIRE(solverPresetNamed(word).has_value());
    CHECK(*solverPresetNamed(word) == preset);
    CHECK(solverPresetName(preset) == word);
  }
  CHECK_FALSE(solverPresetNamed("GBF").has_value());  // the words are case-sensitive
  CHECK_FALSE(solverPresetNamed("").has_value());
  CHECK(solverPresetWords() ==
        "\"gbf\", \"passAsContact\", \"passAsContactShortLoops\", \"gbfShortLoops\", \"passAsContactPatch\", \"weldedPass\" or \"carryingPass\"");
}

}  // TEST_SUITE

// The longer simulations (together about a minute and a half under the sanitizers).
TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

TEST_CASE_TEMPLATE("with the pass as the contact stage the A2 block slides with g(sin - mu cos)", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const double theta = testing::degrees(30.0), mu = 0.3;
  const double a = stacks::kG * (std::sin(theta) - mu * std::cos(theta));
  REQUIRE(a == doctest::Approx(2.3563).epsilon(1e-4));  // the catalogue's closed form, case A2
  testing::InclineScene<D> scene = testing::makeIncline<D>(theta, mu, 0.0);
  runSteps<D>(scene.world, passOnly(), 1000);
  CHECK(scene.travelled() == doctest::Approx(0.5 * a).epsilon(0.01));
  CHECK(scene.speed() == doctest::Approx(a).epsilon(0.01));
  CHECK(std::abs(scene.lift()) < 1e-6);
}

TEST_CASE("with the pass as the contact stage the A2b block holds at 26 degrees and slides at 27<2D>") {
  testing::InclineScene<2> below = testing::makeIncline<2>(testing::degrees(26.0), 0.5, 0.0);
  runSteps<2>(below.world, passOnly(), 2000);
  CHECK(std::abs(below.travelled()) < 1e-4);
  const double a = stacks::kG * (std::sin(testing::degrees(27.0)) - 0.5 * std::cos(testing::degrees(27.0)));
  testing::InclineScene<2> above = testing::makeIncline<2>(testing::degrees(27.0), 0.5, 0.0);
  runSteps<2>(above.world, passOnly(), 2000);
  CHECK(above.travelled() == doctest::Approx(0.5 * a * 4.0).epsilon(0.01));
}

// [test_pass_stack]
TEST_CASE_TEMPLATE("with the pass as the contact stage a stack of 10 boxes stands still to 1e-9 m", Dim, In2D,
                   In3D) {
  // The discrete answer is exact rest, so positions are held to tier T2 (1e-9) and
  // speeds to 1e-6 of the speed g dt that gravity adds each step. GBF's step leaves the
  // contact stage's residual, a thousand times more; with the pass alone every level ends
  // at rest against a frozen one.
  constexpr int D = Dim::value;
  const World<D> start = stacks::boxStack<D>(10, Material{0.0, 0.5, 0.0});
  World<D> pass = start;
  World<D> gbf = start;
  runSteps<D>(pass, passOnly(), 200);
  StepSettings settings;
  settings.effects.shockPropagation = true;
  runSteps<D>(gbf, settings, 200);
  const stacks::StackState<D> p = stacks::measureStack<D>(start, pass, 1, 10);
  const stacks::StackState<D> g = stacks::measureStack<D>(start, gbf, 1, 10);
  const double gdt = stacks::kG * StepSettings{}.dt;
  CHECK(p.maxSpeed < 1e-6 * gdt);
  CHECK(p.drift < 1e-9);
  CHECK(std::abs(p.sag) < 1e-9);
  CHECK(g.maxSpeed > 1e3 * p.maxSpeed);
}
// [test_pass_stack]

// [test_short_loops_stack]
TEST_CASE_TEMPLATE("with short pair loops a stack of 10 boxes still stands still to 1e-9 m", Dim, In2D, In3D) {
  // Caps of 2 break this claim (the appendix's table); caps of 5 ended at 0.2 of the
  // visit's first impulse must keep it: the same tiers as with PhysBAM's caps, exact rest
  // to T2 (1e-9 m) and speeds below 1e-6 of g dt.
  constexpr int D = Dim::value;
  const World<D> start = stacks::boxStack<D>(10, Material{0.0, 0.5, 0.0});
  World<D> world = start;
  runSteps<D>(world, passAsContactStageShortLoops(), 200);
  const stacks::StackState<D> p = stacks::measureStack<D>(start, world, 1, 10);
  const double gdt = stacks::kG * StepSettings{}.dt;
  CHECK(p.maxSpeed < 1e-6 * gdt);
  CHECK(p.drift < 1e-9);
  CHECK(std::abs(p.sag) < 1e-9);
}
// [test_short_loops_stack]

}  // TEST_SUITE

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("chapter 7's candidate lists change nothing in a step but the work: a pyramid and a stack, "
                   "GBF's step and the short pair loops, same bits", Dim, In2D, In3D) {
  // The lists are kept by the collision stage, the contact stage, the graph and the pass;
  // with them on (the default) and off, 40 steps at 60 Hz leave every body with the same
  // bits, and the lists answered most asks.
  constexpr int D = Dim::value;
  const Material material{0.0, 0.6, 0.0};
  World<D> start = stacks::boxStack<D>(6, material, 0.05);
  if constexpr (D == 2) start = stacks::pyramid2d(5, material);
  for (const StepSettings& base : {StepSettings{}, shortLoops()}) {
    StepSettings on = base;
    on.dt = 1.0 / 60.0;
    StepSettings off = on;
    off.detection.narrow.candidateReach = 0.0;
    World<D> a = start, b = start;
    const StepCounters withLists = runSteps<D>(a, on, 40);
    const StepCounters without = runSteps<D>(b, off, 40);
    for (std::size_t k = 0; k < a.bodies.size(); ++k) {
      CHECK(a.bodies[k].position == b.bodies[k].position);
      CHECK(a.bodies[k].velocity == b.bodies[k].velocity);
      CHECK(a.bodies[k].angularMomentum == b.bodies[k].angularMomentum);
      if constexpr (D == 2) {
        CHECK(a.bodies[k].orientation.angle() == b.bodies[k].orientation.angle());
      } else {
        CHECK(a.bodies[k].orientation.coeffs() == b.bodies[k].orientation.coeffs());
      }
    }
    CHECK(withLists.collision.impulses + withLists.contact.impulses + withLists.shock.impulses ==
          without.collision.impulses + without.contact.impulses + without.shock.impulses);
    const auto listed = [](const StepCounters& c) {
      return c.collision.detection.listedQueries + c.contact.detection.listedQueries + c.shock.detection.listedQueries;
    };
    const auto transformed = [](const StepCounters& c) {
      return c.collision.detection.samplesTransformed + c.contact.detection.samplesTransformed +
             c.shock.detection.samplesTransformed;
    };
    CHECK(listed(without) == 0);
    CHECK(listed(withLists) > 0);
    CHECK(transformed(withLists) < transformed(without));
  }
}

}  // TEST_SUITE
