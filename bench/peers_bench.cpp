// Side by side: the same scenes on stackbook and on its peers, Box2D 2.4 (2D) and Bullet 3
// (3D), in one run, alternating the engines, each run in its own child process. Prints per
// scene and engine: ms/step (min over the repetitions of a run's mean, and the median step),
// ms per simulated second, the ratio to the peer, the accuracy at the end of the run (max
// horizontal drift, top sag, max speed, max penetration, energy change), peak memory and
// stackbook's work per step. Scenes, geometry the same on every engine: 1 m boxes, friction
// 0.6, g = 10, dt = 1/60, 10 s, peers at their defaults; piles of nonconvex bodies (stackbook
// only) timed once formed.
//
//   peers_bench [--scenes a,b,...|all] [--seconds T|NAME=T ...] [--reps R|NAME=R ...] [--tiny]
//               [--csv FILE] [--cache DIR|--no-cache] [--pile-pass] [--corners] [--engines a,b,...] [--list]
//
// Build in Release: cmake --preset release && cmake --build build/release --target peers_bench
// The full run and its duration on the project's machine: bench/README.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "stackbook/peers/box_scenes.hpp"
#include "peers/child_run.hpp"
#include "peers/pile_scenes.hpp"
#include "peers/report.hpp"

#ifdef STACKBOOK_HAVE_BOX2D
#include <box2d/b2_common.h>
#endif
#ifdef STACKBOOK_HAVE_BULLET
#include <LinearMath/btScalar.h>
#endif

using namespace peers;

namespace {

/// One scene of the table: boxes for every engine, or a pile for stackbook alone.
struct Entry {
  std::string key;
  bool isPile = false;
  BoxScene boxes;
  PileSpec pile;
  double seconds = 10.0;    ///< simulated seconds timed (piles: once formed)
  int reps = 3;             ///< repetitions of each engine's run
  bool byDefault = true;    ///< run without --scenes
};

std::vector<Entry> catalogue(bool tiny, const std::string& cache) {
  std::vector<Entry> e;
  const auto box = [&](std::string key, BoxScene s) {
    Entry x;
    x.key = std::move(key);
    x.boxes = std::move(s);
    x.seconds = tiny ? 0.1 : 10.0;
    x.reps = tiny ? 2 : 3;
    e.push_back(std::move(x));
  };
  box("stack2d_10", stack(2, tiny ? 2 : 10));
  box("stack2d_20", stack(2, tiny ? 3 : 20));
  box("stack2d_30", stack(2, tiny ? 4 : 30));
  box("pyramid2d_20", pyramid2d(tiny ? 3 : 20));
  box("pyramid2d_100", pyramid2d(tiny ? 5 : 100));
  box("stack3d_10", stack(3, tiny ? 2 : 10));
  box("pyramid3d_8", pyramid3d(tiny ? 2 : 8));
  // The incline (30 degrees, mu 0.3): 2 s slide 4.8 m, well within the ground.
  box("incline2d", incline(2, 30.0, 0.3));
  box("incline3d", incline(3, 30.0, 0.3));
  for (Entry& x : e) {
    if (x.boxes.tilt != 0.0) x.seconds = tiny ? 0.1 : 2.0;
  }
  const auto pile = [&](std::string key, PileSpec p, double seconds, bool byDefault) {
    Entry x;
    x.key = std::move(key);
    x.isPile = true;
    x.pile = std::move(p);
    if (tiny) x.pile.formSeconds = 0.05;
    x.reps = tiny ? 2 : 3;
    x.seconds = tiny ? 0.005 : seconds;
    x.byDefault = byDefault;
    e.push_back(std::move(x));
  };
  pile("pile2d_1000", pile2d(tiny ? 8 : 1000, tiny ? "" : cache), 0.2, true);
  pile("pile3d_100", pile3d(tiny ? 8 : 100, tiny ? "" : cache), 0.2, true);
  pile("pile3d_1000", pile3d(tiny ? 8 : 1000, tiny ? "" : cache), 0.1, false);
  return e;
}

int usage(const char* program) {
  std::fprintf(stderr,
               "usage: %s [--scenes a,b,...|all] [--seconds T|NAME=T ...] [--reps R|NAME=R ...] [--tiny] [--csv FILE]\n"
               "          [--cache DIR|--no-cache] [--pile-pass] [--corners] [--engines a,b,...] [--list]\n",
               program);
  return 2;
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) {
    if (!part.empty()) out.push_back(part);
  }
  return out;
}

void printPeers() {
#ifdef STACKBOOK_HAVE_BOX2D
  std::printf("Box2D (libbox2d-dev 2.4; b2_version says %d.%d.%d) (2D scenes): 8 velocity / 3 position iterations, sleeping off\n", b2_version.major,
              b2_version.minor, b2_version.revision);
#else
  std::printf("Box2D: not found when this program was configured; install the Debian package libbox2d-dev "
              "and reconfigure to run the 2D scenes on it\n");
#endif
#ifdef STACKBOOK_HAVE_BULLET
  std::printf("Bullet %d.%02d (3D scenes, %s precision): default solver, stepSimulation(dt, 0), deactivation off\n",
              btGetVersion() / 100, btGetVersion() % 100, sizeof(btScalar) == 8 ? "double" : "single");
#else
  std::printf("Bullet: not found when this program was configured; install the Debian package libbullet-dev "
              "and reconfigure to run the 3D scenes on it\n");
#endif
}

}  // namespace

int main(int argc, char** argv) {
  bool tiny = false;
  bool list = false;
  bool pilePass = false;
  bool corners = false;
  std::string csvPath;
  std::string cache = "peers_bench_cache";
  std::vector<std::string> wanted;
  std::vector<std::string> engines;  // --engines: only these columns (by their names in the table)
  std::vector<std::string> secondsArgs;
  std::vector<std::string> repsArgs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--tiny") {
      tiny = true;
    } else if (arg == "--list") {
      list = true;
    } else if (arg == "--pile-pass") {
      pilePass = true;
    } else if (arg == "--corners") {
      corners = true;
    } else if (arg == "--no-cache") {
      cache.clear();
    } else if (arg == "--cache" && hasValue) {
      cache = argv[++i];
    } else if (arg == "--csv" && hasValue) {
      csvPath = argv[++i];
    } else if (arg == "--reps" && hasValue) {
      repsArgs.push_back(argv[++i]);
    } else if (arg == "--scenes" && hasValue) {
      wanted = split(argv[++i]);
    } else if (arg == "--engines" && hasValue) {
      engines = split(argv[++i]);
    } else if (arg == "--seconds" && hasValue) {
      secondsArgs.push_back(argv[++i]);
    } else {
      return usage(argv[0]);
    }
  }
  // Every column name the table can have: --engines takes these (a filter, e.g. for profiling one engine).
  const std::vector<std::string> engineNames{"stackbook", "stackbook default", "stackbook welded", "stackbook pass", "stackbook short", "stackbook patch",
                                             "stackbook short corners", "Box2D", "Bullet", "stackbook colours", "stackbook gbf short",
                                             "stackbook gbf short colours"};
  for (const std::string& name : engines) {
    if (std::find(engineNames.begin(), engineNames.end(), name) == engineNames.end()) {
      std::fprintf(stderr, "peers_bench: --engines: unknown engine \"%s\" (the table's engine column names one)\n",
                   name.c_str());
      return 2;
    }
  }
  std::vector<Entry> scenes = catalogue(tiny, cache);
  if (list) {
    for (const Entry& e : scenes) {
      std::printf("%-14s %s%s\n", e.key.c_str(), e.isPile ? e.pile.description.c_str() : e.boxes.description.c_str(),
                  e.byDefault ? "" : " (only when named)");
    }
    return 0;
  }
  // --seconds T sets every box scene (piles and inclines keep their own), NAME=T one scene; --reps alike
  // (R alone sets every scene).
  const auto perScene = [&](const std::vector<std::string>& args, const char* option, bool boxesOnly,
                            const std::function<void(Entry&, double)>& set) {
    for (const std::string& s : args) {
      const auto eq = s.find('=');
      const std::string name = eq == std::string::npos ? "" : s.substr(0, eq);
      const double value = std::atof(eq == std::string::npos ? s.c_str() : s.c_str() + eq + 1);
      bool matched = false;
      for (Entry& e : scenes) {
        if (name.empty() ? !(boxesOnly && (e.isPile || e.boxes.tilt != 0.0)) : e.key == name) {
          set(e, value);
          matched = true;
        }
      }
      if (!(value > 0.0) || !matched) {
        std::fprintf(stderr, "peers_bench: %s %s: expected a value > 0, or NAME=value with a scene of --list\n",
                     option, s.c_str());
        return false;
      }
    }
    return true;
  };
  if (!perScene(secondsArgs, "--seconds", true, [](Entry& e, double t) { e.seconds = t; }) ||
      !perScene(repsArgs, "--reps", false, [](Entry& e, double r) { e.reps = std::max(1, static_cast<int>(r)); })) {
    return 2;
  }
  std::vector<Entry> chosen;
  for (const Entry& e : scenes) {
    bool take = wanted.empty() ? e.byDefault : false;
    for (const std::string& w : wanted) take = take || w == "all" || w == e.key;
    if (take) chosen.push_back(e);
  }
  for (const std::string& w : wanted) {
    bool known = w == "all";
    for (const Entry& e : scenes) known = known || w == e.key;
    if (!known) {
      std::fprintf(stderr, "peers_bench: --scenes: unknown scene \"%s\" (see --list)\n", w.c_str());
      return 2;
    }
  }
  std::FILE* csv = nullptr;
  if (!csvPath.empty()) {
    csv = std::fopen(csvPath.c_str(), "w");
    if (!csv) {
      std::fprintf(stderr, "peers_bench: cannot write %s\n", csvPath.c_str());
      return 1;
    }
    printCsvHeader(csv);
  }

  std::printf("peers_bench: each engine's run repeated (column runs), alternating the engines; ms/step min is the "
              "fastest run's mean step, median is over every step (wall time); CPU ms/step is the median step's "
              "process CPU time, which a loaded machine does not inflate\n");
  printPeers();
  std::printf("\n");
  printTableHeader(stdout);
  int failures = 0;
  for (const Entry& e : chosen) {
    struct Column {
      Row row;
      std::function<std::unique_ptr<Engine>()> make;
    };
    std::vector<Column> columns;
    const auto add = [&](std::string engine, bool isPeer, std::function<std::unique_ptr<Engine>()> make) {
      if (!engines.empty() && std::find(engines.begin(), engines.end(), engine) == engines.end()) return;
      Column c;
      c.row.scene = e.key;
      c.row.engine = std::move(engine);
      c.row.isPeer = isPeer;
      c.make = std::move(make);
      columns.push_back(std::move(c));
    };
    if (!e.isPile) {
      const BoxScene& s = e.boxes;
      add("stackbook", false, [s] { return makeStackbookBoxes(s, stackbook::SolverPreset::Gbf); });
      // The default of a scene that names no preset (chapter 12): the carrying pass.
      add("stackbook default", false, [s] { return makeStackbookBoxes(s, stackbook::kDefaultScenePreset); });
      add("stackbook welded", false, [s] { return makeStackbookBoxes(s, stackbook::SolverPreset::WeldedPass); });
      add("stackbook pass", false, [s] { return makeStackbookBoxes(s, stackbook::SolverPreset::PassAsContact); });
      add("stackbook short", false, [s] { return makeStackbookBoxes(s, stackbook::SolverPreset::PassAsContactShortLoops); });
      add("stackbook patch", false, [s] { return makeStackbookBoxes(s, stackbook::SolverPreset::PassAsContactPatch); });
      if (corners) {  // the same preset on boxes sampled at their corners only
        BoxScene c = s;
        c.stackbookBoxSubdivisions = 1;
        add("stackbook short corners", false,
            [c] { return makeStackbookBoxes(c, stackbook::SolverPreset::PassAsContactShortLoops); });
      }
      if (s.dimension == 2 && haveBox2d()) add("Box2D", true, [s] { return makeBox2d(s); });
      if (s.dimension == 3 && haveBullet()) add("Bullet", true, [s] { return makeBullet(s); });
    } else {
      const PileSpec& p = e.pile;
      add("stackbook", false, [p] { return makeStackbookPile(p, stackbook::SolverPreset::Gbf); });
      add("stackbook default", false, [p] { return makeStackbookPile(p, stackbook::kDefaultScenePreset); });
      PileSpec coloured = p;  // GBF's step, sweeps colour by colour (chapter 10, "Colours")
      coloured.timingPairOrder = stackbook::PairOrder::Colours;
      add("stackbook colours", false, [coloured] { return makeStackbookPile(coloured, stackbook::SolverPreset::Gbf); });
      if (pilePass) add("stackbook pass", false, [p] { return makeStackbookPile(p, stackbook::SolverPreset::PassAsContact); });
      if (pilePass) add("stackbook short", false, [p] { return makeStackbookPile(p, stackbook::SolverPreset::PassAsContactShortLoops); });
      add("stackbook gbf short", false, [p] { return makeStackbookPile(p, stackbook::SolverPreset::GbfShortLoops); });
      add("stackbook gbf short colours", false,
          [coloured] { return makeStackbookPile(coloured, stackbook::SolverPreset::GbfShortLoops); });
    }
    // Body count and dt without building anything in this process (its memory would be
    // counted in every child's peak).
    int bodies = 0;
    double dt = 0.0;
    if (!e.isPile) {
      bodies = static_cast<int>(e.boxes.boxes.size()) - 1;
      dt = e.boxes.dt;
    } else {
      // The pile's dt: every bundled pile uses 1 ms (read from the file in the child otherwise).
      dt = 1e-3;
      bodies = std::atoi(e.pile.name.substr(e.pile.name.find('_') + 1).c_str());
    }
    const long steps = std::max(1L, std::lround(e.seconds / dt));
    for (Column& c : columns) {
      c.row.description = e.isPile ? e.pile.description : e.boxes.description;
      c.row.bodies = bodies;
      c.row.dt = dt;
      c.row.steps = steps;
    }
    for (int rep = 0; rep < e.reps; ++rep) {
      for (Column& c : columns) c.row.runs.push_back(runInChild(c.make, steps));
    }
    double peerMs = -1.0;
    double peerMedian = -1.0;
    double peerCpu = -1.0;
    for (const Column& c : columns) {
      if (c.row.isPeer) {
        peerMs = minMsPerStep(c.row);
        peerMedian = medianMsPerStep(c.row);
        peerCpu = medianCpuMsPerStep(c.row);
      }
    }
    for (Column& c : columns) {
      if (!c.row.isPeer && peerMs > 0.0 && minMsPerStep(c.row) > 0.0) {
        c.row.ratio = minMsPerStep(c.row) / peerMs;
        c.row.medianRatio = medianMsPerStep(c.row) / peerMedian;
        c.row.cpuRatio = peerCpu > 0.0 ? medianCpuMsPerStep(c.row) / peerCpu : -1.0;
      }
      printTableRow(stdout, c.row);
      if (csv) printCsvRow(csv, c.row);
      for (const RunResult& r : c.row.runs) failures += r.ok ? 0 : 1;
    }
    // Each scene's rows reach the terminal, a pipe or the CSV as soon as the scene is done,
    // so that a long run stopped part way keeps the scenes it finished.
    std::fflush(stdout);
    if (csv) std::fflush(csv);
  }
  if (csv) std::fclose(csv);
  std::printf("\nAccuracy is measured after the last repetition against the state when timing started (piles: once "
              "formed). Penetration of boxes is the separating-axis overlap of their geometry, the same for every "
              "engine; of piles, stackbook's deepest sample inside another body.\n");
  return failures == 0 ? 0 : 1;
}
