// Chapter 5: mass properties of closed meshes by signed simplices (Eqs. (5.17)-(5.21)),
// against closed forms, hand decompositions and convergence rates; principal frames
// (Eq. (5.22)); and the rejection of bad meshes and bad inertias.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;

namespace {

/// A box (3D) or rectangle (2D) mesh with the given side lengths, each side split n ways.
template <int D>
SurfaceMesh<D> boxOf(const Vec<D>& size, int n = 1) {
  if constexpr (D == 2) {
    return rectanglePolygon(size, n);
  } else {
    return boxMesh(size, n);
  }
}

/// Closed-form inertia of a uniform box about its centre: m (b^2 + c^2)/12 etc. in 3D, the
/// polar moment m (a^2 + b^2)/12 in 2D.
template <int D>
AngMat<D> boxInertia(double m, const Vec<D>& s) {
  if constexpr (D == 2) {
    return AngMat<2>::Constant(m * s.squaredNorm() / 12.0);
  } else {
    return Vec3(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
                s.x() * s.x() + s.y() * s.y()).asDiagonal() * (m / 12.0);
  }
}

template <int D>
void moveMesh(SurfaceMesh<D>& mesh, const Pose<D>& pose) {
  for (Vec<D>& p : mesh.vertices) p = pose.toWorld(p);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_box_exact]
TEST_CASE_TEMPLATE("a box has the closed-form mass centre and inertia at any pose", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(800 + D);
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    const Vec<D> size = random.vector<D>(0.1, 3.0);
    const double density = random.logUniform(0.1, 1e4);
    SurfaceMesh<D> mesh = boxOf<D>(size, 1 + trial % 3);
    const Pose<D> pose{random.vector<D>(-5.0, 5.0), random.orientation<D>()};
    moveMesh<D>(mesh, pose);
    const MassProperties<D> p = computeMassProperties<D>(mesh, density);
    const double m = density * size.prod();
    CHECK(p.measure == doctest::Approx(size.prod()).epsilon(1e-12));
    CHECK(p.mass == doctest::Approx(m).epsilon(1e-12));
    CHECK_EIGEN_NEAR(p.centerOfMass, pose.position, 1e-12, 1e-12 * size.norm());
    // The tensor turns with the body: I = R I_box R^T.
    const AngMat<D> R = angularRotationMatrix<D>(pose.orientation);
    CHECK_EIGEN_NEAR(p.inertia, AngMat<D>(R * boxInertia<D>(m, size) * R.transpose()), 1e-12);
  }
}
// [test_box_exact]

// [test_icosphere_rate]
TEST_CASE("icosphere volume and inertia converge to the ball at second order") {
  const double r = 0.8, V = 4.0 / 3.0 * M_PI * r * r * r;
  std::vector<double> volumeError, inertiaError;
  for (int level = 1; level <= 4; ++level) {
    CAPTURE(level);
    const MassProperties<3> p = computeMassProperties<3>(icosphereMesh(r, level));
    // Icosahedral symmetry makes the inertia tensor isotropic at every level.
    CHECK_EIGEN_NEAR(p.inertia, Mat3(p.inertia(0, 0) * Mat3::Identity()), 1e-12);
    CHECK_EIGEN_NEAR(p.centerOfMass, Vec3::Zero(), 0.0, 1e-15);
    volumeError.push_back((V - p.measure) / V);                          // inscribed: from below
    inertiaError.push_back(0.4 - p.inertia(0, 0) / (p.mass * r * r));  // 2/5 m r^2
  }
  for (std::size_t k = 2; k < volumeError.size(); ++k) {
    CAPTURE(k);
    // Each level halves the edge length h; the error is O(h^2), so it falls by 4.
    CHECK(volumeError[k - 1] / volumeError[k] == doctest::Approx(4.0).epsilon(0.05));
    CHECK(inertiaError[k - 1] / inertiaError[k] == doctest::Approx(4.0).epsilon(0.05));
  }
  CHECK(volumeError.back() > 0.0);
  CHECK(volumeError.back() < 3e-3);
  CHECK(inertiaError.back() < 3e-3);
}
// [test_icosphere_rate]

// [test_torus_exact]
TEST_CASE("the torus mesh has the exact volume of its polygonal revolution") {
  const double R = 1.0, r = 0.3;
  for (const auto& sizes : {std::pair{8, 3}, std::pair{24, 12}, std::pair{101, 7}}) {
    const int N = sizes.first, M = sizes.second;  // not a structured binding: CAPTURE is a lambda
    CAPTURE(N);
    CAPTURE(M);
    const MassProperties<3> p = computeMassProperties<3>(torusMesh(R, r, N, M));
    // Pappus for the M-gon tube (area (M/2) r^2 sin(2 pi/M), centroid at R) swept by an N-gon:
    // every horizontal slice is an N-gon annulus, N sin(2 pi/N)/(2 pi) of the circular one.
    const double sweep = N * std::sin(2.0 * M_PI / N) / (2.0 * M_PI);
    const double tube = 0.5 * M * r * r * std::sin(2.0 * M_PI / M);
    CHECK(p.measure == doctest::Approx(sweep * 2.0 * M_PI * R * tube).epsilon(1e-12));  // Eq. (5.24)
  }
}
// [test_torus_exact]

TEST_CASE("the torus converges to 2 pi^2 R r^2 and its two closed-form moments at second order") {
  const double R = 1.0, r = 0.3, V = 2.0 * M_PI * M_PI * R * r * r;
  std::vector<Vec3> errors;  // volume, axial moment, transverse moment (relative)
  for (int N = 16; N <= 128; N *= 2) {
    const MassProperties<3> p = computeMassProperties<3>(torusMesh(R, r, N, N / 2));
    const double axial = p.mass * (R * R + 0.75 * r * r);
    const double transverse = p.mass * (0.5 * R * R + 0.625 * r * r);
    errors.emplace_back(1.0 - p.measure / V, 1.0 - p.inertia(2, 2) / axial,
                        1.0 - p.inertia(0, 0) / transverse);
    CHECK(p.inertia(0, 0) == doctest::Approx(p.inertia(1, 1)).epsilon(1e-12));
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    CAPTURE(k);
    const Vec3 ratio = errors[k - 1].cwiseQuotient(errors[k]);
    CHECK(ratio.minCoeff() > 3.4);
    CHECK(ratio.maxCoeff() < 4.1);
  }
  CHECK(errors.back().cwiseAbs().maxCoeff() < 1e-2);
}

TEST_CASE("the cylinder has the volume of its inscribed prism and converges to the solid") {
  const double r = 0.5, h = 2.0;
  double previous = 0.0;
  for (int N = 16; N <= 256; N *= 2) {
    CAPTURE(N);
    const MassProperties<3> p = computeMassProperties<3>(cylinderMesh(r, h, N, 3, 2));
    const double prism = 0.5 * N * r * r * std::sin(2.0 * M_PI / N) * h;
    CHECK(p.measure == doctest::Approx(prism).epsilon(1e-12));
    const double axial = 0.5 * p.mass * r * r, transverse = p.mass * (3.0 * r * r + h * h) / 12.0;
    const double error = 1.0 - p.inertia(2, 2) / axial;
    CHECK(std::abs(1.0 - p.inertia(0, 0) / transverse) < 2.0 * error);
    if (previous > 0.0) CHECK(previous / error == doctest::Approx(4.0).epsilon(0.05));
    previous = error;
  }
}

// [test_polygon_disk]
TEST_CASE("a regular polygon has the exact area and polar moment and converges to the disk") {
  const double r = 1.5;
  double previous = 0.0;
  for (int N = 16; N <= 1024; N *= 2) {
    CAPTURE(N);
    const MassProperties<2> p = computeMassProperties<2>(regularPolygon(r, N), 2.0);
    // N triangles (0, a, b) with |a| = |b| = r and angle alpha = 2 pi / N between them:
    // area r^2 sin(alpha)/2 each, polar moment (area/6)(a.a + a.b + b.b) each, Eq. (5.21).
    const double alpha = 2.0 * M_PI / N;
    CHECK(p.measure == doctest::Approx(0.5 * N * r * r * std::sin(alpha)).epsilon(1e-13));
    CHECK(p.inertia(0, 0) == doctest::Approx(p.mass * r * r * (2.0 + std::cos(alpha)) / 6.0).epsilon(1e-13));
    const double error = 1.0 - p.measure / (M_PI * r * r);
    if (previous > 0.0) CHECK(previous / error == doctest::Approx(4.0).epsilon(0.01));
    previous = error;
  }
  // The disk: m r^2 / 2.
  const MassProperties<2> fine = computeMassProperties<2>(regularPolygon(r, 4096));
  CHECK(fine.inertia(0, 0) == doctest::Approx(0.5 * fine.mass * r * r).epsilon(1e-6));
}
// [test_polygon_disk]

// [test_l_shape]
TEST_CASE("an L-shaped polygon matches its decomposition into two rectangles") {
  // (0,0) (2,0) (2,1) (1,1) (1,3) (0,3): the rectangles [0,2]x[0,1] and [0,1]x[1,3].
  const Polygon L = polygonFromLoop({Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 3),
                                     Vec2(0, 3)});
  const double density = 3.0;
  const MassProperties<2> p = computeMassProperties<2>(L, density);
  struct Part {
    Vec2 lower, upper;
  };
  const Part parts[2] = {{Vec2(0, 0), Vec2(2, 1)}, {Vec2(0, 1), Vec2(1, 3)}};
  double mass = 0.0;
  Vec2 moment = Vec2::Zero();
  for (const Part& part : parts) {
    const Vec2 s = part.upper - part.lower;
    mass += density * s.prod();
    moment += density * s.prod() * 0.5 * (part.lower + part.upper);
  }
  const Vec2 c = moment / mass;
  double J = 0.0;  // each rectangle about its centre, moved to c by the parallel-axis theorem
  for (const Part& part : parts) {
    const Vec2 s = part.upper - part.lower;
    const double m = density * s.prod();
    J += m * s.squaredNorm() / 12.0 + m * (0.5 * (part.lower + part.upper) - c).squaredNorm();
  }
  CHECK(p.mass == doctest::Approx(mass).epsilon(1e-14));
  CHECK_EIGEN_NEAR(p.centerOfMass, c, 1e-14);
  CHECK(p.inertia(0, 0) == doctest::Approx(J).epsilon(1e-14));
}
// [test_l_shape]

TEST_CASE_TEMPLATE("mass properties follow the mesh through any rigid motion", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(820 + D);
  SurfaceMesh<D> shape;
  if constexpr (D == 2) {
    shape = polygonFromLoop({Vec2(0, 0), Vec2(3, 0), Vec2(3, 2), Vec2(1.5, 0.5), Vec2(0.5, 2.5)});
  } else {
    shape = torusMesh(1.0, 0.4, 20, 9);
    for (Vec3& p : shape.vertices) p = Vec3(p.x() * 1.3, p.y(), p.z() * 0.7 + 0.2 * p.x());
  }
  const MassProperties<D> reference = computeMassProperties<D>(shape);
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    const Pose<D> pose{random.vector<D>(-10.0, 10.0), random.orientation<D>()};
    SurfaceMesh<D> moved = shape;
    moveMesh<D>(moved, pose);
    const MassProperties<D> p = computeMassProperties<D>(moved);
    const AngMat<D> R = angularRotationMatrix<D>(pose.orientation);
    CHECK(p.mass == doctest::Approx(reference.mass).epsilon(1e-12));
    CHECK_EIGEN_NEAR(p.centerOfMass, pose.toWorld(reference.centerOfMass), 1e-12);
    CHECK_EIGEN_NEAR(p.inertia, AngMat<D>(R * reference.inertia * R.transpose()), 1e-12);
  }
}

// [test_far_from_origin]
TEST_CASE("an apex at the bounds centre keeps full precision far from the origin") {
  const Vec3 size(1.0, 2.0, 3.0);
  const Mat3 exact = boxInertia<3>(size.prod(), size);
  TriangleMesh mesh = boxMesh(size);
  for (Vec3& p : mesh.vertices) p += Vec3(1e6, 7e5, -3e5);
  const MassProperties<3> centred = computeMassProperties<3>(mesh);
  CHECK_EIGEN_NEAR(centred.inertia, exact, 1e-12);
  // With the apex at the origin the simplices are 1e6 long and the parallel-axis shift
  // subtracts numbers of size 1e12 m from each other: no correct digit is left.
  MassPropertySettings atOrigin;
  atOrigin.apexAtBoundsCenter = false;
  const MassProperties<3> naive = computeMassProperties<3>(mesh, 1.0, atOrigin);
  CHECK((naive.inertia - exact).cwiseAbs().maxCoeff() > 1e-3 * exact.maxCoeff());
}
// [test_far_from_origin]

// [test_bad_meshes]
TEST_CASE("inside-out open and inconsistent meshes are rejected with a message") {
  TriangleMesh inverted = boxMesh(Vec3::Ones());
  for (auto& f : inverted.faces) std::swap(f[1], f[2]);
  CHECK_THROWS_WITH_AS(computeMassProperties<3>(inverted), doctest::Contains("not positive: the mesh is inside-out"),
                       std::invalid_argument);
  TriangleMesh open = boxMesh(Vec3::Ones());
  open.faces.pop_back();
  CHECK_THROWS_WITH_AS(computeMassProperties<3>(open), doctest::Contains("the mesh is open"),
                       std::invalid_argument);
  TriangleMesh flipped = boxMesh(Vec3::Ones());
  std::swap(flipped.faces[3][0], flipped.faces[3][1]);
  CHECK_THROWS_WITH_AS(computeMassProperties<3>(flipped), doctest::Contains("oriented inconsistently"),
                       std::invalid_argument);
  TriangleMesh poisoned = boxMesh(Vec3::Ones());
  poisoned.vertices[5].y() = std::nan("");
  CHECK_THROWS_WITH_AS(computeMassProperties<3>(poisoned), doctest::Contains("vertex 5 is not finite"),
                       std::invalid_argument);
  TriangleMesh dangling = boxMesh(Vec3::Ones());
  dangling.faces[0][2] = 8;
  CHECK_THROWS_WITH_AS(computeMassProperties<3>(dangling),
                       "computeMassProperties: face 0 refers to vertex 8, but there are 8 vertices",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(computeMassProperties<3>(boxMesh(Vec3::Ones()), 0.0),
                       "computeMassProperties: density must be finite and positive, got 0",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(computeMassProperties<3>(TriangleMesh{}), doctest::Contains("no faces"),
                       std::invalid_argument);
  // A clockwise polygon is the 2D inside-out mesh; a closed but flat one has no area.
  const Polygon clockwise = polygonFromLoop({Vec2(0, 0), Vec2(0, 1), Vec2(1, 1), Vec2(1, 0)});
  CHECK_THROWS_WITH_AS(computeMassProperties<2>(clockwise), doctest::Contains("a clockwise polygon"),
                       std::invalid_argument);
  const Polygon flat = polygonFromLoop({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)});
  CHECK_THROWS_AS(computeMassProperties<2>(flat), std::invalid_argument);
  Polygon broken = rectanglePolygon(Vec2::Ones());
  broken.faces.pop_back();
  CHECK_THROWS_WITH_AS(computeMassProperties<2>(broken), doctest::Contains("the polygon is open"),
                       std::invalid_argument);
}
// [test_bad_meshes]

// [test_bad_inertia]
TEST_CASE("invalid inertias are rejected with a message") {
  CHECK_THROWS_WITH_AS(makeDynamicBody<3>(1.0, Vec3(1.0, 1.0, 3.0)),
                       doctest::Contains("violate the triangle inequality"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(makeDynamicBody<3>(1.0, Vec3(1.0, 0.0, 1.0)),
                       "makeDynamicBody: principal moment of inertia 1 must be finite and positive, got 0",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(makeDynamicBody<2>(1.0, AngVec<2>::Constant(INFINITY)),
                       doctest::Contains("must be finite and positive, got inf"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(makeDynamicBody<3>(-1.0, Vec3::Ones()),
                       "makeDynamicBody: mass must be finite and positive, got -1", std::invalid_argument);
  MassProperties<3> p = computeMassProperties<3>(boxMesh(Vec3(1.0, 2.0, 3.0)));
  MassProperties<3> skew = p;
  skew.inertia(0, 1) += 0.1;
  CHECK_THROWS_WITH_AS(principalAxes<3>(skew), "principalAxes: the inertia tensor is not symmetric",
                       std::invalid_argument);
  MassProperties<3> impossible = p;
  impossible.inertia = Vec3(1.0, 1.0, 3.0).asDiagonal();
  CHECK_THROWS_WITH_AS(principalAxes<3>(impossible), doctest::Contains("principalAxes: principal moments"),
                       std::invalid_argument);
  MassProperties<3> poisoned = p;
  poisoned.inertia(2, 2) = std::nan("");
  CHECK_THROWS_WITH_AS(principalAxes<3>(poisoned), "principalAxes: the inertia tensor is not finite",
                       std::invalid_argument);
}
// [test_bad_inertia]

// [test_principal_frame]
TEST_CASE("moving a turned box to its principal frame recovers the turn and the box") {
  RandomSource random(840);
  const Vec3 size(0.5, 1.0, 2.0);
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    // A turn of up to 40 degrees: the box's axes stay the nearest to the coordinate axes.
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(random.uniform(0.0, 0.7), random.unitVector<3>()));
    const Pose<3> pose{random.vector<3>(-3.0, 3.0), turn};
    const TriangleMesh original = boxMesh(size, 2);
    TriangleMesh mesh = original;
    moveMesh<3>(mesh, pose);
    const BodyFrame<3> frame = moveToPrincipalFrame<3>(mesh, 10.0);
    CHECK_EIGEN_NEAR(frame.frame.position, pose.position, 1e-12);
    CHECK_EIGEN_NEAR(frame.frame.orientation.toRotationMatrix(), turn.toRotationMatrix(), 1e-12);
    CHECK_EIGEN_NEAR(frame.principalMoments, Vec3(boxInertia<3>(10.0 * size.prod(), size).diagonal()), 1e-12);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      CHECK_EIGEN_NEAR(mesh.vertices[v], original.vertices[v], 1e-12, 1e-12);
    }
  }
}
// [test_principal_frame]

TEST_CASE("any turn of an unequal box is undone up to a symmetry of the box") {
  RandomSource random(850);
  const Vec3 size(0.5, 1.0, 2.0);
  for (int trial = 0; trial < 50; ++trial) {
    CAPTURE(trial);
    TriangleMesh mesh = boxMesh(size);
    moveMesh<3>(mesh, Pose<3>{random.vector<3>(-3.0, 3.0), random.orientation<3>()});
    const BodyFrame<3> frame = moveToPrincipalFrame<3>(mesh);
    const MassProperties<3> after = computeMassProperties<3>(mesh);
    CHECK_EIGEN_NEAR(after.centerOfMass, Vec3::Zero(), 0.0, 1e-12);
    CHECK_EIGEN_NEAR(after.inertia, Mat3(frame.principalMoments.asDiagonal()), 1e-12);
    // Axis-aligned again: the extents are the sides in some order.
    Vec3 extent = mesh.bounds().extent();
    std::sort(extent.data(), extent.data() + 3);
    CHECK_EIGEN_NEAR(extent, size, 1e-12);
    CHECK(frame.frame.orientation.toRotationMatrix().determinant() == doctest::Approx(1.0).epsilon(1e-12));
  }
}

TEST_CASE("equal moments keep the input axes: a torus keeps its axis and a ball its frame") {
  TriangleMesh torus = torusMesh(1.0, 0.3, 24, 12);
  const BodyFrame<3> torusFrame = moveToPrincipalFrame<3>(torus);
  CHECK_EIGEN_NEAR(torusFrame.frame.orientation.toRotationMatrix(), Mat3::Identity(), 1e-12, 1e-12);
  CHECK(torusFrame.principalMoments.z() > torusFrame.principalMoments.x());
  // Tilted about x: the distinct (axial) axis is the turned z axis, the x axis stays.
  TriangleMesh tilted = torusMesh(1.0, 0.3, 24, 12);
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(0.4, Vec3::UnitX()));
  moveMesh<3>(tilted, Pose<3>{Vec3(1.0, 2.0, 3.0), tilt});
  const BodyFrame<3> tiltedFrame = moveToPrincipalFrame<3>(tilted);
  CHECK_EIGEN_NEAR(tiltedFrame.frame.orientation.toRotationMatrix(), tilt.toRotationMatrix(), 1e-12, 1e-12);
  TriangleMesh ball = icosphereMesh(1.0, 2);
  const BodyFrame<3> ballFrame = moveToPrincipalFrame<3>(ball);
  CHECK_EIGEN_NEAR(ballFrame.frame.orientation.toRotationMatrix(), Mat3::Identity(), 0.0, 0.0);
}

// [test_body_from_mesh]
TEST_CASE_TEMPLATE("a body made from a mesh puts the mesh where the placement puts it", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  RandomSource random(860 + D);
  SurfaceMesh<D> original;
  if constexpr (D == 2) {
    original = polygonFromLoop({Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)});
  } else {
    original = boxMesh(Vec3(0.3, 0.6, 1.1));
    moveMesh<3>(original, Pose<3>{Vec3(2.0, 0.0, 1.0), random.orientation<3>()});
  }
  for (int trial = 0; trial < 10; ++trial) {
    CAPTURE(trial);
    const Pose<D> placement{random.vector<D>(-5.0, 5.0), random.orientation<D>()};
    SurfaceMesh<D> mesh = original;
    const RigidBody<D> body = makeBodyFromMesh<D>(mesh, 7.0, placement);
    const Pose<D> bodyPose{body.position, body.orientation};
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      CHECK_EIGEN_NEAR(bodyPose.toWorld(mesh.vertices[v]), placement.toWorld(original.vertices[v]),
                       1e-12, 1e-12);
    }
    CHECK(body.mass() == doctest::Approx(7.0 * computeMassProperties<D>(original).measure).epsilon(1e-12));
  }
}
// [test_body_from_mesh]

}  // TEST_SUITE
