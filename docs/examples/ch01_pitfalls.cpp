// The measurements behind chapter 1's pitfalls. Output is HTML (see ch01_html.hpp), shown
// on the page with \htmlinclude ch01_pitfalls.out. Each section states what it measures.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "ch01_html.hpp"
#include "stackbook/impulse/collision_matrix.hpp"

using namespace stackbook;
using ch01_html::num;
using ch01_html::paragraph;
using ch01_html::tuple;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

/// Spectral condition number of a symmetric positive definite matrix.
double conditionNumber(const Mat3& K) {
  const Vec3 lambda = Eigen::SelfAdjointEigenSolver<Mat3>(K).eigenvalues();
  return lambda[2] / lambda[0];
}

/// Principal moments of a solid box of mass m with the given side lengths.
Vec3 boxMoments(double m, const Vec3& sides) {
  const Vec3 s2 = sides.cwiseProduct(sides);
  return m / 12.0 * Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
}

void erratum() {
  // A disk of radius 0.5 rolling to the right at 1 m/s without slipping: w = -v/radius.
  const double radius = 0.5;
  RigidBody<2> wheel = makeDynamicBody<2>(1.0, AngVec<2>(0.5 * radius * radius));
  wheel.position = Vec2(0.0, radius);
  wheel.velocity = Vec2(1.0, 0.0);
  wheel.setAngularVelocity(AngVec<2>(-wheel.velocity.x() / radius));
  const Vec2 r(0.0, -radius);  // the point touching the ground
  const Vec2 right = wheel.pointVelocity(r);
  const Vec2 wrong = wheel.velocity + crossAngular<2>(wheel.angularVelocity, wheel.velocity);
  std::cout << paragraph(
      "**The erratum, measured.** A disk of radius " + num(radius) +
      " rolls without slipping at \\f$\\vv = " + tuple(wheel.velocity) + "\\f$, \\f$\\omega = " +
      num(wheel.angularVelocity[0]) + "\\f$. At its contact point, \\f$\\rv = " + tuple(r) +
      "\\f$, Eq. (1.6) gives \\f$\\vv + \\wv\\times\\rv = " + tuple(right, 1e-15) +
      "\\f$: the point in contact is at rest, as rolling means. The misprint "
      "\\f$\\vv + \\wv\\times\\vv = " + tuple(wrong) + "\\f$ gives it a speed of " +
      num(wrong.norm(), 3) + " m/s, more than the wheel's own " + num(wheel.velocity.norm()) +
      " m/s.");
}

void bodyFrameInertia() {
  // A 2 x 1 x 0.5 plank of mass 3, turned 30 degrees about z and 20 about x, touched at a corner.
  const Vec3 sides(2.0, 1.0, 0.5);
  RigidBody<3> plank = makeDynamicBody<3>(3.0, boxMoments(3.0, sides));
  plank.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 6.0, Vec3::UnitZ()) *
                                         Eigen::AngleAxisd(M_PI / 9.0, Vec3::UnitX()));
  const Vec3 r = plank.orientation * Vec3(0.5 * sides);
  const Mat3 right = collisionMatrix<3>(plank, r);
  const Mat3 wrong =
      collisionMatrix<3>(plank.inverseMass, Mat3(plank.inverseInertia.asDiagonal()), r);
  const double error =
      (wrong - right).cwiseAbs().maxCoeff() / right.cwiseAbs().maxCoeff() * 100.0;
  std::cout << paragraph(
      "**Body-frame inertia used as world-frame.** A \\f$2\\times1\\times0.5\\f$ plank of mass 3, "
      "turned 30 degrees about \\f$z\\f$ and 20 about \\f$x\\f$, is touched at a corner. Using "
      "\\f$\\mathbf{I}_{body}^{-1}\\f$ in place of "
      "\\f$\\mathbf{R}\\mathbf{I}_{body}^{-1}\\mathbf{R}^T\\f$ puts an error of " +
      num(error, 2) +
      " % of the largest entry into \\f$\\Kmat\\f$. The error vanishes for an isotropic body and "
      "for an unrotated one, which is why tests with a cube or an unrotated body cannot catch it.");
}

void invertingWorldTensor() {
  std::cout << paragraph(
      "**Inverting the world-frame tensor.** Take the principal moments "
      "\\f$(1, 1, 1/\\rho)\\f$ (a needle, for large \\f$\\rho\\f$), turned by a fixed rotation "
      "\\f$\\mathbf{R}\\f$. Compare \\f$(\\mathbf{R}\\mathbf{I}_{body}\\mathbf{R}^T)^{-1}\\f$, "
      "computed by LU, and Eq. (1.7), each against "
      "\\f$\\mathbf{R}\\mathbf{I}_{body}^{-1}\\mathbf{R}^T\\f$ evaluated in long double from the "
      "same \\f$\\mathbf{R}\\f$. The error, relative to the largest entry:");
  const Mat3 R = Eigen::Quaterniond(0.8, 0.3, -0.4, 0.33).normalized().toRotationMatrix();
  std::vector<std::vector<std::string>> rows;
  for (double rho : {1e2, 1e6, 1e10, 1e14}) {
    const Vec3 moments(1.0, 1.0, 1.0 / rho);
    RigidBody<3> needle;
    needle.inertia = moments;
    needle.inverseInertia = moments.cwiseInverse();
    needle.orientation = Eigen::Quaterniond(R);
    const Mat3 built = needle.inverseInertiaWorld();
    const Mat3 world = R * moments.asDiagonal() * R.transpose();
    const Mat3 inverted = world.inverse();
    const Eigen::Matrix<long double, 3, 3> Rl = R.cast<long double>();
    const Eigen::Matrix<long double, 3, 1> inverseMoments =
        moments.cast<long double>().cwiseInverse();
    const Eigen::Matrix<long double, 3, 3> exact = Rl * inverseMoments.asDiagonal() * Rl.transpose();
    const long double scale = exact.cwiseAbs().maxCoeff();
    auto relativeError = [&](const Mat3& candidate) {
      return static_cast<double>((candidate.cast<long double>() - exact).cwiseAbs().maxCoeff() /
                                 scale);
    };
    rows.push_back({num(rho, 3), num(relativeError(inverted), 2), num(relativeError(built), 2)});
  }
  std::cout << ch01_html::table(
      {"ratio \\f$\\rho\\f$", "inverting the world tensor", "Eq. (1.7)"}, rows);
  std::cout << paragraph(
      "The inverted tensor loses up to about \\f$\\rho\\,\\epsilon\\f$, with the machine "
      "epsilon \\f$\\epsilon\\f$ = " + num(kEps, 3) + ". Eq. (1.7) stays at rounding level whatever the ratio, and with a locked axis "
      "(\\f$1/I_k = 0\\f$) there is no finite world tensor to invert at all.");
}

void asymmetry() {
  std::mt19937_64 engine(2003);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  int asymmetric = 0;
  const int trials = 100000;
  for (int t = 0; t < trials; ++t) {
    const double m = std::exp(2.0 * u(engine));
    const Vec3 sides(1.1 + u(engine), 1.1 + u(engine), 1.1 + u(engine));
    RigidBody<3> body = makeDynamicBody<3>(m, boxMoments(m, sides));
    body.orientation = Eigen::Quaterniond(u(engine), u(engine), u(engine), u(engine)).normalized();
    const Vec3 r(u(engine), u(engine), u(engine));
    const Mat3 K = collisionMatrix<3>(body, r);
    const double a = (K - K.transpose()).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
    worst = std::max(worst, a);
    if (a > 0.0) ++asymmetric;
  }
  std::cout << paragraph(
      "**Symmetry holds only up to rounding.** Over " + std::to_string(trials) +
      " random boxes, orientations and contact points, " + num(100.0 * asymmetric / trials, 3) +
      " % of the assembled \\f$\\Kmat = \\Id/m + \\rstar^T\\Iinv\\rstar\\f$ were not exactly "
      "symmetric, and the largest \\f$\\max_{ik}\\lvert K_{ik} - K_{ki}\\rvert / "
      "\\max_{ik}\\lvert K_{ik}\\rvert\\f$ was " + num(worst / kEps, 2) +
      "\\f$\\,\\epsilon\\f$. `pairCollisionMatrix` returns \\f$(\\KT + \\KT^T)/2\\f$, which is "
      "exactly symmetric, so which triangle a factorisation reads cannot change the result.");
}

void conditioning() {
  std::cout << paragraph(
      "**How ill-conditioned \\f$\\Kmat\\f$ gets.** The condition number "
      "\\f$\\kappa = \\lambda_{max}/\\lambda_{min}\\f$ of one body's \\f$\\Kmat\\f$, for bodies "
      "of mass 1, against the bound \\f$1 + m\\lVert\\rv\\rVert^2/I_{min}\\f$:");
  struct Case {
    std::string body;
    std::string contact;
    Vec3 moments;
    Vec3 r;
  };
  const std::vector<Case> cases = {
      {"unit cube", "centre of a face", boxMoments(1.0, Vec3(1, 1, 1)), Vec3(0, 0, -0.5)},
      {"unit cube", "corner", boxMoments(1.0, Vec3(1, 1, 1)), Vec3(0.5, 0.5, -0.5)},
      {"plank 2 x 1 x 0.1", "corner", boxMoments(1.0, Vec3(2, 1, 0.1)), Vec3(1, 0.5, -0.05)},
      {"rod 1 x 0.02 x 0.02", "corner of an end", boxMoments(1.0, Vec3(1, 0.02, 0.02)),
       Vec3(0.5, 0.01, 0.01)},
      {"unit cube with its moments entered as 1e-4 (instead of 1/6)", "corner",
       Vec3(1e-4, 1e-4, 1e-4), Vec3(0.5, 0.5, -0.5)},
  };
  std::vector<std::vector<std::string>> rows;
  for (const Case& c : cases) {
    const Mat3 K = collisionMatrix<3>(1.0, Mat3(c.moments.cwiseInverse().asDiagonal()), c.r);
    const double bound = 1.0 + c.r.squaredNorm() / c.moments.minCoeff();
    rows.push_back({c.body, c.contact, num(conditionNumber(K), 3), num(bound, 3)});
  }
  std::cout << ch01_html::table({"body", "contact", "\\f$\\kappa\\f$", "bound"}, rows);
  std::cout << paragraph(
      "Consistent inertias keep \\f$\\kappa\\f$ modest, even for a thin rod. The bound is "
      "pessimistic there: the angular impulse \\f$\\rstar\\jv = \\rv\\times\\jv\\f$ is "
      "perpendicular to \\f$\\rv\\f$, so the rod's tiny moment about its own axis, nearly "
      "along \\f$\\rv\\f$, hardly enters. Large condition numbers come from inertias that do "
      "not match the geometry, as in the last row.");
}

}  // namespace

int main() {
  erratum();
  bodyFrameInertia();
  invertingWorldTensor();
  asymmetry();
  conditioning();
}
