#pragma once
/// \file
/// \brief The 2D reduction (\ref ch04): the notes' closed-form 2D K, the scalar
/// normal response n^T K_T n in the form 2D engines use, and the maps that place a planar
/// body or vector inside 3D space and read it back.
///
/// The generic templates already run with D = 2 (`collisionMatrix<2>`, `frictionalImpulse<2>`,
/// ...). Nothing here is needed to simulate in the plane. These functions state the planar
/// formulas in closed form, so the generic code can be checked against them, and they let a
/// planar scene be run through the 3D code, so the two can be checked against each other.

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "stackbook/body/rigid_body.hpp"

namespace stackbook {

// [planar_collision_matrix]
/// The notes' 2D collision matrix of one body, written out (Eq. (4.3)):
/// K = delta/m + (1/I) [[r_y^2, -r_x r_y], [-r_x r_y, r_x^2]].
/// `inverseInertia` is the scalar 1/I about the axis normal to the plane; in 2D it needs
/// no rotation to the world frame (Eq. (4.11)). Equal to `collisionMatrix<2>` (\ref ch04).
inline Mat2 planarCollisionMatrix(double inverseMass, double inverseInertia, const Vec2& r) {
  Mat2 angular;
  angular << r.y() * r.y(), -r.x() * r.y(),
             -r.x() * r.y(), r.x() * r.x();
  return inverseMass * Mat2::Identity() + inverseInertia * angular;  // Eq. (4.3)
}
// [planar_collision_matrix]

// [planar_normal_response]
/// n^T K_T n for a planar pair in the form 2D engines compute it (box2d-lite's kNormal):
/// 1/m_a + 1/m_b + (r_a.r_a - (r_a.n)^2)/I_a + (r_b.r_b - (r_b.n)^2)/I_b (Eqs. (4.7), (4.8)).
/// n must be a unit vector. The frictionless impulse is then j_n = -(1 + e) u_n / kNormal
/// (\ref ch04).
inline double planarNormalResponse(const RigidBody<2>& a, const Vec2& ra, const RigidBody<2>& b,
                                   const Vec2& rb, const Vec2& n) {
  const double rna = ra.dot(n), rnb = rb.dot(n);
  return a.inverseMass + b.inverseMass + a.inverseInertia[0] * (ra.dot(ra) - rna * rna) +
         b.inverseInertia[0] * (rb.dot(rb) - rnb * rnb);  // Eq. (4.8)
}
// [planar_normal_response]

// [lift_to_space]
/// The plane z = 0 inside space: (x, y) -> (x, y, 0) (\ref ch04).
inline Vec3 liftToSpace(const Vec2& p) { return Vec3(p.x(), p.y(), 0.0); }

/// A planar rotation by angle theta, as the rotation by theta about the z axis.
inline Eigen::Quaterniond liftToSpace(const Eigen::Rotation2Dd& q) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(q.angle(), Vec3::UnitZ()));
}

/// Read a vector of space in the plane z = 0: (x, y, z) -> (x, y). The z component is
/// dropped, not checked; a planar motion keeps it zero (Eq. (4.5)).
inline Vec2 dropToPlane(const Vec3& p) { return p.head<2>(); }

/// A planar body as a 3D body moving in the plane z = 0: same mass, position, velocity and
/// orientation (a rotation about z), angular momentum (0, 0, L), and the planar moment I as
/// the principal moment about z. The in-plane principal moments (Ix, Iy) do not affect
/// planar motion (Eq. (4.5)) but must make a physical body: finite, positive, and with
/// (Ix, Iy, I) satisfying the triangle inequality, else std::invalid_argument. A body that
/// cannot rotate in the plane (1/I = 0, e.g. a static body) cannot rotate at all in space
/// (\ref ch04).
inline RigidBody<3> liftToSpace(const RigidBody<2>& body, double Ix, double Iy) {
  RigidBody<3> lifted;
  lifted.position = liftToSpace(body.position);
  lifted.orientation = liftToSpace(body.orientation);
  lifted.velocity = liftToSpace(body.velocity);
  lifted.inverseMass = body.inverseMass;
  const double I = body.inertia[0], inverseI = body.inverseInertia[0];
  if (inverseI > 0.0) {
    const double slack = 1e-12 * (Ix + Iy + I);
    if (!std::isfinite(Ix) || !std::isfinite(Iy) || !(Ix > 0.0) || !(Iy > 0.0) ||
        Ix + Iy < I - slack || Iy + I < Ix - slack || I + Ix < Iy - slack) {
      std::ostringstream msg;
      msg << "liftToSpace: in-plane moments (Ix, Iy) = (" << Ix << ", " << Iy
          << ") must be finite, positive and satisfy the triangle inequality with Iz = " << I;
      throw std::invalid_argument(msg.str());
    }
    lifted.inertia = Vec3(Ix, Iy, I);
    lifted.inverseInertia = Vec3(1.0 / Ix, 1.0 / Iy, inverseI);
  } else {
    lifted.inertia = Vec3(I, I, I);
    lifted.inverseInertia = Vec3::Zero();
  }
  lifted.angularMomentum = Vec3(0.0, 0.0, body.angularMomentum[0]);
  lifted.syncAngularVelocity();
  return lifted;
}

/// A planar body lifted as a lamina: in-plane moments Ix = Iy = I/2, so that
/// Ix + Iy = Iz (the perpendicular-axis theorem for a flat body).
inline RigidBody<3> liftToSpace(const RigidBody<2>& body) {
  return liftToSpace(body, 0.5 * body.inertia[0], 0.5 * body.inertia[0]);
}
// [lift_to_space]

}  // namespace stackbook
