#pragma once
/// \file
/// \brief Running a scene (chapter 10): steps the scene's world with GBF's step and
/// chapter 9's shock propagation for the scene's duration, records frames at the scene's
/// frame rate, sums the step counters, and measures the deepest interpenetration and the
/// energy at the start and the end.
#include <cstdint>
#include <functional>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "stackbook/output/recording.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/stepping/step_counters.hpp"

namespace stackbook {

/// Kinetic energy, potential energy -m g.x of the dynamic bodies, and their sum.
struct EnergyReport {
  double kinetic = 0.0;
  double potential = 0.0;
  double total() const { return kinetic + potential; }
};

/// The energy of a world (static bodies contribute nothing).
template <int D>
EnergyReport worldEnergy(const World<D>& world);

/// The deepest interference in a world at its current poses: max over every surface sample
/// inside another body of -phi (0 if none). Static-static pairs are not examined.
template <int D>
double maxPenetration(const World<D>& world);

/// The step n after which frame f >= 1 of a run at `frameRate` frames per second and step dt
/// is recorded: the first with n dt >= f / frameRate (Eq. (10.3)), found as a whole number of
/// steps, so that frameRate = 1/dt records after every step and no frame is ever dropped.
std::int64_t frameStep(std::int64_t frame, double frameRate, double dt);

// [run_options]
/// How runScene() runs a scene.
struct RunOptions {
  /// Simulated seconds; <= 0 uses the scene's duration.
  double duration = 0.0;
  /// Called after each step with the fraction done (0..1) and the simulated time; may be
  /// empty. The program draws its progress bar from it.
  std::function<void(double fraction, double time)> progress;
};
// [run_options]

// [run_result]
/// What a run produced: the recording (frames at the scene's frame rate, first at t = 0,
/// last at the end), the summed counters, and the measurements.
template <int D>
struct RunResult {
  Recording<D> recording;
  StepCounters counters;
  double simulatedSeconds = 0.0;
  double wallSeconds = 0.0;
  /// Deepest interpenetration at the recorded frames, and when.
  double maxPenetration = 0.0;
  double maxPenetrationTime = 0.0;
  EnergyReport energyStart;
  EnergyReport energyEnd;
  /// Every pose and velocity of the final state is finite.
  bool finite = true;
};

using SceneRun = std::variant<RunResult<2>, RunResult<3>>;
// [run_result]

/// Runs `scene` (a copy of its world; the scene is not changed). Each step is chapter 8's
/// step in the scene's order with chapter 9's shock propagation as its post-contact hook
/// (it runs when the shockPropagation effect does). Throws std::invalid_argument if the
/// step rejects the world or settings.
SceneRun runScene(const Scene& scene, const RunOptions& options = {});

/// The run as JSON: scene, dimension, bodies, dt, steps, effects, wall time per stage,
/// impulses and queries per stage, max penetration, energy at start and end. The program
/// adds "files" and writes it as summary.json.
nlohmann::json runSummaryJson(const Scene& scene, const SceneRun& run);

/// The same summary as a few lines of text for the terminal.
std::string runSummaryText(const nlohmann::json& summary);

}  // namespace stackbook
