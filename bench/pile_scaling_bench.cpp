// How the cost of a formed pile grows with its size: 2D piles of N nonconvex bodies (the
// bundled 1000-body pile's kinds: L, U, star and bone, N/4 each, in its bin), each formed by
// simulating until it settles (cached on disk), then timed. Prints per N: ms/step (min over
// the repetitions of a run's mean, and the median step), the work per step from stackbook's
// counters (impulses, signed-distance queries, narrow-phase pair queries), peak memory, and
// the least-squares slope of log(cost) against log(N) for the time and for each counter.
//
//   pile_scaling_bench [--big | --n 50,100,...] [--steps M] [--reps R] [--threads T] [--colours] [--preset WORD] [--cache DIR|--no-cache]
//
// Default N = 50, 100, 200 (forming them takes a few minutes the first time); --big adds 500
// and 1000 (forming the 1000 pile simulates its 3.9 s of pouring). --threads T times the steps
// with T threads (0: every hardware thread; default: the scene's, every hardware thread); the
// formed piles are the same for any T, so the cache serves every T. --colours times them with
// the sweeps colour by colour (chapter 10, "Colours"; the same formed piles). --preset WORD times
// them under a solver preset (chapter 9; "gbf", GBF's loops, by default; the scene's own is
// "gbfShortLoops"). Build in Release.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "peers/child_run.hpp"
#include "peers/pile_scenes.hpp"
#include "stackbook/stacking/solver_preset.hpp"

using namespace peers;

namespace {

/// The least-squares slope of log(y) against log(x) over the points with y > 0.
double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(y[i] > 0.0)) continue;
    const double lx = std::log(x[i]);
    const double ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
    ++n;
  }
  if (n < 2) return NAN;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

int usage(const char* program) {
  std::fprintf(stderr, "usage: %s [--big | --n 50,100,...] [--steps M] [--reps R] [--threads T] [--colours] [--preset WORD] [--cache DIR|--no-cache]\n", program);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes = {50, 100, 200};
  long steps = 50;
  int reps = 2;
  std::string cache = "peers_bench_cache";
  int threads = -1;  // the timed steps' thread count; -1: the scene's (every hardware thread)
  bool colours = false;  // the timed steps' sweeps colour by colour
  // The timed steps' solver preset (chapter 9): GBF's loops unless named; the piles are formed
  // under the scene's own settings whatever it is.
  stackbook::SolverPreset preset = stackbook::SolverPreset::Gbf;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--big") {
      sizes = {50, 100, 200, 500, 1000};
    } else if (arg == "--n" && hasValue) {
      sizes.clear();
      std::stringstream in(argv[++i]);
      for (std::string part; std::getline(in, part, ',');) sizes.push_back(std::atoi(part.c_str()));
    } else if (arg == "--steps" && hasValue) {
      steps = std::atol(argv[++i]);
    } else if (arg == "--reps" && hasValue) {
      reps = std::atoi(argv[++i]);
    } else if (arg == "--threads" && hasValue) {
      threads = std::atoi(argv[++i]);
    } else if (arg == "--colours") {
      colours = true;
    } else if (arg == "--preset" && hasValue) {
      const std::optional<stackbook::SolverPreset> named = stackbook::solverPresetNamed(argv[++i]);
      if (!named) {
        std::fprintf(stderr, "pile_scaling_bench: --preset %s: expected %s\n", argv[i],
                     stackbook::solverPresetWords().c_str());
        return 2;
      }
      preset = *named;
    } else if (arg == "--cache" && hasValue) {
      cache = argv[++i];
    } else if (arg == "--no-cache") {
      cache.clear();
    } else {
      return usage(argv[0]);
    }
  }
  if (sizes.empty() || steps < 1 || reps < 1 || threads < -1) return usage(argv[0]);

  std::printf("Formed 2D piles of N nonconvex bodies (L, U, star, bone), the scene's settings, dt 1 ms, %ld timed "
              "steps, %d repetition(s), %s%s, timed under the preset \"%s\"\n\n",
              steps, reps, threads < 0 ? "the scene's threads" : (std::to_string(threads) + " thread(s)").c_str(),
              colours ? ", sweeps colour by colour" : "", std::string(stackbook::solverPresetName(preset)).c_str());
  std::printf("| N | ms/step min | ms/step median | CPU ms/step median | impulses/step | phi queries/step | pair queries/step | max speed "
              "(m/s) | peak memory (MB) |\n|---|---|---|---|---|---|---|---|---|\n");
  std::vector<double> n, ms, cpu, impulses, phi, pairs;
  int failures = 0;
  for (const int size : sizes) {
    PileSpec pile;
    try {
      pile = pile2d(size, cache);
      pile.timingThreads = threads;
      if (colours) pile.timingPairOrder = stackbook::PairOrder::Colours;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "pile_scaling_bench: N = %d: %s\n", size, e.what());
      return 2;
    }
    double best = -1.0;
    long peak = 0;
    std::vector<double> all;
    std::vector<double> allCpu;
    RunResult last;
    for (int r = 0; r < reps; ++r) {
      RunResult run = runInChild([pile, preset] { return makeStackbookPile(pile, preset); }, steps);
      peak = std::max(peak, run.peakKilobytes);
      if (!run.ok) {
        last = run;
        break;
      }
      const double m = 1e3 * mean(run.stepSeconds);
      if (best < 0.0 || m < best) best = m;
      all.insert(all.end(), run.stepSeconds.begin(), run.stepSeconds.end());
      allCpu.insert(allCpu.end(), run.stepCpuSeconds.begin(), run.stepCpuSeconds.end());
      last = run;
    }
    if (!last.ok) {
      ++failures;
      std::printf("| %d | failed: %s | | | | | | | |\n", size, last.error.c_str());
      continue;
    }
    const double cpuMs = 1e3 * median(allCpu);
    std::printf("| %d | %.4g | %.4g | %.4g | %.0f | %.0f | %.0f | %.2e | %.1f |\n", size, best, 1e3 * median(all), cpuMs,
                last.work.impulses, last.work.phiQueries, last.work.pairQueries, last.accuracy.maxSpeed,
                static_cast<double>(peak) / 1024.0);
    std::fflush(stdout);
    n.push_back(size);
    ms.push_back(best);
    cpu.push_back(cpuMs);
    impulses.push_back(last.work.impulses);
    phi.push_back(last.work.phiQueries);
    pairs.push_back(last.work.pairQueries);
  }
  std::printf("\nFitted log-log slope against N: wall time (min) %.2f, CPU time (median) %.2f, impulses %.2f, phi "
              "queries %.2f, pair queries %.2f\n",
              logLogSlope(n, ms), logLogSlope(n, cpu), logLogSlope(n, impulses), logLogSlope(n, phi),
              logLogSlope(n, pairs));
  return failures == 0 ? 0 : 1;
}
