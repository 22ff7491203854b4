// Chapter 7, "Candidate lists": what the lists save in counted work (the same on every
// machine) and that they change nothing else. Each scene runs 60 steps at 60 Hz twice, with
// candidate lists off (candidateReach = 0) and on (the default), under GBF's step and under
// the short pair loops of chapter 9; one Markdown row per run pair: samples carried into the
// other body's frame and phi queries per step, lists made per step, the share of one-way
// asks a list answered, and whether every body ends with the same bits. A second table runs
// two bundled nonconvex scenes (scenes/rings_on_pegs_3d.json, scenes/shapes_in_bin_2d.json) for
// their whole duration with their own settings at three reaches (0, 0.05, and
// the default), and at the default with the world's kept lists (World::candidateLists)
// forgotten before every step: the same counts per step.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <variant>

#include "../../tests/ch09/stack_scenes.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/stepping/traditional_step.hpp"

using namespace stackbook;

namespace {

DetectionCounters detection(const StepCounters& c) {
  DetectionCounters d = c.collision.detection;
  d += c.contact.detection;
  d += c.shock.detection;
  return d;
}

template <int D>
bool sameBits(const World<D>& a, const World<D>& b) {
  for (std::size_t k = 0; k < a.bodies.size(); ++k) {
    const RigidBody<D>& x = a.bodies[k];
    const RigidBody<D>& y = b.bodies[k];
    bool same = x.position == y.position && x.velocity == y.velocity && x.angularMomentum == y.angularMomentum;
    if constexpr (D == 2) {
      same = same && x.orientation.angle() == y.orientation.angle();
    } else {
      same = same && x.orientation.coeffs() == y.orientation.coeffs();
    }
    if (!same) return false;
  }
  return true;
}

template <int D>
void row(const char* scene, const World<D>& start, const char* stepName, StepSettings on) {
  constexpr int kSteps = 60;
  on.dt = 1.0 / 60.0;
  StepSettings off = on;
  off.detection.narrow.candidateReach = 0.0;
  World<D> a = start, b = start;
  StepCounters withLists, without;
  for (int n = 0; n < kSteps; ++n) {
    withLists += stackingStep<D>(a, on);
    without += stackingStep<D>(b, off);
  }
  const DetectionCounters x = detection(withLists), y = detection(without);
  const double steps = kSteps;
  const double asks = static_cast<double>(x.listedQueries + x.candidateListsMade);
  std::printf("| %s | %s | %.0f | %.0f | %.0f | %.0f | %.1f | %.1f %% | %s |\n", scene, stepName,
              static_cast<double>(y.samplesTransformed) / steps, static_cast<double>(x.samplesTransformed) / steps,
              static_cast<double>(y.phiQueries) / steps, static_cast<double>(x.phiQueries) / steps,
              static_cast<double>(x.candidateListsMade) / steps,
              asks > 0.0 ? 100.0 * static_cast<double>(x.listedQueries) / asks : 0.0,
              sameBits<D>(a, b) ? "yes" : "**no**");
}

/// One row of the second table: the scene's world stepped for its whole duration with its own
/// settings and the given reach, left in `end` for the comparison of bits.
template <int D>
void reachRow(const std::string& name, const Scene& scene, double reach, World<D>& end, bool forgetEachStep = false) {
  StepSettings settings = scene.settings;
  settings.detection.narrow.candidateReach = reach;
  end = std::get<SceneBodies<D>>(scene.bodies).world;
  const auto steps = static_cast<long>(std::ceil(scene.duration / settings.dt - 1e-9));
  const PostContactHook<D> hook = shockPropagationHook<D>();
  StepCounters total;
  for (long n = 0; n < steps; ++n) {
    if (forgetEachStep) end.candidateLists = CandidateListStore<D>{};  // kept between stages only
    total += step<D>(end, settings, hook);
  }
  const DetectionCounters d = detection(total);
  const double perStep = static_cast<double>(steps);
  const double asks = static_cast<double>(d.listedQueries + d.candidateListsMade);
  std::printf("| `%s.json` | %g%s | %.0f | %.0f | %.1f | %.1f %% |", name.c_str(), reach,
              forgetEachStep ? ", forgotten after every step" : "",
              static_cast<double>(d.samplesTransformed) / perStep, static_cast<double>(d.phiQueries) / perStep,
              static_cast<double>(d.candidateListsMade) / perStep,
              asks > 0.0 ? 100.0 * static_cast<double>(d.listedQueries) / asks : 0.0);
}

template <int D>
void reachRows(const std::string& name) {
  const Scene scene = loadScene("scenes/" + name + ".json");
  World<D> off, end;
  for (const double reach : {0.0, 0.05, NarrowPhaseSettings{}.candidateReach}) {
    reachRow<D>(name, scene, reach, reach == 0.0 ? off : end);
    std::printf(" %s |\n", reach == 0.0 ? "-" : (sameBits<D>(off, end) ? "yes" : "**no**"));
  }
  reachRow<D>(name, scene, NarrowPhaseSettings{}.candidateReach, end, true);
  std::printf(" %s |\n", sameBits<D>(off, end) ? "yes" : "**no**");
}

template <int D>
void rows(const char* scene, const World<D>& start) {
  row<D>(scene, start, "GBF's step", StepSettings{});
  row<D>(scene, start, "short pair loops", passAsContactStageShortLoops());
}

}  // namespace

int main() {
  std::printf("| scene | step | samples carried per step, lists off | lists on | phi queries per step, lists off "
              "| lists on | lists made per step | one-way asks a list answered | same bits |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  const Material material{0.0, 0.6, 0.0};
  rows<2>("2D stack of 10", stacks::boxStack<2>(10, material));
  rows<2>("2D pyramid, base 10", stacks::pyramid2d(10, material));
  rows<3>("3D stack of 10", stacks::boxStack<3>(10, material));
  rows<3>("3D pyramid, base 4", stacks::pyramid3d(4, material));
  std::printf("\nTable: four box scenes, 60 steps at 60 Hz, candidate lists off and on (the default reach).\n\n");
  std::printf("| scene | reach (fraction of r_A) | samples carried per step | phi queries per step | lists made per step "
              "| one-way asks a list answered | same bits as reach 0 |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  reachRows<3>("rings_on_pegs_3d");
  reachRows<2>("shapes_in_bin_2d");
  std::printf("\nTable: two bundled nonconvex scenes for their whole duration with their own settings, at three "
              "reaches, and at the default reach with the world's lists forgotten after every step.\n");
  return 0;
}
