// Chapter 10: bad scene files, tried as a new user would write them. Each gives one
// SceneError whose line names the file, the JSON pointer of the field and the reason.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "stackbook/scene/scene.hpp"

using namespace stackbook;

namespace {

/// A valid 2D scene: a static ground and a box resting on it, with one material.
const char* const kBaseScene = R"({
  "description": "base scene of the error table",
  "dimension": 2,
  "dt": 0.001,
  "duration": 0.5,
  "materials": {"wood": {"friction": 0.5, "restitution": 0.2}},
  "bodies": [
    {"name": "ground", "static": true, "shape": {"type": "box", "size": [4, 1]}, "position": [0, -0.5],
     "material": "wood"},
    {"name": "crate", "shape": {"type": "box", "size": [1, 1]}, "position": [0, 0.5], "density": 100,
     "material": "wood"}
  ]
})";

/// One row of the table: a JSON merge patch (RFC 7386) on the base scene, and what the
/// error must say.
struct BadCase {
  const char* what;
  const char* patch;
  const char* pointer;
  const char* reason;
};

const std::vector<BadCase>& badCases() {
  static const std::vector<BadCase> cases{
      {"top-level typo", R"({"gravty": [0, -9.81]})", "/gravty", "did you mean \"gravity\"?"},
      {"body field typo", R"({"bodies": [{"shape": {"type": "disk", "radius": 1}, "positon": [0, 3]}]})",
       "/bodies/0/positon", "did you mean \"position\"?"},
      {"shape field typo", R"({"bodies": [{"shape": {"type": "disk", "raduis": 1}}]})", "/bodies/0/shape/raduis",
       "did you mean \"radius\"?"},
      {"effect typo", R"({"effects": {"fricton": false}})", "/effects/fricton", "did you mean \"friction\"?"},
      {"dt as a string", R"({"dt": "0.001"})", "/dt", "expected a number, got the string \"0.001\""},
      {"NaN as a string", R"({"duration": "nan"})", "/duration", "expected a number, got the string \"nan\""},
      {"Infinity in a vector", R"({"gravity": [0, "-Infinity"]})", "/gravity/1",
       "expected a number, got the string \"-Infinity\""},
      {"boolean as a number", R"({"dt": true})", "/dt", "expected a number, got the boolean true"},
      {"negative size",
       R"({"bodies": [{"shape": {"type": "box", "size": [-1, 1]}, "position": [0, 5]}]})",
       "/bodies/0/shape/size/0", "must be > 0, got -1"},
      {"zero radius", R"({"bodies": [{"shape": {"type": "disk", "radius": 0}}]})", "/bodies/0/shape/radius",
       "must be > 0, got 0"},
      {"negative mass", R"({"bodies": [{"shape": {"type": "disk", "radius": 1}, "mass": -2}]})",
       "/bodies/0/mass", "must be > 0, got -2"},
      {"negative density", R"({"bodies": [{"shape": {"type": "disk", "radius": 1}, "density": -5}]})",
       "/bodies/0/density", "must be > 0, got -5"},
      {"unknown shape with a hint", R"({"bodies": [{"shape": {"type": "spher", "radius": 1}}]})",
       "/bodies/0/shape/type", "unknown shape type \"spher\" in 2D; did you mean \"sphere\"?"},
      {"unknown shape", R"({"bodies": [{"shape": {"type": "teapot"}}]})", "/bodies/0/shape/type",
       "unknown shape type \"teapot\""},
      {"mesh in 2D", R"({"bodies": [{"shape": {"type": "mesh", "file": "a.obj"}}]})", "/bodies/0/shape/type",
       "OBJ meshes are 3D only"},
      {"dimension 4", R"({"dimension": 4})", "/dimension", "must be 2 or 3, got the number 4"},
      {"dimension as a string", R"({"dimension": "3"})", "/dimension", "must be 2 or 3, got the string \"3\""},
      {"position of the wrong length", R"({"bodies": [{"shape": {"type": "disk", "radius": 1}, "position": [1]}]})",
       "/bodies/0/position", "expected an array of 2 numbers, got an array of 1 elements"},
      {"unknown material", R"({"bodies": [{"shape": {"type": "disk", "radius": 1}, "material": "wod"}]})",
       "/bodies/0/material", "unknown material \"wod\"; did you mean \"wood\"?"},
      {"restitution above one", R"({"materials": {"wood": {"restitution": 1.5}}})", "/materials/wood/restitution",
       "must be in [0, 1], got 1.5"},
      {"negative friction", R"({"materials": {"wood": {"friction": -0.1}}})", "/materials/wood/friction",
       "must be >= 0, got -0.1"},
      {"negative iterations", R"({"solver": {"contactIterations": -1}})", "/solver/contactIterations",
       "must be an integer in [0, 1000], got -1"},
      {"fractional iterations", R"({"solver": {"collisionIterations": 2.5}})", "/solver/collisionIterations",
       "expected an integer, got the number 2.5"},
      {"ramp of the wrong length", R"({"solver": {"contactIterations": 3, "contactRestitution": [-0.5, 0]}})",
       "/solver/contactRestitution", "must hold contactIterations = 3 values, got 2"},
      {"positive ramp value", R"({"solver": {"contactIterations": 2, "contactRestitution": [-0.5, 0.5]}})",
       "/solver/contactRestitution/1", "must be in [-1, 0], got 0.5"},
      {"unknown impulse point", R"({"solver": {"impulsePoint": "middle"}})", "/solver/impulsePoint",
       "must be \"deepest\", \"centre\" or \"patch\", got \"middle\""},
      {"unknown lever arms", R"({"solver": {"leverArms": "endPose"}})", "/solver/leverArms",
       "must be \"startPose\" or \"testedPose\", got \"endPose\""},
      {"held samples as a word", R"({"solver": {"heldSamples": "yes"}})", "/solver/heldSamples",
       "expected true or false, got the string \"yes\""},
      {"negative tie tolerance", R"({"solver": {"tieTolerance": -1e-6}})", "/solver/tieTolerance",
       "must be in [0, 1], got -1e-06"},
      {"unknown friction cone", R"({"solver": {"frictionCone": "pair"}})", "/solver/frictionCone",
       "must be \"impulse\" or \"step\", got \"pair\""},
      {"unknown solver preset", R"({"solver": {"preset": "short"}})", "/solver/preset",
       "must be \"gbf\", \"passAsContact\", \"passAsContactShortLoops\", \"gbfShortLoops\", \"passAsContactPatch\", \"weldedPass\" or \"carryingPass\", got \"short\""},
      {"welded pass without sweeps", R"({"solver": {"shock": {"welded": {"sweepsPerLevel": 0}}}})",
       "/solver/shock/welded/sweepsPerLevel", "must be an integer in [1, 100], got 0"},
      {"welded pass field typo", R"({"solver": {"shock": {"welded": {"bodyWeld": false}}}})",
       "/solver/shock/welded/bodyWeld", "did you mean \"bodyWelds\"?"},
      {"solver preset not a string", R"({"solver": {"preset": true}})", "/solver/preset",
       "expected a string, got the boolean true"},
      {"pass flag not a boolean", R"({"solver": {"shock": {"replacesContactStage": 1}}})",
       "/solver/shock/replacesContactStage", "expected true or false, got the number 1"},
      {"negative candidate reach", R"({"solver": {"candidateReach": -0.1}})", "/solver/candidateReach",
       "must be >= 0, got -0.1"},
      {"zero normal cosine", R"({"solver": {"impulsePointNormalCosine": 0}})",
       "/solver/impulsePointNormalCosine", "must be > 0, got 0"},
      {"static body with a mass",
       R"({"bodies": [{"static": true, "shape": {"type": "disk", "radius": 1}, "mass": 3}]})", "/bodies/0/mass",
       "a static body has no mass"},
      {"overlapping start",
       R"({"bodies": [{"name": "a", "shape": {"type": "disk", "radius": 1}},
                      {"name": "b", "shape": {"type": "disk", "radius": 1}, "position": [1.5, 0]}]})",
       "/bodies/0", "starts 0.5 inside body \"b\" (/bodies/1); move it or set \"allowOverlap\": true"},
      {"torus thicker than its radius", R"({"bodies": [{"shape": {"type": "annulus", "majorRadius": 1, "minorRadius": 2}}]})",
       "/bodies/0/shape/minorRadius", "must be smaller than majorRadius = 1"},
      {"array without spacing",
       R"({"bodies": [{"shape": {"type": "disk", "radius": 1}, "array": {"count": [2, 2]}}]})",
       "/bodies/0/array", "a body array needs \"spacing\""},
      {"bodies not an array", R"({"bodies": {"shape": "disk"}})", "/bodies", "expected an array of bodies, got an object"},
      {"colour out of range", R"({"bodies": [{"shape": {"type": "disk", "radius": 1}, "color": [0.5, 2, 0]}]})",
       "/bodies/0/color/1", "colour components must be in [0, 1], got 2"},
  };
  return cases;
}

std::filesystem::path scratchFile(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "stackbook_ch10_scene_errors";
  std::filesystem::create_directories(dir);
  return dir / name;
}

/// The SceneError that loading `text` from a file gives (fails the test if none).
SceneError errorOf(const std::string& text, const std::string& fileName) {
  const std::filesystem::path path = scratchFile(fileName);
  std::ofstream(path) << text;
  try {
    (void)loadScene(path.string());
  } catch (const SceneError& e) {
    return e;
  }
  FAIL("no SceneError for " << text);
  return SceneError("", "", "");
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("The base scene of the error table is valid") {
  const std::filesystem::path path = scratchFile("base.json");
  std::ofstream(path) << kBaseScene;
  const Scene scene = loadScene(path.string());
  CHECK(scene.bodyCount() == 2);
}

TEST_CASE("Every bad scene gives one line naming the file and the pointer and the reason") {
  int index = 0;
  for (const BadCase& c : badCases()) {
    CAPTURE(c.what);
    nlohmann::json doc = nlohmann::json::parse(kBaseScene);
    doc.merge_patch(nlohmann::json::parse(c.patch));
    const std::string fileName = "bad_" + std::to_string(index++) + ".json";
    const SceneError e = errorOf(doc.dump(2), fileName);
    const std::string line = e.what();
    CAPTURE(line);
    CHECK(e.pointer() == c.pointer);
    CHECK(e.reason().find(c.reason) != std::string::npos);
    CHECK(line.find(fileName) != std::string::npos);
    CHECK(line.find(std::string(c.pointer) + ": ") != std::string::npos);
    CHECK(line.find('\n') == std::string::npos);
  }
}

TEST_CASE("A JSON syntax error names the line and column") {
  const std::string file = std::string(STACKBOOK_TEST_DATA_DIR) + "/bad_syntax.json";
  try {
    (void)loadScene(file);
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK(e.file() == file);
    CHECK(e.pointer().empty());
    CHECK(e.reason().find("line 3, column 15: not valid JSON") != std::string::npos);
  }
}

TEST_CASE("A missing scene file is one error naming it") {
  const std::string file = std::string(STACKBOOK_TEST_DATA_DIR) + "/no_such_scene.json";
  CHECK_THROWS_WITH_AS((void)loadScene(file), (file + ": no such scene file").c_str(), SceneError);
}

TEST_CASE("A missing OBJ file is reported at the shape's file field with the resolved path") {
  const std::string file = std::string(STACKBOOK_TEST_DATA_DIR) + "/bad_mesh_missing.json";
  try {
    (void)loadScene(file);
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK(e.pointer() == "/bodies/1/shape/file");
    CHECK(e.reason().find("no such mesh file: ") != std::string::npos);
    CHECK(e.reason().find("meshes/no_such_mesh.obj") != std::string::npos);
  }
}

TEST_CASE("A mesh with a hole is rejected at the shape's file field") {
  const std::string file = std::string(STACKBOOK_TEST_DATA_DIR) + "/bad_mesh_open.json";
  try {
    (void)loadScene(file);
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK(e.pointer() == "/bodies/1/shape/file");
    // A repairable mesh's line says what is wrong and how to repair it (chapter 10).
    CHECK(e.reason().find("open_box.obj: invalid triangle mesh") != std::string::npos);
    CHECK(e.reason().find("hole edges (first: edge ") != std::string::npos);
    CHECK(e.reason().find("set \"meshMode\": \"repair\" to repair it (chapter 6)") != std::string::npos);
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
  }
}

TEST_CASE("A star in 3D is an unknown shape that says star is 2D only") {
  nlohmann::json doc = nlohmann::json::parse(kBaseScene);
  doc["dimension"] = 3;
  doc["bodies"] = nlohmann::json::parse(R"([{"shape": {"type": "star"}}])");
  try {
    (void)parseScene(doc, "star3d.json", ".");
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK(e.pointer() == "/bodies/0/shape/type");
    CHECK(e.reason().find("star is 2D only") != std::string::npos);
  }
}

TEST_CASE("Overlap is accepted when the scene allows it") {
  nlohmann::json doc = nlohmann::json::parse(kBaseScene);
  doc["bodies"][1]["position"] = {0.0, 0.3};  // 0.2 into the ground
  CHECK_THROWS_AS((void)parseScene(doc, "overlap.json", "."), SceneError);
  doc["allowOverlap"] = true;
  CHECK(parseScene(doc, "overlap.json", ".").bodyCount() == 2);
}

TEST_CASE("An override without an equals sign is an error naming the option") {
  nlohmann::json doc = nlohmann::json::parse(kBaseScene);
  CHECK_THROWS_WITH_AS(applySceneOverride(doc, "dt", "s.json"),
                       "s.json: --set expects key=value (e.g. dt=0.0005), got \"dt\"", SceneError);
}

TEST_CASE("Overrides are checked like the file") {
  const std::filesystem::path path = scratchFile("override.json");
  std::ofstream(path) << kBaseScene;
  try {
    (void)loadScene(path.string(), {"bodies.1.velocity=[1, \"fast\"]"});
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK(e.pointer() == "/bodies/1/velocity/1");
    CHECK(e.reason() == "expected a number, got the string \"fast\"");
  }
}

TEST_CASE("Edit distance counts insertions and deletions and substitutions") {
  CHECK(editDistance("kitten", "sitting") == 3);
  CHECK(editDistance("", "abc") == 3);
  CHECK(editDistance("gravity", "gravity") == 0);
  CHECK(editDistance("gravty", "gravity") == 1);
}

TEST_CASE("A hint is offered only for a plausible typo") {
  const std::vector<std::string> keys{"position", "velocity", "material"};
  CHECK(closestName("positon", keys) == "position");
  CHECK(closestName("Velocity", keys) == "velocity");
  CHECK(closestName("colour", keys).empty());
}

}  // TEST_SUITE
