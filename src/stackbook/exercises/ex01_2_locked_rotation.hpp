#pragma once
/// \file
/// \brief Exercise 1.2: bodies whose rotation is constrained, and the singular K they
/// give (\ref ch01). Three-dimensional: in the plane there is only one axis of rotation,
/// so "locked" is inverseInertia = 0 and "hinged" is the free body.

#include "stackbook/body/rigid_body.hpp"

namespace stackbook {

/// World-frame inverse inertia W of a body that cannot turn about the unit world axis a
/// (a bearing holds it), but turns freely about every axis perpendicular to a.
/// An angular impulse tau then changes the angular velocity by W tau, the response of
/// I dw = tau + lambda a with a . dw = 0 (lambda a: the bearing's reaction torque).
/// For a principal axis this equals zeroing that inverse moment. Build it from
/// body.inverseInertiaWorld() without inverting a world-frame tensor.
AngMat<3> inverseInertiaLockedAbout(const RigidBody<3>& body, const Vec3& a);

/// World-frame inverse inertia W of a body that can turn only about the unit world axis a
/// (a hinge): W tau is parallel to a, and the hinge's reaction torque is perpendicular to a.
AngMat<3> inverseInertiaHingedAbout(const RigidBody<3>& body, const Vec3& a);

}  // namespace stackbook
