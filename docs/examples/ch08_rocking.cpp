// Chapter 8: a block rocking on a floor (Housner's law, Eq. (8.20); validation case A22),
// the probe the chapter's diagnosis reads. It prints, step by step through the first landing,
// every impulse the step applies (stage, point, normal, size) and the angular velocity
// before and after, under the lever arms of Eq. (8.3) with every sample allowed to collide,
// and under the step's defaults; then the ratio the block keeps at each time step under
// each rule, in 2D and 3D. Printed as Markdown (\include{doc} ch08_rocking.out).
#include <cmath>
#include <cstdio>
#include <string>

#include "../../tests/ch08/rocking_block.hpp"  // the rocking block of the tests
#include "stackbook/stepping/traditional_step.hpp"

using namespace stackbook;

namespace {

constexpr double kB = 0.1, kH = 0.3, kTheta0 = 10.0 * M_PI / 180.0;

struct Rules {
  const char* name;
  LeverArms arms;
  bool held;
  bool tied;
};

StepSettings withRules(const Rules& r, double dt) {
  StepSettings s;
  s.dt = dt;
  s.impulsePoint.arms = r.arms;
  s.impulsePoint.heldSamples = r.held;
  s.impulsePoint.tiedLanding = r.tied;
  return s;
}

/// The landing step by step: from two steps before the first impulse at the landing corner
/// until the old pivot is off the floor.
void probe(const Rules& rules, double dt) {
  testing::RockingBlock<2> scene = testing::makeRockingBlock<2>(kB, kH, kTheta0);
  ContactRecorder recorder;
  StepSettings s = withRules(rules, dt);
  s.contactRecorder = &recorder;
  // A dry run finds the landing step, so that the printout can start two steps before it.
  testing::RockingBlock<2> dry = testing::makeRockingBlock<2>(kB, kH, kTheta0);
  ContactRecorder dryRecorder;
  StepSettings drySettings = s;
  drySettings.contactRecorder = &dryRecorder;
  const testing::Landing landing =
      testing::firstLanding<2>(dry, dt, dryRecorder, [&](World<2>& w) { step<2>(w, drySettings); });
  std::printf("**%s**, Δt = %g s (x is measured from the old pivot; the landing corner is at x = %g m):\n\n",
              rules.name, dt, 2.0 * kB);
  std::printf("| step | stage | x (m) | y (m) | normal | impulse (N s) | ω before, after (rad/s) | "
              "old pivot's height after (m) |\n|---|---|---|---|---|---|---|---|\n");
  double lowest = 0.0, predictedSink = 0.0;  // the pivot's lowest height, and Eq. (8.21) summed
  for (long n = 0; n <= landing.step + landing.steps; ++n) {
    recorder.clear();
    const double before = scene.rockingRate();
    if (n < landing.step) {
      const RigidBody<2>& block = scene.body();
      const double aboveA = block.position[1] - scene.cornerHeight(-1.0);  // (x_C - x_A) . y
      predictedSink -= 0.5 * dt * dt * before * before * aboveA;           // Eq. (8.21)
    }
    step<2>(scene.world, s);
    if (n < landing.step) lowest = std::min(lowest, scene.cornerHeight(-1.0));
    if (n < landing.step - 2) continue;
    // The contact stage's many small impulses at the pivot are summed into one line.
    double pivotSum[2] = {0.0, 0.0};
    int pivotCount = 0;
    std::string lines;
    char row[320];
    for (const ContactRecord& r : recorder.records()) {
      if (std::abs(r.point[0]) < 0.1 * kB && r.stage == ContactStage::Contact) {
        pivotSum[0] += r.impulse[0];
        pivotSum[1] += r.impulse[1];
        ++pivotCount;
        continue;
      }
      std::snprintf(row, sizeof row, "| | %s | %.3f | %.2e | (%.2f, %.2f) | (%.4f, %.4f) | | |\n",
                    contactStageName(r.stage), r.point[0], r.point[1], r.normal[0], r.normal[1], r.impulse[0],
                    r.impulse[1]);
      lines += row;
    }
    if (pivotCount > 0) {
      std::snprintf(row, sizeof row, "| | contact | 0 (pivot, %d impulses) | | (0.00, 1.00) | (%.4f, %.4f) | | |\n",
                    pivotCount, pivotSum[0], pivotSum[1]);
      lines += row;
    }
    std::printf("| %ld | | | | | | %.4f, %.4f | %.2e |\n%s", n - landing.step, before, scene.rockingRate(),
                scene.cornerHeight(-1.0), lines.c_str());
  }
  const double r = landing.ratio(), housner = testing::housnerRatio(kB, kH);
  std::printf("\nThe block keeps r = %.4f, %+.1f %% off Housner's ratio. Before the landing the old pivot's lowest "
              "height was %.2e m; with the tested-pose lever arms Eq. (8.21), summed over the steps, predicts "
              "%.2e m.\n\n",
              r, 100.0 * (r / housner - 1.0), lowest, predictedSink);
}

template <int D>
double ratio(const Rules& rules, double dt, double h = kH) {
  testing::RockingBlock<D> scene = testing::makeRockingBlock<D>(kB, h, kTheta0);
  ContactRecorder recorder;
  StepSettings s = withRules(rules, dt);
  s.contactRecorder = &recorder;
  const testing::Landing landing =
      testing::firstLanding<D>(scene, dt, recorder, [&](World<D>& w) { step<D>(w, s); });
  return landing.found ? landing.ratio() : std::nan("");
}

}  // namespace

int main() {
  const Rules tested{"Lever arms at the tested pose, every sample may collide", LeverArms::AtTestedPose, false, false};
  const Rules start{"Lever arms at the start pose, every sample may collide", LeverArms::AtStartPose, false, false};
  const Rules held{"Start pose, held samples passed over", LeverArms::AtStartPose, true, false};
  const Rules all{"The default step's rules: start pose, held samples, tied landing", LeverArms::AtStartPose, true, true};
  std::printf("A block with b = %g m, h = %g m (b/h = 1/3), released from rest at 10 degrees on its corner, "
              "e = 0, mu = 1, GBF's step without shock propagation. Housner's ratio is %.4f.\n\n",
              kB, kH, testing::housnerRatio(kB, kH));
  probe(tested, 7e-4);
  probe(start, 5e-4);
  probe(all, 5e-4);
  const double steps[] = {1e-3, 7e-4, 5e-4, 4e-4, 2.5e-4};
  std::printf("The ratio r the block keeps across its first landing, against Housner's %.4f:\n\n",
              testing::housnerRatio(kB, kH));
  std::printf("| rule | D |");
  for (const double dt : steps) std::printf(" Δt = %g |", dt);
  std::printf("\n|---|---|");
  for (std::size_t k = 0; k < std::size(steps); ++k) std::printf("---|");
  std::printf("\n");
  for (const Rules* r : {&tested, &start, &held, &all}) {
    for (const int D : {2, 3}) {
      std::printf("| %s | %d |", r->name, D);
      for (const double dt : steps) std::printf(" %.4f |", D == 2 ? ratio<2>(*r, dt) : ratio<3>(*r, dt));
      std::printf("\n");
    }
  }
  // A slenderer block in 3D, b/h = 1/5, where a landing on one end of the edge shows most.
  const double slender = 5.0 * kB;
  std::printf("\nThe same in 3D for a block with b/h = 1/5 (Housner's ratio %.4f), measured as above from the "
              "energy, which counts a twist the landing gives the block:\n\n| rule |",
              testing::housnerRatio(kB, slender));
  for (const double dt : steps) std::printf(" Δt = %g |", dt);
  std::printf("\n|---|");
  for (std::size_t k = 0; k < std::size(steps); ++k) std::printf("---|");
  std::printf("\n");
  for (const Rules* r : {&held, &all}) {
    std::printf("| %s |", r->name);
    for (const double dt : steps) std::printf(" %.4f |", ratio<3>(*r, dt, slender));
    std::printf("\n");
  }
  return 0;
}
