#pragma once
/// \file
/// \brief The box scenes every engine runs (peers_bench and the peers of `stackbook sweep`,
/// chapter 11): one engine-neutral description of each (the ground slab and the boxes, their
/// sizes, poses, velocities and masses, friction, gravity, step, the peers' solver knobs),
/// from which the stackbook, Box2D and Bullet adapters build the same geometry.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace peers {

/// One box: full side lengths, centre (the last axis is up: y in 2D, z in 3D; z = 0 in 2D),
/// mass (0: static).
struct BoxSpec {
  Eigen::Vector3d size = Eigen::Vector3d::Ones();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double mass = 1.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< orientation (2D: about z)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();  ///< world frame (2D: z)
  bool isStatic() const { return mass == 0.0; }
};

/// A scene of boxes: body 0 is the static ground slab whose top face is up = 0.
struct BoxScene {
  std::string name;         ///< e.g. "stack2d_10"
  std::string description;  ///< e.g. "2D stack of 10 boxes"
  int dimension = 2;
  double gravity = 10.0;    ///< m/s^2, down the last axis unless tilted
  /// Gravity turned by this angle (radians) from down the last axis towards +x: a block on the
  /// flat ground then slides as on an incline of this slope (0: no tilt).
  double tilt = 0.0;
  double friction = 0.6;    ///< the friction of every contact (each engine's mixing rule accounted for)
  /// The restitution of every contact (each engine's mixing rule accounted for).
  double restitution = 0.0;
  double dt = 1.0 / 60.0;
  /// When set, the gravity vector itself (gravity and tilt are then ignored).
  bool hasGravityVector = false;
  Eigen::Vector3d gravityVec = Eigen::Vector3d::Zero();
  /// Box2D keeps a skin of b2_polygonRadius (1 cm) around every polygon, so boxes of the
  /// scene's size rest that far apart (peers_bench keeps it, as Box2D's users do). When set,
  /// the Box2D adapter builds each box smaller by the skin, so that the rounded box it
  /// collides is the scene's box (the sweeps of chapter 11 compare geometry this way).
  bool box2dSkinInside = false;
  /// Box2D's knobs: velocity and position iterations per step (its testbed's defaults).
  int velocityIterations = 8;
  int positionIterations = 3;
  /// Bullet's knob: sequential-impulse iterations per step (its default).
  int solverIterations = 10;
  /// stackbook's knob: the pieces each box edge is cut into for its surface samples
  /// (SampleMeshSettings::boxSubdivisions, a scene's "samples"): 4, the default, gives a 2D box
  /// 16 samples and a cube 98; 1 leaves the corners only (4 and 8).
  int stackbookBoxSubdivisions = 4;
  std::vector<BoxSpec> boxes;  ///< boxes[0] is the ground
  /// The index of the top box (the one whose sag is reported).
  int top() const;
  /// The gravity vector (3D; 2D uses x and y).
  Eigen::Vector3d gravityVector() const;
  /// The closed-form distance a block slides along +x after t seconds when gravity is tilted:
  /// (g sin(theta) - mu g cos(theta)) t^2 / 2, or 0 when friction holds it (Eq. (10.5)).
  double inclineDistance(double t) const;
};

/// n unit boxes in a column, exactly touching, on a 200 m ground slab 1 m thick.
BoxScene stack(int dimension, int n);
/// A 2D pyramid of unit boxes: `base` in the bottom row, one fewer per row, exactly touching.
BoxScene pyramid2d(int base);
/// A unit box resting on the ground under gravity tilted by `degrees`, with friction mu: an
/// incline whose answer is known (inclineDistance()).
BoxScene incline(int dimension, double degrees, double mu);
/// A 3D pyramid of unit cubes: square layers levels x levels, (levels-1)^2, ..., 1.
BoxScene pyramid3d(int levels);

}  // namespace peers
