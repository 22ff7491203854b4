// Chapter 7, "Candidate lists": what the lists save in counted work (the same on every
// machine) and that they change nothing else. Each scene runs 60 steps at 60 Hz twice, with
// candidate lists off (candidateReach = 0) and on (the default), under GBF's step and under
// the short pair loops of chapter 9; one Markdown row per run pair: samples carried into the
// other body's frame and phi queries per step, lists made per step, the share of one-way
// asks a list answered, and whether every body ends with the same bits.
#include <cstdio>
#include <cstring>

#include "../../tests/ch09/stack_scenes.hpp"

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
  return 0;
}
