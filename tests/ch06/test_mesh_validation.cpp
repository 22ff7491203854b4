// Chapter 6: bad meshes are rejected with messages that name the defect and where it is.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/mesh_validation.hpp"
#include "geometry_helpers.hpp"
#include "support/damaged_mesh.hpp"

using namespace stackbook;
using stackbook::testing::contains;

namespace {


template <int D>
const MeshDefect* firstOf(const MeshCheck& check, MeshDefectKind kind) {
  for (const MeshDefect& d : check.defects) {
    if (d.kind == kind) return &d;
  }
  return nullptr;
}

// A tetrahedron whose face (1, 2, 3) is split at the midpoint m of edge 1-2, with the
// sliver triangle (1, 2, m) closing the crack: closed, consistently oriented, but face 5
// has three collinear vertices.
TriangleMesh tetrahedronWithSliver() {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.5, 0.5, 0)};
  mesh.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 4, 3}, {4, 2, 3}, {1, 2, 4}};
  return mesh;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("valid meshes have no defects") {
  CHECK(findMeshDefects<3>(boxMesh(Vec3(1, 1, 1), 2)).ok());
  CHECK(findMeshDefects<3>(lShapeBoundary<3>()).ok());
  CHECK(findMeshDefects<2>(starPolygon()).ok());
  CHECK(findMeshDefects<2>(annulusPolygon(0.5, 0.2)).ok());
}

// [test_validation_defects]
TEST_CASE("a missing triangle is reported as a hole at its rim edges") {
  TriangleMesh box = boxMesh(Vec3(1, 1, 1));
  box.faces.erase(box.faces.begin() + 3);
  const MeshCheck check = findMeshDefects<3>(box);
  const MeshDefect* hole = firstOf<3>(check, MeshDefectKind::OpenBoundary);
  REQUIRE(hole != nullptr);
  CHECK(hole->vertices.size() == 2);  // the rim edge's two vertices
  CHECK(contains(hole->message, "has a hole there"));
  CHECK(!check.has(MeshDefectKind::InwardOrientation));  // not judged on an open mesh
}

TEST_CASE("a flipped triangle is named as the face that disagrees with its neighbours") {
  TriangleMesh box = boxMesh(Vec3(1, 1, 1));
  std::swap(box.faces[5][1], box.faces[5][2]);
  const MeshCheck check = findMeshDefects<3>(box);
  const MeshDefect* flipped = firstOf<3>(check, MeshDefectKind::InconsistentOrientation);
  REQUIRE(flipped != nullptr);
  CHECK(flipped->face == 5);
  CHECK(contains(flipped->message, "face 5"));
  CHECK(contains(flipped->message, "3 of its edges"));
  CHECK(check.defects.size() == 1);  // the three neighbours are not blamed
}

TEST_CASE("degenerate triangles are reported with their vertices") {
  const MeshCheck sliver = findMeshDefects<3>(tetrahedronWithSliver());
  REQUIRE(sliver.defects.size() == 1);
  CHECK(sliver.defects[0].kind == MeshDefectKind::DegenerateFace);
  CHECK(sliver.defects[0].face == 5);
  CHECK(contains(sliver.defects[0].message, "face 5 (vertices 1, 2, 4) has zero area"));
  TriangleMesh repeated = boxMesh(Vec3(1, 1, 1));
  repeated.faces[0] = {0, 0, 1};
  CHECK(contains(findMeshDefects<3>(repeated).defects[0].message, "face 0 (vertices 0, 0, 1) repeats a vertex"));
}
// [test_validation_defects]

TEST_CASE("a non-finite vertex and an index out of range stop the checks at the structure") {
  TriangleMesh nanVertex = boxMesh(Vec3(1, 1, 1));
  nanVertex.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
  const MeshCheck a = findMeshDefects<3>(nanVertex);
  REQUIRE(a.defects.size() == 1);
  CHECK(a.defects[0].kind == MeshDefectKind::NonFiniteVertex);
  CHECK(contains(a.defects[0].message, "vertex 3 has a non-finite coordinate"));

  TriangleMesh badIndex = boxMesh(Vec3(1, 1, 1));
  badIndex.faces[2][2] = 99;
  const MeshCheck b = findMeshDefects<3>(badIndex);
  REQUIRE(b.defects.size() == 1);
  CHECK(b.defects[0].kind == MeshDefectKind::IndexOutOfRange);
  CHECK(contains(b.defects[0].message, "face 2"));
  CHECK(contains(b.defects[0].message, "refers to vertex 99, but the mesh has 8 vertices"));
}

TEST_CASE("an inside-out mesh is reported with its negative volume") {
  TriangleMesh box = boxMesh(Vec3(1, 2, 3));
  for (auto& f : box.faces) std::swap(f[1], f[2]);
  const MeshCheck check = findMeshDefects<3>(box);
  REQUIRE(check.defects.size() == 1);
  CHECK(check.defects[0].kind == MeshDefectKind::InwardOrientation);
  CHECK(contains(check.defects[0].message, "volume is -6"));
}

TEST_CASE("edges shared by four faces and stray vertices are reported") {
  // Two cubes that touch along one edge only.
  const TriangleMesh touching = latticeSolidBoundary<3>({{0, 0, 0}, {1, 1, 0}}, 1.0);
  const MeshCheck check = findMeshDefects<3>(touching);
  const MeshDefect* edge = firstOf<3>(check, MeshDefectKind::NonManifold);
  REQUIRE(edge != nullptr);
  CHECK(contains(edge->message, "is shared by 4 faces"));

  TriangleMesh stray = boxMesh(Vec3(1, 1, 1));
  stray.vertices.push_back(Vec3(5, 5, 5));
  const MeshCheck s = findMeshDefects<3>(stray);
  REQUIRE(s.defects.size() == 1);
  CHECK(s.defects[0].kind == MeshDefectKind::UnusedVertex);
  CHECK(contains(s.defects[0].message, "vertex 8"));
  CHECK(findMeshDefects<3>(TriangleMesh{}).has(MeshDefectKind::Empty));
}

TEST_CASE("polygon defects are reported at vertices and segments") {
  Polygon open = regularPolygon(1.0, 6);
  open.faces.pop_back();  // the segment (5, 0)
  const MeshCheck a = findMeshDefects<2>(open);
  REQUIRE(a.defects.size() == 2);  // both ends of the gap
  CHECK(a.defects[0].kind == MeshDefectKind::OpenBoundary);
  CHECK(contains(a.defects[0].message, "vertex 0 belongs to face 0 only"));

  Polygon flipped = regularPolygon(1.0, 6);
  std::swap(flipped.faces[2][0], flipped.faces[2][1]);
  const MeshCheck b = findMeshDefects<2>(flipped);
  REQUIRE(b.defects.size() == 1);
  CHECK(b.defects[0].kind == MeshDefectKind::InconsistentOrientation);
  CHECK(b.defects[0].face == 2);

  Polygon clockwise = regularPolygon(1.0, 4);
  for (auto& f : clockwise.faces) std::swap(f[0], f[1]);
  CHECK(contains(findMeshDefects<2>(clockwise).defects[0].message, "area is -2"));

  Polygon zeroLength = polygonFromLoop({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(1, 1)});
  const MeshCheck c = findMeshDefects<2>(zeroLength);
  REQUIRE(c.defects.size() == 1);
  CHECK(contains(c.defects[0].message, "face 1 (vertices 1, 2) has zero length"));
}

TEST_CASE("validateMesh throws a MeshError that names the source and each kind of defect") {
  TriangleMesh box = boxMesh(Vec3(1, 1, 1));
  box.faces.erase(box.faces.begin());
  std::swap(box.faces[6][0], box.faces[6][1]);
  try {
    validateMesh<3>(box, "crate.obj");
    FAIL("no exception");
  } catch (const MeshError& error) {
    const std::string message = error.what();
    CHECK(message.rfind("crate.obj: invalid triangle mesh (8 vertices, 11 faces)", 0) == 0);
    CHECK(contains(message, "hole edges (first: edge"));
    CHECK(error.has(MeshDefectKind::OpenBoundary));
    // The full sentences stay with the error.
    const MeshDefect* hole = nullptr;
    for (const MeshDefect& d : error.defects()) {
      if (d.kind == MeshDefectKind::OpenBoundary && hole == nullptr) hole = &d;
    }
    REQUIRE(hole != nullptr);
    CHECK(contains(hole->message, "the mesh has a hole there"));
  }
  // Many defects of one kind: the line counts them all; the error lists
  // maxReportedPerKind of them, and `omitted` in findMeshDefects counts the rest.
  TriangleMesh many = boxMesh(Vec3(1, 1, 1), 4);
  for (int k = 0; k < 40; ++k) many.vertices.push_back(Vec3(9, 9, k));
  try {
    validateMesh<3>(many, "many");
    FAIL("no exception");
  } catch (const MeshError& error) {
    CHECK(error.defects().size() == 5);
    CHECK(contains(error.what(), "40 defects: 40 unused vertices (first: vertex 98)"));
  }
  CHECK(findMeshDefects<3>(many).omitted == 35);
}

// [test_refused_mesh_line]
TEST_CASE("A mesh with many defects of several kinds is refused in one short line") {
  // 12 missing triangles (36 hole edges), 1 reversed, 100 faces repeating a vertex.
  const test_support::DamagedMesh damaged = test_support::damagedBox(8, 12, 100);
  const MeshCheck check = findMeshDefects<3>(damaged.mesh);
  REQUIRE(check.counts.size() == 3);
  CHECK(check.counts[0] == std::pair{MeshDefectKind::DegenerateFace, damaged.degenerateFaces});
  CHECK(check.counts[1] == std::pair{MeshDefectKind::OpenBoundary, damaged.holeEdges});
  CHECK(check.counts[2] == std::pair{MeshDefectKind::InconsistentOrientation, damaged.flippedFaces});
  try {
    validateMesh<3>(damaged.mesh, "character.obj");
    FAIL("no exception");
  } catch (const MeshError& error) {
    const std::string line = error.what();
    CAPTURE(line);
    CHECK(line.find('\n') == std::string::npos);
    CHECK(line.size() <= 300);
    CHECK(contains(line, "137 defects: 100 degenerate faces (first: face " +
                             std::to_string(damaged.firstDegenerateFace) + "), 36 hole edges (first: edge "));
    CHECK(contains(line, "1 flipped face (face " + std::to_string(damaged.flippedFace) + ")"));
    CHECK(contains(line, "; repairMesh() repairs it (chapter 6)"));
    CHECK(error.summary() + "; repairMesh() repairs it (chapter 6)" == line);
    CHECK(error.defects().size() == 5 + 5 + 1);  // maxReportedPerKind of each kind
  }
}
// [test_refused_mesh_line]

}  // TEST_SUITE
