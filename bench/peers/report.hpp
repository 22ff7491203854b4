#pragma once
// The table and CSV of peers_bench: one row per scene and engine.
#include <cstdio>
#include <string>
#include <vector>

#include "child_run.hpp"

namespace peers {

struct Row {
  std::string scene;        ///< key, e.g. "pyramid2d_20"
  std::string description;  ///< what was run, with its size
  std::string engine;       ///< "stackbook", "stackbook pass", "stackbook short", "Box2D 2.4.1", ...
  bool isPeer = false;
  int bodies = 0;
  double dt = 0.0;
  long steps = 0;
  std::vector<RunResult> runs;  ///< one per repetition
  double ratio = -1.0;          ///< this row's min ms/step over the peer's (stackbook rows)
  double medianRatio = -1.0;    ///< the same for the median steps
  double cpuRatio = -1.0;       ///< the same for the median steps' CPU time
};

/// Min over repetitions of each run's mean ms/step, and the median step over all runs.
double minMsPerStep(const Row& row);
double medianMsPerStep(const Row& row);
/// The median step's CPU time over all runs.
double medianCpuMsPerStep(const Row& row);

void printTableHeader(std::FILE* out);
void printTableRow(std::FILE* out, const Row& row);
void printCsvHeader(std::FILE* out);
void printCsvRow(std::FILE* out, const Row& row);

}  // namespace peers
