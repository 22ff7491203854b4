#pragma once
/// \file
/// \brief One engine running one box scene (peers_bench, and the peers of `stackbook sweep`,
/// chapter 11): stackbook (its defaults, the pass as the contact stage, or that with short
/// pair loops), Box2D 2.4 or Bullet 3. The caller times step() and asks for the states or
/// the accuracy; each adapter builds the scene from the same description (box_scenes.hpp).
#include <memory>
#include <string>
#include <vector>

#include "stackbook/peers/box_scenes.hpp"
#include "stackbook/peers/measures.hpp"
#include "stackbook/stacking/solver_preset.hpp"

namespace stackbook {
struct StepCounters;
struct StepSettings;
}

namespace peers {

/// Work per step, where the engine counts it (stackbook's StepCounters); negative: not counted.
struct Work {
  double impulses = -1.0;    ///< impulses applied per step (all stages)
  double phiQueries = -1.0;  ///< signed-distance queries per step
  double pairQueries = -1.0; ///< narrow-phase pair queries per step
};

/// stackbook's work per step from its counters: the collision, contact and shock stages'
/// impulses, phi queries and pair queries, each divided by the steps counted.
Work workPerStep(const stackbook::StepCounters& counters);

class Engine {
 public:
  virtual ~Engine() = default;
  /// Advance one time step.
  virtual void step() = 0;
  /// The accuracy columns, measured against the state when timing started.
  virtual Accuracy accuracy() const = 0;
  /// Work per step since timing started.
  virtual Work work() const { return {}; }
  /// Called once before the timed steps (a pile forms before this).
  virtual void startTiming() {}
};

/// An engine for box scenes: keeps the start and measures with the shared box measures.
class BoxEngine : public Engine {
 public:
  explicit BoxEngine(BoxScene scene) : scene_(std::move(scene)) {}
  void startTiming() override {
    start_ = states();
    steps_ = 0;
  }
  Accuracy accuracy() const override {
    return boxAccuracy(scene_, start_, states(), static_cast<double>(steps_) * scene_.dt);
  }

  /// Every body's state (the ground first), in the scene's order.
  virtual std::vector<BodyState> states() const = 0;

 protected:
  BoxScene scene_;
  std::vector<BodyState> start_;
  long steps_ = 0;  ///< steps since timing started (each adapter's step() counts them)
};

/// stackbook under one of the solver presets (a column of the table; chapter 9's
/// applySolverPreset(), the table a scene's "solver": {"preset": ...} reads too).
std::unique_ptr<Engine> makeStackbookBoxes(const BoxScene& scene, stackbook::SolverPreset preset);

/// The peers; null when the library was not found at configure time.
std::unique_ptr<BoxEngine> makeBox2d(const BoxScene& scene);
std::unique_ptr<BoxEngine> makeBullet(const BoxScene& scene);
bool haveBox2d();
bool haveBullet();
/// The engines' names with their versions, as the library reports them ("Box2D 2.4.1",
/// "Bullet 3.24"); "Box2D" and "Bullet" when not built.
std::string box2dLabel();
std::string bulletLabel();

}  // namespace peers
