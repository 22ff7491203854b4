// The table and CSV of peers_bench (report.hpp).
#include "report.hpp"

#include <algorithm>

namespace peers {

namespace {

const RunResult* lastGood(const Row& row) {
  for (auto it = row.runs.rbegin(); it != row.runs.rend(); ++it) {
    if (it->ok) return &*it;
  }
  return nullptr;
}

std::string failure(const Row& row) {
  for (const RunResult& r : row.runs) {
    if (!r.ok) return r.error;
  }
  return {};
}

long peakKilobytes(const Row& row) {
  long peak = 0;
  for (const RunResult& r : row.runs) peak = std::max(peak, r.peakKilobytes);
  return peak;
}

std::string measured(double x, const char* format) {
  if (x < 0.0) return "-";
  char text[64];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

/// The incline column: the relative error of the slid distance (its closed form in brackets).
std::string incline(const Accuracy& a) {
  if (a.inclineError < -1.5) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%+.2e (of %.4g m)", a.inclineError, a.inclineDistance);
  return text;
}

std::string ratios(const Row& row) {
  if (!(row.ratio > 0.0)) return "-";
  return measured(row.ratio, "%.3gx") + " / " + measured(row.medianRatio, "%.3gx") + " / " +
         measured(row.cpuRatio, "%.3gx");
}

}  // namespace

double minMsPerStep(const Row& row) {
  double best = -1.0;
  for (const RunResult& r : row.runs) {
    if (!r.ok || r.stepSeconds.empty()) continue;
    const double ms = 1e3 * mean(r.stepSeconds);
    if (best < 0.0 || ms < best) best = ms;
  }
  return best;
}

double medianMsPerStep(const Row& row) {
  std::vector<double> all;
  for (const RunResult& r : row.runs) {
    if (r.ok) all.insert(all.end(), r.stepSeconds.begin(), r.stepSeconds.end());
  }
  return all.empty() ? -1.0 : 1e3 * median(all);
}

double medianCpuMsPerStep(const Row& row) {
  std::vector<double> all;
  for (const RunResult& r : row.runs) {
    if (r.ok) all.insert(all.end(), r.stepCpuSeconds.begin(), r.stepCpuSeconds.end());
  }
  return all.empty() ? -1.0 : 1e3 * median(all);
}

void printTableHeader(std::FILE* out) {
  std::fprintf(out,
               "| scene | engine | bodies | steps | runs | ms/step min | ms/step median | CPU ms/step median | "
               "ms per simulated s | ratio to peer (min / median / CPU) | max drift (m) | top sag (m) | max speed (m/s) | max penetration (m) | "
               "energy change (J) | incline error | peak memory (MB) | impulses/step | phi queries/step |\n");
  std::fprintf(out, "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

void printTableRow(std::FILE* out, const Row& row) {
  const RunResult* r = lastGood(row);
  if (r == nullptr) {
    std::fprintf(out, "| %s | %s | %d | %ld | %zu | failed: %s | | | | | | | | | | | | | |\n", row.description.c_str(),
                 row.engine.c_str(), row.bodies, row.steps, row.runs.size(), failure(row).c_str());
    std::fflush(out);
    return;
  }
  const double ms = minMsPerStep(row);
  const Accuracy& a = r->accuracy;
  std::fprintf(out, "| %s | %s | %d | %ld | %zu | %.4g | %.4g | %.4g | %.4g | %s | %.2e | %.2e | %.2e | %.2e | %.3g | %s | %.1f | %s | %s |%s\n",
               row.description.c_str(), row.engine.c_str(), row.bodies, row.steps, row.runs.size(), ms, medianMsPerStep(row),
               medianCpuMsPerStep(row), ms / row.dt, ratios(row).c_str(), a.drift, a.sag,
               a.maxSpeed, a.penetration, a.energyChange, incline(a).c_str(), static_cast<double>(peakKilobytes(row)) / 1024.0,
               measured(r->work.impulses, "%.0f").c_str(), measured(r->work.phiQueries, "%.0f").c_str(),
               a.finite ? "" : " NOT FINITE");
  std::fflush(out);
}

void printCsvHeader(std::FILE* out) {
  std::fprintf(out,
               "scene,description,engine,bodies,dt,steps,repetitions,ms_per_step_min,ms_per_step_median,"
               "cpu_ms_per_step_median,ms_per_simulated_s,ratio_to_peer,median_ratio_to_peer,cpu_ratio_to_peer,max_drift_m,top_sag_m,max_speed_m_s,max_penetration_m,"
               "energy_change_J,incline_distance_m,incline_error,peak_memory_MB,impulses_per_step,phi_queries_per_step,setup_s,finite,error\n");
}

void printCsvRow(std::FILE* out, const Row& row) {
  const RunResult* r = lastGood(row);
  const Accuracy a = r ? r->accuracy : Accuracy{};
  const Work w = r ? r->work : Work{};
  const double ms = minMsPerStep(row);
  std::string error = failure(row);
  std::replace(error.begin(), error.end(), ',', ';');
  std::replace(error.begin(), error.end(), '"', '\'');
  std::fprintf(out, "%s,\"%s\",%s,%d,%.10g,%ld,%zu,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.2f,%.6g,%.6g,%.4g,%d,\"%s\"\n",
               row.scene.c_str(), row.description.c_str(), row.engine.c_str(), row.bodies, row.dt, row.steps,
               row.runs.size(), ms, medianMsPerStep(row), medianCpuMsPerStep(row), ms > 0.0 ? ms / row.dt : -1.0,
               row.ratio, row.medianRatio, row.cpuRatio, a.drift, a.sag,
               a.maxSpeed, a.penetration, a.energyChange, a.inclineDistance, a.inclineError,
               static_cast<double>(peakKilobytes(row)) / 1024.0, w.impulses, w.phiQueries, r ? r->setupSeconds : 0.0, a.finite ? 1 : 0, error.c_str());
  std::fflush(out);
}

}  // namespace peers
