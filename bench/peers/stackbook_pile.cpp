// The stackbook adapter for piles of nonconvex bodies (peers_bench, pile_scaling_bench): a
// scene file loaded with overrides, formed by simulating until it settles, then timed.
// Formed states are cached on disk, since forming a big pile takes far longer than timing it.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <Eigen/Geometry>

#include "pile_scenes.hpp"
#include "stackbook/peers/engine.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stacking/welded_pass.hpp"
#include "stackbook/stepping/traditional_step.hpp"

namespace peers {

namespace {

using namespace stackbook;

/// The cache file of a pile: its name and a hash of what determines the formed state.
std::string cachePath(const PileSpec& pile) {
  if (pile.cacheDir.empty()) return {};
  std::ifstream in(pile.file, std::ios::binary);
  std::ostringstream key;
  key << in.rdbuf() << '\n' << pile.formSeconds << ' ' << pile.settleSpeed;
  for (const std::string& o : pile.overrides) key << '\n' << o;
  char hash[32];
  std::snprintf(hash, sizeof hash, "%016zx", std::hash<std::string>{}(key.str()));
  return (std::filesystem::path(pile.cacheDir) / (pile.name + "-" + hash + ".state")).string();
}

template <int D>
class StackbookPile final : public Engine {
 public:
  StackbookPile(const PileSpec& pile, stackbook::SolverPreset preset) {
    const Scene scene = loadScene(pile.file, pile.overrides);
    world_ = std::get<SceneBodies<D>>(scene.bodies).world;
    const StepSettings formSettings = scene.settings;
    settings_ = stackbook::applySolverPreset(preset, scene.settings);
    if (pile.timingThreads >= 0) settings_.parallel.threads = pile.timingThreads;
    settings_.pairOrder = pile.timingPairOrder;
    halfDiagonal_.resize(world_.bodies.size());
    for (std::size_t i = 0; i < world_.bodies.size(); ++i) {
      const Aabb<D> box = world_.shapes[i]->bounds();
      halfDiagonal_[i] = 0.5 * (box.upper - box.lower).norm();
    }
    const std::string cache = cachePath(pile);
    if (cache.empty() || !load(cache)) {
      // Form the pile with the scene's own settings (one formed state for every preset).
      const auto steps = static_cast<long>(std::ceil(pile.formSeconds / formSettings.dt - 1e-9));
      const PostContactHook<D> hook = shockPropagationHook<D>();
      for (long n = 1; n <= steps; ++n) {
        stackbook::step<D>(world_, formSettings, hook);
        if (n % 50 == 0 && maxSpeed() < pile.settleSpeed) break;
      }
      if (!cache.empty()) save(cache);
    }
  }

  void step() override { counters_ += sceneStep<D>(world_, settings_, hook_); }  // the step the preset names

  void startTiming() override {
    start_ = world_;
    counters_ = StepCounters{};
    top_ = 0;
    for (std::size_t i = 0; i < world_.bodies.size(); ++i) {
      if (world_.bodies[i].isStatic()) continue;
      if (top_ == 0 || world_.bodies[i].position[D - 1] > world_.bodies[top_].position[D - 1]) top_ = i;
    }
  }

  Work work() const override {
    return workPerStep(counters_);
  }

  Accuracy accuracy() const override {
    Accuracy a;
    a.drift = 0.0;
    for (std::size_t i = 0; i < world_.bodies.size(); ++i) {
      const RigidBody<D>& b = world_.bodies[i];
      if (!b.position.allFinite() || !b.velocity.allFinite()) a.finite = false;
      Vec<D> horizontal = b.position - start_.bodies[i].position;
      horizontal[D - 1] = 0.0;
      a.drift = std::max(a.drift, horizontal.norm());
    }
    a.sag = start_.bodies[top_].position[D - 1] - world_.bodies[top_].position[D - 1];
    a.maxSpeed = maxSpeed();
    a.penetration = maxPenetration<D>(world_);
    a.energyChange = worldEnergy<D>(world_).total() - worldEnergy<D>(start_).total();
    return a;
  }

 private:
  double maxSpeed() const {
    double v = 0.0;
    for (std::size_t i = 0; i < world_.bodies.size(); ++i) {
      const RigidBody<D>& b = world_.bodies[i];
      v = std::max(v, b.velocity.norm() + b.angularVelocity.norm() * halfDiagonal_[i]);
    }
    return v;
  }

  // The cache: per body its position, orientation, velocity and angular momentum, as raw doubles.
  static constexpr int kAngle = D == 2 ? 1 : 4;
  static constexpr int kPerBody = D + kAngle + D + (D == 2 ? 1 : 3);

  bool load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::vector<double> data(world_.bodies.size() * kPerBody);
    in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size() * sizeof(double)));
    if (!in || in.peek() != std::char_traits<char>::eof()) return false;
    const double* p = data.data();
    for (RigidBody<D>& b : world_.bodies) {
      for (int k = 0; k < D; ++k) b.position[k] = *p++;
      if constexpr (D == 2) {
        b.orientation = Eigen::Rotation2Dd(*p++);
      } else {
        b.orientation.coeffs() = Eigen::Vector4d(p[0], p[1], p[2], p[3]);
        p += 4;
      }
      for (int k = 0; k < D; ++k) b.velocity[k] = *p++;
      for (int k = 0; k < b.angularMomentum.size(); ++k) b.angularMomentum[k] = *p++;
      b.syncAngularVelocity();
    }
    return true;
  }

  void save(const std::string& path) const {
    std::vector<double> data;
    for (const RigidBody<D>& b : world_.bodies) {
      for (int k = 0; k < D; ++k) data.push_back(b.position[k]);
      if constexpr (D == 2) {
        data.push_back(b.orientation.angle());
      } else {
        for (int k = 0; k < 4; ++k) data.push_back(b.orientation.coeffs()[k]);
      }
      for (int k = 0; k < D; ++k) data.push_back(b.velocity[k]);
      for (int k = 0; k < b.angularMomentum.size(); ++k) data.push_back(b.angularMomentum[k]);
    }
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    const std::string tmp = path + ".tmp";
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size() * sizeof(double)));
    out.close();
    if (out) std::filesystem::rename(tmp, path, ec);
  }

  World<D> world_;
  World<D> start_;
  StepSettings settings_;
  StepCounters counters_;
  PostContactHook<D> hook_ = shockPropagationHook<D>();
  std::vector<double> halfDiagonal_;
  std::size_t top_ = 0;
};

}  // namespace

std::unique_ptr<Engine> makeStackbookPile(const PileSpec& pile, stackbook::SolverPreset preset) {
  const nlohmann::json doc = readSceneJson(pile.file);
  if (doc.value("dimension", 2) == 2) return std::make_unique<StackbookPile<2>>(pile, preset);
  return std::make_unique<StackbookPile<3>>(pile, preset);
}


}  // namespace peers
