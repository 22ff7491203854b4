// The cost of every bundled scene: runs each scene in scenes/ for its duration (or the one
// given) and prints one Markdown table row per scene: dimension, bodies, steps, wall time per
// step and its split over the stages, impulses per step, the deepest interpenetration, the
// energy at the start and the end, and the effects that ran.
//
//   scenes_bench [--full] [--duration T] [--scenes DIR] [NAME ...]
//
//   --full        also run the full-size scenes (file names ending in "_full.json"), which
//                 take minutes; without it they are listed as skipped
//   --duration T  simulated seconds per scene instead of each scene's own duration
//   --scenes DIR  the folder of scene files (default: the repository's scenes/)
//   NAME ...      only these scenes (file stems, e.g. pyramid_2d)
//
// Time per step is the step alone (StepCounters::totalSeconds: the four stages, shock
// propagation with its contact graph, and the quarantine check), not the recording of
// frames or the penetration measurement runScene() does at each frame. Build in Release:
//   cmake --preset release && cmake --build --preset release --target scenes_bench
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"

namespace fs = std::filesystem;
using namespace stackbook;

namespace {

bool isFullSize(const fs::path& path) {
  const std::string name = path.filename().string();
  const std::string suffix = "_full.json";
  return name.size() >= suffix.size() &&
         name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

struct Options {
  bool full = false;
  double duration = 0.0;  // <= 0: each scene's own
#ifdef STACKBOOK_SCENES_DIR
  fs::path scenes = STACKBOOK_SCENES_DIR;
#else
  fs::path scenes = fs::path(__FILE__).parent_path().parent_path() / "scenes";
#endif
  std::vector<std::string> names;
};

int usage(const char* program) {
  std::cerr << "usage: " << program << " [--full] [--duration T] [--scenes DIR] [NAME ...]\n";
  return 2;
}

double perStepMs(double seconds, std::int64_t steps) {
  return steps > 0 ? 1e3 * seconds / static_cast<double>(steps) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--full") {
      options.full = true;
    } else if (arg == "--duration" && i + 1 < argc) {
      options.duration = std::atof(argv[++i]);
      if (!(options.duration > 0.0)) return usage(argv[0]);
    } else if (arg == "--scenes" && i + 1 < argc) {
      options.scenes = argv[++i];
    } else if (!arg.empty() && arg[0] == '-') {
      return usage(argv[0]);
    } else {
      options.names.push_back(arg);
    }
  }

  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(options.scenes, ec)) {
    const fs::path& p = entry.path();
    if (p.extension() != ".json") continue;
    if (!options.names.empty() &&
        std::find(options.names.begin(), options.names.end(), p.stem().string()) == options.names.end()) {
      continue;
    }
    files.push_back(p);
  }
  if (ec) {
    std::cerr << "scenes_bench: cannot read " << options.scenes << ": " << ec.message() << "\n";
    return 1;
  }
  std::sort(files.begin(), files.end());

  std::cout << "| scene | D | bodies | steps | dt (s) | ms/step | collision | contact | shock | "
               "impulses/step | max penetration (m) | energy start (J) | energy end (J) | effects |\n";
  std::cout << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  int failures = 0;
  for (const fs::path& file : files) {
    const std::string name = file.stem().string();
    if (isFullSize(file) && !options.full) {
      std::cout << "| " << name << " | | | | | skipped (full size; run with --full) | | | | | | | | |\n";
      continue;
    }
    try {
      const Scene scene = loadScene(file.string());
      RunOptions run;
      run.duration = options.duration;
      const SceneRun result = runScene(scene, run);
      const nlohmann::json summary = runSummaryJson(scene, result);
      const StepCounters& c =
          std::visit([](const auto& r) -> const StepCounters& { return r.counters; }, result);
      const std::int64_t impulses = c.collision.impulses + c.contact.impulses + c.shock.impulses;
      std::string effects;
      for (const auto& e : summary.at("effects")) {
        if (!effects.empty()) effects += ' ';
        effects += e.get<std::string>();
      }
      char row[512];
      std::snprintf(row, sizeof row,
                    "| %s | %d | %d | %lld | %g | %.3f | %.3f | %.3f | %.3f | %.1f | %.2e | %.6g | %.6g | %s |",
                    name.c_str(), scene.dimension, scene.bodyCount(), static_cast<long long>(c.steps),
                    scene.settings.dt, perStepMs(c.totalSeconds, c.steps),
                    perStepMs(c.collision.seconds, c.steps), perStepMs(c.contact.seconds, c.steps),
                    perStepMs(c.hookSeconds, c.steps),
                    c.steps > 0 ? static_cast<double>(impulses) / static_cast<double>(c.steps) : 0.0,
                    summary.at("maxPenetration").get<double>(),
                    summary.at("energy").at("start").at("total").get<double>(),
                    summary.at("energy").at("end").at("total").get<double>(), effects.c_str());
      std::cout << row << (summary.at("finite").get<bool>() ? "" : " NOT FINITE") << std::endl;
    } catch (const std::exception& e) {
      ++failures;
      std::cout << "| " << name << " | | | | | failed: " << e.what() << " | | | | | | | | |" << std::endl;
    }
  }
  std::cout << "\nms/step is the step alone; collision, contact and shock are its stages' share in ms/step "
               "(shock: the post-contact hook, contact graph included).\n";
  return failures == 0 ? 0 : 1;
}
