// Chapter 11 (round bodies): with the exact deepest-point query a sphere or disk launched
// sliding on a level floor slips, spins up and rolls as the closed forms say, with no hop
// and no loss of speed once it rolls; the fixed surface samples do not.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/stepping/gbf_step.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;

namespace {

constexpr double kG = 9.81;

/// A ball (disk in 2D) of radius 0.25 m and 1 kg on a static floor 40 m long whose top face
/// is z = 0 (y = 0 in 2D), launched along the first axis at v0 with no spin, friction mu for
/// both. The floor's samples are its corners only, far from the ball's path.
template <int D>
struct SlideScene {
  World<D> world;
  double radius = 0.25;
  RigidBody<D>& ball() { return world.bodies[1]; }
};

template <int D>
SlideScene<D> makeSlide(double v0, double mu) {
  SlideScene<D> s;
  s.world.gravity = Vec<D>::Zero();
  s.world.gravity[D - 1] = -kG;
  const Material m{0.0, mu, 0.0};
  Vec<D> size = Vec<D>::Constant(40.0);
  size[D - 1] = 1.0;
  SampleMeshSettings corners;
  corners.boxSubdivisions = 1;
  Vec<D> below = Vec<D>::Zero();
  below[D - 1] = -0.5;
  s.world.addBody(makeStaticBody<D>(below),
                  std::make_shared<BoxShape<D>>(makeBoxShape<D>(size, corners)), m);
  const double k = D == 3 ? 0.4 : 0.5;
  RigidBody<D> b = makeDynamicBody<D>(1.0, AngVec<D>::Constant(k * s.radius * s.radius));
  b.position = Vec<D>::Zero();
  b.position[0] = -15.0;
  if constexpr (D == 3) b.position[1] = 2.5;
  b.position[D - 1] = s.radius;
  b.velocity = Vec<D>::Zero();
  b.velocity[0] = v0;
  s.world.addBody(b, std::make_shared<SphereShape<D>>(makeSphereShape<D>(s.radius)), m);
  return s;
}

/// Slip speed u = v + omega x r at the lowest point, along the first axis.
template <int D>
double slip(const RigidBody<D>& b, double r) {
  Vec<D> down = Vec<D>::Zero();
  down[D - 1] = -r;
  return b.pointVelocity(down)[0];
}

struct Roll {
  double slipEnd = -1.0;       ///< first time the slip speed is below 1e-6 v0
  double speedAtEnd = 0.0;     ///< speed when slipping ends
  double minRolling = 1e300;   ///< smallest and largest speed while rolling
  double maxRolling = 0.0;
  double maxVertical = 0.0;    ///< largest |vertical speed| while rolling
  double maxVerticalAll = 0.0; ///< largest |vertical speed| over the whole run
};

template <int D>
Roll slideThenRoll(double v0, double mu, double dt, double seconds, SurfaceQuery query) {
  SlideScene<D> s = makeSlide<D>(v0, mu);
  StepSettings settings;
  settings.dt = dt;
  settings.detection.narrow.surfaceQuery = query;
  Roll out;
  const long n = std::lround(seconds / dt);
  for (long k = 1; k <= n; ++k) {
    gbfStep<D>(s.world, settings);
    const RigidBody<D>& b = s.ball();
    const double vz = std::abs(b.velocity[D - 1]);
    out.maxVerticalAll = std::max(out.maxVerticalAll, vz);
    if (out.slipEnd < 0.0) {
      if (std::abs(slip<D>(b, s.radius)) < 1e-6 * v0) {
        out.slipEnd = static_cast<double>(k) * dt;
        out.speedAtEnd = b.velocity[0];
      }
      continue;
    }
    out.minRolling = std::min(out.minRolling, b.velocity[0]);
    out.maxRolling = std::max(out.maxRolling, b.velocity[0]);
    out.maxVertical = std::max(out.maxVertical, vz);
  }
  return out;
}

template <int D>
void checkClosedForm(const Roll& r, double v0, double mu) {
  // Sliding: v = v0 - mu g t, omega r = mu g t / k (k = I / (m r^2)); they meet at
  // t* = k v0 / ((1 + k) mu g) with speed v0 / (1 + k): 5 v0 / 7 and 2 v0 / (7 mu g) for a
  // sphere, 2 v0 / 3 and v0 / (3 mu g) for a disk.
  const double tEnd = D == 3 ? 2.0 * v0 / (7.0 * mu * kG) : v0 / (3.0 * mu * kG);
  const double vEnd = D == 3 ? 5.0 * v0 / 7.0 : 2.0 * v0 / 3.0;
  MESSAGE(D, "D: slip ends at ", r.slipEnd, " s (closed form ", tEnd, "), speed ", r.speedAtEnd,
          " (", vEnd, "), rolling speed in [", r.minRolling, ", ", r.maxRolling,
          "], largest vertical speed while rolling ", r.maxVertical);
  REQUIRE(r.slipEnd > 0.0);
  CHECK(r.slipEnd == doctest::Approx(tEnd).epsilon(0.005));
  CHECK(r.speedAtEnd == doctest::Approx(vEnd).epsilon(0.005));
  CHECK(r.maxVertical < 1e-3);
  CHECK(r.minRolling >= (1.0 - 1e-3) * r.speedAtEnd);
  CHECK(r.maxRolling <= (1.0 + 1e-3) * r.speedAtEnd);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_slide_then_roll]
TEST_CASE_TEMPLATE("deepest-point query: a ball launched sliding at 5 m/s with mu = 0.2 rolls "
                   "off at the closed-form time and speed and without hopping",
                   T, stackbook::testing::In2D, stackbook::testing::In3D) {
  constexpr int D = T::value;
  const double v0 = 5.0, mu = 0.2;
  const Roll r = slideThenRoll<D>(v0, mu, 1e-3, 2.0, SurfaceQuery::DeepestPoint);
  checkClosedForm<D>(r, v0, mu);
}
// [test_slide_then_roll]

TEST_CASE_TEMPLATE("fixed samples: the same ball hops and ends slower (the test above can fail)",
                   T, stackbook::testing::In2D, stackbook::testing::In3D) {
  constexpr int D = T::value;
  const double v0 = 5.0, mu = 0.2;
  const Roll r = slideThenRoll<D>(v0, mu, 1e-3, 2.0, SurfaceQuery::Samples);
  MESSAGE(D, "D samples: largest vertical speed ", r.maxVerticalAll, ", slip end ", r.slipEnd);
  CHECK(r.maxVerticalAll > 1e-2);
}

TEST_CASE_TEMPLATE("deepest-point query of each convex primitive against a flat face is its "
                   "lowest point",
                   T, stackbook::testing::In2D, stackbook::testing::In3D) {
  constexpr int D = T::value;
  // A floor (a big box) in its own frame; each shape turned and placed above it.
  const BoxShape<D> ground = makeBoxShape<D>(Vec<D>::Constant(100.0));
  Mat<D> M = Mat<D>::Identity();
  if constexpr (D == 3) {
    M = Eigen::AngleAxisd(0.3, Vec3(1.0, 0.5, 0.2).normalized()).toRotationMatrix();
  } else {
    M = Eigen::Rotation2Dd(0.3).toRotationMatrix();
  }
  Vec<D> t = Vec<D>::Zero();
  t[D - 1] = 50.5;  // 0.5 m above the floor's top face at 50
  const auto check = [&](const Shape<D>& shape) {
    CAPTURE(shape.describe());
    Vec<D> p = Vec<D>::Zero();
    REQUIRE(shape.deepestPoint(ground, M, t, p));
    CHECK(std::abs(shape.signedDistance(p)) < 1e-12);
    // No sample is lower than the deepest point.
    const double lowest = (M * p + t)[D - 1];
    for (const Vec<D>& s : shape.surfaceSamples()) CHECK((M * s + t)[D - 1] >= lowest - 1e-12);
  };
  check(makeSphereShape<D>(0.3));
  check(makeBoxShape<D>(Vec<D>::Constant(0.4)));
  check(makeCapsuleShape<D>(0.2, 0.1));
  check(makeCylinderShape<D>(0.2, 0.15));
  CHECK(makeSphereShape<D>(0.3).deepestPointIsWholeContact());
  CHECK_FALSE(makeBoxShape<D>(Vec<D>::Constant(0.4)).deepestPointIsWholeContact());
  Vec<D> p = Vec<D>::Zero();
  CHECK_FALSE(makeTorusShape<D>(0.3, 0.1).deepestPoint(ground, M, t, p));
}

}  // TEST_SUITE
