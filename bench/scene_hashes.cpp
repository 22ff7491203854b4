// State hashes of the bundled scenes: the evidence that an optimisation is exact.
//
// For every scene in scenes/ this program steps the scene's world with its own settings
// through the code path of `stackbook run` (chapter 8's step in the scene's order with
// chapter 9's shock propagation as its post-contact hook, as runScene() does) for a fixed
// number of steps, and prints one line per scene:
//
//   NAME STEPS STATE_HASH COUNTER_HASH impulses=I pairQueries=Q phiQueries=P
//
// STATE_HASH is a 64-bit FNV-1a hash of the exact bits of every body's position,
// orientation (the 2D angle, the 3D quaternion's coefficients), velocity, angular
// momentum and cached angular velocity after the last step. COUNTER_HASH hashes the
// integer work counters of the three stages (sweeps, pair visits, impulses per branch,
// cap hits, detection counts) and the quarantined bodies. An exact optimisation keeps
// every STATE_HASH; one that only skips work may lower the detection counts (and so
// change COUNTER_HASH) while the state stays the same bit for bit.
//
//   scene_hashes [--steps N] [--full-steps M] [--threads T] [--set KEY=VALUE ...] [--scenes DIR] [NAME ...]
//
//   --steps N       at most N steps per scene (default: each scene's own duration / dt)
//   --full-steps M  steps for the full-size scenes (file names ending in "_full.json"),
//                   which take minutes at their own duration (default 150)
//   --threads T     run every scene with T threads (solver.threads; 0: every hardware
//                   thread; default: the scene's own setting). The hashes must not depend on T
//                   (chapter 10, "Threads")
//   --set KEY=VALUE override a scene field in every scene, as `stackbook run --set` does
//                   (repeatable): a setting that should change only the time, such as
//                   solver.candidateReach, must keep every STATE_HASH
//   --scenes DIR    the folder of scene files (default: the repository's scenes/)
//   NAME ...        only these scenes (file stems)
//
// To prove a change exact: run it before the change and after, and compare the outputs
// (`diff` on the first three columns). Build it with the benchmarks:
//   cmake --preset release && cmake --build --preset release --target scene_hashes
#include <algorithm>
#include <cinttypes>
#include <cmath>
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

/// 64-bit FNV-1a over raw bytes.
struct Fnv1a {
  std::uint64_t value = 14695981039346656037ull;
  void bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) {
      value ^= p[k];
      value *= 1099511628211ull;
    }
  }
  void real(double x) { bytes(&x, sizeof x); }
  void integer(std::int64_t x) { bytes(&x, sizeof x); }
  template <typename Derived>
  void reals(const Eigen::MatrixBase<Derived>& m) {
    for (Eigen::Index k = 0; k < m.size(); ++k) real(m(k));
  }
};

template <int D>
std::uint64_t stateHash(const World<D>& world) {
  Fnv1a h;
  for (const RigidBody<D>& b : world.bodies) {
    h.reals(b.position);
    if constexpr (D == 2) {
      h.real(b.orientation.angle());
    } else {
      h.reals(b.orientation.coeffs());
    }
    h.reals(b.velocity);
    h.reals(b.angularMomentum);
    h.reals(b.angularVelocity);
  }
  return h.value;
}

void hashStage(Fnv1a& h, const StageCounters& s) {
  for (std::int64_t x : {s.sweeps, s.pairVisits, s.impulses, s.frictionless, s.sticking, s.sliding,
                         s.pairIterationCapHits, s.frictionEvaluations, s.elasticImpulses, s.rollingImpulses,
                         s.stepConeSticks, static_cast<std::int64_t>(s.detection.pairQueries),
                         static_cast<std::int64_t>(s.detection.phiQueries),
                         static_cast<std::int64_t>(s.detection.interferenceSamples)}) {
    h.integer(x);
  }
}

std::uint64_t counterHash(const StepCounters& c) {
  Fnv1a h;
  h.integer(c.steps);
  hashStage(h, c.collision);
  hashStage(h, c.contact);
  hashStage(h, c.shock);
  for (const Quarantine& q : c.quarantined) h.integer(q.body);
  return h.value;
}

template <int D>
void runAndPrint(const std::string& name, const Scene& scene, std::int64_t steps) {
  World<D> world = std::get<SceneBodies<D>>(scene.bodies).world;
  const PostContactHook<D> hook = shockPropagationHook<D>();
  StepCounters counters;
  for (std::int64_t n = 0; n < steps; ++n) counters += sceneStep<D>(world, scene.settings, hook);
  const auto total = [&](auto field) {
    return static_cast<long long>(field(counters.collision) + field(counters.contact) + field(counters.shock));
  };
  std::printf("%s %lld %016" PRIx64 " %016" PRIx64 " impulses=%lld pairQueries=%lld phiQueries=%lld\n",
              name.c_str(), static_cast<long long>(steps), stateHash<D>(world), counterHash(counters),
              total([](const StageCounters& s) { return static_cast<std::int64_t>(s.impulses); }),
              total([](const StageCounters& s) { return static_cast<std::int64_t>(s.detection.pairQueries); }),
              total([](const StageCounters& s) { return static_cast<std::int64_t>(s.detection.phiQueries); }));
  std::fflush(stdout);
}

bool isFullSize(const fs::path& path) {
  const std::string name = path.filename().string();
  const std::string suffix = "_full.json";
  return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int usage(const char* program) {
  std::cerr << "usage: " << program
            << " [--steps N] [--full-steps M] [--threads T] [--set KEY=VALUE ...] [--scenes DIR] [NAME ...]\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::int64_t fixedSteps = 0;
  std::int64_t fullSteps = 150;
#ifdef STACKBOOK_SCENES_DIR
  fs::path scenes = STACKBOOK_SCENES_DIR;
#else
  fs::path scenes = fs::path(__FILE__).parent_path().parent_path() / "scenes";
#endif
  int threads = -1;  // -1: the scene's own solver.threads
  std::vector<std::string> names;
  std::vector<std::string> overrides;  // --set KEY=VALUE, as loadScene() takes them
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--steps" && i + 1 < argc) {
      fixedSteps = std::atoll(argv[++i]);
      if (fixedSteps <= 0) return usage(argv[0]);
    } else if (arg == "--full-steps" && i + 1 < argc) {
      fullSteps = std::atoll(argv[++i]);
      if (fullSteps <= 0) return usage(argv[0]);
    } else if (arg == "--threads" && i + 1 < argc) {
      threads = std::atoi(argv[++i]);
      if (threads < 0 || threads > 1024) return usage(argv[0]);
    } else if (arg == "--set" && i + 1 < argc) {
      overrides.push_back(argv[++i]);
    } else if (arg == "--scenes" && i + 1 < argc) {
      scenes = argv[++i];
    } else if (!arg.empty() && arg[0] == '-') {
      return usage(argv[0]);
    } else {
      names.push_back(arg);
    }
  }

  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(scenes, ec)) {
    const fs::path& p = entry.path();
    if (p.extension() != ".json") continue;
    if (!names.empty() && std::find(names.begin(), names.end(), p.stem().string()) == names.end()) continue;
    files.push_back(p);
  }
  if (ec) {
    std::cerr << "scene_hashes: cannot read " << scenes << ": " << ec.message() << "\n";
    return 1;
  }
  std::sort(files.begin(), files.end());

  int failures = 0;
  for (const fs::path& file : files) {
    const std::string name = file.stem().string();
    try {
      Scene scene = loadScene(file.string(), overrides);
      if (threads >= 0) scene.settings.parallel.threads = threads;
      std::int64_t steps = static_cast<std::int64_t>(std::ceil(scene.duration / scene.settings.dt - 1e-9));
      if (isFullSize(file)) steps = std::min(steps, fullSteps);
      if (fixedSteps > 0) steps = std::min(steps, fixedSteps);
      if (scene.dimension == 2) {
        runAndPrint<2>(name, scene, steps);
      } else {
        runAndPrint<3>(name, scene, steps);
      }
    } catch (const std::exception& e) {
      ++failures;
      std::printf("%s failed: %s\n", name.c_str(), e.what());
    }
  }
  return failures == 0 ? 0 : 1;
}
