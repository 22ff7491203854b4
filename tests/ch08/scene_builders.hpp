#pragma once
// Scenes for chapter 8's tests and for the chapter's documentation programs
// (docs/examples/ch08_*.cpp), without doctest: a static incline (a big box turned by theta) with a unit
// box on it, a static ground with a ball or a box above it, built the same way in 2D
// and 3D. Axis 0 is "along", the last axis is "up"; the incline turns axis 0 towards up.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/stepping/traditional_step.hpp"
#include "../support/tilt.hpp"

namespace stackbook::testing {

inline constexpr double kG = 9.81;

inline double degrees(double deg) { return deg * M_PI / 180.0; }


/// Unit vector along axis k.
template <int D>
Vec<D> axis(int k) {
  Vec<D> e = Vec<D>::Zero();
  e[k] = 1.0;
  return e;
}

/// The up axis (y in 2D, z in 3D).
template <int D>
Vec<D> up() {
  return axis<D>(D - 1);
}

/// Side lengths with every entry `side`, except the up axis `height`.
template <int D>
Vec<D> boxSize(double side, double height) {
  Vec<D> s = Vec<D>::Constant(side);
  s[D - 1] = height;
  return s;
}

/// A uniform cube (square) of side 1 and mass 1: I = m (a^2 + b^2) / 12 = 1/6 per axis.
template <int D>
RigidBody<D> unitBox() {
  return makeDynamicBody<D>(1.0, AngVec<D>::Constant(1.0 / 6.0));
}

/// A uniform ball (disk in 2D) of mass 1: I = 2/5 m r^2 (3D), 1/2 m r^2 (2D).
template <int D>
RigidBody<D> ball(double radius) {
  const double k = D == 3 ? 0.4 : 0.5;
  return makeDynamicBody<D>(1.0, AngVec<D>::Constant(k * radius * radius));
}

template <int D>
std::shared_ptr<const Shape<D>> unitBoxShape() {
  return std::make_shared<BoxShape<D>>(makeBoxShape<D>(Vec<D>::Constant(1.0)));
}

/// A static slab 20 m long (and wide, in 3D) and 1 m thick whose top face passes
/// through the origin, turned by theta.
template <int D>
int addSlab(World<D>& world, double theta, const Material& material) {
  const Orientation<D> q = tilt<D>(theta);
  const Vec<D> normal = q * up<D>();
  auto shape = std::make_shared<BoxShape<D>>(makeBoxShape<D>(boxSize<D>(20.0, 1.0)));
  return world.addBody(makeStaticBody<D>(Vec<D>(-0.5 * normal), q), shape, material);
}

/// A unit box resting on an incline of angle theta (the box's bottom face on the slab's
/// top face, exactly touching), `along` metres up the slope from the origin, with the
/// velocity v0 down the slope.
template <int D>
struct InclineScene {
  World<D> world;
  int block = -1;
  Vec<D> downSlope;  ///< unit vector down the slope
  Vec<D> normal;     ///< unit normal of the slope
  Vec<D> start;      ///< the block's initial centre

  /// Distance travelled down the slope since the start.
  double travelled() const {
    return (world.bodies[static_cast<std::size_t>(block)].position - start).dot(downSlope);
  }
  /// Velocity down the slope.
  double speed() const {
    return world.bodies[static_cast<std::size_t>(block)].velocity.dot(downSlope);
  }
  /// Height of the centre above the slope, minus the half height 0.5.
  double lift() const {
    return world.bodies[static_cast<std::size_t>(block)].position.dot(normal) - 0.5;
  }
};

template <int D>
InclineScene<D> makeIncline(double theta, double mu, double e, double along = 0.0,
                            double v0Down = 0.0) {
  InclineScene<D> scene;
  scene.world.gravity = -kG * up<D>();
  const Orientation<D> q = tilt<D>(theta);
  scene.normal = q * up<D>();
  scene.downSlope = -(q * axis<D>(0));
  const Material material{e, mu, 0.0};
  addSlab<D>(scene.world, theta, material);
  RigidBody<D> box = unitBox<D>();
  box.orientation = q;
  box.position = 0.5 * scene.normal - along * scene.downSlope;
  box.velocity = v0Down * scene.downSlope;
  box.syncAngularVelocity();
  scene.start = box.position;
  scene.block = scene.world.addBody(box, unitBoxShape<D>(), material);
  return scene;
}

/// Run `seconds` of simulation (rounded to whole steps), calling after(world) after
/// each step. Returns the counters of all steps.
template <int D, class After>
StepCounters simulate(World<D>& world, const StepSettings& settings, double seconds,
                      After&& after) {
  const long steps = std::lround(seconds / settings.dt);
  StepCounters total;
  for (long n = 0; n < steps; ++n) {
    total += step<D>(world, settings);
    after(world);
  }
  return total;
}

template <int D>
StepCounters simulate(World<D>& world, const StepSettings& settings, double seconds) {
  return simulate<D>(world, settings, seconds, [](const World<D>&) {});
}

/// FNV-1a hash of the bits of every double of every body's state.
template <int D>
std::uint64_t stateHash(const World<D>& world) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    for (int b = 0; b < 8; ++b) {
      h ^= (bits >> (8 * b)) & 0xffu;
      h *= 1099511628211ull;
    }
  };
  for (const RigidBody<D>& body : world.bodies) {
    for (int k = 0; k < D; ++k) {
      mix(body.position[k]);
      mix(body.velocity[k]);
    }
    for (int k = 0; k < body.angularMomentum.size(); ++k) {
      mix(body.angularMomentum[k]);
      mix(body.angularVelocity[k]);
    }
    if constexpr (D == 2) {
      mix(body.orientation.angle());
    } else {
      for (int k = 0; k < 4; ++k) mix(body.orientation.coeffs()[k]);
    }
  }
  return h;
}

}  // namespace stackbook::testing

namespace stackbook::testing {

/// A ball (disk) of the given radius above a horizontal static slab whose top face is
/// y = 0 (z = 0): the ball is turned so that one surface sample points straight down
/// (in 2D the 48-gon has a vertex at -90 degrees already), and its centre is `gap` above
/// the height at which that sample touches the ground.
template <int D>
struct DropScene {
  World<D> world;
  int body = -1;
  double contactHeight = 0.0;  ///< centre height at which the lowest sample touches y = 0

  const RigidBody<D>& dropped() const { return world.bodies[static_cast<std::size_t>(body)]; }
  double height() const { return dropped().position[D - 1] - contactHeight; }
  double upSpeed() const { return dropped().velocity[D - 1]; }
};

/// The body-frame surface sample of `shape` that is lowest once `b` is turned so that it
/// points straight down (3D; in 2D the ball's ring already has a vertex at -90 degrees).
template <int D>
Vec<D> turnLowestSampleDown(RigidBody<D>& b, const Shape<D>& shape) {
  Vec<D> lowest = shape.surfaceSamples().front();
  for (const Vec<D>& s : shape.surfaceSamples()) {
    if (s[D - 1] < lowest[D - 1]) lowest = s;
  }
  if constexpr (D == 3) {
    b.orientation = Eigen::Quaterniond::FromTwoVectors(lowest, Vec3(0.0, 0.0, -1.0));
  }
  return lowest;
}

template <int D>
DropScene<D> makeBallDrop(double radius, double gap, const Material& material) {
  DropScene<D> scene;
  scene.world.gravity = -kG * up<D>();
  addSlab<D>(scene.world, 0.0, material);
  auto shape = std::make_shared<SphereShape<D>>(makeSphereShape<D>(radius));
  RigidBody<D> b = ball<D>(radius);
  const Vec<D> lowest = turnLowestSampleDown<D>(b, *shape);
  scene.contactHeight = -(b.orientation * lowest)[D - 1];
  b.position = (scene.contactHeight + gap) * up<D>();
  b.syncAngularVelocity();
  scene.body = scene.world.addBody(b, shape, material);
  return scene;
}

/// A unit box resting flat on the horizontal slab (bottom face on y = 0).
template <int D>
DropScene<D> makeRestingBox(const Material& material) {
  DropScene<D> scene;
  scene.world.gravity = -kG * up<D>();
  addSlab<D>(scene.world, 0.0, material);
  RigidBody<D> box = unitBox<D>();
  box.position = 0.5 * up<D>();
  scene.contactHeight = 0.5;
  scene.body = scene.world.addBody(box, unitBoxShape<D>(), material);
  return scene;
}

}  // namespace stackbook::testing

namespace stackbook::testing {

/// The analytic ball (disk in 2D) of radius R whose samples are a ring of `segments`
/// points in the plane of axis 0 and the up axis, the plane it rolls in (in 3D, plus the
/// two poles on axis 1, with the faces of a bipyramid). Contact while rolling along axis 0
/// is then with a regular `segments`-gon: each switch from one vertex to the next is a
/// small plastic impact that keeps the fraction 1 - (1 - cos(2 pi / segments)) / (1 + k)
/// of the angular velocity about the new vertex, k = I / (m R^2).
template <int D>
std::shared_ptr<const Shape<D>> rollingBallShape(double radius, int segments) {
  if constexpr (D == 2) {
    return std::make_shared<SphereShape<2>>(SphereSdf<2>(radius), regularPolygon(radius, segments));
  } else {
    SurfaceMesh<3> mesh;
    for (int k = 0; k < segments; ++k) {
      const double t = 2.0 * M_PI * k / segments;
      mesh.vertices.push_back(Vec3(radius * std::cos(t), 0.0, radius * std::sin(t)));
    }
    const int north = segments, south = segments + 1;
    mesh.vertices.push_back(Vec3(0.0, radius, 0.0));
    mesh.vertices.push_back(Vec3(0.0, -radius, 0.0));
    for (int k = 0; k < segments; ++k) {
      const int next = (k + 1) % segments;
      mesh.faces.push_back({k, next, north});
      mesh.faces.push_back({next, k, south});
    }
    return std::make_shared<SphereShape<3>>(SphereSdf<3>(radius), std::move(mesh));
  }
}

/// A ball rolling without slipping along axis 0 at speed v0 on the level static slab
/// (top face at height 0), one ring vertex exactly touching the ground.
template <int D>
struct RollingScene {
  World<D> world;
  int body = -1;
  double radius = 0.0;

  const RigidBody<D>& ball() const { return world.bodies[static_cast<std::size_t>(body)]; }
  double speed() const { return ball().velocity[0]; }
  /// The angular speed of rolling, positive when it rolls along +axis 0.
  double rollRate() const {
    if constexpr (D == 2) {
      return -ball().angularVelocity[0];
    } else {
      return ball().angularVelocity[1];
    }
  }
  /// Slip speed |v - omega R| of the rolling contact.
  double slip() const { return std::abs(speed() - rollRate() * radius); }
};

template <int D>
RollingScene<D> makeRollingBall(double radius, double v0, const Material& ground,
                                const Material& ballMaterial, int segments = 2000) {
  RollingScene<D> scene;
  scene.radius = radius;
  scene.world.gravity = -kG * up<D>();
  addSlab<D>(scene.world, 0.0, ground);
  RigidBody<D> b = ball<D>(radius);
  b.position = radius * up<D>();
  b.velocity = v0 * axis<D>(0);
  AngVec<D> w = AngVec<D>::Zero();
  if constexpr (D == 2) {
    w[0] = -v0 / radius;
  } else {
    w[1] = v0 / radius;
  }
  b.setAngularVelocity(w);
  scene.body = scene.world.addBody(b, rollingBallShape<D>(radius, segments), ballMaterial);
  return scene;
}

}  // namespace stackbook::testing

namespace stackbook::testing {

/// A box tilted by 0.3 rad, its lowest corner 2.6 cm above a 20 degree incline, with
/// friction mu and restitution e: it lands on a corner, tips and rubs, which exercises both
/// stages and every branch of the impulse.
template <int D>
World<D> makeTumblingBox(double mu, double e, double muRolling = 0.0) {
  InclineScene<D> scene = makeIncline<D>(degrees(20.0), mu, e);
  for (Material& m : scene.world.materials) m.rollingFriction = muRolling;
  RigidBody<D>& box = scene.world.bodies[static_cast<std::size_t>(scene.block)];
  box.orientation = tilt<D>(degrees(20.0) + 0.3);
  box.position += 0.15 * scene.normal;
  box.syncAngularVelocity();
  return scene.world;
}

}  // namespace stackbook::testing
