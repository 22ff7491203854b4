// Run this now (chapter 11): one sweep spec, docs/sweeps/slide_roll_2d_sweep.json (a disk
// launched sliding that must roll at 2 v0 / 3 from t = v0 / (3 mu g)), run through the
// sweep's own functions: every run of its grid, its two errors against the closed forms,
// and the observed order between consecutive time steps, Eq. (11.2). Costs are left out:
// they are the machine's; the errors are the method's and the same on every machine.
#include <cmath>
#include <cstdio>
#include <string>

#include "stackbook/scene/sweep.hpp"

using namespace stackbook;

int main() {
  SweepSpec spec = loadSweepSpec("docs/sweeps/slide_roll_2d_sweep.json");
  std::printf("%s: %zu runs of %s\n\n", spec.name.c_str(), sweepRuns(spec).size(), spec.scene.c_str());
  std::printf("%-14s %-8s %-16s %-6s %-16s %-6s\n", "surface query", "dt (s)", spec.errors[0].name.c_str(),
              "order", spec.errors[1].name.c_str(), "order");
  std::string previousConfig;
  double previousDt = 0.0, previous[2] = {0.0, 0.0};
  for (const SweepRun& run : sweepRuns(spec)) {
    const SweepRow row = runSweepRun(spec, run);
    const double dt = std::stod(run.value);
    const bool sameLine = run.config == previousConfig;
    std::string query = run.config;
    if (const auto eq = query.find('='); eq != std::string::npos) query = query.substr(eq + 1);
    std::printf("%-14s %-8g", query.c_str(), dt);
    for (int k = 0; k < 2; ++k) {
      const double e = row.errors[static_cast<std::size_t>(k)];
      // Eq. (11.2): the slope of log error against log dt between this run and the last,
      // where both errors are finite and above rounding (1e-9).
      const bool measurable = std::isfinite(e) && e > 1e-9;
      const bool slope = sameLine && measurable && std::isfinite(previous[k]) && previous[k] > 1e-9;
      char order[16] = "";
      if (slope) std::snprintf(order, sizeof order, "%.2f", std::log(previous[k] / e) / std::log(previousDt / dt));
      if (std::isfinite(e)) {
        std::printf(" %-16.3e %-6s", e, order);
      } else {
        std::printf(" %-16s %-6s", "never", order);
      }
      previous[k] = e;
    }
    std::printf("\n");
    previousConfig = run.config;
    previousDt = dt;
  }
}
