// Chapter 10: mesh files in scenes. Strict mode (the default) rejects a self-intersecting
// OBJ with one line naming the file, the field and the crossing; "meshMode": "repair"
// loads a downloaded-style mesh, says what it repaired (notes) and what is approximate
// (warnings), and gives it mass properties close to the intact solid's; bad values of the
// two new fields are named.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "stackbook/scene/scene.hpp"
#include "support/damaged_mesh.hpp"

using namespace stackbook;
using nlohmann::json;

namespace {

json meshScene(const json& shape) {
  return json{{"dimension", 3},
              {"bodies",
               {{{"name", "ground"}, {"static", true}, {"shape", {{"type", "box"}, {"size", {8, 8, 1}}}},
                 {"position", {0, 0, -0.5}}},
                {{"name", "download"}, {"shape", shape}, {"position", {0, 0, 0.5}}}}}};
}

std::string errorOf(const json& doc) {
  try {
    (void)parseScene(doc, "mesh.json", STACKBOOK_TEST_DATA_DIR);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("Strict mode names a self-intersecting OBJ in one line") {
  const std::string e = errorOf(meshScene({{"type", "mesh"}, {"file", "two_overlapping_cubes.obj"}}));
  CHECK(contains(e, "mesh.json: /bodies/1/shape/file: two_overlapping_cubes.obj: the surface intersects itself"));
  CHECK(contains(e, "passes through face"));
  CHECK(contains(e, "set \"meshMode\": \"repair\" to repair it (chapter 6)"));
  CHECK(e.find('\n') == std::string::npos);
}

// [test_scene_refused_mesh]
TEST_CASE("A downloaded mesh with 137 defects is refused in one short line, OBJ, STL and PLY alike") {
  const test_support::DamagedMesh damaged = test_support::damagedBox(8, 12, 100);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "stackbook_ch10_refused_mesh";
  std::filesystem::create_directories(dir);
  for (const std::string name : {"character.obj", "character.stl", "character.ply"}) {
    CAPTURE(name);
    test_support::writeMeshFile(damaged.mesh, dir / name);
    try {
      (void)parseScene(meshScene({{"type", "mesh"}, {"file", name}}), "mesh.json", dir);
      FAIL("no error");
    } catch (const SceneError& e) {
      const std::string line = e.what();
      CAPTURE(line);
      CHECK(line.find('\n') == std::string::npos);
      CHECK(line.size() <= 300);
      CHECK(line.rfind("mesh.json: /bodies/1/shape/file: " + name + ": invalid triangle mesh (", 0) == 0);
      // The counts per kind, each with its first place.
      CHECK(contains(line, "137 defects: 100 degenerate faces (first: face "));
      CHECK(contains(line, ", 36 hole edges (first: edge "));
      CHECK(contains(line, ", 1 flipped face (face "));
      CHECK(contains(line, "set \"meshMode\": \"repair\" to repair it (chapter 6)"));
      CHECK(contains(line, "stackbook check --all-defects"));
      // Every defect, each with its sentence, for `stackbook check --all-defects`.
      REQUIRE(e.details().size() == static_cast<std::size_t>(damaged.defects()));
      CHECK(contains(e.details().front(), "degenerate face: face "));
      CHECK(contains(e.details().front(), "repeats a vertex"));
      CHECK(contains(e.details().back(), "inconsistent orientation (flipped face): face "));
    }
    // With "meshMode": "repair" the same file loads.
    const Scene repaired = parseScene(meshScene({{"type", "mesh"}, {"file", name}, {"meshMode", "repair"}}), "mesh.json", dir);
    CHECK(repaired.bodyCount() == 2);
  }
}
// [test_scene_refused_mesh]

TEST_CASE("Repair mode: a welded mesh is exact, a damaged one approximate, and both say so") {
  {
    const Scene scene = parseScene(
        meshScene({{"type", "mesh"}, {"file", "cube_near_duplicates.obj"}, {"meshMode", "repair"}}), "mesh.json",
        STACKBOOK_TEST_DATA_DIR);
    REQUIRE(scene.notes.size() == 1);
    CHECK(contains(scene.notes[0], "mesh.json: /bodies/1/shape/file: welded 28 duplicate vertices"));
    CHECK(scene.warnings.empty());
    // The unit cube at density 1000 (the default): mass 1000 to the noise of the corners.
    const RigidBody<3>& cube = std::get<SceneBodies<3>>(scene.bodies).world.bodies.at(1);
    CHECK(cube.mass() == doctest::Approx(1000.0).epsilon(1e-7));
  }
  {
    const Scene scene = parseScene(
        meshScene({{"type", "mesh"}, {"file", "downloaded_l_block.obj"}, {"meshMode", "repair"}, {"sdfResolution", 24}}),
        "mesh.json", STACKBOOK_TEST_DATA_DIR);
    bool welded = false, turned = false, sliver = false, repeated = false;
    for (const std::string& n : scene.notes) {
      welded = welded || contains(n, "welded");
      turned = turned || contains(n, "turned 2 faces");
      sliver = sliver || contains(n, "dropped 1 degenerate faces");
      repeated = repeated || contains(n, "dropped 1 repeated faces");
    }
    CHECK(welded);
    CHECK(turned);
    CHECK(sliver);
    CHECK(repeated);
    REQUIRE(!scene.warnings.empty());
    CHECK(contains(scene.warnings[0], "mesh.json: /bodies/1/shape/file: approximate: holes"));
    // The L-block of three 0.15 m cubes: volume 3 (0.15)^3, at density 1000 a mass of
    // 10.125 kg. Its faces fall on the boundaries of the cells of Eq. (6.23) (h = 0.3 / 24),
    // so only the cells under the hole (a triangle of area 0.15^2, one cell deep) are in doubt.
    const RigidBody<3>& l = std::get<SceneBodies<3>>(scene.bodies).world.bodies.at(1);
    CHECK(std::abs(l.mass() - 10.125) <= 1000.0 * (0.15 * 0.15) * (0.3 / 24));
  }
}

TEST_CASE("Bad meshMode and weldTolerance values are named") {
  CHECK(contains(errorOf(meshScene({{"type", "mesh"}, {"file", "cube.obj"}, {"meshMode", "fix"}})),
                 "/bodies/1/shape/meshMode: must be \"strict\" or \"repair\", got \"fix\""));
  CHECK(contains(errorOf(meshScene({{"type", "mesh"}, {"file", "cube.obj"}, {"weldTolerance", 1e-5}})),
                 "/bodies/1/shape/weldTolerance: applies only with \"meshMode\": \"repair\""));
  CHECK(contains(errorOf(meshScene({{"type", "mesh"}, {"file", "cube.obj"}, {"meshMode", "repair"},
                                    {"weldTolerance", 0.5}})),
                 "/bodies/1/shape/weldTolerance: must be in [0, 0.01)"));
}

}  // TEST_SUITE
