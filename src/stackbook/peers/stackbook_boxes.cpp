// The stackbook adapter for box scenes (peers_bench): a World built from the scene's boxes,
// stepped by GBF's step with shock propagation (stackingStep) at the scene's dt.
#include <Eigen/Geometry>

#include "stackbook/peers/engine.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/stacking/solver_preset.hpp"

namespace peers {

Work workPerStep(const stackbook::StepCounters& counters) {
  Work w;
  const double n = counters.steps > 0 ? static_cast<double>(counters.steps) : 1.0;
  const stackbook::StageCounters* stages[] = {&counters.collision, &counters.contact, &counters.shock};
  w.impulses = w.phiQueries = w.pairQueries = 0.0;
  for (const stackbook::StageCounters* s : stages) {
    w.impulses += static_cast<double>(s->impulses) / n;
    w.phiQueries += static_cast<double>(s->detection.phiQueries) / n;
    w.pairQueries += static_cast<double>(s->detection.pairQueries) / n;
  }
  return w;
}

namespace {

using namespace stackbook;

template <int D>
class StackbookBoxes final : public BoxEngine {
 public:
  StackbookBoxes(const BoxScene& scene, SolverPreset preset) : BoxEngine(scene) {
    settings_ = applySolverPreset(preset, StepSettings{});
    settings_.dt = scene.dt;
    world_.gravity = scene.gravityVector().head<D>();
    const Material material{scene.restitution, scene.friction, 0.0};  // pairs take the smaller mu: Eq. (8.4)
    for (const BoxSpec& b : scene.boxes) {
      const Vec<D> size = b.size.head<D>();
      const Vec<D> centre = b.centre.head<D>();
      RigidBody<D> body;
      if (b.isStatic()) {
        body = makeStaticBody<D>(centre, orientationOf(b.rotation));
      } else {
        AngVec<D> inertia;
        const Eigen::Vector3d q = b.size.cwiseProduct(b.size);
        if constexpr (D == 2) {
          inertia[0] = b.mass * (q[0] + q[1]) / 12.0;
        } else {
          inertia << b.mass * (q[1] + q[2]) / 12.0, b.mass * (q[0] + q[2]) / 12.0, b.mass * (q[0] + q[1]) / 12.0;
        }
        body = makeDynamicBody<D>(b.mass, inertia);
        body.position = centre;
        body.orientation = orientationOf(b.rotation);
        body.velocity = b.velocity.head<D>();
        if constexpr (D == 2) {
          body.angularVelocity[0] = b.angularVelocity.z();
        } else {
          body.angularVelocity = b.angularVelocity;
        }
      }
      world_.addBody(body, shapeFor(size), material);
    }
  }

  void step() override {
    ++steps_;
    counters_ += stackingStep<D>(world_, settings_);
  }

  void startTiming() override {
    BoxEngine::startTiming();
    counters_ = StepCounters{};
  }

  Work work() const override {
    return workPerStep(counters_);
  }

  std::vector<BodyState> states() const override {
    std::vector<BodyState> out;
    out.reserve(world_.bodies.size());
    for (const RigidBody<D>& b : world_.bodies) {
      BodyState s;
      s.position.head<D>() = b.position;
      s.velocity.head<D>() = b.velocity;
      if constexpr (D == 2) {
        s.rotation.topLeftCorner<2, 2>() = b.orientation.toRotationMatrix();
        s.angularVelocity.z() = b.angularVelocity[0];
      } else {
        s.rotation = b.orientation.toRotationMatrix();
        s.angularVelocity = b.angularVelocity;
      }
      out.push_back(s);
    }
    return out;
  }

 private:
  static Orientation<D> orientationOf(const Eigen::Matrix3d& r) {
    if constexpr (D == 2) {
      return Orientation<D>(std::atan2(r(1, 0), r(0, 0)));
    } else {
      return Orientation<D>(Eigen::Quaterniond(r).normalized());
    }
  }

  /// One shape per distinct size (every unit box shares one).
  std::shared_ptr<const Shape<D>> shapeFor(const Vec<D>& size) {
    for (const auto& [s, shape] : shapes_) {
      if (s == size) return shape;
    }
    SampleMeshSettings mesh;
    mesh.boxSubdivisions = scene_.stackbookBoxSubdivisions;
    shapes_.emplace_back(size, std::make_shared<BoxShape<D>>(makeBoxShape<D>(size, mesh)));
    return shapes_.back().second;
  }

  World<D> world_;
  StepSettings settings_;
  StepCounters counters_;
  std::vector<std::pair<Vec<D>, std::shared_ptr<const Shape<D>>>> shapes_;
};

}  // namespace

std::unique_ptr<Engine> makeStackbookBoxes(const BoxScene& scene, SolverPreset preset) {
  if (scene.dimension == 2) return std::make_unique<StackbookBoxes<2>>(scene, preset);
  return std::make_unique<StackbookBoxes<3>>(scene, preset);
}

}  // namespace peers
