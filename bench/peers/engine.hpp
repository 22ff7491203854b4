#pragma once
// One engine running one scene in peers_bench: stackbook (its defaults, or the pass as the
// contact stage), Box2D 2.4 or Bullet 3. The program times step() and asks for the accuracy
// at the end; each adapter builds the scene from the same description.
#include <memory>
#include <string>
#include <vector>

#include "box_scenes.hpp"
#include "measures.hpp"

namespace peers {

/// Work per step, where the engine counts it (stackbook's StepCounters); negative: not counted.
struct Work {
  double impulses = -1.0;    ///< impulses applied per step (all stages)
  double phiQueries = -1.0;  ///< signed-distance queries per step
  double pairQueries = -1.0; ///< narrow-phase pair queries per step
};

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

/// The two stackbook configurations of the table.
enum class StackbookConfig {
  Defaults,          ///< StepSettings{} with shock propagation (stackingStep)
  PassAsContactStage ///< passAsContactStage(): 20 sweeps per level, one cone per step
};

std::unique_ptr<Engine> makeStackbookBoxes(const BoxScene& scene, StackbookConfig config);

/// A pile of nonconvex bodies read from a scene file (with --set style overrides), formed by
/// simulating until every body is slower than `settleSpeed` or `formSeconds` have passed.
/// A formed state is kept in `cacheDir` (empty: no cache) and reused by later runs.
struct PileSpec {
  std::string name;
  std::string description;
  std::string file;
  std::vector<std::string> overrides;
  double formSeconds = 3.0;
  double settleSpeed = 0.05;
  std::string cacheDir;
};
std::unique_ptr<Engine> makeStackbookPile(const PileSpec& pile, StackbookConfig config);

/// The peers; null when the library was not found at configure time.
std::unique_ptr<BoxEngine> makeBox2d(const BoxScene& scene);
std::unique_ptr<BoxEngine> makeBullet(const BoxScene& scene);
bool haveBox2d();
bool haveBullet();

}  // namespace peers
