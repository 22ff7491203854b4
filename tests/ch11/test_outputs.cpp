// Chapter 11 (what a user needs to measure): frames at whole step counts, so none is
// dropped; velocities in the trajectory; the energy at every frame.
#include <doctest/doctest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "stackbook/output/trajectory_csv.hpp"
#include "stackbook/scene/simulation.hpp"
#include "stackbook/scene/sweep.hpp"

using namespace stackbook;

namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("stackbook_ch11_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The frame steps of a run of `steps` steps, counted as runScene counts them.
std::int64_t countFrames(double frameRate, double dt, std::int64_t steps, bool& consecutive) {
  std::int64_t frames = 1, frame = 1, previous = 0;  // the frame at t = 0
  consecutive = true;
  for (std::int64_t n = 1; n <= steps; ++n) {
    if (n >= frameStep(frame, frameRate, dt) || n == steps) {
      ++frames;
      if (n != previous + 1) consecutive = false;
      previous = n;
      while (frameStep(frame, frameRate, dt) <= n) ++frame;
    }
  }
  return frames;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_frame_count]
TEST_CASE("frameRate = 1/dt records a frame after every step: 100 000 steps and 100 001 frames") {
  for (const double dt : {1e-3, 1e-4, 1.0 / 60.0, 7e-4, 3e-3}) {
    CAPTURE(dt);
    bool consecutive = false;
    CHECK(countFrames(1.0 / dt, dt, 100000, consecutive) == 100001);
    CHECK(consecutive);
  }
  // 30 frames per second at dt = 1e-3: frame f after step ceil(f * 1000 / 30).
  CHECK(frameStep(1, 30.0, 1e-3) == 34);
  CHECK(frameStep(3, 30.0, 1e-3) == 100);
  CHECK(frameStep(300, 30.0, 1e-3) == 10000);
  bool consecutive = false;
  CHECK(countFrames(30.0, 1e-3, 100000, consecutive) == 3001);  // t = 0 and 3000 frames, the last at the end
}
// [test_frame_count]

TEST_CASE("a run at frameRate = 1/dt records every step's time exactly and and velocities and energies") {
  // A ball in free fall from rest: v = -g t at frame t = n dt (semi-implicit Euler is exact
  // for velocity), E = K + U constant up to the integrator's first-order position error.
  const std::string text = R"({"dimension": 3, "gravity": [0, 0, -9.81], "dt": 0.001, "duration": 0.05,
    "output": {"frameRate": 1000},
    "bodies": [{"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "density": 1000,
                "position": [0, 0, 1], "angularVelocity": [0, 0, 2]}]})";
  const auto dir = scratch("frames");
  const auto path = dir / "fall.json";
  std::ofstream(path) << text;
  const Scene scene = loadScene(path.string());
  const SceneRun run = runScene(scene);
  const auto& r = std::get<RunResult<3>>(run);
  REQUIRE(r.recording.frameCount() == 51);
  for (std::size_t f = 0; f < r.recording.frameCount(); ++f) {
    CHECK(r.recording.times()[f] == static_cast<double>(f) * 0.001);
    CHECK(r.recording.velocities()[f][0].z() == doctest::Approx(-9.81 * r.recording.times()[f]).epsilon(1e-12));
    CHECK(r.recording.angularVelocities()[f][0].z() == doctest::Approx(2.0).epsilon(1e-12));
  }
  const double E0 = r.recording.energies().front().total();
  CHECK(r.recording.energies().front().kinetic > 0.0);
  CHECK(r.recording.energies().back().total() == doctest::Approx(E0).epsilon(1e-3));
  writeTrajectoryCsv(r.recording, (dir / "trajectory.csv").string());
  writeEnergyCsv(r.recording, (dir / "energy.csv").string());
  const auto rows = readSweepCsv((dir / "trajectory.csv").string());
  REQUIRE(rows.size() == 52);
  CHECK(rows[0] == std::vector<std::string>{"time", "body", "name", "x", "y", "z", "qw", "qx", "qy", "qz",
                                            "vx", "vy", "vz", "wx", "wy", "wz"});
  CHECK(std::stod(rows[51][12]) == r.recording.velocities()[50][0].z());
  CHECK(std::stod(rows[51][15]) == r.recording.angularVelocities()[50][0].z());
  const auto energy = readSweepCsv((dir / "energy.csv").string());
  REQUIRE(energy.size() == 52);
  CHECK(energy[0] == std::vector<std::string>{"time", "kinetic", "potential", "total"});
  CHECK(std::stod(energy[51][1]) == r.recording.energies()[50].kinetic);
  CHECK(std::stod(energy[51][2]) == r.recording.energies()[50].potential);
}

}  // TEST_SUITE
