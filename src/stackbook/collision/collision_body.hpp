#pragma once
/// \file
/// \brief What collision detection sees of a body: its state, its shape, the pose to test
/// at and whether it is static; and the world bounding box of a shape at a pose (\ref ch07).

#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "stackbook/body/rigid_body.hpp"
#include "stackbook/geometry/shape.hpp"
#include "stackbook/math/pose.hpp"

namespace stackbook {

// [rotation_cache]
/// A pose's rotation matrix R, kept with the orientation it was built from. In 2D R is
/// rebuilt from the angle by a sine and a cosine, and the impulse loops ask the same view
/// for R after every impulse, so a 2D view keeps it: matrixOf(q) returns the kept R when q
/// has the same bits as the angle it was built from, and builds R from q otherwise. The
/// answer is rotationMatrix(q) bit for bit either way, so a stale cache costs time, never a
/// result. In 3D R is a few products of the quaternion's components, cheaper to build than
/// to keep, so nothing is kept. \ref ch07
template <int D>
class RotationCache {
 public:
  /// rotationMatrix(q), built.
  Mat<D> matrixOf(const Orientation<D>& q) const { return rotationMatrix<D>(q); }
  /// Nothing to keep in 3D.
  void keep(const Orientation<D>&) {}
};

template <>
class RotationCache<2> {
 public:
  /// rotationMatrix(q), from the cache when q's angle has the kept angle's bits.
  Mat<2> matrixOf(const Orientation<2>& q) const {
    const double angle = q.angle();
    return std::memcmp(&angle, &angle_, sizeof angle) == 0 ? R_ : rotationMatrix<2>(q);
  }
  /// Keep q's angle and matrix.
  void keep(const Orientation<2>& q) {
    angle_ = q.angle();
    R_ = rotationMatrix<2>(q);
  }

 private:
  double angle_ = 0.0;                                 ///< the angle R_ was built from
  Mat<2> R_ = rotationMatrix<2>(identityOrientation<2>());  ///< R of angle_, bit for bit
};
// [rotation_cache]

// [lever_arms]
/// Where the approach test and the impulse measure a sample's lever arms (chapter 12,
/// "Where the lever arms are measured", Eq. (8.22)).
enum class LeverArms {
  /// At the pose the sample was found at, the tested pose (Eq. (7.4)): r = p - x'.
  AtTestedPose,
  /// At the body's pose at the start of the step: the sample's body point carried back,
  /// r = R R'^T (p - x'), and the normal likewise (PhysBAM's choice; the default).
  AtStartPose,
};
// [lever_arms]

// [collision_body]
/// A read-only view of one body for collision detection (\ref ch07).
///
/// The pose is a value of its own because GBF tests bodies where they *will be*
/// (a predicted pose, chapter 8) while the velocities that decide whether a sample is
/// approaching are the body's current ones. Nothing here changes the body.
template <int D>
struct CollisionBody {
  const RigidBody<D>* body = nullptr;  ///< velocities v and omega for the approach test
  const Shape<D>* shape = nullptr;     ///< phi, N, surface samples, body-frame bounds
  Pose<D> pose;                        ///< where the shape is tested: current or predicted
  bool isStatic = false;               ///< two static bodies are never paired
  /// R of `pose`, kept by collisionBodyAt() and setPose(); right for any pose (see RotationCache).
  RotationCache<D> rotation;
  /// Where leverArm() and carriedDirection() measure (chapter 8, Eq. (8.22)).
  LeverArms arms = LeverArms::AtTestedPose;
  /// How far the step's loads move the tested pose: x' - (x + dt v) = dt^2 a (Eq. (8.1));
  /// zero unless the collision stage asks for held samples (chapter 12, Eq. (12.6)).
  Vec<D> loadDrop = Vec<D>::Zero();

  /// R R'^T, the rotation that carries a direction of the body at the tested pose back to the
  /// body's own pose (Eq. (8.22)); kept by measureArms() and setPose() under LeverArms::AtStartPose.
  Mat<D> carry = Mat<D>::Identity();

  /// Moves the view to `p` and keeps its rotation matrix (and, measuring at the start pose, its
  /// carry).
  void setPose(const Pose<D>& p) {
    pose = p;
    rotation.keep(p.orientation);
    if (arms == LeverArms::AtStartPose) keepCarry();
  }
  /// Measure lever arms as `a` says from now on (Eq. (8.22)).
  void measureArms(LeverArms a) {
    arms = a;
    if (arms == LeverArms::AtStartPose) keepCarry();
  }
  void keepCarry() { carry = rotationMatrix<D>(body->orientation) * poseRotation().transpose(); }
  /// rotationMatrix(pose.orientation), bit for bit, without rebuilding it when the view kept it.
  Mat<D> poseRotation() const { return rotation.matrixOf(pose.orientation); }

  // [lever_arm]
  /// The lever arm of the body point found at world point `p` at the tested pose: p - x'
  /// (Eq. (7.4)), or under LeverArms::AtStartPose that point carried back to the body's
  /// pose, R R'^T (p - x') (Eq. (8.22)).
  /// A point that is no fixed point of the body (`bodyPoint` false: an exact deepest point,
  /// chapter 11) keeps p - x' either way.
  Vec<D> leverArm(const Vec<D>& p, bool bodyPoint = true) const {
    const Vec<D> r = p - pose.position;
    if (arms == LeverArms::AtTestedPose || !bodyPoint) return r;
    return carry * r;  // Eq. (8.22): R R'^T (p - x')
  }
  /// A direction `n` of the body at the tested pose (a normal), as leverArm() carries it.
  Vec<D> carriedDirection(const Vec<D>& n, bool bodyPoint = true) const {
    if (arms == LeverArms::AtTestedPose || !bodyPoint) return n;
    return carry * n;  // Eq. (8.22)
  }
  // [lever_arm]

  // [held_sample]
  /// True when the body point at world point `p` of this view, found inside `other` at
  /// the tested poses, is outside it once the two bodies' load drops are taken back
  /// (Eq. (12.6)): it interferes only because the step's loads move the two bodies apart
  /// by dt^2 (a - a_other). `inOther` is p in `other`'s frame at its tested pose.
  bool interferesByLoadsAlone(const CollisionBody<D>& other, const Mat<D>& Rother, const Vec<D>& inOther) const {
    const Vec<D> drop = loadDrop - other.loadDrop;
    if (drop.isZero(0.0)) return false;
    return other.shape->signedDistance(Vec<D>(inOther - Rother.transpose() * drop)) >= 0.0;
  }
  // [held_sample]
};
// [collision_body]

/// A collision view of `body` with `shape`, tested at `pose`. The view keeps pointers:
/// body and shape must outlive it. `isStatic` is taken from the body (inverse mass and
/// inverse inertia zero). \ref ch07
template <int D>
CollisionBody<D> collisionBodyAt(const RigidBody<D>& body, const Shape<D>& shape,
                                 const Pose<D>& pose) {
  CollisionBody<D> view{&body, &shape, pose, body.isStatic(), {}, LeverArms::AtTestedPose, Vec<D>::Zero(),
                        Mat<D>::Identity()};
  view.rotation.keep(pose.orientation);
  return view;
}

/// A collision view of `body` with `shape` at the body's current pose. \ref ch07
template <int D>
CollisionBody<D> collisionBody(const RigidBody<D>& body, const Shape<D>& shape) {
  return collisionBodyAt<D>(body, shape, Pose<D>{body.position, body.orientation});
}

// A view must not point at a temporary body or shape.
template <int D>
CollisionBody<D> collisionBodyAt(const RigidBody<D>&&, const Shape<D>&, const Pose<D>&) = delete;
template <int D>
CollisionBody<D> collisionBodyAt(const RigidBody<D>&, const Shape<D>&&, const Pose<D>&) = delete;
template <int D>
CollisionBody<D> collisionBody(const RigidBody<D>&&, const Shape<D>&) = delete;
template <int D>
CollisionBody<D> collisionBody(const RigidBody<D>&, const Shape<D>&&) = delete;

/// Throws std::invalid_argument unless the view has a body and a shape; `caller` and
/// `index` name the view in the message.
template <int D>
void checkCollisionBody(const CollisionBody<D>& view, int index, const char* caller) {
  if (view.body != nullptr && view.shape != nullptr) return;
  std::ostringstream msg;
  msg << caller << ": body " << index << " has no "
      << (view.body == nullptr ? "RigidBody (body is null)" : "Shape (shape is null)");
  throw std::invalid_argument(msg.str());
}

// [world_bounds]
namespace detail {
/// worldBounds() with the pose's rotation matrix R = rotationMatrix(pose.orientation) at hand.
template <int D>
Aabb<D> worldBoundsWithMatrix(const Shape<D>& shape, const Pose<D>& pose, const Mat<D>& R) {
  const Aabb<D> local = shape.bounds();
  if (local.isEmpty()) return local;
  // x + R c; in 2D with the R above (Eigen rebuilds it on every rotation of a vector, with
  // the same bits), in 3D by the quaternion as Pose::toWorld() does.
  Vec<D> centre;
  if constexpr (D == 2) {
    centre = pose.position + R * local.center();
  } else {
    centre = pose.toWorld(local.center());
  }
  const Vec<D> half = R.cwiseAbs() * Vec<D>(0.5 * local.extent());  // Eq. (7.8)
  return Aabb<D>{Vec<D>(centre - half), Vec<D>(centre + half)};
}
}  // namespace detail

/// World-frame bounding box of `shape` placed at `pose`: the smallest axis-aligned box
/// around the 2^D corners of the body-frame box after p -> x + R p, computed without
/// visiting the corners: centre x + R c, half-extent |R| h, with |R| the entrywise
/// absolute value (Eq. (7.8)). Valid for every shape, because the body-frame box holds
/// the whole body; it is loose when the shape does not fill its box (a sphere: up to
/// a factor sqrt(D) on a side). An empty body-frame box stays empty. \ref ch07
template <int D>
Aabb<D> worldBounds(const Shape<D>& shape, const Pose<D>& pose) {
  return detail::worldBoundsWithMatrix<D>(shape, pose, rotationMatrix<D>(pose.orientation));
}
// [world_bounds]

// [world_bounds_of_samples]
/// The smallest world-frame box around the shape's surface samples at `pose`. Tight, and
/// a bound of the body only when the body is the polytope its samples span (a mesh whose
/// vertices are the samples). For a smooth shape sampled at a few points (a sphere whose
/// samples are icosahedron vertices) the surface bulges between samples and out of this
/// box: use worldBounds() there. Costs one transform per sample instead of O(1). \ref ch07
template <int D>
Aabb<D> worldBoundsOfSamples(const Shape<D>& shape, const Pose<D>& pose) {
  Aabb<D> box;
  for (const Vec<D>& s : shape.surfaceSamples()) box.extend(pose.toWorld(s));
  return box;
}
// [world_bounds_of_samples]

}  // namespace stackbook
