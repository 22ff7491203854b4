// Chapter 11 (the rotation knob, derived in chapter 5): the implicit midpoint rule on the
// body-frame angular momentum keeps a tumbling box's energy, flips it with the period of
// Landau and Lifshitz section 37, keeps the two stable spins stable, and leaves L and the
// old exponential map exactly as they were.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "stackbook/body/integrate.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/stepping/gbf_step.hpp"

using namespace stackbook;

namespace {

/// The tumbling box: half-extents (0.1, 0.2, 0.3) m, 1 kg, moments m (b^2 + c^2) / 3 with
/// b, c the other two half-extents; the intermediate moment belongs to the y axis.
Vec3 boxMoments() {
  const Vec3 h(0.1, 0.2, 0.3);
  return Vec3(h.y() * h.y() + h.z() * h.z(), h.x() * h.x() + h.z() * h.z(),
              h.x() * h.x() + h.y() * h.y()) / 3.0;
}

RigidBody<3> spinningBox(const Vec3& omegaBody) {
  RigidBody<3> box = makeDynamicBody<3>(1.0, boxMoments());
  box.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3(1.0, 2.0, -1.0).normalized()));
  box.setAngularVelocity(box.orientation * omegaBody);
  return box;
}

Vec3 bodyRate(const RigidBody<3>& b) { return b.orientation.conjugate() * b.angularVelocity; }

/// K(k) by the arithmetic-geometric mean, K = pi / (2 AGM(1, sqrt(1 - k^2))): written here so
/// that the test does not share the library's std::comp_ellint_1 call.
double ellipticK(double k) {
  double a = 1.0, g = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 40; ++i) {
    const double an = 0.5 * (a + g);
    g = std::sqrt(a * g);
    a = an;
  }
  return M_PI / (2.0 * a);
}

/// Landau-Lifshitz section 37, Eq. (37.10) and its modulus: the period of omega for moments
/// I1 < I2 < I3 (here sorted from the box: z, y, x), energy E and L^2, on the side
/// L^2 > 2 E I2 where omega circles the axis of I3.
double landauPeriod(const Vec3& omegaBody) {
  const Vec3 I = boxMoments();
  const double I1 = I.z(), I2 = I.y(), I3 = I.x();
  const double E = 0.5 * omegaBody.dot(I.cwiseProduct(omegaBody));
  const double L2 = I.cwiseProduct(omegaBody).squaredNorm();
  REQUIRE(L2 > 2.0 * E * I2);
  const double lambda = std::sqrt((I3 - I2) * (L2 - 2.0 * E * I1) / (I1 * I2 * I3));
  const double k2 = (I2 - I1) * (2.0 * E * I3 - L2) / ((I3 - I2) * (L2 - 2.0 * E * I1));
  return 4.0 * ellipticK(std::sqrt(k2)) / lambda;
}

struct Tumble {
  std::vector<double> flips;  ///< times of the sign changes of the body y rate
  double largestEnergyError = 0.0;
  Vec3 largestRate = Vec3::Zero();  ///< max |component| of the body rate
  RigidBody<3> last;
};

Tumble tumble(const Vec3& omegaBody, double dt, double duration, RotationUpdate rule) {
  RigidBody<3> box = spinningBox(omegaBody);
  const double E0 = box.kineticEnergy();
  Tumble t;
  double previous = bodyRate(box).y();
  const long n = std::lround(duration / dt);
  for (long k = 1; k <= n; ++k) {
    advanceFreeBody<3>(box, dt, ExternalLoads<3>{}, rule);
    const Vec3 w = bodyRate(box);
    if ((previous > 0.0) != (w.y() > 0.0)) {
      t.flips.push_back((static_cast<double>(k - 1) + previous / (previous - w.y())) * dt);
    }
    previous = w.y();
    t.largestEnergyError = std::max(t.largestEnergyError, std::abs(box.kineticEnergy() / E0 - 1.0));
    t.largestRate = t.largestRate.cwiseMax(w.cwiseAbs());
  }
  t.last = box;
  return t;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_midpoint_flips]
TEST_CASE("implicit midpoint: a box spun near its intermediate axis flips with the Landau-Lifshitz "
          "period for 100 s at dt = 1e-3 and and keeps its energy within 1 %") {
  const Vec3 omega0(0.1, 10.0, 0.1);
  const double T = landauPeriod(omega0);
  const Tumble t = tumble(omega0, 1e-3, 100.0, RotationUpdate::ImplicitMidpoint);
  MESSAGE("period ", T, " s; flips ", t.flips.size(), "; energy error ", t.largestEnergyError);
  // The y rate is A sn(lambda t + c): one sign change every T/2.
  REQUIRE(static_cast<double>(t.flips.size()) >= std::floor(2.0 * 100.0 / T) - 1.0);
  CHECK(static_cast<double>(t.flips.size()) <= std::ceil(2.0 * 100.0 / T) + 1.0);
  double worst = 0.0;
  for (std::size_t i = 1; i < t.flips.size(); ++i) {
    worst = std::max(worst, std::abs((t.flips[i] - t.flips[i - 1]) / (0.5 * T) - 1.0));
  }
  MESSAGE("worst half period against T/2: ", worst);
  CHECK(worst < 0.02);
  // The last flip is where n half periods put it: the error does not accumulate.
  const double n = static_cast<double>(t.flips.size() - 1);
  CHECK(std::abs((t.flips.back() - t.flips.front()) / (n * 0.5 * T) - 1.0) < 0.02);
  CHECK(t.largestEnergyError < 0.01);
}
// [test_midpoint_flips]

TEST_CASE("the exponential map fails the same flip test: its energy gain speeds the flips up") {
  // The test above can fail: the old rule, on the same box and step, does.
  const Vec3 omega0(0.1, 10.0, 0.1);
  const double T = landauPeriod(omega0);
  const Tumble t = tumble(omega0, 1e-3, 100.0, RotationUpdate::ExponentialMap);
  REQUIRE(t.flips.size() >= 3);
  double worst = 0.0;
  for (std::size_t i = 1; i < t.flips.size(); ++i) {
    worst = std::max(worst, std::abs((t.flips[i] - t.flips[i - 1]) / (0.5 * T) - 1.0));
  }
  MESSAGE("exponential map: worst half period ", worst, ", energy error ", t.largestEnergyError);
  CHECK(worst > 0.02);
  CHECK(t.largestEnergyError > 0.01);
}

TEST_CASE("implicit midpoint: spins about the largest and the smallest axis stay near their axis") {
  const Vec3 I = boxMoments();
  for (const int axis : {0, 2}) {
    CAPTURE(axis);
    Vec3 omega0 = Vec3::Constant(0.1);
    omega0[axis] = 10.0;
    const Tumble t = tumble(omega0, 1e-3, 100.0, RotationUpdate::ImplicitMidpoint);
    // The exact motion bounds each off-axis rate: where the third rate is zero, E and L^2
    // fix the largest |omega_j|: omega_j^2 = (L^2 - 2 E I_a) / (I_j (I_j - I_a)), a the spin axis.
    const double E = 0.5 * omega0.dot(I.cwiseProduct(omega0));
    const double L2 = I.cwiseProduct(omega0).squaredNorm();
    for (int j = 0; j < 3; ++j) {
      if (j == axis) continue;
      const double bound = std::sqrt((L2 - 2.0 * E * I[axis]) / (I[j] * (I[j] - I[axis])));
      CAPTURE(j);
      CHECK(t.largestRate[j] <= 1.01 * bound);
    }
    CHECK(std::abs(bodyRate(t.last)[axis]) > 0.99 * omega0[axis]);
    CHECK(t.largestEnergyError < 1e-9);
  }
}

TEST_CASE("both rotation rules leave the world angular momentum untouched: the exponential map "
          "selected is the old update bit for bit") {
  const Vec3 omega0(0.3, 1.0, 0.3);
  for (const RotationUpdate rule : {RotationUpdate::ExponentialMap, RotationUpdate::ImplicitMidpoint}) {
    RigidBody<3> box = spinningBox(omega0);
    const Vec3 L0 = box.angularMomentum;
    for (int k = 0; k < 2000; ++k) advanceFreeBody<3>(box, 1e-3, ExternalLoads<3>{}, rule);
    CHECK(box.angularMomentum == L0);
    CHECK((box.orientation.conjugate() * box.angularMomentum).norm() ==
          doctest::Approx(L0.norm()).epsilon(1e-13));
  }
  RigidBody<3> a = spinningBox(omega0), b = a;
  a.velocity = b.velocity = Vec3(1.0, -2.0, 0.5);
  for (int k = 0; k < 500; ++k) {
    advancePosition<3>(a, 1e-3);
    advancePosition<3>(b, 1e-3, RotationUpdate::ExponentialMap);
    const Pose<3> p = predictPose<3>(a, 1e-3), q = predictPose<3>(b, 1e-3, RotationUpdate::ExponentialMap);
    REQUIRE(p.orientation.coeffs() == q.orientation.coeffs());
  }
  CHECK(a.orientation.coeffs() == b.orientation.coeffs());
  CHECK(a.position == b.position);
  CHECK(a.angularVelocity == b.angularVelocity);
}

TEST_CASE("implicit midpoint: predictPose gives the pose advancePosition reaches: in 2D both rules agree") {
  RigidBody<3> box = spinningBox(Vec3(0.1, 10.0, 0.1));
  box.velocity = Vec3(0.5, 0.0, -1.0);
  const Pose<3> predicted = predictPose<3>(box, 1e-3, RotationUpdate::ImplicitMidpoint);
  advancePosition<3>(box, 1e-3, RotationUpdate::ImplicitMidpoint);
  CHECK(predicted.position == box.position);
  CHECK(predicted.orientation.coeffs() == box.orientation.coeffs());

  RigidBody<2> disk = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.5));
  disk.setAngularVelocity(AngVec<2>::Constant(3.0));
  RigidBody<2> other = disk;
  for (int k = 0; k < 100; ++k) {
    advancePosition<2>(disk, 1e-2, RotationUpdate::ImplicitMidpoint);
    advancePosition<2>(other, 1e-2, RotationUpdate::ExponentialMap);
  }
  CHECK(disk.orientation.angle() == other.orientation.angle());
}

TEST_CASE("implicit midpoint is second order: halving dt quarters the flip-period error") {
  const Vec3 omega0(0.3, 1.0, 0.3);
  const double T = landauPeriod(omega0);
  std::vector<double> errors;
  for (const double dt : {0.04, 0.02}) {
    const Tumble t = tumble(omega0, dt, 2.2 * T, RotationUpdate::ImplicitMidpoint);
    REQUIRE(t.flips.size() >= 5);
    errors.push_back(std::abs((t.flips[4] - t.flips[0]) / (2.0 * T) - 1.0));
  }
  MESSAGE("period errors at dt = 0.04, 0.02: ", errors[0], ", ", errors[1]);
  CHECK(errors[0] / errors[1] == doctest::Approx(4.0).epsilon(0.1));
}

TEST_CASE("the step's rotation setting reaches the position update: a free tumbling box in a "
          "gbfStep world keeps its energy under the midpoint rule") {
  World<3> world;
  world.addBody(spinningBox(Vec3(0.1, 10.0, 0.1)), std::make_shared<BoxShape<3>>(makeBoxShape<3>(Vec3(0.2, 0.4, 0.6))));
  StepSettings settings;
  settings.rotation = RotationUpdate::ImplicitMidpoint;
  const double E0 = world.bodies[0].kineticEnergy();
  for (int k = 0; k < 20000; ++k) gbfStep<3>(world, settings);
  CHECK(world.bodies[0].kineticEnergy() == doctest::Approx(E0).epsilon(1e-9));
}

}  // TEST_SUITE
