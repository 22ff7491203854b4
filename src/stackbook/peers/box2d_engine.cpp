// The Box2D 2.4 adapter of peers_bench, written against Box2D's public API (box2d/box2d.h):
// one b2World with the scene's gravity, a static ground box, dynamic boxes of the scene's
// size and mass (density = mass / area), stepped with the scene's velocity and position
// iterations (Box2D's testbed defaults: 8 and 3). Box2D mixes friction as sqrt(mu_a mu_b), so every fixture gets
// the scene's mu. Sleeping is off, as it is in stackbook's columns (and as Box2D's own benchmarks run),
// so that every engine does every step's work.
#include "stackbook/peers/engine.hpp"

#ifdef STACKBOOK_HAVE_BOX2D
#include <box2d/box2d.h>

#include <cmath>

namespace peers {

namespace {

class Box2dEngine final : public BoxEngine {
 public:
  explicit Box2dEngine(const BoxScene& scene) : BoxEngine(scene),
        world_(b2Vec2(static_cast<float>(scene.gravityVector().x()), static_cast<float>(scene.gravityVector().y()))) {
    world_.SetAllowSleeping(false);
    for (const BoxSpec& spec : scene.boxes) {
      b2BodyDef def;
      def.type = spec.isStatic() ? b2_staticBody : b2_dynamicBody;
      def.position.Set(static_cast<float>(spec.centre.x()), static_cast<float>(spec.centre.y()));
      def.angle = static_cast<float>(std::atan2(spec.rotation(1, 0), spec.rotation(0, 0)));
      def.linearVelocity.Set(static_cast<float>(spec.velocity.x()), static_cast<float>(spec.velocity.y()));
      def.angularVelocity = static_cast<float>(spec.angularVelocity.z());
      b2Body* body = world_.CreateBody(&def);
      b2PolygonShape box;
      const double skin = scene.box2dSkinInside ? static_cast<double>(b2_polygonRadius) : 0.0;
      box.SetAsBox(static_cast<float>(0.5 * spec.size.x() - skin), static_cast<float>(0.5 * spec.size.y() - skin));
      b2FixtureDef fixture;
      fixture.shape = &box;
      fixture.density = spec.isStatic() ? 0.0f : static_cast<float>(spec.mass / (spec.size.x() * spec.size.y()));
      fixture.friction = static_cast<float>(scene.friction);
      fixture.restitution = static_cast<float>(scene.restitution);  // Box2D mixes max(e_a, e_b)
      body->CreateFixture(&fixture);
      bodies_.push_back(body);
    }
  }

  void step() override {
    ++steps_;
    world_.Step(static_cast<float>(scene_.dt), scene_.velocityIterations, scene_.positionIterations);
  }

  std::vector<BodyState> states() const override {
    std::vector<BodyState> out;
    out.reserve(bodies_.size());
    for (const b2Body* b : bodies_) {
      BodyState s;
      const b2Vec2 c = b->GetWorldCenter();
      const b2Vec2 v = b->GetLinearVelocity();
      s.position = Eigen::Vector3d(c.x, c.y, 0.0);
      s.velocity = Eigen::Vector3d(v.x, v.y, 0.0);
      const double angle = b->GetAngle();
      s.rotation.topLeftCorner<2, 2>() << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
      s.angularVelocity.z() = b->GetAngularVelocity();
      out.push_back(s);
    }
    return out;
  }

 private:
  b2World world_;
  std::vector<b2Body*> bodies_;
};

}  // namespace

std::unique_ptr<BoxEngine> makeBox2d(const BoxScene& scene) {
  if (scene.dimension != 2) return nullptr;
  return std::make_unique<Box2dEngine>(scene);
}
bool haveBox2d() { return true; }
std::string box2dLabel() {
  return "Box2D " + std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
         std::to_string(b2_version.revision);
}

}  // namespace peers

#else

namespace peers {
std::unique_ptr<BoxEngine> makeBox2d(const BoxScene&) { return nullptr; }
bool haveBox2d() { return false; }
std::string box2dLabel() { return "Box2D"; }
}  // namespace peers

#endif
