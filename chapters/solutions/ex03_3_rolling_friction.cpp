// Exercise 3.3 (chapter 3): rolling and spinning friction, the reference solution.
#include "stackbook/exercises/ex03_3_rolling_friction.hpp"

#include <algorithm>

#include <Eigen/Cholesky>

#include "stackbook/impulse/collision_matrix.hpp"

namespace stackbook::exercises {

namespace {

/// Shrinks the length of v by amount, stopping at zero.
Vec3 shrink(const Vec3& v, double amount) {
  const double length = v.norm();
  return length > amount ? Vec3((1.0 - amount / length) * v) : Vec3::Zero();
}

}  // namespace

RollingFrictionImpulse rollingFrictionImpulse(const RigidBody<3>& a, const Vec3& ra,
                                              const RigidBody<3>& b, const Vec3& rb,
                                              const Vec3& n, double jn, double muRolling) {
  const Vec3 w = a.angularVelocity - b.angularVelocity;
  const Vec3 spin = w.dot(n) * n, roll = w - spin;
  const double amount = muRolling * std::max(jn, 0.0);
  const Vec3 target = shrink(spin, amount) + shrink(roll, amount);

  const Mat3 Ia = a.inverseInertiaWorld(), Ib = b.inverseInertiaWorld();
  const Mat3 C = crossMatrix<3>(ra).transpose() * Ia + crossMatrix<3>(rb).transpose() * Ib;
  Eigen::Matrix<double, 6, 6> M;
  M << pairCollisionMatrix<3>(a, ra, b, rb), C, C.transpose(), Ia + Ib;
  Eigen::Matrix<double, 6, 1> rhs;
  rhs << Vec3::Zero(), Vec3(target - w);
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(M);
  const double smallest = ldlt.vectorD().minCoeff();
  if (ldlt.info() != Eigen::Success || !(smallest > 1e-12 * M.trace())) return {};
  const Eigen::Matrix<double, 6, 1> x = ldlt.solve(rhs);
  RollingFrictionImpulse result;
  result.j = x.head<3>();
  result.tau = x.tail<3>();
  return result;
}

void applyRollingFriction(RigidBody<3>& a, const Vec3& ra, RigidBody<3>& b, const Vec3& rb,
                          const RollingFrictionImpulse& impulse) {
  a.applyImpulse(ra, impulse.j);
  a.applyAngularImpulse(impulse.tau);
  b.applyImpulse(rb, Vec3(-impulse.j));
  b.applyAngularImpulse(Vec3(-impulse.tau));
}

}  // namespace stackbook::exercises
