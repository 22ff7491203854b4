// Chapter 6: the procedural nonconvex meshes are closed, outward and of the right size.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/mesh_validation.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using stackbook::testing::In2D;
using stackbook::testing::In3D;

namespace {

// Area factor of a regular N-gon inscribed in a circle: (N/2) sin(2 pi/N) / pi.
double polygonFactor(int n) { return n * std::sin(2.0 * M_PI / n) / (2.0 * M_PI); }

// Measure enclosed by revolving (3D, about z with an inscribed N-gon) or mirroring (2D) a
// profile polyline in the (r, z) half-plane: a sum of signed frustums (3D) or trapezoids
// (2D) over the profile's segments, independent of how the mesh is built.
template <int D>
double revolvedMeasure(const std::vector<Vec2>& profile, int segments) {
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const double r1 = profile[i].x(), r2 = profile[i + 1].x();
    const double dz = profile[i + 1].y() - profile[i].y();
    sum += D == 3 ? M_PI * dz * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0 : dz * (r1 + r2);
  }
  return D == 3 ? polygonFactor(segments) * sum : sum;
}

template <int D>
void requireValid(const SurfaceMesh<D>& mesh, const std::string& name) {
  const MeshCheck check = findMeshDefects<D>(mesh);
  for (const MeshDefect& d : check.defects) INFO(name << ": " << d.message);
  CHECK_MESSAGE(check.ok(), name);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("every procedural nonconvex mesh is closed and outward", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  requireValid<D>(lShapeBoundary<D>(0.5, 1), "L");
  requireValid<D>(lShapeBoundary<D>(0.5, 3), "L subdivided");
  requireValid<D>(cupBoundary<D>(), "cup");
  requireValid<D>(boneBoundary<D>(), "bone");
  // Balls that meet exactly where the neck would start: no neck segment at all.
  const double rise = std::sqrt(0.3 * 0.3 - 0.12 * 0.12);
  requireValid<D>(boneBoundary<D>(BoneDimensions{0.3, 0.12, 2.0 * rise}), "bone without neck");
  requireValid<D>(capsuleBoundary<D>(0.5, 0.25), "capsule");
  requireValid<D>(ringBoundary<D>(0.5, 0.2), "ring");
  if constexpr (D == 2) {
    requireValid<2>(starPolygon(), "star");
    requireValid<2>(uPolygon(), "U");
  }
}

// [test_mesh_measures]
TEST_CASE_TEMPLATE("procedural meshes enclose the volume of their closed forms", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // L: three cells of side a.
  const double a = 0.5;
  CHECK(signedMeasure<D>(lShapeBoundary<D>(a, 2)) == doctest::Approx(3.0 * std::pow(a, D)).epsilon(1e-12));
  // Cup: outer cylinder minus the cavity, each cross-section an inscribed N-gon in 3D.
  const CupDimensions cup;  // R 0.5, H 0.8, t 0.1, b 0.1
  const int n = 48;
  const double R = cup.outerRadius, H = cup.height, t = cup.wallThickness, b = cup.bottomThickness;
  const double cupMeasure =
      D == 3 ? polygonFactor(n) * M_PI * (R * R * H - (R - t) * (R - t) * (H - b))
             : 2.0 * (R * H - (R - t) * (H - b));
  CHECK(signedMeasure<D>(cupBoundary<D>(cup, n)) == doctest::Approx(cupMeasure).epsilon(1e-12));
  // Bone: frustums (3D) or trapezoids (2D) of its profile.
  const BoneDimensions bone;
  const std::vector<Vec2> profile = boneProfile(bone, 0.04);
  CHECK(signedMeasure<D>(boneBoundary<D>(bone, n, 0.04)) ==
        doctest::Approx(revolvedMeasure<D>(profile, n)).epsilon(1e-12));
}
// [test_mesh_measures]

TEST_CASE("polygons enclose the areas of their closed forms") {
  // Star: 2P triangles from the centre with sides R and r at angle pi/P.
  const double R = 0.5, r = 0.2;
  const int P = 5;
  CHECK(signedMeasure<2>(starPolygon(R, r, P, 3)) ==
        doctest::Approx(P * R * r * std::sin(M_PI / P)).epsilon(1e-12));
  // Annulus: outer N-gon minus inner N-gon.
  const int n = 40;
  CHECK(signedMeasure<2>(annulusPolygon(0.5, 0.2, n)) ==
        doctest::Approx(0.5 * n * std::sin(2.0 * M_PI / n) * (0.49 - 0.09)).epsilon(1e-12));
}

TEST_CASE_TEMPLATE("vertices of the bone and the capsule lie on the smooth surface", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  const BoneDimensions bone;
  const double rise = std::sqrt(bone.ballRadius * bone.ballRadius - bone.neckRadius * bone.neckRadius);
  const double half = 0.5 * bone.length;
  for (const Vec<D>& p : boneBoundary<D>(bone).vertices) {
    Vec<D> top = p, bottom = p;
    top[D - 1] -= half;
    bottom[D - 1] += half;
    double gap = std::min(std::abs(top.norm() - bone.ballRadius),
                          std::abs(bottom.norm() - bone.ballRadius));
    if (std::abs(p[D - 1]) <= half - rise + 1e-12) {
      gap = std::min(gap, std::abs(p.template head<D - 1>().norm() - bone.neckRadius));
    }
    CHECK(gap < 1e-12);
  }
  const CapsuleSdf<D> capsule(0.4, 0.25);
  for (const Vec<D>& p : capsuleBoundary<D>(0.4, 0.25).vertices) {
    CHECK(std::abs(capsule.distance(p)) < 1e-12);
  }
}

TEST_CASE("nonconvex generators reject impossible dimensions by name") {
  const auto message = [](auto&& build) {
    try {
      build();
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no exception");
  };
  CHECK(message([] { cupBoundary<3>(CupDimensions{0.5, 0.8, 0.5, 0.1}); })
            .find("wallThickness") != std::string::npos);
  CHECK(message([] { boneBoundary<3>(BoneDimensions{0.2, 0.3, 1.0}); })
            .find("neckRadius") != std::string::npos);
  CHECK(message([] { boneBoundary<2>(BoneDimensions{0.3, 0.1, 0.2}); })
            .find("length") != std::string::npos);
  CHECK(message([] { starPolygon(0.2, 0.5); }).find("innerRadius") != std::string::npos);
  CHECK(message([] { revolvedBoundary<3>({Vec2(0.1, 0), Vec2(1, 1), Vec2(0, 2)}); })
            .find("axis") != std::string::npos);
  CHECK(message([] { latticeSolidBoundary<2>({}, 1.0); }).find("no cells") != std::string::npos);
}

}  // TEST_SUITE
