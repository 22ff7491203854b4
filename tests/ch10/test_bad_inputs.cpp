// Chapter 10: bad input as users (and fuzzers) bring it. Every input of the regression
// corpus (tests/ch10/corpus) gives the built `stackbook` one line on stderr naming the
// file and the JSON pointer, and exit code 1, within a bound on time (the command runs
// under `timeout`, so a hang fails the exit-code check rather than the test run); and
// every corpus file runs through the fuzz targets' bodies (tests/support/fuzz_inputs.hpp)
// as an ordinary test.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "stackbook/scene/scene.hpp"
#include "support/fuzz_inputs.hpp"
#include "support/run_program.hpp"

namespace bad_inputs {

namespace fs = std::filesystem;
using stackbook::test_support::kExitBadInput;
using stackbook::test_support::kExitOk;
using Outcome = stackbook::test_support::ProgramOutcome;

const fs::path kCorpus = fs::path(STACKBOOK_TEST_DATA_DIR).parent_path() / "corpus";

std::string slurp(const fs::path& p) { return stackbook::test_support::slurpFile(p); }

/// Runs `stackbook ARGUMENTS` in `workDir`; a bad input must be answered well within 120 s
/// (a hang ends as exit 124, a failed exit-code check).
Outcome runProgram(const std::string& arguments, const fs::path& workDir) {
  return stackbook::test_support::runProgram(arguments, workDir, 120);
}

/// A bad input: the corpus scene, the arguments after it, and the pointer the line names.
struct BadInput {
  const char* scene;
  const char* arguments;
  const char* pointer;
};

// [bad_inputs]
const BadInput kBadInputs[] = {
    // 1. nesting: refused at the depth limit, not a stack overflow
    {"deep_nesting.json", "", "/duration/0/0/0"},
    {"set_base.json", "--set \"duration=$(printf '%.0s[' $(seq 1000))\"", "/duration"},
    // 2. the library's words never reach the user
    {"number_overflow.json", "", "/duration"},
    {"nan_literal.json", "", "line 1, column 24: not valid JSON"},
    {"nan_literal.json", "", "JSON has no NaN or Infinity"},
    {"infinity_literal.json", "", "JSON has no NaN or Infinity: write a finite number"},
    {"set_base.json", "--set dt=1e999", "/dt"},
    {"set_base.json", "--set bodies.x.name=a", "/bodies/x"},
    {"set_base.json", "--set bodies.-1.name=a", "/bodies/-1"},
    {"set_base.json", "--set 'a~b=1'", "/a~b"},
    {"set_base.json", "--set dt.x=1", "/dt/x"},
    {"set_base.json", "--set solver.preset=shortLoops", "/solver/preset"},
    {"set_base.json", "--set \"$(printf 'bodies.1.name=\\377\\376')\"", "/bodies/1/name"},
    {"set_base.json", "--set \"$(printf 'description=\\377')\"", "/description"},
    {"invalid_utf8_name.json", "", "line 1"},
    // 3. a frame rate that used to hang the run
    {"huge_frame_rate.json", "", "/output/frameRate"},
    {"frames_memory.json", "", "/output/frameRate"},
    // 4. memory and time: estimated before anything large is built or run
    {"long_bone.json", "", "/bodies/1/shape/length"},
    {"bone_1e300.json", "", "/bodies/1/shape/length"},
    {"identical_bodies.json", "", "/bodies/2"},
    {"overlap_pairs.json", "", "/bodies/1"},
    {"too_many_steps.json", "", "/dt"},
    {"too_many_body_steps.json", "", "/dt"},
    // 5. what check accepts, run runs: derived quantities checked at the boundary
    {"tiny_size.json", "", "/bodies/1/shape/size/0"},
    {"tiny_mass.json", "", "/bodies/1/mass"},
    {"huge_quaternion.json", "", "/bodies/1/quaternion/2"},
    {"huge_angular_velocity.json", "", "/bodies/1/angularVelocity"},
    {"huge_gravity.json", "", "/gravity/1"},
    {"huge_angle.json", "", "/bodies/1/angleDeg"},
    {"huge_spacing.json", "", "/bodies/1/array/spacing/0"},
    // 6. silent wrong results
    {"huge_axis.json", "", "/bodies/1/axis/0"},
    {"huge_velocity.json", "", "/bodies/1/velocity/0"},
    // 7. misleading messages
    {"unsigned_integer.json", "", "/solver/contactIterations"},
    {"obj_subnormal.json", "", "/bodies/1/shape/file"},
    {"obj_overflow.json", "", "/bodies/1/shape/file"},
    {"obj_nul_byte.json", "", "/bodies/1/shape/file"},
    {"ply_huge_count.json", "", "/bodies/1/shape/file"},
    // paths that name something other than a file
    {"mesh_dev_zero.json", "", "/bodies/1/shape/file: the mesh file is not a regular file"},
    {"mesh_folder.json", "", "/bodies/1/shape/file: the mesh file is a folder"},
    {".", "", "the scene is a folder, not a file"},
    {"/dev/zero", "", "the scene is not a regular file"},
    // 8. outputs and keys
    {"duplicate_key.json", "", "/dt"},
    {"set_base.json", "--set bodies.1000000000.name=x", "/bodies/1000000000"},
    {"set_base.json", "--set bodies.5.name=x", "/bodies/5"},
    {"obj_self_intersecting.json", "", "/bodies/1/shape/file"},
    {"control_in_key.json", "", "/dura\\x0ation"},
};
// [bad_inputs]

/// What the line must say about each input, beyond the file and the pointer.
void checkOneLine(const Outcome& o, const std::string& file, const std::string& pointer) {
  CHECK(o.code == kExitBadInput);
  CHECK(std::count(o.err.begin(), o.err.end(), '\n') == 1);
  CHECK(o.err.rfind("stackbook: error: " + file + ": ", 0) == 0);
  CHECK(o.err.find(pointer) != std::string::npos);
  CHECK(o.err.find("json.exception") == std::string::npos);
  CHECK(std::none_of(o.err.begin(), o.err.end() - 1, [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7F || u >= 0x80;  // the corpus's messages are ASCII once escaped
  }));
}

std::vector<fs::path> corpusFiles(const char* folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kCorpus / folder)) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace bad_inputs

TEST_SUITE(STACKBOOK_CHAPTER) {

using namespace bad_inputs;  // NOLINT(google-build-using-namespace)
namespace fs = std::filesystem;

TEST_CASE("every bad input of the corpus gives check and run one line with the file and the pointer and exit 1") {
  for (const BadInput& input : kBadInputs) {
    for (const char* command : {"check", "run -q --out /tmp/stackbook_ch10_bad_inputs/out"}) {
      const std::string scene = input.scene, arguments = input.arguments, how = command;
      CAPTURE(scene);
      CAPTURE(arguments);
      CAPTURE(how);
      const Outcome o = runProgram(std::string(command) + " " + input.scene + " " + input.arguments, kCorpus / "scene");
      checkOneLine(o, input.scene, input.pointer);
    }
  }
}

TEST_CASE("a scene path that is not UTF-8 is escaped in the error line and written as U+FFFD in summary.json") {
  const fs::path dir = fs::temp_directory_path() / "stackbook_ch10_bad_inputs" / "bad\xff" "dir";
  fs::create_directories(dir);
  fs::copy_file(kCorpus / "scene" / "set_base.json", dir / "s.json", fs::copy_options::overwrite_existing);
  const Outcome bad = runProgram("check 'bad\xff" "dir/s.json' --set dt=-1", dir.parent_path());
  checkOneLine(bad, "bad\\xffdir/s.json", "/dt");
  const Outcome good = runProgram("run -q 'bad\xff" "dir/s.json' --out out_utf8", dir.parent_path());
  CHECK(good.code == kExitOk);
  const std::string summary = slurp(dir.parent_path() / "out_utf8" / "summary.json");
  CHECK(summary.find("bad\xef\xbf\xbd" "dir/s.json") != std::string::npos);
}

TEST_CASE("--out is probed before the run: a file, a folder under a file, a place nobody may write is one line and exit 1") {
  const fs::path dir = fs::temp_directory_path() / "stackbook_ch10_bad_inputs";
  fs::create_directories(dir);
  { std::ofstream(dir / "a_file") << "x"; }
  const std::string scene = (kCorpus / "scene" / "set_base.json").string();
  // The tests may run as root, for whom permission bits do not stop a write: the places
  // nobody can write are in /proc (no new folder can be made there, and its existing
  // folders take no new files).
  const std::pair<const char*, const char*> cases[] = {
      {"a_file", "exists and is not a folder"},
      {"a_file/sub", "cannot create the folder"},       // ENOTDIR
      {"/dev/null", "exists and is not a folder"},
      {"/proc/stackbook_out", "cannot create the folder"},
      {"/proc/self", "cannot write files in the folder"},
  };
  for (const auto& outAndReason : cases) {
    const std::string out = outAndReason.first, reason = outAndReason.second;  // CAPTURE cannot take a binding
    CAPTURE(out);
    // Without -q a run prints its summary on stdout: nothing there means nothing ran.
    const Outcome o = runProgram("run '" + scene + "' --out " + out, dir);
    CHECK(o.code == kExitBadInput);
    CHECK(std::count(o.err.begin(), o.err.end(), '\n') == 1);
    CHECK(o.err.rfind("stackbook: error: --out " + out + ": " + reason, 0) == 0);
    CHECK(o.out.empty());
  }
  // A good run leaves complete files only: no temporary name is left behind.
  const Outcome ok = runProgram("run -q '" + scene + "' --out good", dir);
  CHECK(ok.code == kExitOk);
  for (const auto& entry : fs::directory_iterator(dir / "good")) {
    CHECK(entry.path().extension() != ".part");
    CHECK(entry.path().filename().string().rfind(".stackbook-probe", 0) != 0);
  }
}

TEST_CASE("--dt, --duration and --threads are checked as the scene's fields: one line at their pointer, exit 1") {
  const std::pair<const char*, const char*> cases[] = {
      {"--dt abc", "/dt"},
      {"--dt 1e999", "/dt"},
      {"--duration nan", "/duration"},
      {"--duration -1", "/duration"},
      {"--threads abc", "/solver/threads"},
      {"--threads -1", "/solver/threads"},
      {"--threads 99999999999999999999", "/solver/threads"},  // not saturated to a valid-looking number
  };
  for (const auto& optionAndPointer : cases) {
    const std::string option = optionAndPointer.first;
    CAPTURE(option);
    const Outcome o = runProgram("run -q set_base.json " + option + " --out /tmp/stackbook_ch10_bad_inputs/out",
                                 kCorpus / "scene");
    checkOneLine(o, "set_base.json", optionAndPointer.second);
    CHECK(o.err.find("9223372036854775807") == std::string::npos);
  }
}

TEST_CASE("every scene of the corpus goes through the scene fuzz target's body without a finding") {
  for (const fs::path& file : corpusFiles("scene")) {
    if (file.extension() != ".json" && file.extension() != ".set") continue;
    CAPTURE(file.filename().string());
    CHECK(stackbook::fuzz::sceneInput(slurp(file), kCorpus / "scene") == "");
  }
}

TEST_CASE("every mesh of the corpus goes through the OBJ fuzz target's body without a finding") {
  for (const fs::path& file : corpusFiles("obj")) {
    CAPTURE(file.filename().string());
    CHECK(stackbook::fuzz::objInput(slurp(file)) == "");
  }
}

TEST_CASE("a frame rate far above 1/dt records every step and the run ends") {
  const Outcome o = runProgram("run -q fast_frames.json --out /tmp/stackbook_ch10_bad_inputs/fast", kCorpus / "scene");
  CHECK(o.code == kExitOk);
  CHECK(o.err.empty());
}

TEST_CASE("--set may append to an array (index = size) but never pads it") {
  nlohmann::json doc = nlohmann::json::parse(R"({"bodies": [{}, {}]})");
  stackbook::applySceneOverride(doc, "bodies.2.name=x", "f.json");
  CHECK(doc["bodies"].size() == 3);
  CHECK(doc["bodies"][2]["name"] == "x");
  CHECK_THROWS_AS(stackbook::applySceneOverride(doc, "bodies.9.name=x", "f.json"), stackbook::SceneError);
  CHECK(doc["bodies"].size() == 3);
}

}  // TEST_SUITE
