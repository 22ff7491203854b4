// Chapter 12, "The default step": the scenes whose outcome depends on whether lower bodies feel
// the load above them, under GBF's step, under the two earlier candidates for a default (chapter
// 9's welded pass and the pass as the contact stage with sticking patches) and under the default
// of a scene that names no preset, the carrying pass. The towers are chapter 9's A19 (ten unit
// boxes, each offset 0.2 from the one below: it must fall) and the same tower offset 0.08 (it may
// stand), in 2D and 3D at 60 Hz; the rest are bundled scenes at their own dt for their whole
// duration. One Markdown row per scene and step: what the scene asks (the top box's height, the
// plank's angle), the largest distance a body moved, the largest rise of kinetic plus potential
// energy over its start, and the milliseconds per step (one thread). It fails if the default
// stops keeping the chapter's claims: the tilted towers fall (top below 2 m within 3 s), the
// offset ones and the plank on two stacks stand (1 mm), the seesaw tips within 0.5 degrees of
// GBF's step, the card house stands (5 mm), and no scene gains energy.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "../../tests/ch09/stack_scenes.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"
#include "stackbook/stacking/solver_preset.hpp"

using namespace stackbook;

namespace {

struct Outcome {
  double asked = std::nan("");  // the scene's own measure: the top box's height (m) or the plank's angle (deg)
  double moved = 0.0;           // largest distance of a body from its start at the end, m
  double energyGain = 0.0;      // largest rise of kinetic plus potential energy, J
  double msPerStep = 0.0;
};

template <int D>
Outcome run(World<D> world, const StepSettings& settings, double seconds, const std::function<double(const World<D>&)>& asked) {
  const World<D> start = world;
  const long steps = std::lround(seconds / settings.dt);
  const double e0 = worldEnergy<D>(world).total();
  Outcome out;
  const auto t0 = std::chrono::steady_clock::now();
  for (long n = 0; n < steps; ++n) {
    stackingStep<D>(world, settings);
    out.energyGain = std::max(out.energyGain, worldEnergy<D>(world).total() - e0);
  }
  out.msPerStep = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() /
                  static_cast<double>(steps);
  for (std::size_t b = 0; b < world.bodies.size(); ++b) {
    out.moved = std::max(out.moved, (world.bodies[b].position - start.bodies[b].position).norm());
  }
  out.asked = asked(world);
  return out;
}

struct Step {
  const char* label;
  SolverPreset preset;
};
const Step kSteps[] = {{"GBF's step, `\"gbf\"`", SolverPreset::Gbf},
                       {"the welded pass, `\"weldedPass\"`", SolverPreset::WeldedPass},
                       {"sticking patches, `\"passAsContactPatch\"`", SolverPreset::PassAsContactPatch},
                       {"**the carrying pass, `\"carryingPass\"` (the default)**", SolverPreset::CarryingPass}};

/// Two decimals; a value that prints as 0.00 prints without its sign; "-" where the scene asks nothing.
std::string twoDecimals(double x) {
  if (std::isnan(x)) return "-";
  char text[48];
  std::snprintf(text, sizeof text, "%.2f", std::abs(x) < 5e-3 ? 0.0 : x);
  return text;
}

void row(const std::string& scene, const char* step, const Outcome& o) {
  std::printf("| %s | %s | %s | %.1e | %.1e | %.3f |\n", scene.c_str(), step, twoDecimals(o.asked).c_str(), o.moved,
              o.energyGain, o.msPerStep);
}

}  // namespace

int main() {
  std::printf("| scene | step | top box height (m) or plank angle (deg) at the end | largest move (m) | "
              "largest energy gain (J) | ms per step |\n");
  std::printf("|---|---|---|---|---|---|\n");
  bool holds = true;
  const auto claim = [&holds](bool ok, const char* what) {
    if (!ok) {
      std::fprintf(stderr, "the default no longer keeps chapter 12's claim: %s\n", what);
      holds = false;
    }
  };
  const Material material{0.0, 0.6, 0.0};
  // The towers, 2D and 3D, at 60 Hz.
  for (const double offset : {0.2, 0.08}) {
    const double seconds = offset > 0.1 ? 3.0 : 10.0;
    const auto tower = [&](auto dimension) {
      constexpr int D = decltype(dimension)::value;
      const World<D> world = stacks::boxStack<D>(10, material, offset);
      char scene[96];
      std::snprintf(scene, sizeof scene, "%dD tower, offset %.2f, %.0f s at 60 Hz", D, offset, seconds);
      for (const Step& s : kSteps) {
        StepSettings settings = applySolverPreset(s.preset, StepSettings{});
        settings.dt = 1.0 / 60.0;
        const Outcome o = run<D>(world, settings, seconds, [](const World<D>& w) { return w.bodies[10].position[D - 1]; });
        row(scene, s.label, o);
        if (s.preset == kDefaultScenePreset) {
          if (offset > 0.1) claim(o.asked < 2.0, "the tilted tower falls");
          if (offset < 0.1) claim(o.moved < 1e-3, "the offset tower stands");
          claim(o.energyGain < 1e-9, "no energy gained on the towers");
        }
      }
    };
    tower(std::integral_constant<int, 2>{});
    tower(std::integral_constant<int, 3>{});
  }
  // The bundled scenes whose lower bodies must feel the load above them.
  for (const char* name : {"seesaw_2d", "plank_on_two_stacks_2d", "card_house_2d", "heavy_on_light_2d"}) {
    Scene scene = loadScene(std::string("scenes/") + name + ".json");
    scene.settings.parallel.threads = 1;
    const SceneBodies<2>& bodies = std::get<SceneBodies<2>>(scene.bodies);
    std::size_t plank = bodies.visuals.size();
    for (std::size_t b = 0; b < bodies.visuals.size(); ++b) {
      if (bodies.visuals[b].name == "plank") plank = b;
    }
    const auto angle = [plank](const World<2>& w) {
      if (plank >= w.bodies.size()) return std::nan("");
      const Vec2 axis = w.bodies[plank].orientation * Vec2(1.0, 0.0);
      return std::atan2(axis.y(), axis.x()) * 180.0 / M_PI;
    };
    double gbfAngle = std::nan("");
    for (const Step& s : kSteps) {
      const StepSettings settings = applySolverPreset(s.preset, scene.settings);
      const Outcome o = run<2>(bodies.world, settings, scene.duration, angle);
      row(std::string("`") + name + ".json`", s.label, o);
      if (s.preset == SolverPreset::Gbf) gbfAngle = o.asked;
      if (s.preset != kDefaultScenePreset) continue;
      const std::string scene_name = name;
      claim(o.energyGain < 1e-9, "no energy gained on the bundled scenes");
      if (scene_name == "seesaw_2d") claim(std::abs(o.asked - gbfAngle) < 0.5, "the seesaw tips as under GBF's step");
      if (scene_name == "plank_on_two_stacks_2d") claim(std::abs(o.asked) < 0.06 && o.moved < 1e-3, "the plank stands");
      if (scene_name == "card_house_2d") claim(o.moved < 5e-3, "the card house stands");
      if (scene_name == "heavy_on_light_2d") claim(o.moved < 1e-3, "the heavy box on the light one stands");
    }
  }
  std::printf("\nTable: the scenes that tell a step which bodies carry the load above them, under GBF's step, the welded "
              "pass, the pass as the contact stage with sticking patches and the default; one thread, one run each.\n");
  return holds ? 0 : 1;
}
