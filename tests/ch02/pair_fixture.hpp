#pragma once
// Shared set-up for the chapter 2 tests: a random approaching contact between two bodies,
// and the invariants of the pair (linear momentum, angular momentum about a fixed point,
// kinetic energy) computed from the bodies' state, independently of the impulse code.

#include <cmath>
#include <limits>

#include <doctest/doctest.h>

#include "stackbook/impulse/collision_matrix.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

namespace stackbook::testing {

/// A scalar expected value at tier T1: relative, 1e-12. (doctest::Approx on its own also
/// adds an absolute 1e-12, which is loose for small values. Its comparison is strict, so a
/// scale of the smallest normal double instead of 0 lets an exact 0 match 0.)
inline doctest::Approx tierOne(double expected) {
  return doctest::Approx(expected)
      .epsilon(kTierImpulseAlgebra)
      .scale(std::numeric_limits<double>::min());
}

/// Two bodies touching at one world point p, with the unit normal n pointing from b
/// toward a and the offsets ra = p - x_a, rb = p - x_b.
template <int D>
struct PairContact {
  RigidBody<D> a;
  RigidBody<D> b;
  Vec<D> p;
  Vec<D> n;
  Vec<D> ra;
  Vec<D> rb;

  Vec<D> relative() const { return relativeVelocity<D>(a, ra, b, rb); }
  Mat<D> K() const { return pairCollisionMatrix<D>(a, ra, b, rb); }
  double un() const { return relative().dot(n); }
};

/// Reverse all motion of a body (v -> -v, L -> -L): the relative velocity changes sign.
template <int D>
void reverseMotion(RigidBody<D>& body) {
  body.velocity = -body.velocity;
  body.angularMomentum = -body.angularMomentum;
  body.syncAngularVelocity();
}

/// Random bodies, a random contact point and normal, with the motion reversed if needed so
/// the contact approaches clearly: u_n <= -0.05 |u|.
template <int D>
PairContact<D> randomApproachingContact(RandomSource& random) {
  for (;;) {
    PairContact<D> c{random.dynamicBody<D>(), random.dynamicBody<D>(), random.vector<D>(-3.0, 3.0),
                     random.unitVector<D>(), Vec<D>::Zero(), Vec<D>::Zero()};
    c.ra = c.p - c.a.position;
    c.rb = c.p - c.b.position;
    if (c.un() > 0.0) {
      reverseMotion<D>(c.a);
      reverseMotion<D>(c.b);
    }
    if (c.un() <= -0.05 * c.relative().norm()) return c;
  }
}

/// Total linear momentum of the dynamic bodies (a static body has no finite momentum).
template <int D>
Vec<D> linearMomentum(const RigidBody<D>& a, const RigidBody<D>& b) {
  Vec<D> P = Vec<D>::Zero();
  for (const RigidBody<D>* body : {&a, &b}) {
    if (body->inverseMass > 0.0) P += body->velocity / body->inverseMass;
  }
  return P;
}

/// Angular momentum of one dynamic body about the fixed point o: spin plus orbital part,
/// L + (x - o) x m v.
template <int D>
AngVec<D> angularMomentumAbout(const RigidBody<D>& body, const Vec<D>& o) {
  if (body.inverseMass == 0.0) return body.angularMomentum;
  return body.angularMomentum +
         cross<D>(Vec<D>(body.position - o), Vec<D>(body.velocity / body.inverseMass));
}

/// The size of the terms summed in angularMomentumAbout, for a relative tolerance.
template <int D>
double angularMomentumScale(const RigidBody<D>& body, const Vec<D>& o) {
  double scale = body.angularMomentum.norm();
  if (body.inverseMass > 0.0) {
    scale += (body.position - o).norm() * body.velocity.norm() / body.inverseMass;
  }
  return scale;
}

/// Velocity scale of a contact: the point velocities of both bodies at the contact.
template <int D>
double pointVelocityScale(const PairContact<D>& c) {
  return c.a.pointVelocity(c.ra).norm() + c.b.pointVelocity(c.rb).norm();
}

}  // namespace stackbook::testing
