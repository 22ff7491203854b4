// Chapter 5 exercises: suite ch05_exercises, skipped by default. The exercises preset builds
// them into build/exercises/tests/ch05/test_ch05_exercises. It registers one CTest entry per
// exercise, ex05.1 to ex05.3, with the labels exercise and ch05. Run all of them, or one, with
//   ctest --preset exercises -L ch05
//   ctest --preset exercises -R ex05.1
// An entry runs its tests once its stub has no "// TODO(reader)" comment left. The binary
// runs them at any time:
//   build/exercises/tests/ch05/test_ch05_exercises --no-skip -ts=ch05_exercises -tc="Exercise 5.1*"
// The main build runs them against the reference solutions: ctest --preset solutions -L ch05
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "stackbook/body/torque_free.hpp"
#include "stackbook/exercises/ex05_1_gyroscopic_correction.hpp"
#include "stackbook/exercises/ex05_2_compound_body.hpp"
#include "stackbook/exercises/ex05_3_solid_of_revolution.hpp"
#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;
namespace ex = stackbook::exercises;

namespace {

RigidBody<3> spinningBody(const Vec3& moments, const Vec3& omegaBody) {
  RigidBody<3> body = makeDynamicBody<3>(1.0, moments);
  body.setAngularVelocity(omegaBody);
  return body;
}

/// Concatenate closed meshes into one (still closed) mesh.
TriangleMesh merged(const std::vector<TriangleMesh>& meshes) {
  TriangleMesh all;
  for (const TriangleMesh& mesh : meshes) {
    const int offset = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    for (const auto& f : mesh.faces) all.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  }
  return all;
}

/// The product moment of a counterclockwise polygon, the integral of x y over its area, by
/// Eq. (5.21): the (0, 1) entry of the triangles' second moments with the apex at the origin.
double productMoment(const std::vector<Vec2>& loop) {
  double sum = 0.0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec2& a = loop[k];
    const Vec2& b = loop[(k + 1) % loop.size()];
    const Vec2 s = a + b;
    const double area = 0.5 * (a.x() * b.y() - a.y() * b.x());
    sum += area / 12.0 * (a.x() * a.y() + b.x() * b.y() + s.x() * s.y());
  }
  return sum;
}

template <int D>
SurfaceMesh<D> placed(SurfaceMesh<D> mesh, const Pose<D>& pose) {
  for (Vec<D>& p : mesh.vertices) p = pose.toWorld(p);
  return mesh;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER "_exercises" * doctest::skip()) {

// ---------------------------------------------------------------------------------------
// Exercise 5.1: the gyroscopic correction.

TEST_CASE("Exercise 5.1: one corrected step turns by exp(dt w) with the midpoint angular velocity") {
  RandomSource random(900);
  for (int trial = 0; trial < 50; ++trial) {
    CAPTURE(trial);
    RigidBody<3> body = random.dynamicBody<3>();
    const RigidBody<3> before = body;
    const double dt = 0.05;
    ex::advancePositionGyroscopic<3>(body, dt);
    const Vec3 w = before.angularVelocity -
                   0.5 * dt * before.inverseInertiaWorld() * before.angularVelocity.cross(before.angularMomentum);
    const Mat3 expected = (Eigen::AngleAxisd(dt * w.norm(), w.normalized()) * before.orientation).toRotationMatrix();
    CHECK_EIGEN_NEAR(body.orientation.toRotationMatrix(), expected, 1e-13, 1e-14);
    CHECK_EIGEN_NEAR(body.position, Vec3(before.position + dt * before.velocity), 1e-15);
    CHECK(body.angularMomentum == before.angularMomentum);
    CHECK_EIGEN_NEAR(body.angularVelocity, Vec3(body.inverseInertiaWorld() * body.angularMomentum), 1e-12);
  }
  // In the plane omega x L = 0: the corrected update is the chapter's.
  RigidBody<2> disk = random.dynamicBody<2>();
  RigidBody<2> plain = disk;
  ex::advancePositionGyroscopic<2>(disk, 0.05);
  advancePosition<2>(plain, 0.05);
  CHECK(disk.orientation.angle() == plain.orientation.angle());
}

TEST_CASE("Exercise 5.1: the symmetric top's energy error becomes 1e-8 J and falls at least fourfold per halving") {
  const auto drift = [](double dt) {
    RigidBody<3> top = spinningBody(Vec3(0.04, 0.04, 0.02), Vec3(1.0, 0.0, 10.0));
    const double E0 = top.kineticEnergy();
    const Vec3 L0 = top.angularMomentum;
    const int n = static_cast<int>(std::lround(10.0 / dt));
    for (int step = 0; step < n; ++step) ex::advanceFreeBodyGyroscopic<3>(top, dt);
    CHECK(top.angularMomentum == L0);
    return std::abs(top.kineticEnergy() - E0);
  };
  const double coarse = drift(1e-3), fine = drift(5e-4);
  // The chapter's update gains 4.4e-3 J here (Eq. (5.14)); the correction cancels that term.
  CHECK(coarse < 1e-6);
  CHECK(coarse / fine > 3.5);
}

TEST_CASE("Exercise 5.1: the intermediate-axis flip period converges at second order") {
  const Vec3 I = Vec3(0.13, 0.10, 0.05) / 12.0;  // the box 0.1 x 0.2 x 0.3 of 1 kg
  const Vec3 omega0(0.3, 1.0, 0.3);
  const TorqueFreeInvariants inv = torqueFreeInvariants(I, omega0);
  const double T = polhodePeriod(I, inv.energy, inv.momentumSquared).period;
  const auto periodError = [&](double dt) {
    RigidBody<3> box = spinningBody(I, omega0);
    std::vector<double> flips;
    double previous = omega0.y();
    const int n = static_cast<int>(1.25 * T / dt);
    for (int k = 1; k <= n; ++k) {
      ex::advanceFreeBodyGyroscopic<3>(box, dt);
      const double current = (box.orientation.inverse() * box.angularVelocity).y();
      if ((previous > 0.0) != (current > 0.0)) flips.push_back((k - 1 + previous / (previous - current)) * dt);
      previous = current;
    }
    REQUIRE(flips.size() >= 3);
    return (flips[2] - flips[0]) / T - 1.0;
  };
  const double coarse = periodError(4e-3), fine = periodError(2e-3);
  CHECK(std::abs(fine) < 1e-5);  // the chapter's update is 5.7 % off at dt = 2e-3
  CHECK(coarse / fine == doctest::Approx(4.0).epsilon(0.15));
}

// ---------------------------------------------------------------------------------------
// Exercise 5.2: compound bodies.

TEST_CASE("Exercise 5.2: two placed boxes combine to the mass properties of their merged mesh") {
  RandomSource random(920);
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    const Vec3 sizeA = random.vector<3>(0.2, 1.0), sizeB = random.vector<3>(0.2, 1.0);
    // Far enough apart not to overlap, each turned arbitrarily.
    const Pose<3> poseA{Vec3(-2.0, 0.0, 0.0) + random.vector<3>(-0.3, 0.3), random.orientation<3>()};
    const Pose<3> poseB{Vec3(2.0, 0.5, 0.0) + random.vector<3>(-0.3, 0.3), random.orientation<3>()};
    const TriangleMesh a = boxMesh(sizeA), b = boxMesh(sizeB);
    const std::vector<ex::CompoundPart<3>> parts = {{computeMassProperties<3>(a, 3.0), poseA},
                                                    {computeMassProperties<3>(b, 3.0), poseB}};
    const MassProperties<3> combined = ex::combineMassProperties<3>(parts);
    const MassProperties<3> direct =
        computeMassProperties<3>(merged({placed<3>(a, poseA), placed<3>(b, poseB)}), 3.0);
    CHECK(combined.mass == doctest::Approx(direct.mass).epsilon(1e-12));
    CHECK(combined.measure == doctest::Approx(direct.measure).epsilon(1e-12));
    CHECK_EIGEN_NEAR(combined.centerOfMass, direct.centerOfMass, 1e-12);
    CHECK_EIGEN_NEAR(combined.inertia, direct.inertia, 1e-12);
  }
}

TEST_CASE("Exercise 5.2: the L-shaped polygon is the sum of its two rectangles") {
  const Polygon L = polygonFromLoop({Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)});
  const MassProperties<2> direct = computeMassProperties<2>(L, 2.0);
  // Rectangles centred at the origin, placed at their centres; the upper one turned by 90 degrees.
  const std::vector<ex::CompoundPart<2>> parts = {
      {computeMassProperties<2>(rectanglePolygon(Vec2(2, 1)), 2.0), Pose<2>{Vec2(1.0, 0.5), Eigen::Rotation2Dd(0.0)}},
      {computeMassProperties<2>(rectanglePolygon(Vec2(2, 1)), 2.0),
       Pose<2>{Vec2(0.5, 2.0), Eigen::Rotation2Dd(0.5 * M_PI)}}};
  const MassProperties<2> combined = ex::combineMassProperties<2>(parts);
  CHECK(combined.mass == doctest::Approx(direct.mass).epsilon(1e-14));
  CHECK_EIGEN_NEAR(combined.centerOfMass, direct.centerOfMass, 1e-14);
  CHECK(combined.inertia(0, 0) == doctest::Approx(direct.inertia(0, 0)).epsilon(1e-14));
  CHECK_THROWS_AS(ex::combineMassProperties<2>({}), std::invalid_argument);
}

TEST_CASE("Exercise 5.2: a dumbbell has the textbook transverse moment") {
  // Two balls of radius r whose centres are 2a apart, as icospheres; no bar.
  const double r = 0.1, a = 0.5;
  const MassProperties<3> ball = computeMassProperties<3>(icosphereMesh(r, 4));
  const std::vector<ex::CompoundPart<3>> parts = {{ball, Pose<3>{Vec3(-a, 0, 0), Eigen::Quaterniond::Identity()}},
                                                  {ball, Pose<3>{Vec3(a, 0, 0), Eigen::Quaterniond::Identity()}}};
  const MassProperties<3> dumbbell = ex::combineMassProperties<3>(parts);
  const double m = 2.0 * ball.mass;
  // Each ball: its own moment plus (m/2) a^2 about the y and z axes, nothing extra about x.
  CHECK(dumbbell.inertia(0, 0) == doctest::Approx(2.0 * ball.inertia(0, 0)).epsilon(1e-12));
  CHECK(dumbbell.inertia(1, 1) == doctest::Approx(2.0 * ball.inertia(1, 1) + m * a * a).epsilon(1e-12));
  CHECK_EIGEN_NEAR(dumbbell.centerOfMass, Vec3::Zero(), 0.0, 1e-15);
}

// ---------------------------------------------------------------------------------------
// Exercise 5.3: solids of revolution.

TEST_CASE("Exercise 5.3: a revolved regular polygon is the torus mesh") {
  const double R = 1.0, rho = 0.3;
  const int N = 24, M = 12;
  std::vector<Vec2> circle;
  for (int k = 0; k < M; ++k) {
    const double v = 2.0 * M_PI * k / M;
    circle.push_back(Vec2(R + rho * std::cos(v), rho * std::sin(v)));
  }
  const TriangleMesh revolved = ex::revolveProfile(circle, N);
  const TriangleMesh torus = torusMesh(R, rho, N, M);
  REQUIRE(revolved.vertices.size() == torus.vertices.size());
  const MassProperties<3> a = computeMassProperties<3>(revolved), b = computeMassProperties<3>(torus);
  CHECK(a.measure == doctest::Approx(b.measure).epsilon(1e-12));
  CHECK_EIGEN_NEAR(a.inertia, b.inertia, 1e-12);
}

TEST_CASE("Exercise 5.3: the revolved volume obeys Pappus with the polygon factor") {
  // A trapezoid and an L-shaped profile in (r, z), counterclockwise.
  const std::vector<std::vector<Vec2>> profiles = {
      {Vec2(0.5, 0.0), Vec2(1.5, 0.0), Vec2(1.0, 1.0), Vec2(0.5, 1.0)},
      {Vec2(0.2, 0.0), Vec2(1.0, 0.0), Vec2(1.0, 0.3), Vec2(0.5, 0.3), Vec2(0.5, 2.0), Vec2(0.2, 2.0)}};
  for (const std::vector<Vec2>& profile : profiles) {
    const MassProperties<2> section = computeMassProperties<2>(polygonFromLoop(profile));
    double previous = 0.0;
    for (int N = 8; N <= 128; N *= 2) {
      CAPTURE(N);
      const MassProperties<3> solid = computeMassProperties<3>(ex::revolveProfile(profile, N));
      // Every slice z = const is an N-gon annulus: N sin(2 pi/N)/(2 pi) of the round one.
      const double factor = N * std::sin(2.0 * M_PI / N) / (2.0 * M_PI);
      const double pappus = 2.0 * M_PI * section.centerOfMass.x() * section.measure;
      CHECK(solid.measure == doctest::Approx(factor * pappus).epsilon(1e-12));
      // Every slice is scaled by the same factor, so the height of the centroid is that of the
      // round solid: the integral of r z over the profile divided by that of r.
      const double height = productMoment(profile) / (section.centerOfMass.x() * section.measure);
      CHECK(solid.centerOfMass.z() == doctest::Approx(height).epsilon(1e-12));
      const double error = 1.0 - solid.measure / pappus;
      if (previous > 0.0) CHECK(previous / error == doctest::Approx(4.0).epsilon(0.02));
      previous = error;
    }
  }
}

TEST_CASE("Exercise 5.3: profiles on the axis or clockwise are rejected") {
  CHECK_THROWS_AS(ex::revolveProfile({Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(1.0, 1.0)}, 8), std::invalid_argument);
  CHECK_THROWS_AS(ex::revolveProfile({Vec2(1.0, 0.0), Vec2(1.0, 1.0), Vec2(2.0, 0.0)}, 8), std::invalid_argument);
  CHECK_THROWS_AS(ex::revolveProfile({Vec2(1.0, 0.0), Vec2(2.0, 0.0), Vec2(2.0, 1.0)}, 2), std::invalid_argument);
}

}  // TEST_SUITE
