// Chapter 6: meshes as people download them. Strict loading rejects each defect with a
// message that names the file and the defect (self-intersections included); repairMesh
// welds, drops, orients and says so one line per repair; what it cannot repair (holes,
// overlapping parts) is reported and left to the winding number; STL (ASCII and binary)
// and PLY read like OBJ, with the line or element of a malformed file.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "stackbook/geometry/mesh_file.hpp"
#include "stackbook/geometry/mesh_repair.hpp"
#include "stackbook/geometry/winding_mass_properties.hpp"
#include "stackbook/geometry/winding_number.hpp"

using namespace stackbook;

namespace {

std::string data(const std::string& name) { return std::string(STACKBOOK_CH06_DATA) + "/" + name; }

/// Loads a file as repair mode does: nothing merged, nothing validated.
TriangleMesh loadRaw(const std::string& name) {
  ObjLoadSettings raw;
  raw.mergeTolerance = -1.0;
  raw.dropUnusedVertices = false;
  raw.validate = false;
  return loadMeshFile(data(name), raw);
}

/// The message of the MeshError that strict loading throws, "" if it loads.
std::string strictError(const std::string& name) {
  try {
    loadMeshFile(data(name));
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool anyLineContains(const std::vector<std::string>& lines, const std::string& part) {
  for (const std::string& line : lines) {
    if (contains(line, part)) return true;
  }
  return false;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_repair_weld]
TEST_CASE("Repair welds corners repeated with noise, which strict loading leaves open") {
  // 12 triangles, each with its own 3 corners perturbed by up to 1e-9: 36 vertices.
  CHECK(contains(strictError("cube_near_duplicates.obj"), "hole"));
  TriangleMesh mesh = loadRaw("cube_near_duplicates.obj");
  REQUIRE(mesh.vertices.size() == 36);
  const MeshRepairReport report = repairMesh(mesh);
  CHECK(mesh.vertices.size() == 8);
  CHECK(mesh.faces.size() == 12);
  REQUIRE(report.repairs.size() == 1);
  CHECK(contains(report.repairs[0], "welded 28 duplicate vertices"));
  CHECK(report.watertight());
  CHECK_NOTHROW(validateMesh<3>(mesh, "welded cube"));
  // The welded corners are within 1e-9 of the unit cube's: volume 1 to O(1e-9).
  CHECK(std::abs(signedMeasure<3>(mesh) - 1.0) < 1e-8);
}
// [test_repair_weld]

TEST_CASE("Repair turns flipped faces and an inside-out mesh, and drops repeated and degenerate faces") {
  {
    CHECK(contains(strictError("cube_two_flipped.obj"), "flipped"));
    TriangleMesh mesh = loadRaw("cube_two_flipped.obj");
    const MeshRepairReport report = repairMesh(mesh);
    REQUIRE(report.repairs.size() == 1);
    CHECK(contains(report.repairs[0], "turned 2 faces"));
    CHECK(contains(report.repairs[0], "faces 10, 11"));
    CHECK(report.watertight());
    CHECK(signedMeasure<3>(mesh) == doctest::Approx(1.0).epsilon(1e-12));
  }
  {
    TriangleMesh mesh = loadRaw("cube_inside_out_repeated.obj");
    REQUIRE(mesh.faces.size() == 14);
    const MeshRepairReport report = repairMesh(mesh);
    CHECK(anyLineContains(report.repairs, "dropped 1 degenerate faces"));
    CHECK(anyLineContains(report.repairs, "dropped 1 repeated faces"));
    CHECK(anyLineContains(report.repairs, "turned 12 faces"));
    CHECK(mesh.faces.size() == 12);
    CHECK(report.watertight());
    CHECK(signedMeasure<3>(mesh) == doctest::Approx(1.0).epsilon(1e-12));
  }
}

// [test_repair_hole]
TEST_CASE("A hole stays: reported as approximate, and the winding number still tells inside from outside") {
  CHECK(contains(strictError("cube_hole.obj"), "hole"));
  TriangleMesh mesh = loadRaw("cube_hole.obj");
  const MeshRepairReport report = repairMesh(mesh);
  CHECK(report.repairs.empty());
  REQUIRE(!report.watertight());
  CHECK(anyLineContains(report.remaining, "holes"));
  CHECK(anyLineContains(report.remaining, "winding number"));
  // The missing triangle is 1/12 of the cube's solid angle seen from its centre.
  CHECK(windingNumber<3>(mesh, Vec3(0.5, 0.5, 0.5)) == doctest::Approx(11.0 / 12.0).epsilon(1e-12));
  CHECK(insideByWindingNumber<3>(mesh, Vec3(0.5, 0.5, 0.9)));
  CHECK(!insideByWindingNumber<3>(mesh, Vec3(0.5, 0.5, 1.5)));
  // The solid {w > 1/2}: volume 1 up to the cells under the hole (area 1/2, depth <= h).
  const int cells = 16;
  const MassProperties<3> p = windingNumberMassProperties(mesh, 1.0, cells);
  CHECK(std::abs(p.measure - 1.0) <= 0.5 / cells);
  CHECK((p.centerOfMass - Vec3::Constant(0.5)).norm() <= 1.0 / cells);
}
// [test_repair_hole]

// [test_repair_overlap]
TEST_CASE("Two overlapping cubes: strict loading names the crossing, repair keeps them as one solid") {
  const std::string message = strictError("two_overlapping_cubes.obj");
  CHECK(contains(message, "two_overlapping_cubes.obj: the surface intersects itself"));
  CHECK(contains(message, "passes through face"));
  CHECK(contains(message, "self-intersection"));
  CHECK(contains(message, "repairMesh() repairs it (chapter 6)"));  // a scene file says "meshMode" instead
  CHECK(message.find('\n') == std::string::npos);
  // One closed cube has no crossing; touching faces are not crossings either.
  CHECK(findSelfIntersections(loadMeshFile(data("cube_ascii.stl"))).empty());
  TriangleMesh mesh = loadRaw("two_overlapping_cubes.obj");
  CHECK(!findSelfIntersections(mesh).empty());
  const MeshRepairReport report = repairMesh(mesh);
  CHECK(anyLineContains(report.remaining, "intersects itself"));
  // In the overlap w = 2, in one cube only w = 1: both count as inside.
  CHECK(windingNumber<3>(mesh, Vec3(0.75, 0.75, 0.75)) == doctest::Approx(2.0).epsilon(1e-12));
  CHECK(insideByWindingNumber<3>(mesh, Vec3(0.25, 0.25, 0.25)));
  // The union's volume is 2 - 1/8, not the 2 that the divergence theorem would count.
  const int cells = 24;  // the cubes' faces fall on cell boundaries: exact
  const MassProperties<3> p = windingNumberMassProperties(mesh, 1.0, cells);
  CHECK(p.measure == doctest::Approx(2.0 - 0.125).epsilon(1e-12));
  CHECK(signedMeasure<3>(mesh) == doctest::Approx(2.0).epsilon(1e-12));
}
// [test_repair_overlap]

TEST_CASE("STL (ASCII and binary) and PLY read like OBJ") {
  for (const char* name : {"cube_ascii.stl", "cube_binary.stl"}) {
    CAPTURE(name);
    const TriangleMesh mesh = loadMeshFile(data(name));  // strict: exact corners merged
    CHECK(mesh.vertices.size() == 8);
    CHECK(mesh.faces.size() == 12);
    CHECK(signedMeasure<3>(mesh) == doctest::Approx(1.0).epsilon(1e-12));
  }
  CHECK(contains(strictError("cube_flipped.ply"), "cube_flipped.ply"));
  CHECK(contains(strictError("cube_flipped.ply"), "flipped"));
  TriangleMesh ply = loadRaw("cube_flipped.ply");
  const MeshRepairReport report = repairMesh(ply);
  CHECK(anyLineContains(report.repairs, "turned 2 faces"));
  CHECK(report.watertight());
}

TEST_CASE("Malformed STL files: the line or the header that is wrong") {
  const std::string vertex = strictError("bad_vertex.stl");
  CHECK(contains(vertex, "bad_vertex.stl: line 5"));
  CHECK(contains(vertex, "coordinate 2 ('abc') is not a number"));
  const std::string truncated = strictError("truncated_binary.stl");
  CHECK(contains(truncated, "truncated_binary.stl: the binary STL header announces 12 triangles (684 bytes)"));
  CHECK(contains(truncated, "654 bytes"));
  CHECK(contains(strictError("no_such_file.ply"), "does not exist"));
  try {
    loadMeshFile(data("cube.off"));
    FAIL("an unknown extension must be refused");
  } catch (const MeshError& e) {
    CHECK(contains(e.what(), "reads .obj, .stl and .ply"));
  }
}

TEST_CASE("Malformed PLY headers: the line that is wrong, before assimp reserves what the counts announce") {
  const std::string tail =
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const auto plyError = [](const std::string& text) {
    try {
      parseAssimpMesh(text, "bad.ply", ObjLoadSettings{});
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // A billion vertices announced in 150 bytes: refused from the header (assimp would
  // reserve more than 10 GB first).
  CHECK(contains(plyError("ply\nformat ascii 1.0\nelement vertex 1000000000\n" + tail),
                 "bad.ply: the PLY header announces elements of at least 6e+09 bytes, but the file has 26 bytes"));
  CHECK(contains(plyError("ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + tail),
                 "announces elements of at least 37 bytes"));
  CHECK(contains(plyError("ply\nformat ascii 1.0\nelement vertex -5\n" + tail),
                 "bad.ply: header line 3 ('element vertex -5'): the element count '-5' is not a non-negative integer"));
  CHECK(contains(plyError("ply\nformat ascii 1.0\nelement vertex 3\nproperty flaot w\n" + tail),
                 "header line 4 ('property flaot w'): unknown property type 'flaot'"));
  CHECK(contains(plyError("ply\nformat text 1.0\nelement vertex 3\n" + tail), "unknown format 'text'"));
  CHECK(contains(plyError("ply\nformat ascii 1.0\nelement vertex 3\n"), "no 'end_header' line"));
  CHECK(contains(plyError("solid x\n"), "not a PLY file"));
  // The same header with its true count reads (a single triangle: not a solid, but read).
  CHECK(contains(plyError("ply\nformat ascii 1.0\nelement vertex 3\n" + tail), "hole"));
}

TEST_CASE("orientFaces turns the one flipped triangle of a tetrahedron") {
  TriangleMesh mesh = loadRaw("flipped_face.obj");
  int conflicts = -1;
  const std::vector<int> turned = orientFaces(mesh, conflicts);
  CHECK(conflicts == 0);
  REQUIRE(turned.size() == 1);
  CHECK(turned[0] == 3);
  CHECK_NOTHROW(validateMesh<3>(mesh, "tetrahedron"));
}

}  // TEST_SUITE
