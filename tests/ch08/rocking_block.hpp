#pragma once
// A block rocking on a floor (Housner 1963), for chapter 8's tests and documentation
// programs (docs/examples/ch08_rocking.cpp) and chapter 11's rocking sweep: a uniform block of
// half-width b and half-height h (2D), or half extents (b, 0.5, h) rocking about an edge
// along y (3D), released from rest on its corner (edge) at the origin, tilted by theta0
// towards the other corner. Without doctest, the same in 2D and 3D.

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/stepping/contact_recorder.hpp"
#include "stackbook/stepping/world.hpp"
#include "../support/tilt.hpp"

namespace stackbook::testing {

// [housner_ratio]
/// Housner's ratio (Eq. (8.20)): the angular velocity a block keeps when an inelastic,
/// non-slipping impact moves its pivot from one corner to the other. alpha = atan(b / h).
inline double housnerRatio(double b, double h) {
  const double s = std::sin(std::atan2(b, h));
  return 1.0 - 1.5 * s * s;
}
// [housner_ratio]

template <int D>
struct RockingBlock {
  World<D> world;
  int block = -1;
  double b = 0.0, h = 0.0, g = 9.81;

  const RigidBody<D>& body() const { return world.bodies[static_cast<std::size_t>(block)]; }

  /// Mechanical energy above rest (the block flat, centre at height h): kinetic plus
  /// m g (y - h).
  double energyAboveRest() const {
    const RigidBody<D>& B = body();
    const double kinetic = 0.5 * B.velocity.squaredNorm() / B.inverseMass +
                           0.5 * B.angularVelocity.dot(B.angularMomentum);
    return kinetic + g * (B.position[D - 1] - h) / B.inverseMass;
  }
  /// The angular velocity about the rocking axis (2D: the scalar; 3D: about -y, so that
  /// it has the sign of the tilt rate in both).
  double rockingRate() const {
    if constexpr (D == 2) {
      return body().angularVelocity[0];
    } else {
      return -body().angularVelocity[1];
    }
  }
  /// Height above the floor of the bottom corner (edge) at local x = side * b.
  double cornerHeight(double side) const {
    Vec<D> local = Vec<D>::Zero();
    local[0] = side * b;
    local[D - 1] = -h;
    return (body().position + body().orientation * local)[D - 1];
  }
};

/// The block on a static floor whose top is the plane y = 0 (z = 0): e = 0 and the given mu
/// for both, tilted by theta0 on the corner (edge) at the origin.
template <int D>
RockingBlock<D> makeRockingBlock(double b, double h, double theta0, double mu = 1.0) {
  RockingBlock<D> scene;
  scene.b = b;
  scene.h = h;
  Vec<D> up = Vec<D>::Zero();
  up[D - 1] = 1.0;
  scene.world.gravity = -scene.g * up;
  const Material material{0.0, mu, 0.0};
  Vec<D> floorSize = Vec<D>::Constant(40.0);
  floorSize[D - 1] = 1.0;
  scene.world.addBody(makeStaticBody<D>(Vec<D>(-0.5 * up)),
                      std::make_shared<BoxShape<D>>(makeBoxShape<D>(floorSize)), material);
  Vec<D> size = Vec<D>::Constant(1.0);
  size[0] = 2.0 * b;
  size[D - 1] = 2.0 * h;
  // Uniform mass 1: I = (s_j^2 + s_k^2) / 12 about each principal axis i.
  AngVec<D> inertia;
  if constexpr (D == 2) {
    inertia[0] = (size[0] * size[0] + size[1] * size[1]) / 12.0;
  } else {
    inertia = Vec3((size[1] * size[1] + size[2] * size[2]) / 12.0, (size[0] * size[0] + size[2] * size[2]) / 12.0,
                   (size[0] * size[0] + size[1] * size[1]) / 12.0);
  }
  RigidBody<D> block = makeDynamicBody<D>(1.0, inertia);
  block.orientation = tilt<D>(theta0);  // turns axis 0 towards up: the corner at +b rises
  Vec<D> pivotToCentre = Vec<D>::Zero();
  pivotToCentre[0] = b;
  pivotToCentre[D - 1] = h;
  block.position = block.orientation * pivotToCentre;
  block.syncAngularVelocity();
  scene.block = scene.world.addBody(block, std::make_shared<BoxShape<D>>(makeBoxShape<D>(size)), material);
  return scene;
}

/// What one landing did: the energy above rest just before it and once the old pivot has
/// left the floor, and the ratio sqrt(E+ / E-) the block goes on rocking with.
struct Landing {
  bool found = false;
  long step = -1;       ///< the step whose impulses first reach the landing corner
  long steps = 0;       ///< steps from that one until the old pivot is off the floor
  double before = 0.0;  ///< E- (J)
  double after = 0.0;   ///< E+ (J)
  double largestRise = 0.0;  ///< the largest rise of E over one step of the landing (J)
  double ratio() const { return std::sqrt(after / before); }
};

/// Step the block (stepper(world)) until its first landing on the corner at +b is over, and
/// return it: the landing starts with the first step that applies an impulse at a point
/// with x > b, and ends at the end of the first later step after which the old pivot (the
/// corner at -b) is above the floor and took no impulse. Gives up (found = false) after
/// `maxSeconds`.
template <int D, class Stepper>
Landing firstLanding(RockingBlock<D>& scene, double dt, ContactRecorder& recorder, Stepper&& stepper,
                     double maxSeconds = 3.0) {
  Landing out;
  const long maxSteps = std::lround(maxSeconds / dt);
  for (long n = 0; n < maxSteps; ++n) {
    const double before = scene.energyAboveRest();
    recorder.clear();
    stepper(scene.world);
    const double after = scene.energyAboveRest();
    bool landingSide = false, pivotSide = false;
    for (const ContactRecord& r : recorder.records()) {
      (r.point[0] > scene.b ? landingSide : pivotSide) = true;
    }
    if (!out.found && landingSide) {
      out.found = true;
      out.step = n;
      out.before = before;
    }
    if (!out.found) continue;
    out.largestRise = std::max(out.largestRise, after - before);
    if (!pivotSide && scene.cornerHeight(-1.0) > 0.0) {
      out.after = after;
      out.steps = n - out.step + 1;
      return out;
    }
  }
  out.found = false;
  return out;
}

}  // namespace stackbook::testing
