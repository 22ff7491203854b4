// Threads and determinism (chapter 10): the bundled scenes stepped with 1 and 2 (or more)
// threads, alternating, printing the wall time per step of each and their ratio, and the
// hash of the exact state bits after the run for each thread count (they must agree).
//
//   threads_bench [--steps N] [--repeats R] [--threads A,B] [--hash] [--scenes DIR] [NAME ...]
//
//   --steps N     steps per run (default 200)
//   --repeats R   alternating runs per thread count (default 3); min and median are printed
//   --threads A,B the two thread counts compared (default 1,2)
//   --hash        only print one line per scene: its name and the state hash after N steps
//                 with the scene's own settings (to compare two builds of the step)
//   NAME ...      only these scenes (file stems, e.g. shapes_in_bin_2d)
//
// Build in Release: cmake --preset release && cmake --build --preset release --target threads_bench
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "stackbook/scene/scene.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stacking/welded_pass.hpp"
#include "stackbook/stepping/traditional_step.hpp"

namespace fs = std::filesystem;
using namespace stackbook;

namespace {

/// FNV-1a over the bytes of every double of the bodies' state.
struct StateHash {
  std::uint64_t h = 1469598103934665603ULL;
  void add(double x) {
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &x, sizeof(double));
    for (const unsigned char b : bytes) {
      h ^= b;
      h *= 1099511628211ULL;
    }
  }
};

template <int D>
std::uint64_t worldHash(const World<D>& world) {
  StateHash hash;
  for (const RigidBody<D>& b : world.bodies) {
    for (int k = 0; k < D; ++k) hash.add(b.position[k]);
    for (int k = 0; k < D; ++k) hash.add(b.velocity[k]);
    for (int k = 0; k < b.angularMomentum.size(); ++k) hash.add(b.angularMomentum[k]);
    if constexpr (D == 2) {
      hash.add(b.orientation.angle());
    } else {
      for (int k = 0; k < 4; ++k) hash.add(b.orientation.coeffs()[k]);
    }
  }
  return hash.h;
}

struct RunOutcome {
  double seconds = 0.0;  // step time only
  std::uint64_t hash = 0;
};

template <int D>
RunOutcome runSteps(const Scene& scene, const StepSettings& settings, int steps) {
  World<D> world = std::get<SceneBodies<D>>(scene.bodies).world;
  const PostContactHook<D> hook = shockPropagationHook<D>();
  RunOutcome out;
  for (int n = 0; n < steps; ++n) out.seconds += sceneStep<D>(world, settings, hook).totalSeconds;
  out.hash = worldHash<D>(world);
  return out;
}

RunOutcome runScene(const Scene& scene, const StepSettings& settings, int steps) {
  return scene.dimension == 2 ? runSteps<2>(scene, settings, steps) : runSteps<3>(scene, settings, steps);
}

int usage(const char* program) {
  std::cerr << "usage: " << program
            << " [--steps N] [--repeats R] [--threads A,B] [--hash] [--scenes DIR] [NAME ...]\n";
  return 2;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int steps = 200;
  int repeats = 3;
  int threadsA = 1;
  int threadsB = 2;
  bool hashOnly = false;
#ifdef STACKBOOK_SCENES_DIR
  fs::path dir = STACKBOOK_SCENES_DIR;
#else
  fs::path dir = "scenes";
#endif
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--steps" && i + 1 < argc) {
      steps = std::atoi(argv[++i]);
    } else if (arg == "--repeats" && i + 1 < argc) {
      repeats = std::atoi(argv[++i]);
    } else if (arg == "--threads" && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%d,%d", &threadsA, &threadsB) != 2) return usage(argv[0]);
    } else if (arg == "--hash") {
      hashOnly = true;
    } else if (arg == "--scenes" && i + 1 < argc) {
      dir = argv[++i];
    } else if (!arg.empty() && arg[0] == '-') {
      return usage(argv[0]);
    } else {
      names.push_back(arg);
    }
  }
  if (steps < 1 || repeats < 1 || threadsA < 1 || threadsB < 1) return usage(argv[0]);
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    const std::string stem = entry.path().stem().string();
    if (names.empty() ? stem.ends_with("_full")
                      : std::find(names.begin(), names.end(), stem) == names.end()) {
      continue;
    }
    files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (!hashOnly) {
    std::printf("| scene | bodies | steps | %d thread ms/step (min, median) | %d threads ms/step "
                "(min, median) | ratio of mins | same state |\n|---|---|---|---|---|---|---|\n",
                threadsA, threadsB);
  }
  for (const fs::path& file : files) {
    try {
      const Scene scene = loadScene(file.string());
      if (hashOnly) {
        std::printf("%s %016llx\n", file.stem().string().c_str(),
                    static_cast<unsigned long long>(runScene(scene, scene.settings, steps).hash));
        std::fflush(stdout);
        continue;
      }
      StepSettings a = scene.settings, b = scene.settings;
      a.parallel.threads = threadsA;
      b.parallel.threads = threadsB;
      std::vector<double> ta, tb;
      std::uint64_t ha = 0, hb = 0;
      for (int r = 0; r < repeats; ++r) {  // alternating, so drift in the machine's load hits both
        const RunOutcome oa = runScene(scene, a, steps);
        const RunOutcome ob = runScene(scene, b, steps);
        ta.push_back(1e3 * oa.seconds / steps);
        tb.push_back(1e3 * ob.seconds / steps);
        ha = oa.hash;
        hb = ob.hash;
      }
      const double minA = *std::min_element(ta.begin(), ta.end());
      const double minB = *std::min_element(tb.begin(), tb.end());
      std::printf("| %s | %d | %d | %.3f, %.3f | %.3f, %.3f | %.2f | %s |\n",
                  file.stem().string().c_str(), scene.bodyCount(), steps, minA, median(ta), minB,
                  median(tb), minA / minB, ha == hb ? "yes" : "NO");
      std::fflush(stdout);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", file.string().c_str(), e.what());
      return 1;
    }
  }
  return 0;
}
