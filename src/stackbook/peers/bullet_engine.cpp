// The Bullet 3 adapter of peers_bench, written against Bullet's public API
// (btBulletDynamicsCommon.h): a btDiscreteDynamicsWorld with the default collision
// configuration, dispatcher, dynamic-AABB-tree broad phase and sequential-impulse solver at
// its defaults (split impulse; the scene's iteration count, 10 by default), gravity down z, a static ground box and
// dynamic boxes of the scene's size and mass. stepSimulation(dt, 0) takes exactly one step
// of dt. Bullet mixes friction as mu_a mu_b, so each body gets sqrt(mu) to make the pair's
// mu the scene's. Deactivation (sleeping) is off, as it is in stackbook's columns.
#include "stackbook/peers/engine.hpp"

#ifdef STACKBOOK_HAVE_BULLET
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>

namespace peers {

namespace {

class BulletEngine final : public BoxEngine {
 public:
  explicit BulletEngine(const BoxScene& scene)
      : BoxEngine(scene),
        dispatcher_(&configuration_),
        world_(&dispatcher_, &broadphase_, &solver_, &configuration_) {
    const Eigen::Vector3d g = scene.gravityVector();
    world_.setGravity(btVector3(static_cast<btScalar>(g.x()), static_cast<btScalar>(g.y()), static_cast<btScalar>(g.z())));
    const auto mu = static_cast<btScalar>(std::sqrt(scene.friction));
    const auto restitution = static_cast<btScalar>(std::sqrt(scene.restitution));  // also mixed as e_a e_b
    world_.getSolverInfo().m_numIterations = scene.solverIterations;
    for (const BoxSpec& spec : scene.boxes) {
      const btVector3 half(static_cast<btScalar>(0.5 * spec.size.x()), static_cast<btScalar>(0.5 * spec.size.y()),
                           static_cast<btScalar>(0.5 * spec.size.z()));
      shapes_.push_back(std::make_unique<btBoxShape>(half));
      const auto mass = static_cast<btScalar>(spec.mass);
      btVector3 inertia(0, 0, 0);
      if (!spec.isStatic()) shapes_.back()->calculateLocalInertia(mass, inertia);
      btTransform pose;
      pose.setIdentity();
      pose.setBasis(btMatrix3x3(
          static_cast<btScalar>(spec.rotation(0, 0)), static_cast<btScalar>(spec.rotation(0, 1)),
          static_cast<btScalar>(spec.rotation(0, 2)), static_cast<btScalar>(spec.rotation(1, 0)),
          static_cast<btScalar>(spec.rotation(1, 1)), static_cast<btScalar>(spec.rotation(1, 2)),
          static_cast<btScalar>(spec.rotation(2, 0)), static_cast<btScalar>(spec.rotation(2, 1)),
          static_cast<btScalar>(spec.rotation(2, 2))));
      pose.setOrigin(btVector3(static_cast<btScalar>(spec.centre.x()), static_cast<btScalar>(spec.centre.y()),
                               static_cast<btScalar>(spec.centre.z())));
      btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shapes_.back().get(), inertia);
      info.m_startWorldTransform = pose;
      info.m_friction = mu;
      info.m_restitution = restitution;
      bodies_.push_back(std::make_unique<btRigidBody>(info));
      bodies_.back()->setActivationState(DISABLE_DEACTIVATION);
      if (!spec.isStatic()) {
        bodies_.back()->setLinearVelocity(btVector3(static_cast<btScalar>(spec.velocity.x()),
                                                    static_cast<btScalar>(spec.velocity.y()),
                                                    static_cast<btScalar>(spec.velocity.z())));
        bodies_.back()->setAngularVelocity(btVector3(static_cast<btScalar>(spec.angularVelocity.x()),
                                                     static_cast<btScalar>(spec.angularVelocity.y()),
                                                     static_cast<btScalar>(spec.angularVelocity.z())));
      }
      world_.addRigidBody(bodies_.back().get());
    }
  }

  ~BulletEngine() override {
    for (auto& b : bodies_) world_.removeRigidBody(b.get());
  }

  void step() override {
    ++steps_;
    world_.stepSimulation(static_cast<btScalar>(scene_.dt), 0);
  }

  std::vector<BodyState> states() const override {
    std::vector<BodyState> out;
    out.reserve(bodies_.size());
    for (const auto& b : bodies_) {
      BodyState s;
      const btTransform& t = b->getWorldTransform();
      const btVector3& p = t.getOrigin();
      s.position = Eigen::Vector3d(p.x(), p.y(), p.z());
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) s.rotation(r, c) = t.getBasis()[r][c];
      }
      const btVector3& v = b->getLinearVelocity();
      const btVector3& w = b->getAngularVelocity();
      s.velocity = Eigen::Vector3d(v.x(), v.y(), v.z());
      s.angularVelocity = Eigen::Vector3d(w.x(), w.y(), w.z());
      out.push_back(s);
    }
    return out;
  }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  std::vector<std::unique_ptr<btBoxShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
};

}  // namespace

std::unique_ptr<BoxEngine> makeBullet(const BoxScene& scene) {
  if (scene.dimension != 3) return nullptr;
  return std::make_unique<BulletEngine>(scene);
}
bool haveBullet() { return true; }
std::string bulletLabel() {
  char text[32];
  std::snprintf(text, sizeof text, "Bullet %d.%02d", btGetVersion() / 100, btGetVersion() % 100);
  return text;
}

}  // namespace peers

#else

namespace peers {
std::unique_ptr<BoxEngine> makeBullet(const BoxScene&) { return nullptr; }
bool haveBullet() { return false; }
std::string bulletLabel() { return "Bullet"; }
}  // namespace peers

#endif
