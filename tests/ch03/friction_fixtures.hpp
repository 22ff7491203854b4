#pragma once
// Contacts for the chapter 3 tests, and reference formulas derived independently of
// frictional_impulse.hpp: they use an explicit inverse of K (fine for a 2 x 2 or 3 x 3
// reference, never used by the library) and check results on the bodies themselves.

#include <algorithm>
#include <cmath>

#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"
#include "support/random_bodies.hpp"

namespace stackbook::testing {

/// Two bodies touching at one point: body a at offset ra, body b at offset rb, unit
/// normal n from b toward a. Everything the tests measure is measured on the bodies.
template <int D>
struct PairContact {
  RigidBody<D> a, b;
  Vec<D> ra = Vec<D>::Zero(), rb = Vec<D>::Zero();
  Vec<D> n = Vec<D>::UnitY();

  Mat<D> K() const { return pairCollisionMatrix<D>(a, ra, b, rb); }
  Vec<D> u() const { return relativeVelocity<D>(a, ra, b, rb); }
  double kineticEnergy() const { return a.kineticEnergy() + b.kineticEnergy(); }
  double inverseMassSum() const { return a.inverseMass + b.inverseMass; }

  /// The same contact after +j on a and -j on b.
  PairContact after(const Vec<D>& j) const {
    PairContact c = *this;
    applyPairImpulse<D>(c.a, c.ra, c.b, c.rb, j);
    return c;
  }

  /// Give body a the velocity that makes the relative contact velocity equal `target`.
  void setRelativeVelocity(const Vec<D>& target) {
    a.velocity += target - u();
  }
};

/// A unit vector perpendicular to n (in 3D a random one).
template <int D>
Vec<D> randomTangent(RandomSource& random, const Vec<D>& n) {
  for (;;) {
    const Vec<D> v = random.unitVector<D>();
    const Vec<D> t = v - v.dot(n) * n;
    if (t.norm() > 0.1) return t.normalized();
  }
}

/// What body b is: immovable, immovable but moving (kinematic), or a dynamic body.
enum class Partner { Static, Kinematic, Dynamic };

/// A random contact: random bodies, offsets, normal, and a relative velocity with
/// u_n in [-2, -0.1] and |u_t| / |u_n| = slipRatio (exactly 0 when slipRatio = 0).
template <int D>
PairContact<D> randomContact(RandomSource& random, Partner partner, double slipRatio) {
  PairContact<D> c;
  c.a = random.dynamicBody<D>();
  if (partner == Partner::Dynamic) {
    c.b = random.dynamicBody<D>();
  } else {
    c.b = makeStaticBody<D>(random.vector<D>(-3.0, 3.0), random.orientation<D>());
    if (partner == Partner::Kinematic) {
      c.b.velocity = random.vector<D>(-2.0, 2.0);
      // A kinematic body's angular velocity is prescribed; L plays no role for it.
      c.b.angularVelocity = random.angularVector<D>(-2.0, 2.0);
    }
  }
  const Vec<D> p = c.a.position + random.vector<D>(-1.0, 1.0);
  c.ra = p - c.a.position;
  c.rb = p - c.b.position;
  c.n = random.unitVector<D>();
  const double un = -random.uniform(0.1, 2.0);
  c.setRelativeVelocity(Vec<D>(un * c.n + slipRatio * std::abs(un) * randomTangent<D>(random, c.n)));
  return c;
}

/// A uniform rod (length 1, mass 1, I = 1/12 about its centre) at angle theta above the
/// floor, touching a static floor (normal +y) with its lower end (\ref ch03, A21).
inline PairContact<2> rodOnFloor(double theta, const Vec2& u) {
  PairContact<2> c;
  c.a = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0 / 12.0));
  c.a.orientation = Eigen::Rotation2Dd(theta);
  c.a.position = Vec2(0.0, 0.5 * std::sin(theta));
  c.b = makeStaticBody<2>();
  c.ra = -0.5 * Vec2(std::cos(theta), std::sin(theta));
  c.rb = c.a.position + c.ra;
  c.n = Vec2(0.0, 1.0);
  c.setRelativeVelocity(u);
  return c;
}

/// A slender 3D rod (0.05 x 0.05 x 1, mass 1) tilted by theta from the floor in the x-z
/// plane, lower end on a static floor with normal +z.
inline PairContact<3> rodOnFloor3(double theta, const Vec3& u) {
  const double a = 0.05, L = 1.0;
  PairContact<3> c;
  c.a = makeDynamicBody<3>(1.0, Vec3((a * a + L * L) / 12.0, (a * a + L * L) / 12.0, a * a / 6.0));
  // Body z (the rod axis) is turned into the x-z plane at theta above the floor.
  c.a.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * M_PI - theta, Vec3::UnitY()));
  c.a.syncAngularVelocity();
  const Vec3 axis = c.a.orientation * Vec3::UnitZ();
  c.ra = -0.5 * L * axis;
  c.a.position = Vec3(0.0, 0.0, -c.ra.z());
  c.b = makeStaticBody<3>();
  c.rb = c.a.position + c.ra;
  c.n = Vec3::UnitZ();
  c.setRelativeVelocity(u);
  return c;
}

// ---- Reference formulas (explicit inverse; independent of the library's solve) --------

/// The sticking impulse K^{-1}(-e u_n n - u) (Eq. (3.2)), by an explicit inverse.
template <int D>
Vec<D> stickingReference(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n, double e) {
  const Mat<D> Kinv = K.inverse();
  return Kinv * Vec<D>(-e * u.dot(n) * n - u);
}

/// e_max = sqrt(u^T K^{-1} u / (u_n^2 n^T K^{-1} n)) (Eq. (3.9)), by an explicit inverse.
template <int D>
double eMaxReference(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n) {
  const Mat<D> Kinv = K.inverse();
  const double un = u.dot(n);
  return std::sqrt(u.dot(Kinv * u) / (un * un * n.dot(Kinv * n)));
}

/// Normal and tangential parts of a vector.
template <int D>
double normalPart(const Vec<D>& v, const Vec<D>& n) {
  return v.dot(n);
}
template <int D>
Vec<D> tangentialPart(const Vec<D>& v, const Vec<D>& n) {
  return v - v.dot(n) * n;
}

/// The slip direction of the default rule (SlipDirectionRule::Blended, Eq. (3.4)),
/// restated from its definition with an explicit inverse: T* = -j*_t/|j*_t| from the
/// sticking trial with restitution eTrial; T* if u_t = 0 or T* . u_t <= 0; otherwise the
/// unit vector along (1 - rho) u_t/|u_t| + rho T*, with rho = min(1, mu j_n / |j*_t|) and
/// j_n the kinetic normal impulse of Eq. (3.5) along T* with restitution e.
template <int D>
Vec<D> blendedSlipReference(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n, double e,
                            double eTrial, double mu) {
  const Vec<D> jStar = stickingReference<D>(K, u, n, eTrial);
  const Vec<D> jt = jStar - jStar.dot(n) * n;
  const Vec<D> impact = -jt.normalized();
  const Vec<D> ut = u - u.dot(n) * n;
  if (ut.norm() == 0.0 || impact.dot(ut) <= 0.0) return impact;
  const double jn = -(1.0 + e) * u.dot(n) / n.dot(K * Vec<D>(n - mu * impact));
  const double rho = std::min(1.0, mu * jn / jt.norm());
  return ((1.0 - rho) * ut.normalized() + rho * impact).normalized();
}

/// The normal impulse j_n of the kinetic impulse written out from Eq. (3.5).
template <int D>
double kineticNormalReference(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n,
                              const Vec<D>& T, double e, double mu) {
  return -(1.0 + e) * u.dot(n) / n.dot(K * Vec<D>(n - mu * T));
}

}  // namespace stackbook::testing
