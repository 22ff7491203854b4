// Chapter 8: GBF's order against the traditional order on validation case A1 (a unit
// box at rest on a 20 degree incline, mu = 0.5, e = 1), the A2 slide error at two step
// sizes and the A2b stick/slide switch under both slip-direction rules of chapter 3, and
// what the step costs, stage by stage. Printed as Markdown for the course page
// (\include{doc} ch08_step_orders.out). Wall times vary from run to run; counts do not.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "../../tests/ch08/scene_builders.hpp"  // the A1/A2 incline of the tests

using namespace stackbook;
using stackbook::testing::kG;

namespace {

template <int D>
void orders(double seconds) {
  for (const StepOrder order : {StepOrder::Gbf, StepOrder::Traditional}) {
    testing::InclineScene<D> scene = testing::makeIncline<D>(20.0 * M_PI / 180.0, 0.5, 1.0);
    StepSettings settings;
    settings.order = order;
    double maxLift = 0.0;
    const long steps = std::lround(seconds / settings.dt);
    for (long n = 0; n < steps; ++n) {
      step<D>(scene.world, settings);
      maxLift = std::max(maxLift, std::abs(scene.lift()));
    }
    std::printf("| %dD | %s | %.3e | %.3e |\n", D, order == StepOrder::Gbf ? "GBF" : "traditional",
                scene.travelled(), maxLift);
  }
}

template <int D>
void slideErrors(SlipDirectionRule rule, const char* name) {
  const double theta = 30.0 * M_PI / 180.0, mu = 0.3;
  const double exact = 0.5 * kG * (std::sin(theta) - mu * std::cos(theta));
  for (const double dt : {1e-3, 5e-4}) {
    testing::InclineScene<D> scene = testing::makeIncline<D>(theta, mu, 0.0);
    StepSettings settings;
    settings.dt = dt;
    settings.friction.slipDirection = rule;
    const long steps = std::lround(1.0 / dt);
    for (long n = 0; n < steps; ++n) step<D>(scene.world, settings);
    std::printf("| %dD | %s | %g | %.6f | %.6f | %+.3f %% |\n", D, name, dt, scene.travelled(),
                exact, 100.0 * (scene.travelled() - exact) / exact);
  }
}

/// A2b: with mu = 0.5 the friction angle is atan(0.5) = 26.57 degrees; a box at rest at 26
/// degrees must stay, at 27 it must slide with a = g (sin - mu cos). The switch is where the
/// two slip-direction rules differ most in 3D (chapter 3, continuity).
template <int D>
void switchRow(SlipDirectionRule rule, const char* name, double degrees) {
  const double theta = degrees * M_PI / 180.0, mu = 0.5;
  const double exact = std::max(0.0, 0.5 * kG * (std::sin(theta) - mu * std::cos(theta)));
  testing::InclineScene<D> scene = testing::makeIncline<D>(theta, mu, 0.0);
  StepSettings settings;
  settings.friction.slipDirection = rule;
  const long steps = std::lround(1.0 / settings.dt);
  double maxLift = 0.0;
  for (long n = 0; n < steps; ++n) {
    step<D>(scene.world, settings);
    maxLift = std::max(maxLift, std::abs(scene.lift()));
  }
  char error[32] = "(stays)";
  if (exact > 0.0) std::snprintf(error, sizeof error, "%+.3f %%", 100.0 * (scene.travelled() - exact) / exact);
  std::printf("| %dD | %s | %g | %.3e | %.3e | %s | %.3e |\n", D, name, degrees, scene.travelled(), exact,
              error, maxLift);
}

void costs(const std::vector<double>& schedule, const char* name) {
  testing::InclineScene<3> scene = testing::makeIncline<3>(20.0 * M_PI / 180.0, 0.5, 1.0);
  StepSettings settings;
  settings.contactRestitution = schedule;
  StepCounters total;
  for (int n = 0; n < 1000; ++n) total += gbfStep<3>(scene.world, settings);
  const auto row = [name](const char* stage, const StageCounters& c) {
    std::printf("| %s | %s | %lld | %lld | %lld | %lld | %lld | %lld | %lld | %.0f |\n", name, stage,
                static_cast<long long>(c.sweeps), static_cast<long long>(c.impulses),
                static_cast<long long>(c.frictionless), static_cast<long long>(c.sticking),
                static_cast<long long>(c.sliding), static_cast<long long>(c.pairIterationCapHits),
                static_cast<long long>(c.detection.phiQueries), c.seconds * 1e3);
  };
  row("collision", total.collision);
  row("contact", total.contact);
  std::printf("| %s | travel after 1 s: %.2e m | | | | | | | | |\n", name, scene.travelled());
}

}  // namespace

int main() {
  std::printf("\\ref case_A1 \"A1\", the elastic box at rest on a 20 degree incline, in both step orders:\n\n");
  std::printf("| dimension | order | travel down the slope after 1 s (m) | largest lift (m) |\n"
              "|---|---|---|---|\n");
  orders<2>(1.0);
  orders<3>(1.0);
  std::printf("\n\\ref case_A2 \"A2\", a box sliding down a 30 degree incline with mu = 0.3 for 1 s, "
              "under both slip-direction rules at two step sizes:\n");
  std::printf("\n| dimension | slip direction | dt (s) | s(1 s) (m) | a/2 (m) | error |\n"
              "|---|---|---|---|---|---|\n");
  slideErrors<2>(SlipDirectionRule::RelativeVelocity, "GBF (u_t)");
  slideErrors<3>(SlipDirectionRule::RelativeVelocity, "GBF (u_t)");
  slideErrors<3>(SlipDirectionRule::Blended, "Blended (chapter 3)");
  std::printf("\n\\ref case_A2b \"A2b\", either side of the friction angle (mu = 0.5, 1 s at the default "
              "step), under both rules:\n\n"
              "| dimension | slip direction | incline (degrees) | s(1 s) (m) | a/2 (m) | error | largest lift (m) |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const double degrees : {26.0, 27.0}) {
    switchRow<2>(SlipDirectionRule::RelativeVelocity, "GBF (u_t)", degrees);
    switchRow<3>(SlipDirectionRule::RelativeVelocity, "GBF (u_t)", degrees);
    switchRow<3>(SlipDirectionRule::Blended, "Blended (chapter 3)", degrees);
  }
  std::printf("\n\\ref case_A1 \"A1\" in 3D, 1000 steps of GBF's order (unit box: 98 surface samples), with GBF's "
              "ramp e_k = -1 + k/10 and with e_k = 0 in all ten sweeps:\n\n"
              "| schedule | stage | sweeps | impulses | frictionless | sticking | sliding | "
              "pair caps hit | phi queries | wall ms |\n|---|---|---|---|---|---|---|---|---|---|\n");
  costs({}, "ramp");
  costs(std::vector<double>(10, 0.0), "all zero");
}
