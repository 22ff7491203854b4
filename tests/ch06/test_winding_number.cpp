// Chapter 6: the generalised winding number, the sign of the signed distance.
#include <doctest/doctest.h>

#include <cmath>

#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/winding_number.hpp"
#include "support/dimensions.hpp"
#include "geometry_helpers.hpp"

using namespace stackbook;
using stackbook::testing::at;
using stackbook::testing::In2D;
using stackbook::testing::In3D;

namespace {


template <int D>
SurfaceMesh<D> merged(const SurfaceMesh<D>& a, const SurfaceMesh<D>& b, const Vec<D>& shiftB) {
  SurfaceMesh<D> m = a;
  const int offset = static_cast<int>(a.vertices.size());
  for (const Vec<D>& v : b.vertices) m.vertices.push_back(v + shiftB);
  for (auto f : b.faces) {
    for (int& i : f) i += offset;
    m.faces.push_back(f);
  }
  return m;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("one face subtends the angle its closed form gives") {
  // The triangle (e_x, e_y, e_z) covers one octant of the directions seen from the origin:
  // 4 pi / 8 steradians, positive because its outward normal (1, 1, 1) points away.
  TriangleMesh octant;
  octant.vertices = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  octant.faces = {{0, 1, 2}};
  CHECK(faceSubtendedAngle<3>(octant, 0, Vec3::Zero()) == doctest::Approx(M_PI / 2).epsilon(1e-15));
  CHECK(faceSubtendedAngle<3>(octant, 0, Vec3(1, 1, 1)) < 0.0);  // seen from outside
  // The segment from (1, -1) to (1, 1) is seen from the origin under a right angle.
  Polygon segment;
  segment.vertices = {Vec2(1, -1), Vec2(1, 1)};
  segment.faces = {{0, 1}};
  CHECK(faceSubtendedAngle<2>(segment, 0, Vec2::Zero()) == doctest::Approx(M_PI / 2).epsilon(1e-15));
}

// [test_winding_nonconvex]
TEST_CASE_TEMPLATE("winding number is one inside and zero outside nonconvex bodies", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  // Cup (R 0.5, H 0.8, wall 0.1, bottom 0.1), centred on its box: z runs from -0.4 to 0.4.
  const SurfaceMesh<D> cup = cupBoundary<D>();
  CHECK(windingNumber<D>(cup, at<D>(0.45, 0.0)) == doctest::Approx(1.0).epsilon(1e-12));  // wall
  CHECK(windingNumber<D>(cup, at<D>(0.0, -0.35)) == doctest::Approx(1.0).epsilon(1e-12)); // bottom
  CHECK(std::abs(windingNumber<D>(cup, at<D>(0.0, 0.2))) < 1e-12);   // the cavity is outside
  CHECK(std::abs(windingNumber<D>(cup, at<D>(2.0, 0.0))) < 1e-12);
  // Ring (R 0.5, r 0.2): the hole is outside, the tube inside.
  const SurfaceMesh<D> ring = ringBoundary<D>(0.5, 0.2);
  CHECK(std::abs(windingNumber<D>(ring, Vec<D>::Zero())) < 1e-12);
  CHECK(windingNumber<D>(ring, at<D>(0.5, 0.0)) == doctest::Approx(1.0).epsilon(1e-12));
  // Bone (balls r 0.3 at z = +-0.6, neck r 0.12): beside the neck is outside.
  const SurfaceMesh<D> bone = boneBoundary<D>();
  CHECK(std::abs(windingNumber<D>(bone, at<D>(0.2, 0.0))) < 1e-12);
  CHECK(windingNumber<D>(bone, at<D>(0.0, 0.0)) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(windingNumber<D>(bone, at<D>(0.1, 0.6)) == doctest::Approx(1.0).epsilon(1e-12));
  // L (cells of 0.5, centred): the missing quadrant is outside.
  const SurfaceMesh<D> ell = lShapeBoundary<D>();
  Vec<D> notch = Vec<D>::Zero(), arm = Vec<D>::Zero();
  notch[0] = notch[1] = 0.25;
  arm[0] = arm[1] = -0.25;
  CHECK(std::abs(windingNumber<D>(ell, notch)) < 1e-12);
  CHECK(windingNumber<D>(ell, arm) == doctest::Approx(1.0).epsilon(1e-12));
}
// [test_winding_nonconvex]

TEST_CASE_TEMPLATE("winding number counts overlapping closed components", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Two unit spheres (disks) 1.2 apart as one mesh: w = 2 in the overlap, 1 in one only.
  SurfaceMesh<D> one;
  if constexpr (D == 3) {
    one = icosphereMesh(1.0, 2);
  } else {
    one = regularPolygon(1.0, 64);
  }
  Vec<D> shift = Vec<D>::Zero();
  shift[0] = 1.2;
  const SurfaceMesh<D> two = merged<D>(one, one, shift);
  Vec<D> overlap = Vec<D>::Zero(), onlyFirst = Vec<D>::Zero();
  overlap[0] = 0.6;
  onlyFirst[0] = -0.5;
  CHECK(windingNumber<D>(two, overlap) == doctest::Approx(2.0).epsilon(1e-12));
  CHECK(windingNumber<D>(two, onlyFirst) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(insideByWindingNumber<D>(two, overlap));
}

TEST_CASE("winding number of a mesh with a missing face degrades by that face's share") {
  // The icosahedron's 20 faces are congruent and equidistant from its centre, so each
  // subtends 4 pi / 20 there: with one face removed, w(centre) = 1 - 1/20 exactly, and the
  // centre is still classified inside. A ray-parity test would depend on the ray's luck.
  TriangleMesh icosahedron = icosphereMesh(1.0, 0);
  CHECK(windingNumber<3>(icosahedron, Vec3::Zero()) == doctest::Approx(1.0).epsilon(1e-14));
  icosahedron.faces.erase(icosahedron.faces.begin());
  CHECK(windingNumber<3>(icosahedron, Vec3::Zero()) == doctest::Approx(0.95).epsilon(1e-14));
  CHECK(insideByWindingNumber<3>(icosahedron, Vec3::Zero()));
}

}  // TEST_SUITE
