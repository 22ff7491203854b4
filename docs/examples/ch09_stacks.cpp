// Chapter 9: what shock propagation buys, measured. Prints Markdown tables for the chapter
// page: box stacks (validation B14), heavy on light (B4), the plank on two unequal stacks
// (B17, topological levels against BFS depth), the card A-frame (A17), the tilted stack
// (A19), the 2D pyramid (B15) and the cost per stage on the pyramid, the largest scene, and
// the pass as the contact stage against GBF's step on the same scenes (Eq. (9.9)). The
// runs use StepSettings{} (dt = 1e-3, GBF's loop counts) unless a table says otherwise,
// and unit boxes of mass 1.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "../../tests/ch09/stack_scenes.hpp"

using namespace stackbook;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void stacksTable() {
  const double seconds = 1.0;
  std::printf("| boxes | shock propagation | drift (m) | top sag (m) | tolerance N 1e-4 (m) | max speed (m/s) | largest gap (m) | ms per step |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const int n : {10, 20, 30}) {
    const World<2> start = stacks::boxStack<2>(n, Material{0.0, 0.5, 0.0});
    for (const bool shock : {false, true}) {
      World<2> world = start;
      const auto t = std::chrono::steady_clock::now();
      const StepCounters c = stacks::run<2>(world, StepSettings{}, seconds, shock);
      const double wall = secondsSince(t);
      const stacks::StackState<2> s = stacks::measureStack<2>(start, world, 1, n);
      std::printf("| %d | %s | %.2e | %.2e | %.1e | %.2e | %.2e | %.2f |\n", n, shock ? "on" : "off",
                  s.drift, s.sag, n * 1e-4, s.maxSpeed, s.largestGap,
                  1e3 * wall / static_cast<double>(c.steps));
    }
  }
  std::printf("\nTable: 2D stacks after %.1f s, mu = 0.5, e = 0. Drift: the largest horizontal "
              "displacement of a box; sag: the top box's drop (negative: it rose).\n\n", seconds);
}

void heavyTable() {
  std::printf("| shock propagation | heavy box sinks (m) | light box speed (m/s) | heavy box speed (m/s) |\n");
  std::printf("|---|---|---|---|\n");
  const Material material{0.0, 0.5, 0.0};
  World<2> start = stacks::groundWorld<2>(material);
  stacks::addBox<2>(start, Vec2(1.0, 1.0), 1.0, Vec2(0.0, 0.5), material);
  stacks::addBox<2>(start, Vec2(1.0, 1.0), 1000.0, Vec2(0.0, 1.5), material);
  for (const bool shock : {false, true}) {
    World<2> world = start;
    stacks::run<2>(world, StepSettings{}, 1.0, shock);
    std::printf("| %s | %.2e | %.2e | %.2e |\n", shock ? "on" : "off",
                start.bodies[2].position.y() - world.bodies[2].position.y(),
                world.bodies[1].velocity.norm(), world.bodies[2].velocity.norm());
  }
  std::printf("\nTable: a 1000 kg box on a 1 kg box on the ground (2D), after 1 s.\n\n");
}

void plankTable() {
  std::printf("| levels | largest plank tilt in 1 s (rad) | plank tilt at 1 s (rad) | steps with a contact still approaching faster than 1e-5 m/s |\n");
  std::printf("|---|---|---|---|\n");
  for (const Layering layering : {Layering::Topological, Layering::BfsDepth}) {
    World<2> world = stacks::plankOnTwoStacks<2>(Material{0.0, 0.5, 0.0});
    StepSettings settings;
    settings.effects.shockPropagation = true;
    double largest = 0.0;
    int approaching = 0;
    const PostContactHook<2> hook = [layering, &approaching](World<2>& w, const StepSettings& s, StepCounters& c) {
      shockPropagation<2>(w, s, c.shock, layering);
      const ContactGraph graph = worldContactGraph<2>(w, stepGraphSettings(s, c.effects));
      if (approachingContacts<2>(w, graph, s.dt, 1e-5) > 0) ++approaching;
    };
    for (int n = 0; n < 1000; ++n) {
      gbfStep<2>(world, settings, hook);
      largest = std::max(largest, stacks::plankTilt<2>(world));
    }
    std::printf("| %s | %.2e | %.2e | %d of 1000 |\n",
                layering == Layering::Topological ? "topological" : "BFS depth", largest,
                stacks::plankTilt<2>(world), approaching);
  }
  std::printf("\nTable: the plank on a 2-box and a 4-box stack (2D), 1 s with shock propagation.\n\n");
}

void cardsTable() {
  std::printf("| mu | left card centre height at start (m) | at 1 s (m) | at 2 s (m) | left card turned by (rad) |\n");
  std::printf("|---|---|---|---|---|\n");
  const double beta = 25.0 * M_PI / 180.0;
  for (const double mu : {0.30, 0.25, 0.22, 0.15}) {
    World<2> world = stacks::cardFrame(beta, Material{0.0, mu, 0.0});
    const World<2> start = world;
    stacks::run<2>(world, StepSettings{}, 1.0, true);
    const double at1 = world.bodies[1].position.y();
    stacks::run<2>(world, StepSettings{}, 1.0, true);
    std::printf("| %.2f | %.4f | %.4f | %.4f | %.2e |\n", mu, start.bodies[1].position.y(), at1,
                world.bodies[1].position.y(),
                std::abs(world.bodies[1].orientation.angle() - start.bodies[1].orientation.angle()));
  }
  std::printf("\nTable: the card A-frame, beta = 25 degrees, cards 1 m by 1 cm; "
              "mu_req = tan(beta)/2 = %.4f.\n\n", std::tan(beta) / 2.0);
}

void tiltedTable() {
  std::printf("| shock propagation | top box drop at 0.5 s (m) | at 1 s (m) | at 2 s (m) |\n");
  std::printf("|---|---|---|---|\n");
  for (const bool shock : {false, true}) {
    World<2> world = stacks::boxStack<2>(10, Material{0.0, 0.5, 0.0}, 0.2);
    const double y0 = world.bodies[10].position.y();
    double drop[3];
    stacks::run<2>(world, StepSettings{}, 0.5, shock);
    drop[0] = y0 - world.bodies[10].position.y();
    stacks::run<2>(world, StepSettings{}, 0.5, shock);
    drop[1] = y0 - world.bodies[10].position.y();
    stacks::run<2>(world, StepSettings{}, 1.0, shock);
    drop[2] = y0 - world.bodies[10].position.y();
    std::printf("| %s | %.2e | %.2e | %.2e |\n", shock ? "on" : "off", drop[0], drop[1], drop[2]);
  }
  std::printf("\nTable: ten unit boxes, each 0.2 to the side of the one below (2D); it must topple.\n\n");
}

void pyramidTables() {
  const int base = 20;
  const double seconds = 0.3;
  const World<2> start = stacks::pyramid2d(base, Material{0.0, 0.5, 0.0});
  StepCounters counters[2];
  std::printf("| shock propagation | mirror error at 0.1 s (m) | mirror error at %.1f s (m) | largest displacement (m) | apex drop (m) |\n", seconds);
  std::printf("|---|---|---|---|---|\n");
  for (const bool shock : {false, true}) {
    World<2> world = start;
    StepCounters& c = counters[shock ? 1 : 0];
    c = stacks::run<2>(world, StepSettings{}, 0.1, shock);
    const double early = stacks::mirrorError(world, base);
    c += stacks::run<2>(world, StepSettings{}, seconds - 0.1, shock);
    const double moved = stacks::largestDisplacement<2>(start, world);
    const std::size_t apex = world.bodies.size() - 1;
    std::printf("| %s | %.2e | %.2e | %.2e | %.2e |\n", shock ? "on" : "off", early, stacks::mirrorError(world, base),
                moved, start.bodies[apex].position.y() - world.bodies[apex].position.y());
  }
  std::printf("\nTable: the 2D pyramid with a %d-box base (%zu boxes), after %.1f s.\n\n", base,
              start.bodies.size() - 1, seconds);

  const StepCounters& c = counters[1];
  const double steps = static_cast<double>(c.steps);
  std::printf("| stage | ms per step | sweeps per step | pair visits per step | impulses per step | narrow-phase pair queries per step | pair loops that hit the cap per step |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  const auto row = [steps](const char* name, const StageCounters& s) {
    std::printf("| %s | %.2f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", name, 1e3 * s.seconds / steps,
                static_cast<double>(s.sweeps) / steps, static_cast<double>(s.pairVisits) / steps,
                static_cast<double>(s.impulses) / steps,
                static_cast<double>(s.detection.pairQueries) / steps,
                static_cast<double>(s.pairIterationCapHits) / steps);
  };
  row("collision", c.collision);
  row("contact", c.contact);
  row("shock propagation (graph, levels, pass)", c.shock);
  std::printf("| whole step | %.2f | | | | | |\n", 1e3 * c.totalSeconds / steps);
  std::printf("\nTable: the work of each stage on the pyramid with shock propagation, "
              "averaged over %.0f steps.\n", steps);
}

void passAsContactTable() {
  // The same scenes under GBF's step with the pass (StepSettings{}) and with the pass as
  // the contact stage (passAsContactStage(): no contact stage, 20 sweeps per level, one
  // cone per step), each with shock propagation forced on.
  const StepSettings settings[2] = {StepSettings{}, passAsContactStage()};
  std::printf("| scene | measure | GBF's step with the pass | the pass as the contact stage |\n");
  std::printf("|---|---|---|---|\n");
  double value[2][8];
  double msPerStep[2];
  for (int k = 0; k < 2; ++k) {
    const World<2> stack = stacks::boxStack<2>(30, Material{0.0, 0.5, 0.0});
    World<2> world = stack;
    stacks::run<2>(world, settings[k], 1.0, true);
    const stacks::StackState<2> s = stacks::measureStack<2>(stack, world, 1, 30);
    value[k][0] = s.maxSpeed;
    value[k][1] = s.drift;

    const World<2> pyramid = stacks::pyramid2d(20, Material{0.0, 0.5, 0.0});
    world = pyramid;
    const auto t = std::chrono::steady_clock::now();
    const StepCounters c = stacks::run<2>(world, settings[k], 0.3, true);
    msPerStep[k] = 1e3 * secondsSince(t) / static_cast<double>(c.steps);
    value[k][2] = stacks::mirrorError(world, 20);
    value[k][3] = stacks::largestDisplacement<2>(pyramid, world);

    world = stacks::seesaw(Material{0.0, 0.5, 0.0});
    stacks::run<2>(world, settings[k], 0.3, true);
    value[k][4] = stacks::seesawAngle(world);

    const World<2> tilted = stacks::boxStack<2>(10, Material{0.0, 0.5, 0.0}, 0.2);
    world = tilted;
    stacks::run<2>(world, settings[k], 2.0, true);
    value[k][5] = tilted.bodies[10].position.y() - world.bodies[10].position.y();

    const double beta = 25.0 * M_PI / 180.0;
    for (const int j : {0, 1}) {
      const World<2> frame = stacks::cardFrame(beta, Material{0.0, j == 0 ? 0.25 : 0.22, 0.0});
      world = frame;
      stacks::run<2>(world, settings[k], 2.0, true);
      value[k][6 + j] = stacks::largestDisplacement<2>(frame, world);
    }
  }
  const char* rows[8][2] = {{"30-box stack, 1 s", "largest speed (m/s)"},
                            {"30-box stack, 1 s", "drift (m)"},
                            {"pyramid, base 20, 0.3 s", "mirror error (m)"},
                            {"pyramid, base 20, 0.3 s", "largest displacement (m)"},
                            {"seesaw, 0.3 s", "plank angle (rad)"},
                            {"tilted stack (\\ref case_A19 \"A19\"), 2 s", "top box drop (m)"},
                            {"A-frame, mu 0.25 (stands), 2 s", "largest card displacement (m)"},
                            {"A-frame, mu 0.22 (falls), 2 s", "largest card displacement (m)"}};
  for (int r = 0; r < 8; ++r) {
    std::printf("| %s | %s | %.2e | %.2e |\n", rows[r][0], rows[r][1], value[0][r], value[1][r]);
  }
  std::printf("| pyramid, base 20 | ms per step | %.1f | %.1f |\n", msPerStep[0], msPerStep[1]);
  std::printf("\nTable: GBF's step with shock propagation against the pass as the contact stage "
              "(Eq. (9.9)), 2D, dt = 1e-3.\n");
}

/// The pass as the contact stage with PhysBAM's pair caps (10 impulses per pair per level
/// sweep, 20 per pair per collision sweep; passAsContactStage()'s default) and with caps of 2, at a
/// game time step: the largest horizontal drift and speed of any box, impulses and ms per step.
template <int D>
void capsRow(const char* name, const World<D>& start, double seconds, double dt) {
  const StepSettings caps[2] = {passAsContactStage(), passAsContactStage(StepSettings{}, 20, 2)};
  double drift[2] = {0.0, 0.0}, speed[2] = {0.0, 0.0}, impulses[2] = {0.0, 0.0}, ms[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    StepSettings settings = caps[k];
    settings.dt = dt;
    World<D> world = start;
    const auto t = std::chrono::steady_clock::now();
    const StepCounters c = stacks::run<D>(world, settings, seconds, true);
    const double steps = static_cast<double>(c.steps);
    ms[k] = 1e3 * secondsSince(t) / steps;
    impulses[k] = static_cast<double>(c.collision.impulses + c.contact.impulses + c.shock.impulses) / steps;
    for (std::size_t b = 0; b < world.bodies.size(); ++b) {
      if (world.bodies[b].isStatic()) continue;
      Vec<D> horizontal = world.bodies[b].position - start.bodies[b].position;
      horizontal[D - 1] = 0.0;
      drift[k] = std::max(drift[k], horizontal.norm());
      speed[k] = std::max(speed[k], world.bodies[b].velocity.norm());
    }
  }
  std::printf("| %s, dt = %s, %.1f s | %.2e / %.2e | %.2e / %.2e | %.0f / %.0f | %.2f / %.2f |\n", name,
              dt > 0.01 ? "1/60" : "1e-3", seconds, drift[0],
              drift[1], speed[0], speed[1], impulses[0], impulses[1], ms[0], ms[1]);
}

void passCapsTable() {
  std::printf("| scene | max drift (m) | max speed (m/s) | impulses per step | ms per step |\n");
  std::printf("|---|---|---|---|---|\n");
  const Material wood{0.0, 0.6, 0.0};
  capsRow<2>("2D pyramid, base 20 (210 boxes)", stacks::pyramid2d(20, wood), 10.0, 1.0 / 60.0);
  capsRow<2>("2D stack of 30", stacks::boxStack<2>(30, wood), 10.0, 1.0 / 60.0);
  capsRow<3>("3D pyramid, 8 levels (204 cubes)", stacks::pyramid3d(8, wood), 2.0, 1.0 / 60.0);
  capsRow<2>("2D stack of 10", stacks::boxStack<2>(10, Material{0.0, 0.5, 0.0}), 0.2, 1e-3);
  capsRow<3>("3D stack of 10", stacks::boxStack<3>(10, Material{0.0, 0.5, 0.0}), 0.2, 1e-3);
  std::printf("\nTable: the pass as the contact stage with PhysBAM's pair caps (10 in the pass, 20 in the "
              "collision stage; passAsContactStage()'s default) / with caps of 2 (passAsContactStage(base, 20, 2)), "
              "mu = 0.6, e = 0.\n");
}

}  // namespace

int main() {
  std::printf("#### Tall stacks\n\nValidation case \\ref case_B14 \"B14\".\n\n");
  stacksTable();
  std::printf("#### Heavy on light\n\nValidation case \\ref case_B4 \"B4\".\n\n");
  heavyTable();
  std::printf("#### The plank on two stacks\n\nValidation case \\ref case_B17 \"B17\".\n\n");
  plankTable();
  std::printf("#### The card A-frame\n\nValidation case \\ref case_A17 \"A17\".\n\n");
  cardsTable();
  std::printf("#### The tilted stack\n\nValidation case \\ref case_A19 \"A19\".\n\n");
  tiltedTable();
  std::printf("#### The pyramid and the cost of each stage\n\nValidation case \\ref case_B15 \"B15\".\n\n");
  pyramidTables();
  std::printf("\n#### The pass as the contact stage\n\n");
  passAsContactTable();
  std::printf("\n#### The pair caps of the pass as the contact stage\n\n");
  passCapsTable();
  return 0;
}
