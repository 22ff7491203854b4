// The peers of `stackbook sweep` (sweep_peers.hpp).
#include "stackbook/peers/sweep_peers.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>

#include <Eigen/Geometry>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/peers/engine.hpp"
#include "stackbook/scene/sweep.hpp"

namespace peers {

using stackbook::SceneError;
using stackbook::SweepError;
using stackbook::SweepRow;
using stackbook::SweepRun;
using stackbook::SweepSpec;
using stackbook::SweepTrajectory;

namespace {

template <int D>
BoxScene boxSceneFrom(const stackbook::SceneBodies<D>& bodies, const std::string& file) {
  const stackbook::World<D>& world = bodies.world;
  BoxScene out;
  out.dimension = D;
  out.hasGravityVector = true;
  out.gravityVec.head<D>() = world.gravity;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const auto* box = dynamic_cast<const stackbook::BoxShape<D>*>(world.shapes[i].get());
    const std::string where = i < bodies.pointers.size() ? bodies.pointers[i] : "/bodies/" + std::to_string(i);
    if (box == nullptr) throw SceneError(file, where, "the peers run scenes of boxes only");
    const stackbook::Material& m = world.materials[i];
    const stackbook::Material& m0 = world.materials[0];
    if (m.friction != m0.friction || m.restitution != m0.restitution) {
      throw SceneError(file, where, "the peers mix materials by their own rules: give every body the same material");
    }
    out.friction = m0.friction;
    out.restitution = m0.restitution;
    const stackbook::RigidBody<D>& b = world.bodies[i];
    BoxSpec spec;
    spec.size.head<D>() = 2.0 * box->sdf().halfExtents;
    spec.centre.head<D>() = b.position;
    spec.mass = b.isStatic() ? 0.0 : b.mass();
    spec.velocity.head<D>() = b.velocity;
    if constexpr (D == 2) {
      spec.rotation.topLeftCorner<2, 2>() = b.orientation.toRotationMatrix();
      spec.angularVelocity.z() = b.angularVelocity[0];
    } else {
      spec.rotation = b.orientation.toRotationMatrix();
      spec.angularVelocity = b.angularVelocity;
    }
    out.boxes.push_back(spec);
  }
  if (out.boxes.empty() || !out.boxes[0].isStatic()) {
    throw SceneError(file, "/bodies/0", "the peers need a static ground box as body 0");
  }
  return out;
}

bool needsPenetration(const SweepSpec& spec) {
  for (const SweepError& e : spec.errors) {
    if (e.quantity == "maxPenetration") return true;
  }
  return false;
}

SweepRow runPeer(const SweepSpec& spec, const SweepRun& run) {
  const std::string pointer = "/peers/" + std::to_string(run.peer);
  const std::string& name = spec.peers.at(static_cast<std::size_t>(run.peer)).engine;
  std::vector<std::string> overrides = run.overrides;
  for (const auto& [key, value] : run.peerKnobs) {
    if (key == "dt") overrides.push_back("dt=" + value.dump());
  }
  const stackbook::Scene scene = stackbook::loadScene(spec.scene, overrides);
  BoxScene boxes = std::visit([&](const auto& b) { return boxSceneFrom(b, spec.scene); }, scene.bodies);
  boxes.dt = scene.settings.dt;
  boxes.box2dSkinInside = true;  // Box2D collides the scene's boxes, not boxes 1 cm larger
  for (const auto& [key, value] : run.peerKnobs) {
    if (key == "velocityIterations") boxes.velocityIterations = value.get<int>();
    if (key == "positionIterations") boxes.positionIterations = value.get<int>();
    if (key == "iterations") boxes.solverIterations = value.get<int>();
  }
  std::unique_ptr<BoxEngine> engine = name == "box2d" ? makeBox2d(boxes) : makeBullet(boxes);
  if (engine == nullptr) {
    throw SceneError(spec.file, pointer + "/engine",
                     name + (name == "box2d" ? " runs 2D scenes" : " runs 3D scenes") + ", and " + spec.scene + " is " +
                         std::to_string(boxes.dimension) + "D");
  }
  // The same step count as stackbook's runScene(): the duration rounded up to whole steps.
  const auto steps = static_cast<std::int64_t>(std::ceil(scene.duration / boxes.dt - 1e-9));
  const bool every = stackbook::sweepNeedsEveryStep(spec), penetration = needsPenetration(spec);
  SweepTrajectory t;
  t.dimension = boxes.dimension;
  t.gravity = boxes.gravityVector();
  for (const BoxSpec& b : boxes.boxes) t.isStatic.push_back(b.isStatic());
  const auto record = [&](double time) {
    const std::vector<BodyState> states = engine->states();
    std::vector<stackbook::SweepBodyState> frame;
    frame.reserve(states.size());
    for (const BodyState& s : states) frame.push_back({s.position, s.rotation, s.velocity, s.angularVelocity});
    t.times.push_back(time);
    t.frames.push_back(std::move(frame));
    t.energies.push_back(boxEnergy(boxes, states));
    if (penetration) t.maxPenetration = std::max(t.maxPenetration, boxPenetration(boxes, states));
  };
  engine->startTiming();
  record(0.0);
  double seconds = 0.0;
  for (std::int64_t k = 1; k <= steps; ++k) {
    const auto start = std::chrono::steady_clock::now();
    engine->step();
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (every || k == steps) record(static_cast<double>(k) * boxes.dt);
  }
  SweepRow row;
  row.run = run;
  row.steps = steps;
  row.msPerStep = steps > 0 ? 1e3 * seconds / static_cast<double>(steps) : 0.0;
  const double simulated = static_cast<double>(steps) * boxes.dt;
  row.msPerSimulatedSecond = simulated > 0.0 ? 1e3 * seconds / simulated : 0.0;
  for (const SweepError& e : spec.errors) row.errors.push_back(stackbook::measureSweepTrajectory(e, t, spec.file));
  return row;
}

}  // namespace

BoxScene boxSceneOf(const stackbook::Scene& scene, const std::string& file) {
  BoxScene out = std::visit([&](const auto& b) { return boxSceneFrom(b, file); }, scene.bodies);
  out.dt = scene.settings.dt;
  return out;
}

void registerSweepPeers() {
  if (haveBox2d()) stackbook::registerSweepPeer({"box2d", box2dLabel(), 2, runPeer});
  if (haveBullet()) stackbook::registerSweepPeer({"bullet", bulletLabel(), 3, runPeer});
}

}  // namespace peers
