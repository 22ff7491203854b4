#pragma once
// One timed engine run in a fork()ed child process (peers_bench, pile_scaling_bench): the
// child builds the scene, times every step, measures the accuracy and reports back through
// a pipe; the parent reads the child's own peak resident memory from wait4(). A child per
// run keeps each engine's peak memory apart and a crash in one engine from ending the table.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stackbook/peers/engine.hpp"

namespace peers {

struct RunResult {
  bool ok = false;
  std::string error;               ///< why the run failed (when !ok)
  std::vector<double> stepSeconds; ///< wall time of each timed step
  /// CPU time of each timed step (the process's, all threads): unlike the wall time it does
  /// not count the time the step waited for a core on a loaded machine.
  std::vector<double> stepCpuSeconds;
  Accuracy accuracy;
  Work work;
  double setupSeconds = 0.0;       ///< building (and forming) the scene
  long peakKilobytes = 0;          ///< the child's ru_maxrss
};

/// Runs `steps` timed steps of the engine `make` builds, in a child process.
RunResult runInChild(const std::function<std::unique_ptr<Engine>()>& make, long steps);

/// Minimum and median of a list (0 for an empty one).
double minimum(const std::vector<double>& v);
double median(std::vector<double> v);
double mean(const std::vector<double>& v);

}  // namespace peers
