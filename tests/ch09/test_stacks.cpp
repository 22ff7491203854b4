// Chapter 9, slow suite: the validation cases of shock propagation (the validation catalogue's B4,
// B14, B15, B17, A17, A19) simulated for a fraction of a second to two seconds each.
// Run with: ctest --preset main -L ch09_slow   (about 40 s optimised; see the chapter).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../support/dimensions.hpp"
#include "stack_scenes.hpp"

using namespace stackbook;
using stackbook::stacks::largestDisplacement;
using stackbook::stacks::mirrorError;

namespace {

constexpr double kStackSeconds = 1.0;  // simulated time of the B14 stacks (the catalogue asks 10 s)

/// A17 on either side of mu_req = 0.2332 under `settings`, 2 s: at mu 0.25 neither card of
/// the 25-degree A-frame moves 1 mm, at 0.22 both centres drop below half their height.
void cardsStandAt025AndFallAt022(const StepSettings& settings) {
  const double beta = 25.0 * M_PI / 180.0;
  World<2> stands = stacks::cardFrame(beta, Material{0.0, 0.25, 0.0});
  World<2> falls = stacks::cardFrame(beta, Material{0.0, 0.22, 0.0});
  const World<2> frame = stands;
  stacks::run<2>(stands, settings, 2.0, true);
  stacks::run<2>(falls, settings, 2.0, true);
  for (const std::size_t card : {std::size_t{1}, std::size_t{2}}) {
    CHECK((stands.bodies[card].position - frame.bodies[card].position).norm() < 1e-3);
    CHECK(falls.bodies[card].position.y() < 0.5 * frame.bodies[card].position.y());
  }
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

// [b14_stacks]
TEST_CASE("B14: stacks of 10 20 and 30 boxes stand with shock propagation and sink without it") {
  // 2D unit boxes, mu = 0.5, e = 0, 1 s. With the pass: every box within 0.01 m of its
  // start horizontally, speeds below 1e-3 m/s, the top within N * 1e-4 m of its height,
  // no gap between neighbours. Without it (chapter 8's step alone): the top sinks by more
  // than ten times that tolerance.
  const Material material{0.0, 0.5, 0.0};
  for (const int n : {10, 20, 30}) {
    CAPTURE(n);
    const World<2> start = stacks::boxStack<2>(n, material);
    World<2> on = start;
    World<2> off = start;
    stacks::run<2>(on, StepSettings{}, kStackSeconds, true);
    stacks::run<2>(off, StepSettings{}, kStackSeconds, false);
    const stacks::StackState<2> a = stacks::measureStack<2>(start, on, 1, n);
    const stacks::StackState<2> b = stacks::measureStack<2>(start, off, 1, n);
    const double tolerance = n * 1e-4;
    CHECK(a.drift < 0.01);
    CHECK(a.maxSpeed < 1e-3);
    CHECK(std::abs(a.sag) < tolerance);
    CHECK(a.largestGap < 1e-4);
    CHECK(b.sag > 10.0 * tolerance);
  }
}
// [b14_stacks]

TEST_CASE("B14: a stack of 10 boxes with e = 0.3 stands with shock propagation") {
  const Material material{0.3, 0.5, 0.0};
  const World<2> start = stacks::boxStack<2>(10, material);
  World<2> on = start;
  stacks::run<2>(on, StepSettings{}, kStackSeconds, true);
  const stacks::StackState<2> a = stacks::measureStack<2>(start, on, 1, 10);
  CHECK(a.drift < 0.01);
  CHECK(a.maxSpeed < 1e-3);
  CHECK(std::abs(a.sag) < 10 * 1e-4);
  CHECK(a.largestGap < 1e-4);
}

TEST_CASE("B14 in 3D: a stack of 10 cubes stands with shock propagation and sinks without it") {
  // 0.3 s (3D detection costs about five times 2D).
  const Material material{0.0, 0.5, 0.0};
  const World<3> start = stacks::boxStack<3>(10, material);
  World<3> on = start;
  World<3> off = start;
  stacks::run<3>(on, StepSettings{}, 0.3, true);
  stacks::run<3>(off, StepSettings{}, 0.3, false);
  const stacks::StackState<3> a = stacks::measureStack<3>(start, on, 1, 10);
  const stacks::StackState<3> b = stacks::measureStack<3>(start, off, 1, 10);
  CHECK(a.drift < 0.01);
  CHECK(a.maxSpeed < 1e-3);
  CHECK(std::abs(a.sag) < 10 * 1e-4);
  CHECK(a.largestGap < 1e-4);
  CHECK(b.sag > 10.0 * 10 * 1e-4);
}

// [b17_plank]
TEST_CASE("B17: a plank on a 2-box and a 4-box stack stays level with topological levels and tilts with BFS depth") {
  const Material material{0.0, 0.5, 0.0};
  const World<2> start = stacks::plankOnTwoStacks<2>(material);
  // The world's graph is the design note's: plank 7 after box 6 topologically, before it by depth.
  const ContactGraph graph = worldContactGraph<2>(start, ContactGraphSettings{});
  const std::vector<ContactPair> expected{{0, 1}, {0, 3}, {1, 2}, {2, 7}, {3, 4}, {4, 5}, {5, 6}, {6, 7}};
  CHECK(graph.edges() == expected);
  CHECK(topologicalLevels(graph).levelOfBody[7] > topologicalLevels(graph).levelOfBody[6]);
  CHECK(bfsDepthLevels(graph).levelOfBody[7] < bfsDepthLevels(graph).levelOfBody[6]);

  double tiltTopological = 0.0;
  double tiltDepth = 0.0;
  World<2> topological = start;
  World<2> depth = start;
  StepSettings settings;
  settings.effects.shockPropagation = true;
  for (int n = 0; n < 1000; ++n) {  // 1 s; every step terminates (all loops capped)
    stackingStep<2>(topological, settings, Layering::Topological);
    stackingStep<2>(depth, settings, Layering::BfsDepth);
    tiltTopological = std::max(tiltTopological, stacks::plankTilt<2>(topological));
    tiltDepth = std::max(tiltDepth, stacks::plankTilt<2>(depth));
  }
  CHECK(tiltTopological < 1e-3);
  CHECK(tiltDepth > 1e-3);  // box 6 squeezed between frozen box 5 and the frozen plank
}
// [b17_plank]

TEST_CASE("B17 in 3D: the plank on two unequal stacks stays level with topological levels") {
  const World<3> start = stacks::plankOnTwoStacks<3>(Material{0.0, 0.5, 0.0});
  World<3> world = start;
  StepSettings settings;
  settings.effects.shockPropagation = true;
  double tilt = 0.0;
  for (int n = 0; n < 250; ++n) {
    stackingStep<3>(world, settings);
    tilt = std::max(tilt, stacks::plankTilt<3>(world));
  }
  CHECK(tilt < 1e-3);
}

// [b4_heavy]
TEST_CASE_TEMPLATE("B4: a 1000 kg box on a 1 kg box holds with shock propagation and crushes it without", Dim,
                   stackbook::testing::In2D, stackbook::testing::In3D) {
  constexpr int D = Dim::value;
  const Material material{0.0, 0.5, 0.0};
  World<D> start = stacks::groundWorld<D>(material);
  stacks::addBox<D>(start, Vec<D>::Ones(), 1.0, Vec<D>(0.5 * stacks::up<D>()), material);
  stacks::addBox<D>(start, Vec<D>::Ones(), 1000.0, Vec<D>(1.5 * stacks::up<D>()), material);
  World<D> on = start;
  stacks::run<D>(on, StepSettings{}, 1.0, true);
  CHECK(start.bodies[2].position[D - 1] - on.bodies[2].position[D - 1] < 1e-3);  // heavy sinks < 1 mm
  CHECK(on.bodies[1].velocity.norm() < 1e-3);
  CHECK(on.bodies[2].velocity.norm() < 1e-3);
  CHECK(0.5 * on.bodies[1].velocity.squaredNorm() < 1e-6);  // the light box is not ejected
  if constexpr (D == 2) {
    World<D> off = start;
    stacks::run<D>(off, StepSettings{}, 1.0, false);
    CHECK(start.bodies[2].position[D - 1] - off.bodies[2].position[D - 1] > 0.1);
  }
}
// [b4_heavy]

// [b15_pyramid]
TEST_CASE("B15: a 2D pyramid with a 20-box base holds its height with shock propagation") {
  // 210 boxes, 0.3 s. With the pass no box moves 1 cm and the apex keeps its height to
  // 1 mm (without it the apex sinks by centimetres: the chapter's table; not run here, to
  // keep the slow suite within its budget). GBF's step does NOT meet the validation's
  // symmetry test (mirror error < 1e-3): the contact stage leaves velocities the pass
  // cannot touch (Eq. (9.8)) and the pyramid walks sideways (the chapter gives the
  // measured numbers); the bound here, 1e-2, only guards against this getting worse.
  // The pass as the contact stage meets it (the next test).
  const World<2> start = stacks::pyramid2d(20, Material{0.0, 0.5, 0.0});
  World<2> on = start;
  stacks::run<2>(on, StepSettings{}, 0.3, true);
  const std::size_t apex = start.bodies.size() - 1;
  CHECK(largestDisplacement<2>(start, on) < 0.01);
  CHECK(std::abs(start.bodies[apex].position.y() - on.bodies[apex].position.y()) < 1e-3);
  CHECK(mirrorError(on, 20) < 1e-2);
}
// [b15_pyramid]

// [b15_corner_threshold]
TEST_CASE("B15: a 5-box-base pyramid creeps below the corner friction threshold and holds above it") {
  // 15 boxes, 1 s, shock propagation on, GBF's deepest-sample rule. At mu = 0.8, above the
  // 3/5 a square needs to stick at one corner (Eq. (9.7)), no box moves 5e-5 m; at
  // mu = 0.5, below it, the corner impulses slide and some box creeps more than 1e-4 m.
  double moved[2] = {0.0, 0.0};
  const double mus[2] = {0.8, 0.5};
  for (int k = 0; k < 2; ++k) {
    const World<2> start = stacks::pyramid2d(5, Material{0.0, mus[k], 0.0});
    World<2> world = start;
    stacks::run<2>(world, StepSettings{}, 1.0, true);
    moved[k] = largestDisplacement<2>(start, world);
  }
  CHECK(moved[0] < 5e-5);
  CHECK(moved[1] > 1e-4);
}
// [b15_corner_threshold]

// [b15_step_cone]
TEST_CASE("B15 and A17 under one cone per step: the 5-box-base pyramid holds at mu 0.5 and the cards keep their threshold") {
  // Eq. (8.13): with the pair's total impulse of the step in the cone, the corner impulses
  // of a resting box may stick although each alone needs 3/5: the pyramid that creeps
  // more than 1e-4 m in 1 s under GBF's cone moves less than 2e-5 m. The rule is still
  // Coulomb's: the A-frame stands above mu_req = 0.2332 (at 0.25) and falls below it (0.22).
  StepSettings settings;
  settings.frictionCone = FrictionConeRule::StepTotal;
  const World<2> start = stacks::pyramid2d(5, Material{0.0, 0.5, 0.0});
  World<2> pyramid = start;
  stacks::run<2>(pyramid, settings, 1.0, true);
  CHECK(largestDisplacement<2>(start, pyramid) < 2e-5);

  cardsStandAt025AndFallAt022(settings);
}
// [b15_step_cone]

// [b15_pass_as_contact]
TEST_CASE("B15 with the pass as the contact stage: the 20-box-base pyramid stays mirror-symmetric and still") {
  // Eq. (9.9): no contact stage, 20 sweeps per level, one cone per step. 210 boxes, 1 s.
  // B15 asks for a mirror error below 1e-3 after 10 s and no box moving 1 cm; over 1 s
  // that is 1e-4 and 1e-3 (measured: 2.5e-6 and 1.2e-6; bench/pyramid_bench runs the
  // 10 s: 3.4e-5). GBF's step walks the same pyramid by 8 cm in 10 s and fails both.
  const World<2> start = stacks::pyramid2d(20, Material{0.0, 0.5, 0.0});
  World<2> world = start;
  stacks::run<2>(world, passAsContactStage(), 1.0, true);
  CHECK(mirrorError(world, 20) < 1e-4);
  CHECK(largestDisplacement<2>(start, world) < 1e-3);
}

TEST_CASE("B15 and A17 with the pass as the contact stage: a 3D pyramid stands still and the cards keep their threshold") {
  // 14 cubes, 0.25 s: B15's mirror bound over 0.25 s is 2.5e-5 m, which no cube moving
  // less than half of it can break (measured: 3.5e-8 m; GBF's step: about 2e-4 m in
  // 0.5 s). The A-frame's two cards are
  // each a level alone on the ground, swept now that no contact stage does it: they
  // stand above mu_req = 0.2332 (at 0.25) and fall below it (0.22).
  const World<3> start = stacks::pyramid3d(3, Material{0.0, 0.5, 0.0});
  World<3> world = start;
  stacks::run<3>(world, passAsContactStage(), 0.25, true);
  CHECK(largestDisplacement<3>(start, world) < 0.5 * 2.5e-5);

  cardsStandAt025AndFallAt022(passAsContactStage());
}
// [b15_pass_as_contact]

// [b15_short_loops]
TEST_CASE("B15 and A17 with short pair loops: the pyramids stand as still and the cards keep their threshold") {
  // passAsContactStageShortLoops() against the bounds the pass as the contact stage meets
  // with PhysBAM's caps (the two tests above): over 1 s B15's mirror bound is 1e-4 m and
  // no box may move 1e-3 m in the 20-box-base pyramid; over 0.25 s no cube of the 3D
  // pyramid may move half of 2.5e-5 m; and the A-frame stands at mu 0.25 and falls at 0.22.
  const StepSettings settings = passAsContactStageShortLoops();
  const World<2> start = stacks::pyramid2d(20, Material{0.0, 0.5, 0.0});
  World<2> world = start;
  const StepCounters c = stacks::run<2>(world, settings, 1.0, true);
  CHECK(mirrorError(world, 20) < 1e-4);
  CHECK(largestDisplacement<2>(start, world) < 1e-3);
  CHECK(c.shock.pairConvergences > 0);  // the tolerance did end visits

  const World<3> start3 = stacks::pyramid3d(3, Material{0.0, 0.5, 0.0});
  World<3> world3 = start3;
  stacks::run<3>(world3, settings, 0.25, true);
  CHECK(largestDisplacement<3>(start3, world3) < 0.5 * 2.5e-5);

  cardsStandAt025AndFallAt022(settings);
}
// [b15_short_loops]

TEST_CASE("B15 in 3D: a pyramid of 14 cubes stands") {
  const World<3> start = stacks::pyramid3d(3, Material{0.0, 0.5, 0.0});
  World<3> world = start;
  stacks::run<3>(world, StepSettings{}, 0.25, true);
  CHECK(largestDisplacement<3>(start, world) < 0.01);
}

// [a17_cards]
TEST_CASE("A17: a card A-frame at 25 degrees stands at mu 0.30 and falls at mu 0.15") {
  // mu_req = tan(25 deg) / 2 = 0.2332 (the chapter derives it).
  const double beta = 25.0 * M_PI / 180.0;
  World<2> stands = stacks::cardFrame(beta, Material{0.0, 0.30, 0.0});
  World<2> falls = stacks::cardFrame(beta, Material{0.0, 0.15, 0.0});
  const World<2> start = stands;
  stacks::run<2>(stands, StepSettings{}, 2.0, true);
  stacks::run<2>(falls, StepSettings{}, 2.0, true);
  for (const int card : {1, 2}) {
    const std::size_t k = static_cast<std::size_t>(card);
    CHECK((stands.bodies[k].position - start.bodies[k].position).norm() < 1e-3);
    CHECK(falls.bodies[k].position.y() < 0.5 * start.bodies[k].position.y());
  }
}
// [a17_cards]

// [a19_tilted]
TEST_CASE("A19: a tilted stack topples without shock propagation and shock propagation holds it up") {
  // Ten unit boxes, each 0.2 to the side of the one below: the six boxes above box 4 have
  // their centre of mass 0.7 from box 4's centre, past its edge, so the stack must fall.
  // Chapter 8's step lets it fall (the top drops more than one box height in 2.5 s). The
  // pass freezes each box before the boxes above it press on it: every box alone is stable
  // on its frozen support, and the stack stays up. This asserts the known failure; the
  // chapter discusses it.
  const World<2> start = stacks::boxStack<2>(10, Material{0.0, 0.5, 0.0}, 0.2);
  World<2> off = start;
  World<2> on = start;
  stacks::run<2>(off, StepSettings{}, 2.5, false);
  stacks::run<2>(on, StepSettings{}, 1.0, true);
  CHECK(start.bodies[10].position.y() - off.bodies[10].position.y() > 1.0);
  CHECK(std::abs(start.bodies[10].position.y() - on.bodies[10].position.y()) < 1e-3);
}
// [a19_tilted]

}  // TEST_SUITE
