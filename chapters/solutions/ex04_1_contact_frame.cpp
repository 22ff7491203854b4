// Exercise 4.1, reference solution: the 2D pair K in the contact frame.
//
// With K = delta/m + (|r|^2 delta - r r^T)/I (Eq. (4.4)) and t = (-n_y, n_x):
//   n^T K n = 1/m + (|r|^2 - (r.n)^2)/I = 1/m + (r x n)^2/I        (Eqs. (4.7), (4.8))
//   n^T K t = (0 - (r.n)(r.t))/I           = (r x n)(r.n)/I         since r.t = -(r x n)
//   t^T K t = 1/m + (|r|^2 - (r.t)^2)/I    = 1/m + (r.n)^2/I
// and the kinetic denominator of Eq. (3.5) with T = s t is n^T K n - mu s n^T K t.
#include "stackbook/exercises/ex04_1_contact_frame.hpp"

#include <limits>

namespace stackbook::exercises {

namespace {

ContactFrameK bodyFrameK(const RigidBody<2>& body, const Vec2& r, const Vec2& n) {
  const double invM = body.inverseMass, invI = body.inverseInertia[0];
  const double rCrossN = r.x() * n.y() - r.y() * n.x();
  const double rDotN = r.dot(n);
  ContactFrameK k;
  k.nn = invM + invI * rCrossN * rCrossN;
  k.nt = invI * rCrossN * rDotN;
  k.tt = invM + invI * rDotN * rDotN;
  return k;
}

}  // namespace

ContactFrameK contactFrameK(const RigidBody<2>& a, const Vec2& ra, const RigidBody<2>& b,
                            const Vec2& rb, const Vec2& n) {
  const ContactFrameK ka = bodyFrameK(a, ra, n), kb = bodyFrameK(b, rb, n);
  return ContactFrameK{ka.nn + kb.nn, ka.nt + kb.nt, ka.tt + kb.tt};
}

double painleveFriction(const ContactFrameK& k, double slipSign) {
  // n^T K (n - mu s t) = k.nn - mu s k.nt; k.nn > 0, so it vanishes at mu = k.nn / (s k.nt)
  // when s k.nt > 0, and never otherwise.
  const double coupling = slipSign * k.nt;
  if (!(coupling > 0.0)) return std::numeric_limits<double>::infinity();
  return k.nn / coupling;
}

}  // namespace stackbook::exercises
