// Chapter 6: loading OBJ files, and rejecting bad ones with the file and the defect named.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/geometry/obj_loader.hpp"
#include "geometry_helpers.hpp"

using namespace stackbook;
using stackbook::testing::contains;

namespace {

// STACKBOOK_CH06_DATA is set by tests/ch06/CMakeLists.txt to the folder of OBJ files.
std::string dataFile(const std::string& name) { return std::string(STACKBOOK_CH06_DATA) + "/" + name; }

// The message of the MeshError that loading `name` throws ("" if it loads).
std::string loadError(const std::string& name) {
  try {
    loadObjMesh(dataFile(name));
  } catch (const MeshError& error) {
    return error.what();
  }
  return "";
}

// The full sentences of the defects that error keeps ("kind: sentence", one per line).
std::string loadDefects(const std::string& name) {
  try {
    loadObjMesh(dataFile(name));
  } catch (const MeshError& error) {
    std::string all;
    for (const MeshDefect& d : error.defects()) all += std::string(meshDefectName(d.kind)) + ": " + d.message + "\n";
    return all;
  }
  return "";
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_obj_round_trip]
TEST_CASE("a box survives the OBJ round trip bit for bit") {
  const TriangleMesh box = boxMesh(Vec3(1.0, 0.6, 0.4), 3);
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("stackbook_ch06_box_" + std::to_string(::getpid()) + ".obj");
  saveObjMesh(box, path.string(), "box 1 x 0.6 x 0.4, 3 x 3 quads per face");
  const TriangleMesh loaded = loadObjMesh(path.string());
  std::filesystem::remove(path);
  REQUIRE(loaded.vertices.size() == box.vertices.size());
  REQUIRE(loaded.faces.size() == box.faces.size());
  for (std::size_t i = 0; i < box.vertices.size(); ++i) CHECK(loaded.vertices[i] == box.vertices[i]);
  for (std::size_t f = 0; f < box.faces.size(); ++f) CHECK(loaded.faces[f] == box.faces[f]);
}
// [test_obj_round_trip]

TEST_CASE("quadrilateral faces are triangulated and repeated corners are merged") {
  const TriangleMesh quads = loadObjMesh(dataFile("cube_quads.obj"));
  CHECK(quads.vertices.size() == 8);
  CHECK(quads.faces.size() == 12);
  CHECK(signedMeasure<3>(quads) == doctest::Approx(1.0).epsilon(1e-15));
  // Written face by face, the cube has 24 vertices; merged, it is closed with 8.
  const TriangleMesh split = loadObjMesh(dataFile("cube_split_vertices.obj"));
  CHECK(split.vertices.size() == 8);
  CHECK(split.faces.size() == 12);
  CHECK(signedMeasure<3>(split) == doctest::Approx(1.0).epsilon(1e-15));
  // Without merging the same file is 6 separate squares: every edge is a hole.
  ObjLoadSettings noMerge;
  noMerge.mergeTolerance = -1.0;
  CHECK_THROWS_WITH_AS(loadObjMesh(dataFile("cube_split_vertices.obj"), noMerge),
                       doctest::Contains("hole"), MeshError);
}

// [test_obj_errors]
TEST_CASE("bad OBJ files are rejected with the file and the defect named") {
  const std::string missing = loadError("no_such_file.obj");
  CHECK(contains(missing, "no_such_file.obj: cannot open the file: it does not exist"));

  const std::string malformed = loadError("malformed_vertex.obj");
  CHECK(contains(malformed, "malformed_vertex.obj: line 3 ('v 1 abc 0')"));
  CHECK(contains(malformed, "coordinate 2 ('abc') is not a number"));

  CHECK(contains(loadError("nan_vertex.obj"), "line 4 ('v 0 nan 0'): non-finite vertex coordinate 2"));
  CHECK(contains(loadError("bad_index.obj"),
                 "line 9 ('f 2 3 9'): face refers to vertex 9, but the file has 4 vertices"));
  CHECK(contains(loadError("no_faces.obj"), "no_faces.obj: the file contains no faces"));

  // A mesh that fails its checks: one line with the count of each kind and where the
  // first one is; the error keeps each defect's full sentence.
  const std::string open = loadError("open_box.obj");
  CHECK(contains(open, "open_box.obj: invalid triangle mesh"));
  CHECK(contains(open, "hole edges (first: edge"));
  CHECK(contains(loadDefects("open_box.obj"), "hole (open boundary): edge"));

  CHECK(contains(loadError("flipped_face.obj"), "1 flipped face (face 3)"));
  CHECK(contains(loadDefects("flipped_face.obj"), "inconsistent orientation (flipped face): face 3"));

  CHECK(contains(loadError("degenerate_triangle.obj"), "1 degenerate face (face 5)"));
  CHECK(contains(loadDefects("degenerate_triangle.obj"), "degenerate face: face 5 (vertices 1, 2, 4) has zero area"));

  CHECK(contains(loadError("inside_out.obj"), "faces oriented inward"));
  CHECK(contains(loadDefects("inside_out.obj"), "inward orientation: the enclosed volume is -0.166667"));
  for (const char* name : {"open_box.obj", "flipped_face.obj", "degenerate_triangle.obj", "inside_out.obj"}) {
    CAPTURE(name);
    CHECK(contains(loadError(name), "repairMesh() repairs it (chapter 6)"));
    CHECK(loadError(name).find('\n') == std::string::npos);
  }
}
// [test_obj_errors]

TEST_CASE("OBJ text with a face of two vertices or a zero index is malformed") {
  const std::string tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  CHECK_THROWS_WITH_AS(parseObjMesh(tetra + "f 1 2\n", "two.obj"),
                       doctest::Contains("two.obj: line 5 ('f 1 2'): malformed face: 2 vertices"),
                       MeshError);
  CHECK_THROWS_WITH_AS(parseObjMesh(tetra + "f 1 2 0\n", "zero.obj"),
                       doctest::Contains("'0' is not a vertex reference"), MeshError);
  // Negative indices count back from the last vertex defined: the tetrahedron loads.
  const TriangleMesh relative =
      parseObjMesh(tetra + "f -4 -2 -3\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n", "relative.obj");
  CHECK(signedMeasure<3>(relative) == doctest::Approx(1.0 / 6.0).epsilon(1e-15));
}

// The line checks and tinyobjloader must read the same lines: each input below was split
// differently by the two before tinyobjloader was given the checked lines only.
TEST_CASE("the OBJ line checks and tinyobjloader read the same lines, words and bytes") {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  const std::string f = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const double sixth = 1.0 / 6.0;
  CHECK(signedMeasure<3>(parseObjMesh(v + f, "tetra.obj")) == doctest::Approx(sixth).epsilon(1e-15));
  // A lone carriage return ends a line (old Mac files), for both readers: the face after
  // a comment is a face, and checked.
  std::string mac = v + f;
  std::replace(mac.begin(), mac.end(), '\n', '\r');
  CHECK(signedMeasure<3>(parseObjMesh(mac, "mac.obj")) == doctest::Approx(sixth).epsilon(1e-15));
  CHECK_THROWS_WITH_AS(parseObjMesh(v + f + "# a comment\rf 1 2 9\n", "cr.obj"),
                       doctest::Contains("cr.obj: line 10 ('f 1 2 9'): face refers to vertex 9, but the file has 4"),
                       MeshError);
  // A '#' starts a comment anywhere: tinyobjloader alone read "3#x 9" as vertices 3 and 9.
  CHECK(parseObjMesh(v + "f 1 3 2#x 9\n" + f.substr(8), "hash.obj").faces.size() == 4);
  // Vertical tab and form feed separate words for the checks; tinyobjloader alone read
  // "1\v3" as vertex 1, and "v\f0 0 0" as no vertex at all.
  CHECK(signedMeasure<3>(parseObjMesh("v\f0 0 0\n" + v.substr(8) + "f 1\v3 2\n" + f.substr(8), "vt.obj")) ==
        doctest::Approx(sixth).epsilon(1e-15));
  // A NUL byte ended the line for tinyobjloader, not for the checks: now it is an error.
  CHECK_THROWS_WITH_AS(parseObjMesh(v + f + std::string("f 1 2 3\0 9\n", 11), "nul.obj"),
                       doctest::Contains("nul.obj: line 9: a NUL byte: an OBJ file is text"), MeshError);
  // Lines the solid does not use are not given to tinyobjloader, which allocates 8192
  // values for each `t` line: 2000 of them would take more than 600 MB.
  std::string tags;
  for (int k = 0; k < 2000; ++k) tags += "t crease 8192/8192/8192\n";
  CHECK(parseObjMesh(tags + v + f, "tags.obj").faces.size() == 4);
  // A polygon's triangulation costs the square of its vertices per ear: at most 1000.
  std::string polygon = "f";
  for (int k = 0; k < 1001; ++k) polygon += " " + std::to_string(1 + k % 4);
  CHECK_THROWS_WITH_AS(parseObjMesh(v + polygon + "\n", "poly.obj"),
                       doctest::Contains("poly.obj: line 5 ('f 1 2 3 4 1 2 3 4"), MeshError);
  CHECK_THROWS_WITH_AS(parseObjMesh(v + polygon + "\n", "poly.obj"),
                       doctest::Contains("a face of 1001 vertices; at most 1000"), MeshError);
  // A message quotes at most 60 bytes of a line.
  try {
    parseObjMesh("v 1 2 " + std::string(100000, 'x') + "\n", "long.obj");
    FAIL("a long malformed line loaded");
  } catch (const MeshError& error) {
    CHECK(std::string(error.what()).size() < 300);
  }
}

}  // TEST_SUITE
