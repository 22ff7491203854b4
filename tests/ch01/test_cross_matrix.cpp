// Chapter 1: the cross-product matrix r* (Eqs. (1.3), (1.4)) and the velocity of a
// material point (Eq. (1.6)), each checked against an independent computation.
#include <cmath>
#include <limits>

#include <doctest/doctest.h>

#include "stackbook/body/rigid_body.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::kEps;
using stackbook::testing::RandomSource;

namespace {

/// r x b written out component by component, independently of crossMatrix:
/// the 3D vector product, and in 2D the z component r_x b_y - r_y b_x.
template <int D>
AngVec<D> crossByComponents(const Vec<D>& r, const Vec<D>& b) {
  if constexpr (D == 2) {
    return AngVec<2>(r.x() * b.y() - r.y() * b.x());
  } else {
    return AngVec<3>(r.y() * b.z() - r.z() * b.y(), r.z() * b.x() - r.x() * b.z(),
                     r.x() * b.y() - r.y() * b.x());
  }
}

/// w x r for an angular w, written out: in 2D w is the z component, so
/// (w e_z) x r = w (-r_y, r_x); in 3D it is the vector product.
template <int D>
Vec<D> angularCrossByComponents(const AngVec<D>& w, const Vec<D>& r) {
  if constexpr (D == 2) {
    return Vec<2>(-w[0] * r.y(), w[0] * r.x());
  } else {
    return Vec<3>(w.y() * r.z() - w.z() * r.y(), w.z() * r.x() - w.x() * r.z(),
                  w.x() * r.y() - w.y() * r.x());
  }
}

/// The orientation reached from q0 after turning for time t at the constant world-frame
/// angular velocity w: R(t) = exp(t w*) R(0), the exact solution of dR/dt = w* R.
template <int D>
Orientation<D> rotatedBy(const Orientation<D>& q0, const AngVec<D>& w, double t) {
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(q0.angle() + w[0] * t);
  } else {
    const double speed = w.norm();
    if (speed == 0.0) return q0;
    return Eigen::Quaterniond(Eigen::AngleAxisd(speed * t, w / speed)) * q0;
  }
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_cross_identities]
TEST_CASE_TEMPLATE("the cross-product matrix gives r x b = r* b and w x r = r*^T w",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(11 + D);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const Vec<D> r = random.vector<D>(-4.0, 4.0);
    const Vec<D> b = random.vector<D>(-4.0, 4.0);
    const AngVec<D> w = random.angularVector<D>(-4.0, 4.0);
    const CrossMat<D> rs = crossMatrix<D>(r);
    // Eq. (1.3): r x b = r* b.
    CHECK_EIGEN_NEAR(AngVec<D>(rs * b), crossByComponents<D>(r, b), 4 * kEps);
    // Eq. (1.4): w x r = r*^T w for an angular w.
    CHECK_EIGEN_NEAR(Vec<D>(rs.transpose() * w), angularCrossByComponents<D>(w, r), 4 * kEps);
    // r* r = 0 exactly: a push through the centre of mass has no moment.
    CHECK(AngVec<D>(rs * r).isZero(0.0));
    if constexpr (D == 3) {
      // In 3D, b x r = -(r x b): r* is skew-symmetric, r*^T = -r*.
      CHECK(Mat<3>(rs + rs.transpose()).isZero(0.0));
      CHECK_EIGEN_NEAR(Vec<3>(rs.transpose() * b), Vec<3>(b.cross(r)), 4 * kEps);
    }
  }
}
// [test_cross_identities]

// [test_point_velocity]
TEST_CASE_TEMPLATE("point velocity is the time derivative of a material point and not v + w x v",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(23 + D);
  const double h = 1e-4;  // central-difference step
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const RigidBody<D> body = random.dynamicBody<D>();
    const AngVec<D> w = body.angularVelocity;
    const Vec<D> pBody = random.vector<D>(-1.0, 1.0);  // a material point, body frame
    // World position of the material point while the body moves freely:
    // x_p(t) = x + v t + R(t) p, with R(t) turning at the constant w.
    auto worldPoint = [&](double t) -> Vec<D> {
      return body.position + t * body.velocity + rotatedBy<D>(body.orientation, w, t) * pBody;
    };
    const Vec<D> r = body.orientation * pBody;  // offset from the centre of mass at t = 0
    const Vec<D> derivative = (worldPoint(h) - worldPoint(-h)) / (2.0 * h);
    // The central difference of a circular motion is exact up to the factor
    // sin(|w| h)/(|w| h) on the rotational part, so its truncation error is at most
    // (|w| h)^2 / 6 |w x r|; rounding adds about eps |x_p| / h.
    const Vec<D> spin = crossAngular<D>(w, r);
    const double truncation = std::pow(w.norm() * h, 2) / 6.0 * spin.norm();
    const double rounding = 8.0 * kEps * (body.position.norm() + r.norm() + 1.0) / h;
    const double tolerance = truncation + rounding;
    CHECK((body.pointVelocity(r) - derivative).norm() <= tolerance);  // Eq. (1.6)
    // The notes' printed formula, v + w x v, misses by far more than the tolerance.
    const Vec<D> erratum = body.velocity + crossAngular<D>(w, body.velocity);
    CHECK((erratum - derivative).norm() > 1e3 * tolerance);
  }
}
// [test_point_velocity]

}  // TEST_SUITE
