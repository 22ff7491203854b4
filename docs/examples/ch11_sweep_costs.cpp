// What the full sweeps of chapter 11 cost (chapter 11, "Peers on the same axes"): for each
// checked-in CSV of docs/sweeps/results/, its runs, how many of them are a peer's, and the
// computation its rows record, the sum over its runs of steps times milliseconds per step,
// as a Markdown table with the total. That is one core's time for the runs alone: what
// `sweep_results` takes is about this divided by its jobs (2), plus loading the scenes.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "stackbook/scene/sweep.hpp"

using namespace stackbook;
namespace fs = std::filesystem;

int main() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator("docs/sweeps/results")) {
    if (entry.path().extension() == ".csv") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::printf("| sweep | runs | of them a peer's | computation (s) |\n|---|---|---|---|\n");
  double total = 0.0;
  std::size_t runs = 0, peerRuns = 0;
  for (const fs::path& file : files) {
    const auto rows = readSweepCsv(file.string());
    double seconds = 0.0;
    std::size_t peers = 0;
    // Columns: run, scene, engine, config, knob, value, steps, ms per step, ...
    for (std::size_t r = 1; r < rows.size(); ++r) {
      seconds += std::strtod(rows[r][6].c_str(), nullptr) * std::strtod(rows[r][7].c_str(), nullptr) / 1000.0;
      if (rows[r][2] != "stackbook") ++peers;
    }
    std::printf("| `%s` | %zu | %zu | %.1f |\n", file.stem().c_str(), rows.size() - 1, peers, seconds);
    total += seconds;
    runs += rows.size() - 1;
    peerRuns += peers;
  }
  std::printf("| all | %zu | %zu | %.1f |\n", runs, peerRuns, total);
  return 0;
}
