// Chapter 10: the stackbook program as a user runs it: exit codes, one error line on
// stderr for bad input, the files a run writes, the list of bundled scenes, help.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/damaged_mesh.hpp"
#include "support/run_program.hpp"

namespace fs = std::filesystem;

namespace {

using stackbook::test_support::kExitBadInput;
using stackbook::test_support::kExitOk;
using Outcome = stackbook::test_support::ProgramOutcome;

std::string slurp(const fs::path& p) { return stackbook::test_support::slurpFile(p); }

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / "stackbook_ch10_program";
  fs::create_directories(dir);
  return dir;
}

/// Runs the program with `arguments` (shell syntax) in `workDir`.
Outcome run(const std::string& arguments, const fs::path& workDir = scratch()) {
  Outcome o = stackbook::test_support::runProgram(arguments, workDir);
  REQUIRE_MESSAGE(o.code != -1, o.err);
  return o;
}

long lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("stackbook check accepts a bundled scene by name") {
  const Outcome o = run("check incline");
  CHECK(o.code == kExitOk);
  CHECK(o.out.find("incline.json: ok (2D, 4 bodies") != std::string::npos);
  CHECK(o.err.empty());
}

TEST_CASE("stackbook check of a bad scene exits 1 with one error line naming file and pointer") {
  const std::string file = std::string(STACKBOOK_TEST_DATA_DIR) + "/bad_mesh_missing.json";
  const Outcome o = run("check '" + file + "'");
  CHECK(o.code == kExitBadInput);
  CHECK(lines(o.err) == 1);
  CHECK(o.err.rfind("stackbook: error: " + file + ": /bodies/1/shape/file: no such mesh file", 0) == 0);
}

TEST_CASE("stackbook check --all-defects lists every defect of a refused mesh after its one line") {
  const stackbook::test_support::DamagedMesh damaged = stackbook::test_support::damagedBox(8, 12, 100);
  const fs::path dir = scratch() / "refused_mesh";
  fs::create_directories(dir);
  stackbook::test_support::writeMeshFile(damaged.mesh, dir / "character.obj");
  const nlohmann::json scene = {
      {"dimension", 3},
      {"bodies",
       {{{"static", true}, {"shape", {{"type", "box"}, {"size", {8, 8, 1}}}}, {"position", {0, 0, -0.5}}},
        {{"shape", {{"type", "mesh"}, {"file", "character.obj"}}}, {"position", {0, 0, 1}}}}}};
  std::ofstream(dir / "character.json") << scene.dump(2);
  const std::string file = (dir / "character.json").string();
  const Outcome plain = run("check '" + file + "'");
  CHECK(plain.code == kExitBadInput);
  CHECK(lines(plain.err) == 1);
  CHECK(plain.err.find("set \"meshMode\": \"repair\" to repair it (chapter 6)") != std::string::npos);
  const Outcome all = run("check --all-defects '" + file + "'");
  CHECK(all.code == kExitBadInput);
  CHECK(lines(all.err) == 1 + damaged.defects());
  CHECK(all.err.rfind(plain.err, 0) == 0);  // the same line first
  CHECK(all.err.find("\n  degenerate face: face ") != std::string::npos);
}

TEST_CASE("stackbook run of a missing scene exits 1 with one error line") {
  const Outcome o = run("run no_such_scene");
  CHECK(o.code == kExitBadInput);
  CHECK(lines(o.err) == 1);
  CHECK(o.err.find("no_such_scene: no such scene file") != std::string::npos);
}

TEST_CASE("An unknown option exits 1 with one error line") {
  const Outcome o = run("run incline --speed 3");
  CHECK(o.code == kExitBadInput);
  CHECK(lines(o.err) == 1);
  CHECK(o.err.find("--speed") != std::string::npos);
}

TEST_CASE("stackbook run writes the trajectory and the animation and the summary") {
  const fs::path out = scratch() / "incline_run";
  fs::remove_all(out);
  const Outcome o = run("run incline --duration 0.02 --set output.frameRate=100 --quiet --out '" + out.string() + "'");
  CHECK(o.code == kExitOk);
  CHECK(o.err.empty());
  CHECK(fs::is_regular_file(out / "trajectory.csv"));
  CHECK(fs::is_regular_file(out / "animation.svg"));
  REQUIRE(fs::is_regular_file(out / "summary.json"));
  const nlohmann::json s = nlohmann::json::parse(slurp(out / "summary.json"));
  CHECK(s.at("steps") == 20);
  CHECK(s.at("bodies") == 4);
  CHECK(s.at("frames") == 3);  // t = 0, 0.01, 0.02
  CHECK(s.at("files").size() == 4);  // trajectory.csv, energy.csv, animation.svg, summary.json
  CHECK(lines(slurp(out / "energy.csv")) == 1 + 3);
  CHECK(s.at("effects") == nlohmann::json{"gravity", "collision", "contact", "friction"});
  CHECK(s.at("pairOrder") == "list");  // the default; a scene's "colours" is said (below)
  // trajectory.csv: a header and 3 frames of 4 bodies.
  CHECK(lines(slurp(out / "trajectory.csv")) == 1 + 3 * 4);
}

TEST_CASE("stackbook run of a 3D scene writes the glTF animation and its viewer page") {
  const fs::path out = scratch() / "stack3d_run";
  fs::remove_all(out);
  const Outcome o = run("run box_stack_3d --dt 0.002 --duration 0.01 --quiet --out '" + out.string() + "'");
  CHECK(o.code == kExitOk);
  CHECK(fs::is_regular_file(out / "animation.glb"));
  CHECK(fs::is_regular_file(out / "viewer.html"));
  CHECK_FALSE(fs::exists(out / "animation.svg"));
  const nlohmann::json s = nlohmann::json::parse(slurp(out / "summary.json"));
  CHECK(s.at("steps") == 5);
  CHECK(s.at("pairOrder") == "list");
  CHECK(s.at("dt") == 0.002);
  CHECK(s.at("files").size() == 5);  // trajectory.csv, energy.csv, animation.glb, viewer.html, summary.json
  // The scene names no preset: the carrying pass (chapter 12) ran, and the straight stack of
  // cubes carries every load, so no body was found not carrying; the welded pass did not run.
  const nlohmann::json& freeze = s.at("freeze");
  CHECK(freeze.at("rule") == "whenItCarries");
  CHECK(freeze.at("uncarriedBodies") == 0);
  CHECK(s.at("weldedPass").at("enabled") == false);
  CHECK(s.at("weldedPass").at("passes") == 0);
}

TEST_CASE("stackbook run prints the summary with effects and stages and energy and files") {
  const fs::path out = scratch() / "balls_run";
  const Outcome o = run("run bouncing_balls_2d --duration 0.01 --out '" + out.string() + "'");
  CHECK(o.code == kExitOk);
  for (const char* part : {"5 bodies, 2D, 10 steps", "effects: gravity, collision, restitution", "collision",
                           "contact", "shockPropagation", "max penetration", "energy (kinetic + potential)",
                           "summary.json"}) {
    CHECK_MESSAGE(o.out.find(part) != std::string::npos, part);
  }
  CHECK(o.out.find("colour by colour") == std::string::npos);  // the list order is not announced
  // The colour order (chapter 10, "Colours") changes the result, so the summary says so.
  const Outcome coloured = run("run bouncing_balls_2d --duration 0.01 --threads 2 --set 'solver.pairOrder=\"colours\"' --out '" +
                               out.string() + "'");
  CHECK(coloured.code == kExitOk);
  CHECK(coloured.out.find("pairs swept colour by colour on 2 thread(s)") != std::string::npos);
  CHECK(nlohmann::json::parse(slurp(out / "summary.json")).at("pairOrder") == "colours");
}

TEST_CASE("stackbook list names every bundled scene with its description") {
  const Outcome o = run("list");
  CHECK(o.code == kExitOk);
  for (const auto& entry : fs::directory_iterator(STACKBOOK_SCENES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    CHECK_MESSAGE(o.out.find("  " + entry.path().stem().string() + " ") != std::string::npos, entry.path());
  }
  CHECK(o.out.find("Three blocks on a 30 degree incline") != std::string::npos);
}

TEST_CASE("Help is available for the program and every command") {
  for (const char* args : {"--help", "run --help", "check --help", "list --help"}) {
    const Outcome o = run(args);
    CAPTURE(args);
    CHECK(o.code == kExitOk);
    CHECK(o.out.find("Usage") != std::string::npos);
  }
  CHECK(run("run --help").out.find("--set") != std::string::npos);
}

}  // TEST_SUITE

TEST_SUITE(STACKBOOK_CHAPTER "_slow") {

TEST_CASE("stackbook without arguments runs the demo and says where its outputs are") {
  const fs::path dir = scratch() / "demo";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Outcome o = run("", dir);
  CHECK(o.code == kExitOk);
  CHECK(o.out.find("The demo's outputs are in " + (dir / "stackbook-out").string()) != std::string::npos);
  CHECK(fs::is_regular_file(dir / "stackbook-out" / "pyramid_2d" / "animation.svg"));
}

}  // TEST_SUITE
