// Exercise 2.4 (reference solution): two contacts of one pair resolved at once, as a 2 x 2
// linear complementarity problem solved by enumerating its four active sets.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "stackbook/exercises/ex02_4_two_contacts.hpp"
#include "stackbook/impulse/collision_matrix.hpp"

namespace stackbook::exercises {

template <int D>
Eigen::Matrix2d twoContactMatrix(const RigidBody<D>& a, const RigidBody<D>& b,
                                 const std::array<ContactPoint<D>, 2>& contacts) {
  const AngMat<D> inverseInertiaA = a.inverseInertiaWorld();
  const AngMat<D> inverseInertiaB = b.inverseInertiaWorld();
  Eigen::Matrix2d A;
  for (int c = 0; c < 2; ++c) {
    for (int k = 0; k < 2; ++k) {
      const ContactPoint<D>& pc = contacts[c];
      const ContactPoint<D>& pk = contacts[k];
      // n_c^T r_c*^T I^{-1} r_k* n_k = (r_c x n_c)^T I^{-1} (r_k x n_k), for each body.
      const AngVec<D> acn = cross<D>(pc.ra, pc.n), akn = cross<D>(pk.ra, pk.n);
      const AngVec<D> bcn = cross<D>(pc.rb, pc.n), bkn = cross<D>(pk.rb, pk.n);
      A(c, k) = (a.inverseMass + b.inverseMass) * pc.n.dot(pk.n) +
                acn.dot(inverseInertiaA * akn) + bcn.dot(inverseInertiaB * bkn);
    }
  }
  return 0.5 * (A + A.transpose());
}

template <int D>
Eigen::Vector2d simultaneousNormalImpulses(const RigidBody<D>& a, const RigidBody<D>& b,
                                           const std::array<ContactPoint<D>, 2>& contacts,
                                           double e) {
  if (!(e >= 0.0 && e <= 1.0)) {
    std::ostringstream msg;
    msg << "simultaneousNormalImpulses: restitution e must be in [0, 1], got " << e;
    throw std::invalid_argument(msg.str());
  }
  const Eigen::Matrix2d A = twoContactMatrix<D>(a, b, contacts);
  // w = A j + q is the post-impact w_c = u_c' + e min(u_c, 0) of each contact.
  Eigen::Vector2d q;
  for (int c = 0; c < 2; ++c) {
    const ContactPoint<D>& p = contacts[c];
    const double uc = relativeVelocity<D>(a, p.ra, b, p.rb).dot(p.n);
    q[c] = uc + e * std::min(uc, 0.0);
  }
  if ((q.array() >= 0.0).all()) return Eigen::Vector2d::Zero();  // nothing approaches

  const double scale = A.cwiseAbs().maxCoeff();
  const double tolerance = 1e-12;
  auto solves = [&](const Eigen::Vector2d& j) {
    const Eigen::Vector2d w = A * j + q;
    const double size = q.cwiseAbs().maxCoeff() + scale * j.cwiseAbs().maxCoeff();
    return (j.array() >= 0.0).all() && (w.array() >= -tolerance * size).all();
  };
  // Active set {1, 2}: A j = -q, when A is not singular (LDL^T with a pivot test).
  const Eigen::LDLT<Eigen::Matrix2d> ldlt(A);
  if (ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > tolerance * A.trace()) {
    const Eigen::Vector2d j = ldlt.solve(Eigen::Vector2d(-q));
    if (solves(j)) return j;
  }
  // Active sets {1} and {2}: one contact takes the whole impulse.
  for (int c = 0; c < 2; ++c) {
    if (!(A(c, c) > tolerance * scale)) continue;
    Eigen::Vector2d j = Eigen::Vector2d::Zero();
    j[c] = -q[c] / A(c, c);
    if (solves(j)) return j;
  }
  return Eigen::Vector2d::Zero();  // an immovable pair: no impulse can help
}

template Eigen::Matrix2d twoContactMatrix<2>(const RigidBody<2>&, const RigidBody<2>&,
                                             const std::array<ContactPoint<2>, 2>&);
template Eigen::Matrix2d twoContactMatrix<3>(const RigidBody<3>&, const RigidBody<3>&,
                                             const std::array<ContactPoint<3>, 2>&);
template Eigen::Vector2d simultaneousNormalImpulses<2>(const RigidBody<2>&, const RigidBody<2>&,
                                                       const std::array<ContactPoint<2>, 2>&,
                                                       double);
template Eigen::Vector2d simultaneousNormalImpulses<3>(const RigidBody<3>&, const RigidBody<3>&,
                                                       const std::array<ContactPoint<3>, 2>&,
                                                       double);

}  // namespace stackbook::exercises
