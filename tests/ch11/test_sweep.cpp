// Chapter 11 (the sweep command): the spec parser's one-line errors, a tiny sweep's rows,
// resuming, determinism, the independent command lines of --list, and the first-order
// claim the chapter makes about the time step.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "stackbook/body/torque_free.hpp"
#include "stackbook/scene/sweep.hpp"
#include "support/run_program.hpp"

using namespace stackbook;
namespace fs = std::filesystem;

namespace {

fs::path sweepScratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("stackbook_ch11_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

/// A ball dropped from rest for 0.1 s (no floor): semi-implicit Euler gives v = -g T exactly
/// and z = z0 - g T^2/2 - g T dt/2, an error of exactly first order in dt.
const char* kFallScene = R"({"dimension": 3, "gravity": [0, 0, -10], "dt": 0.001, "duration": 0.1,
  "bodies": [{"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "mass": 1,
              "position": [0, 0, 1]}]})";

const char* kFallSpec = R"({"name": "fall", "scene": "fall.json",
  "knobs": [{"key": "dt", "values": [0.004, 0.002, 0.001]},
            {"key": "solver.contactIterations", "values": [10, 5]}],
  "errors": [{"name": "height", "quantity": "position", "body": 0, "axis": 2, "expected": 0.95},
             {"name": "speed", "quantity": "velocity", "body": 0, "axis": 2, "expected": -1.0}]})";

std::string specError(const std::string& text) {
  const fs::path dir = sweepScratch("spec_error");
  write(dir / "fall.json", kFallScene);
  write(dir / "bad.json", text);
  try {
    loadSweepSpec((dir / "bad.json").string());
  } catch (const SceneError& e) {
    const std::string what = e.what();
    CHECK(what.find('\n') == std::string::npos);
    CHECK(what.rfind((dir / "bad.json").string(), 0) == 0);  // starts with the file
    return what.substr((dir / "bad.json").string().size());
  }
  FAIL("no error for " << text);
  return "";
}

using stackbook::test_support::programPath;

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_sweep_parser]
TEST_CASE("sweep spec errors are one line naming the file and the field and what is wrong") {
  CHECK(specError("{\"scene\": \"fall.json\", \"knobs\": [}") .rfind(": line 1, column ", 0) == 0);
  CHECK(specError(R"({"knobs": [{"key": "dt", "values": [1e-3]}], "errors": [{"quantity": "energyDrift"}]})") ==
        ": missing field \"scene\"");
  CHECK(specError(R"({"scene": "fall.json", "knobs": [{"key": "dt", "value": [1e-3]}], "errors": [{"quantity": "energyDrift"}]})") ==
        ": /knobs/0/value: unknown field (did you mean \"values\"?)");
  CHECK(specError(R"({"scene": "fall.json", "knobs": [{"key": "dt", "values": []}], "errors": [{"quantity": "energyDrift"}]})") ==
        ": /knobs/0/values: must be a non-empty array");
  CHECK(specError(R"({"scene": "fall.json", "knobs": [{"key": "dt", "values": [1e-3]}], "errors": [{"quantity": "energyDrfit"}]})") ==
        ": /errors/0/quantity: unknown quantity \"energyDrfit\" (did you mean \"energyDrift\"?)");
  CHECK(specError(R"({"scene": "fall.json", "knobs": [{"key": "dt", "values": [1e-3]}], "errors": [{"quantity": "rollingStart"}]})") ==
        ": /errors/0: missing field \"radius\" (rollingStart needs the ball's radius)");
  CHECK(specError(R"({"scene": "fall.json", "knobs": [{"key": "dt", "values": [1e-3]}], "errors": [{"quantity": "position", "axis": 3}]})") ==
        ": /errors/0/axis: must be 0, 1 or 2, got 3");
  CHECK(specError(R"({"scene": "fall.json", "knobs": [{"key": "dt", "values": [1e-3]}, {"key": "dt", "values": [2]}], "errors": [{"quantity": "maxPenetration"}]})") ==
        ": /knobs/1/key: \"dt\" is already a knob");
}
// [test_sweep_parser]

// [test_sweep_rows]
TEST_CASE("a tiny sweep writes one row per run and resumes without rerunning and and is deterministic") {
  const fs::path dir = sweepScratch("sweep_rows");
  write(dir / "fall.json", kFallScene);
  write(dir / "fall_sweep.json", kFallSpec);
  const SweepSpec spec = loadSweepSpec((dir / "fall_sweep.json").string());
  const std::vector<SweepRun> runs = sweepRuns(spec);
  REQUIRE(runs.size() == 6);
  CHECK(runs[1].knob == "dt");
  CHECK(runs[1].value == "0.002");
  CHECK(runs[1].config == "solver.contactIterations=10");
  CHECK(runs[4].config == "solver.contactIterations=5");

  SweepOptions options;
  options.csvPath = (dir / "out" / "fall.csv").string();
  options.jobs = 2;
  CHECK(runSweep(spec, options) == 6);
  const auto rows = readSweepCsv(options.csvPath);
  REQUIRE(rows.size() == 7);
  CHECK(rows[0] == std::vector<std::string>{"run", "scene", "engine", "config", "knob", "value", "steps",
                                            "ms_per_step", "ms_per_simulated_second", "height", "speed"});
  for (std::size_t r = 1; r < rows.size(); ++r) {
    CHECK(rows[r][0] == std::to_string(r - 1));  // index order, whichever worker finished first
    CHECK(rows[r][1] == "fall");
    CHECK(rows[r][2] == "stackbook");
  }
  // The closed forms: speed exact, height off by g T dt / 2 (relative to 0.95).
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const double dt = std::stod(rows[r][5]);
    CHECK(std::stod(rows[r][6]) == static_cast<double>(std::lround(0.1 / dt)));
    CHECK(std::stod(rows[r][9]) == doctest::Approx(10.0 * 0.1 * dt / 2.0 / 0.95).epsilon(1e-9));
    CHECK(std::stod(rows[r][10]) < 1e-12);
  }
  // Resume: nothing left to do; a lost row is remade, identical to the first time.
  CHECK(runSweep(spec, options) == 0);
  std::ifstream in(options.csvPath);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  in.close();
  std::ofstream cut(options.csvPath, std::ios::trunc);
  for (std::size_t k = 0; k + 2 < lines.size(); ++k) cut << lines[k] << "\n";
  cut.close();
  CHECK(runSweep(spec, options) == 2);
  const auto again = readSweepCsv(options.csvPath);
  REQUIRE(again.size() == 7);
  for (std::size_t r = 1; r < again.size(); ++r) {
    CHECK(again[r][0] == rows[r][0]);
    CHECK(again[r][9] == rows[r][9]);  // errors bit-identical (the costs are wall time)
    CHECK(again[r][10] == rows[r][10]);
  }
}
// [test_sweep_rows]

TEST_CASE("the time step's error is first order: halving dt halves the height error") {
  const fs::path dir = sweepScratch("sweep_order");
  write(dir / "fall.json", kFallScene);
  write(dir / "fall_sweep.json", kFallSpec);
  const SweepSpec spec = loadSweepSpec((dir / "fall_sweep.json").string());
  const std::vector<SweepRun> runs = sweepRuns(spec);
  const double e4 = runSweepRun(spec, runs[0]).errors[0], e2 = runSweepRun(spec, runs[1]).errors[0],
               e1 = runSweepRun(spec, runs[2]).errors[0];
  CHECK(e4 / e2 == doctest::Approx(2.0).epsilon(1e-6));
  CHECK(e2 / e1 == doctest::Approx(2.0).epsilon(1e-6));
}

TEST_CASE("the windowed self-consistency error of a fall is the first-order gap g T (dt - dt / refine) / 2") {
  // Each window restarts both runs from the fine state: the velocity is exact in both, and
  // over a window T the positions part by g T dt / 2 - g T (dt / refine) / 2 (Eq. (11.3)).
  const fs::path dir = sweepScratch("sweep_windowed");
  write(dir / "fall.json", kFallScene);
  write(dir / "windowed.json", R"({"scene": "fall.json", "knobs": [{"key": "dt", "values": [0.004, 0.002]}],
    "errors": [{"name": "windowed", "quantity": "windowed", "windows": 3, "window": 0.02, "refine": 8}]})");
  const SweepSpec spec = loadSweepSpec((dir / "windowed.json").string());
  const std::vector<SweepRun> runs = sweepRuns(spec);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const double dt = k == 0 ? 0.004 : 0.002;
    CHECK(runSweepRun(spec, runs[k]).errors[0] ==
          doctest::Approx(10.0 * 0.02 * (dt - dt / 8.0) / 2.0).epsilon(1e-9));
  }
}

TEST_CASE("the chapter's sweep specs load and and their expected values are the closed forms") {
  const std::string dir = std::string(STACKBOOK_SOURCE_DIR) + "/docs/sweeps/";
  const double v0 = 5.0, mu = 0.2, g = 9.81;
  const SweepSpec ball = loadSweepSpec(dir + "slide_roll_3d_sweep.json");
  CHECK(ball.errors.at(0).expected == doctest::Approx(5.0 * v0 / 7.0).epsilon(1e-15));
  CHECK(ball.errors.at(1).expected == doctest::Approx(2.0 * v0 / (7.0 * mu * g)).epsilon(1e-15));
  const SweepSpec disk = loadSweepSpec(dir + "slide_roll_2d_sweep.json");
  CHECK(disk.errors.at(0).expected == doctest::Approx(2.0 * v0 / 3.0).epsilon(1e-15));
  CHECK(disk.errors.at(1).expected == doctest::Approx(v0 / (3.0 * mu * g)).epsilon(1e-15));
  const SweepSpec box = loadSweepSpec(dir + "tumbling_box_sweep.json");
  const Vec3 I = Vec3(0.4 * 0.4 + 0.6 * 0.6, 0.2 * 0.2 + 0.6 * 0.6, 0.2 * 0.2 + 0.4 * 0.4) / 12.0;
  const TorqueFreeInvariants inv = torqueFreeInvariants(I, Vec3(0.1, 10.0, 0.1));
  CHECK(box.errors.at(0).expected ==
        doctest::Approx(polhodePeriod(I, inv.energy, inv.momentumSquared).period).epsilon(1e-12));
  // A ball resting on the top ball (centre 0.6 m up the axis) of a bone tilted by 3 degrees:
  // its centre 0.3 + 0.1 m straight above that ball's centre.
  const double tilt = 3.0 * M_PI / 180.0;
  const SweepSpec grid3 = loadSweepSpec(dir + "sdf_resolution_3d_sweep.json");
  CHECK(grid3.errors.at(0).expected == doctest::Approx(0.6 * std::cos(tilt) + 0.4).epsilon(1e-15));
  const Scene resting = loadScene(grid3.scene);
  CHECK(std::get<SceneBodies<3>>(resting.bodies).world.bodies.at(1).position.x() == doctest::Approx(0.6 * std::sin(tilt)).epsilon(1e-15));
  const SweepSpec samples3 = loadSweepSpec(dir + "samples_3d_sweep.json");
  CHECK(samples3.errors.at(0).expected == doctest::Approx(5.0 * v0 / 7.0).epsilon(1e-15));
  for (const SweepSpec* spec : {&ball, &disk, &box, &grid3, &samples3}) CHECK_NOTHROW(loadScene(spec->scene));
}

TEST_CASE("a plot labels a knob value briefly: 4 digits, a time step by its reciprocal, words as written") {
  CHECK(sweepValueLabel("0.016666666666666666") == "1/60");
  CHECK(sweepValueLabel("0.0020833333333333333") == "1/480");
  CHECK(sweepValueLabel("0.001") == "0.001");
  CHECK(sweepValueLabel("0.0005") == "0.0005");
  CHECK(sweepValueLabel("16") == "16");
  CHECK(sweepValueLabel("0.123456") == "0.1235");  // not a reciprocal: rounded, not renamed
  CHECK(sweepValueLabel("true") == "true");
  CHECK(sweepValueLabel("\"deepestPoint\"") == "\"deepestPoint\"");
}

TEST_CASE("the summary across sweeps keeps per scene and accuracy the cheapest run of every sweep of that scene") {
  // Two sweeps of the same scene, rows written here: the cheapest run within each accuracy is
  // taken over both, named with its sweep and its fixed overrides; a peer's likewise.
  const fs::path dir = sweepScratch("summary");
  write(dir / "fall.json", kFallScene);
  write(dir / "a.json", R"({"name": "a", "scene": "fall.json", "knobs": [{"key": "dt", "values": [0.004, 0.002, 0.001]}],
    "errors": [{"name": "height", "quantity": "position", "body": 0, "axis": 2, "expected": 0.95}]})");
  write(dir / "b.json", R"({"name": "b", "scene": "fall.json", "set": ["solver.contactIterations=5"],
    "knobs": [{"key": "dt", "values": [0.004, 0.002, 0.001]}],
    "errors": [{"name": "height", "quantity": "position", "body": 0, "axis": 2, "expected": 0.95}]})");
  const SweepSpec a = loadSweepSpec((dir / "a.json").string()), b = loadSweepSpec((dir / "b.json").string());
  write(dir / "a.csv", sweepCsvHeader(a) +
                           "0,fall.json,stackbook,-,dt,0.004,25,0.4,10,0.02\n"
                           "1,fall.json,stackbook,-,dt,0.002,50,0.4,20,0.005\n"
                           "2,fall.json,stackbook,-,dt,0.001,100,0.4,40,0.0004\n"
                           "3,fall.json,Box2D 2.4.1,velocityIterations=8,dt,0.004,25,0.04,1,0.003\n");
  write(dir / "b.csv", sweepCsvHeader(b) +
                           "0,fall.json,stackbook,-,dt,0.004,25,0.3,7.5,0.03\n"
                           "1,fall.json,stackbook,-,dt,0.002,50,0.3,15,0.008\n"
                           "2,fall.json,stackbook,-,dt,0.001,100,0.3,30,0.0009\n");
  const std::string table = sweepSummaryTable({a, b}, {(dir / "a.csv").string(), (dir / "b.csv").string()});
  std::istringstream lines(table);
  std::vector<std::string> line;
  for (std::string l; std::getline(lines, l);) line.push_back(l);
  REQUIRE(line.size() == 5);  // header, rule, 1 %, 0.1 %, 0.01 %
  CHECK(line[0].find("cheapest peer run") != std::string::npos);
  CHECK(line[2] == "| fall.json | height (position against 0.95) | 1 % | dt = 0.002, solver.contactIterations=5 (b) | "
                   "0.008 | 15 | Box2D 2.4.1: dt = 0.004, velocityIterations=8 (a) | 0.003 | 1 |");
  CHECK(line[3] == "| fall.json | height (position against 0.95) | 0.1 % | dt = 0.001, solver.contactIterations=5 (b) | "
                   "0.0009 | 30 | none | | |");
  CHECK(line[4] == "| fall.json | height (position against 0.95) | 0.01 % | none | | | none | | |");
  CHECK_THROWS(sweepSummaryTable({a, b}, {(dir / "a.csv").string()}));
}

TEST_CASE("the Pareto front keeps the runs no other run beats on both cost and error") {
  const std::vector<double> cost = {1.0, 2.0, 3.0, 2.5, 4.0};
  const std::vector<double> error = {0.5, 0.2, 0.3, 0.1, 0.1};
  CHECK(paretoFront(cost, error) == std::vector<std::size_t>{0, 1, 3});
}

TEST_CASE("stackbook sweep --list prints one independent command line per run and and a bad spec "
          "is one line on stderr with exit code 1") {
  const fs::path program = programPath();
  REQUIRE_MESSAGE(!program.empty(), "the stackbook program is not built");
  const fs::path dir = sweepScratch("sweep_list");
  write(dir / "fall.json", kFallScene);
  write(dir / "fall_sweep.json", kFallSpec);
  const std::string out = (dir / "list.txt").string(), err = (dir / "err.txt").string();
  const std::string list = "cd '" + dir.string() + "' && '" + program.string() + "' sweep fall_sweep.json --list >'" +
                           out + "' 2>'" + err + "'";
  REQUIRE(std::system(list.c_str()) == 0);
  std::ifstream in(out);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  REQUIRE(lines.size() == 6);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    CHECK(lines[k] == "stackbook sweep fall_sweep.json --csv stackbook-out/sweeps/fall.csv --no-plot --jobs 1 --run " +
                          std::to_string(k));
  }
  // Run two of the listed lines as a cluster would, each on its own: two rows.
  for (const std::size_t k : {std::size_t{4}, std::size_t{1}}) {
    std::string line = lines[k];
    line.replace(0, std::string("stackbook").size(), "'" + program.string() + "'");
    REQUIRE(std::system(("cd '" + dir.string() + "' && " + line + " >/dev/null 2>&1").c_str()) == 0);
  }
  const auto rows = readSweepCsv((dir / "stackbook-out" / "sweeps" / "fall.csv").string());
  REQUIRE(rows.size() == 3);
  CHECK(rows[1][0] == "4");
  CHECK(rows[2][0] == "1");

  write(dir / "bad.json", R"({"scene": "fall.json", "knobs": [{"key": "dt", "values": 3}], "errors": []})");
  const std::string bad = "cd '" + dir.string() + "' && '" + program.string() + "' sweep bad.json >'" + out +
                          "' 2>'" + err + "'";
  const int status = std::system(bad.c_str());
  CHECK(WEXITSTATUS(status) == stackbook::test_support::kExitBadInput);
  std::ifstream e(err);
  std::string message((std::istreambuf_iterator<char>(e)), std::istreambuf_iterator<char>());
  CHECK(message == "stackbook: error: bad.json: /knobs/0/values: must be a non-empty array\n");
}

}  // TEST_SUITE
