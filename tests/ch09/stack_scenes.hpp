#pragma once
// Scenes for chapter 9: box stacks, a plank on two stacks of unequal count, a heavy box
// on a light one, a 2D pyramid, a card A-frame, a tilted stack and GBF's seesaw, built on
// a static ground slab whose top face is the plane "up = 0". Used by the tests and by the
// programs docs/examples/ch09_*.cpp and bench/stack_bench.cpp (which include this file).

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stepping/traditional_step.hpp"

namespace stackbook::stacks {

inline constexpr double kG = 9.81;

template <int D>
Vec<D> up() {
  Vec<D> e = Vec<D>::Zero();
  e[D - 1] = 1.0;
  return e;
}

/// A uniform box of the given sides and mass: I_k = m (sum of the other two squared sides) / 12
/// (2D: m (a^2 + b^2) / 12).
template <int D>
RigidBody<D> uniformBox(const Vec<D>& sides, double mass) {
  AngVec<D> inertia;
  if constexpr (D == 2) {
    inertia[0] = mass * sides.squaredNorm() / 12.0;
  } else {
    inertia << mass * (sides[1] * sides[1] + sides[2] * sides[2]) / 12.0,
        mass * (sides[0] * sides[0] + sides[2] * sides[2]) / 12.0,
        mass * (sides[0] * sides[0] + sides[1] * sides[1]) / 12.0;
  }
  return makeDynamicBody<D>(mass, inertia);
}

template <int D>
std::shared_ptr<const Shape<D>> boxShape(const Vec<D>& sides) {
  return std::make_shared<BoxShape<D>>(makeBoxShape<D>(sides));
}

/// A static slab 200 m wide and 1 m thick whose top face is up = 0.
template <int D>
int addGround(World<D>& world, const Material& material) {
  Vec<D> sides = Vec<D>::Constant(200.0);
  sides[D - 1] = 1.0;
  return world.addBody(makeStaticBody<D>(Vec<D>(-0.5 * up<D>()), Orientation<D>::Identity()),
                       boxShape<D>(sides), material);
}

/// A world with gravity -g up and the ground (body 0).
template <int D>
World<D> groundWorld(const Material& material) {
  World<D> world;
  world.gravity = -kG * up<D>();
  addGround<D>(world, material);
  return world;
}

/// Add an axis-aligned box with its centre at `centre`. Returns its index.
template <int D>
int addBox(World<D>& world, const Vec<D>& sides, double mass, const Vec<D>& centre,
           const Material& material) {
  RigidBody<D> b = uniformBox<D>(sides, mass);
  b.position = centre;
  return world.addBody(b, boxShape<D>(sides), material);
}

/// A stack of n unit boxes (mass 1) on the ground, body k (1..n) centred at height k - 1/2,
/// horizontally offset by `offset` per box (0: straight; A19 uses 0.2). Boxes exactly touch.
template <int D>
World<D> boxStack(int n, const Material& material, double offset = 0.0) {
  World<D> world = groundWorld<D>(material);
  const Vec<D> unit = Vec<D>::Constant(1.0);
  const std::shared_ptr<const Shape<D>> shape = boxShape<D>(unit);
  for (int k = 1; k <= n; ++k) {
    RigidBody<D> b = uniformBox<D>(unit, 1.0);
    b.position = (static_cast<double>(k) - 0.5) * up<D>();
    b.position[0] = offset * static_cast<double>(k - 1);
    world.addBody(b, shape, material);
  }
  return world;
}

/// Measurements of a stack of boxes 1..n after a run.
template <int D>
struct StackState {
  double drift = 0.0;      ///< largest horizontal distance of a centre from its start
  double maxSpeed = 0.0;   ///< largest |v| + |omega| * (half diagonal) over the boxes
  double sag = 0.0;        ///< start height - current height of the top box
  double largestGap = 0.0; ///< largest (centre distance - 1) between neighbours: > 0 separates
};

template <int D>
StackState<D> measureStack(const World<D>& start, const World<D>& now, int first, int last) {
  StackState<D> s;
  const double halfDiagonal = 0.5 * std::sqrt(static_cast<double>(D));
  for (int k = first; k <= last; ++k) {
    const RigidBody<D>& b = now.bodies[static_cast<std::size_t>(k)];
    const RigidBody<D>& b0 = start.bodies[static_cast<std::size_t>(k)];
    Vec<D> horizontal = b.position - b0.position;
    horizontal[D - 1] = 0.0;
    s.drift = std::max(s.drift, horizontal.norm());
    s.maxSpeed = std::max(s.maxSpeed, b.velocity.norm() + b.angularVelocity.norm() * halfDiagonal);
    if (k > first) {
      const RigidBody<D>& below = now.bodies[static_cast<std::size_t>(k - 1)];
      s.largestGap = std::max(s.largestGap, (b.position[D - 1] - below.position[D - 1]) - 1.0);
    }
  }
  s.sag = start.bodies[static_cast<std::size_t>(last)].position[D - 1] -
          now.bodies[static_cast<std::size_t>(last)].position[D - 1];
  return s;
}

/// Run `seconds` (rounded to steps) of gbfStep (shock off) or stackingStep (shock on).
/// Returns the summed counters.
template <int D>
StepCounters run(World<D>& world, StepSettings settings, double seconds, bool shock,
                 Layering layering = Layering::Topological) {
  settings.effects.shockPropagation = shock;
  const long steps = std::lround(seconds / settings.dt);
  StepCounters total;
  for (long n = 0; n < steps; ++n) total += stackingStep<D>(world, settings, layering);
  return total;
}

/// The plank scene of the design note: a stack of 2 boxes of height h and a stack of 4
/// boxes of height h/2 (side h in the other directions), 1.5 m apart, and a plank of
/// thickness h/4 across both tops at height 2h. Bodies: ground 0, left 1 2, right 3..6,
/// plank 7.
template <int D>
World<D> plankOnTwoStacks(const Material& material, double h = 0.5) {
  World<D> world = groundWorld<D>(material);
  Vec<D> tall = Vec<D>::Constant(h);
  Vec<D> flat = Vec<D>::Constant(h);
  flat[D - 1] = 0.5 * h;
  for (int k = 0; k < 2; ++k) {
    Vec<D> c = (h * (static_cast<double>(k) + 0.5)) * up<D>();
    c[0] = -0.75;
    addBox<D>(world, tall, 1.0, c, material);
  }
  for (int k = 0; k < 4; ++k) {
    Vec<D> c = (0.5 * h * (static_cast<double>(k) + 0.5)) * up<D>();
    c[0] = 0.75;
    addBox<D>(world, flat, 0.5, c, material);
  }
  Vec<D> plank = Vec<D>::Constant(h);
  plank[0] = 1.5 + h;
  plank[D - 1] = 0.25 * h;
  addBox<D>(world, plank, 1.0, Vec<D>((2.0 * h + 0.125 * h) * up<D>()), material);
  return world;
}

/// The tilt of the plank (body 7): the angle of its axis 0 against the horizontal.
template <int D>
double plankTilt(const World<D>& world) {
  const Vec<D> a = world.bodies[7].orientation * Vec<D>(Vec<D>::UnitX());
  return std::atan2(std::abs(a[D - 1]), std::hypot(a[0], D == 3 ? a[1] : 0.0));
}

/// GBF's seesaw: a plank 4 m x 0.1 m (mass 1) balanced on a static post 0.2 m wide and
/// 0.5 m tall, a 0.4 m box of mass 5 on its right end. Bodies: ground 0, post 1, plank 2,
/// box 3. The box's weight turns the plank about the post's right corner.
inline World<2> seesaw(const Material& material) {
  World<2> world = groundWorld<2>(material);
  world.addBody(makeStaticBody<2>(Vec2(0.0, 0.25), Orientation<2>::Identity()),
                boxShape<2>(Vec2(0.2, 0.5)), material);
  addBox<2>(world, Vec2(4.0, 0.1), 1.0, Vec2(0.0, 0.55), material);
  addBox<2>(world, Vec2(0.4, 0.4), 5.0, Vec2(1.7, 0.8), material);
  return world;
}

/// The seesaw plank's (body 2) angle against the horizontal, negative when its right end is down.
inline double seesawAngle(const World<2>& world) {
  const Vec2 axis = world.bodies[2].orientation * Vec2(1.0, 0.0);
  return std::atan2(axis.y(), axis.x());
}

/// A 2D pyramid of square boxes (side 1, mass 1) with `base` boxes in the bottom row and
/// one box fewer per row, rows centred on x = 0, a gap `gap` between neighbours in a row.
inline World<2> pyramid2d(int base, const Material& material, double gap = 0.0) {
  World<2> world = groundWorld<2>(material);
  const std::shared_ptr<const Shape<2>> shape = boxShape<2>(Vec2(1.0, 1.0));
  for (int row = 0; row < base; ++row) {
    const int count = base - row;
    const double width = static_cast<double>(count) + static_cast<double>(count - 1) * gap;
    for (int i = 0; i < count; ++i) {
      RigidBody<2> b = uniformBox<2>(Vec2(1.0, 1.0), 1.0);
      b.position = Vec2(-0.5 * width + 0.5 + static_cast<double>(i) * (1.0 + gap),
                        static_cast<double>(row) + 0.5);
      world.addBody(b, shape, material);
    }
  }
  return world;
}

/// B15's symmetry measure for a pyramid built by pyramid2d(): the largest |x_i + x_mirror(i)|
/// over its rows (zero for a pyramid that stands still, since it starts centred on x = 0).
inline double mirrorError(const World<2>& world, int base) {
  double error = 0.0;
  int first = 1;
  for (int row = 0; row < base; ++row) {
    const int count = base - row;
    for (int i = 0; i < count; ++i) {
      const double xa = world.bodies[static_cast<std::size_t>(first + i)].position.x();
      const double xb = world.bodies[static_cast<std::size_t>(first + count - 1 - i)].position.x();
      error = std::max(error, std::abs(xa + xb));
    }
    first += count;
  }
  return error;
}

/// The largest distance any body other than body 0 (the ground) has moved from `start`.
template <int D>
double largestDisplacement(const World<D>& start, const World<D>& now) {
  double moved = 0.0;
  for (std::size_t k = 1; k < now.bodies.size(); ++k) {
    moved = std::max(moved, (now.bodies[k].position - start.bodies[k].position).norm());
  }
  return moved;
}

/// A 3D pyramid of unit cubes: square layers base x base, (base-1) x (base-1), ...,
/// each centred on the z axis.
inline World<3> pyramid3d(int base, const Material& material) {
  World<3> world = groundWorld<3>(material);
  const std::shared_ptr<const Shape<3>> shape = boxShape<3>(Vec3::Ones());
  for (int layer = 0; layer < base; ++layer) {
    const int count = base - layer;
    for (int i = 0; i < count; ++i) {
      for (int j = 0; j < count; ++j) {
        RigidBody<3> b = uniformBox<3>(Vec3::Ones(), 1.0);
        b.position = Vec3(-0.5 * count + 0.5 + i, -0.5 * count + 0.5 + j, layer + 0.5);
        world.addBody(b, shape, material);
      }
    }
  }
  return world;
}

/// A 2D card A-frame: two thin cards (length `length`, thickness `thickness`, mass 1)
/// leaning on each other, each at angle beta from the vertical, their top edges touching
/// at x = 0 and their feet on the ground. Bodies: ground 0, left card 1, right card 2.
inline World<2> cardFrame(double beta, const Material& material, double length = 1.0,
                          double thickness = 0.01) {
  World<2> world = groundWorld<2>(material);
  const Vec2 sides(thickness, length);
  for (const double side : {-1.0, 1.0}) {
    RigidBody<2> card = uniformBox<2>(sides, 1.0);
    // Left card turned by -beta (its top leans right, towards x = 0), right card by +beta.
    const double angle = side * beta;
    card.orientation = Eigen::Rotation2Dd(angle);
    const Vec2 axisUp = card.orientation * Vec2(0.0, 1.0);
    const Vec2 axisOut = card.orientation * Vec2(1.0, 0.0);
    // The inner top corner touches x = 0; the lowest corner touches the ground.
    const Vec2 innerTop = 0.5 * length * axisUp - side * 0.5 * thickness * axisOut;
    const Vec2 outerFoot = -0.5 * length * axisUp + side * 0.5 * thickness * axisOut;
    const Vec2 innerFoot = -0.5 * length * axisUp - side * 0.5 * thickness * axisOut;
    const double lowest = std::min(outerFoot.y(), innerFoot.y());
    card.position = Vec2(-innerTop.x(), -lowest);
    card.syncAngularVelocity();
    world.addBody(card, boxShape<2>(sides), material);
  }
  return world;
}

}  // namespace stackbook::stacks
