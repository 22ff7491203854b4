// Chapter 10: the contacts output. contacts.csv has the documented columns, one row per
// impulse the run applied; the impulses in it, read back from the text, account for a
// dropped box's momentum change; asking for contacts changes no bit of the trajectory;
// the SVG and glTF outputs draw them only when asked.
#include <doctest/doctest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "output_fixtures.hpp"
#include "stackbook/output/animated_gltf.hpp"
#include "stackbook/output/animated_svg.hpp"
#include "stackbook/output/contacts_csv.hpp"
#include "stackbook/output/csv.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stacking/welded_pass.hpp"
#include "stackbook/stepping/traditional_step.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;
using nlohmann::json;

namespace {

/// A box dropped with a sideways velocity onto a static ground (dimension D), recording
/// `frameRate` frames per second, with the contacts output on or off.
template <int D>
json droppedBoxScene(bool contacts, double frameRate = 50.0) {
  json ground = D == 2 ? json{{"name", "ground"}, {"static", true}, {"shape", {{"type", "box"}, {"size", {8, 1}}}},
                              {"position", {0, -0.5}}}
                       : json{{"name", "ground"}, {"static", true}, {"shape", {{"type", "box"}, {"size", {8, 8, 1}}}},
                              {"position", {0, 0, -0.5}}};
  json box = D == 2 ? json{{"name", "box, dropped"}, {"shape", {{"type", "box"}, {"size", {1, 1}}}},
                           {"position", {0, 0.55}}, {"velocity", {0.5, -0.3}}, {"angularVelocity", 0.4}}
                    : json{{"name", "box, dropped"}, {"shape", {{"type", "box"}, {"size", {1, 1, 1}}}},
                           {"position", {0, 0, 0.55}}, {"velocity", {0.5, 0.1, -0.3}},
                           {"angularVelocity", {0.2, 0.4, 0}}};
  ground["material"] = "rubber";
  box["material"] = "rubber";
  return json{{"dimension", D},
              {"dt", 0.001},
              {"duration", 0.4},
              {"materials", {{"rubber", {{"friction", 0.4}, {"restitution", 0.3}}}}},
              {"output", {{"frameRate", frameRate}, {"contacts", contacts}}},
              {"bodies", {ground, box}}};
}

/// The fields of one CSV line (the line feed was taken off by getline).
std::vector<std::string> splitCsvLine(const std::string& line) { return csvRecords(line + "\n").at(0); }

template <int D>
const RunResult<D>& resultOf(const SceneRun& run) {
  return std::get<RunResult<D>>(run);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_contacts_columns]
TEST_CASE_TEMPLATE("contacts.csv: the documented columns, one row per impulse of the run", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const Scene scene = parseScene(droppedBoxScene<D>(true), "drop.json", ".");
  const SceneRun run = runScene(scene);
  const RunResult<D>& r = resultOf<D>(run);
  const std::int64_t impulses = r.counters.collision.impulses + r.counters.contact.impulses + r.counters.shock.impulses;
  REQUIRE(impulses > 0);
  CHECK(r.recording.contacts().size() == static_cast<std::size_t>(impulses));
  CHECK(runSummaryJson(scene, run).at("contacts").get<std::int64_t>() == impulses);

  const auto path = scratchFolder("contacts_columns") / "contacts.csv";
  writeContactsCsv<D>(r.recording, path.string());
  std::istringstream in(readWhole(path));
  std::string line;
  REQUIRE(std::getline(in, line));
  CHECK(line == (D == 2 ? "frame,time,stage,bodyA,nameA,bodyB,nameB,x,y,nx,ny,jx,jy"
                        : "frame,time,stage,bodyA,nameA,bodyB,nameB,x,y,z,nx,ny,nz,jx,jy,jz"));
  std::size_t rows = 0;
  std::size_t previousFrame = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = splitCsvLine(line);
    REQUIRE(f.size() == static_cast<std::size_t>(7 + 3 * D));
    const std::size_t frame = std::stoul(f[0]);
    const double time = std::strtod(f[1].c_str(), nullptr);
    CHECK(frame >= previousFrame);  // rows in the order the steps applied them
    previousFrame = frame;
    REQUIRE(frame < r.recording.frameCount());
    CHECK(time <= r.recording.times()[frame]);  // the step leads to its frame
    CHECK((frame == 0 || time > r.recording.times()[frame - 1]));
    CHECK((f[2] == "collision" || f[2] == "contact" || f[2] == "shock"));
    CHECK(((f[3] == "0" && f[4] == "ground" && f[5] == "1") || (f[3] == "1" && f[5] == "0" && f[6] == "ground")));
    CHECK((f[4] == "box, dropped" || f[6] == "box, dropped"));  // a comma: the name is quoted
    double n2 = 0.0;
    for (int k = 0; k < D; ++k) n2 += std::pow(std::strtod(f[static_cast<std::size_t>(7 + D + k)].c_str(), nullptr), 2);
    CHECK(std::abs(n2 - 1.0) < 1e-12);  // a unit normal
    ++rows;
  }
  CHECK(rows == static_cast<std::size_t>(impulses));
}
// [test_contacts_columns]

// [test_contacts_momentum]
TEST_CASE_TEMPLATE("contacts.csv: the impulses on the box add up to its momentum change", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const Scene scene = parseScene(droppedBoxScene<D>(true), "drop.json", ".");
  const SceneRun run = runScene(scene);
  const RunResult<D>& r = resultOf<D>(run);
  const auto path = scratchFolder("contacts_momentum") / "contacts.csv";
  writeContactsCsv<D>(r.recording, path.string());

  // The same run by hand, to know the final velocity (the recording keeps poses only);
  // it is the same trajectory bit for bit, which the last pose confirms.
  World<D> world = std::get<SceneBodies<D>>(scene.bodies).world;
  const RigidBody<D> start = world.bodies[1];
  const auto steps = static_cast<int>(std::ceil(scene.duration / scene.settings.dt - 1e-9));
  const PostContactHook<D> hook = shockPropagationHook<D>();
  for (int n = 0; n < steps; ++n) sceneStep<D>(world, scene.settings, hook);
  const RigidBody<D>& end = world.bodies[1];
  REQUIRE(r.recording.poses().back()[1].position == end.position);

  Vec<D> sum = Vec<D>::Zero();
  std::istringstream in(readWhole(path));
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const std::vector<std::string> f = splitCsvLine(line);
    const double sign = f[3] == "1" ? 1.0 : -1.0;  // +j on body A, -j on body B
    for (int k = 0; k < D; ++k) sum[k] += sign * std::strtod(f[static_cast<std::size_t>(7 + 2 * D + k)].c_str(), nullptr);
  }
  const double T = steps * scene.settings.dt;
  const Vec<D> expected = end.mass() * (end.velocity - start.velocity) - end.mass() * T * world.gravity;
  // Invariant tier: the file's decimals read back exactly; the sums differ in order only.
  CHECK((sum - expected).norm() < 1e-12 * steps * (1.0 + end.mass() * 9.81 * T));
}
// [test_contacts_momentum]

TEST_CASE_TEMPLATE("Recording contacts changes no bit of the trajectory", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  for (const double frameRate : {50.0, 1000.0}) {
    const SceneRun off = runScene(parseScene(droppedBoxScene<D>(false, frameRate), "drop.json", "."));
    const SceneRun on = runScene(parseScene(droppedBoxScene<D>(true, frameRate), "drop.json", "."));
    const Recording<D>& a = resultOf<D>(off).recording;
    const Recording<D>& b = resultOf<D>(on).recording;
    CHECK(a.contacts().empty());
    CHECK(!b.contacts().empty());
    REQUIRE(a.frameCount() == b.frameCount());
    bool same = true;
    for (std::size_t f = 0; f < a.frameCount(); ++f) {
      for (std::size_t i = 0; i < a.bodyCount(); ++i) {
        const Pose<D>& p = a.poses()[f][i];
        const Pose<D>& q = b.poses()[f][i];
        same = same && p.position == q.position;
        if constexpr (D == 2) {
          same = same && p.orientation.angle() == q.orientation.angle();
        } else {
          same = same && p.orientation.coeffs() == q.orientation.coeffs();
        }
      }
    }
    CHECK(same);
  }
}

TEST_CASE("The SVG and glTF outputs draw contacts only when asked") {
  const auto folder = scratchFolder("contacts_drawn");
  {
    const SceneRun run = runScene(parseScene(droppedBoxScene<2>(true), "drop.json", "."));
    const Recording<2>& recording = resultOf<2>(run).recording;
    SvgOptions options;
    writeAnimatedSvg(recording, (folder / "plain.svg").string(), options);
    options.drawContacts = true;
    writeAnimatedSvg(recording, (folder / "contacts.svg").string(), options);
    CHECK(readWhole(folder / "plain.svg").find("class=\"contacts\"") == std::string::npos);
    const std::string svg = readWhole(folder / "contacts.svg");
    CHECK(svg.find("class=\"contacts\"") != std::string::npos);
    CHECK(svg.find("<circle") != std::string::npos);
  }
  {
    const SceneRun run = runScene(parseScene(droppedBoxScene<3>(true), "drop.json", "."));
    const Recording<3>& recording = resultOf<3>(run).recording;
    GlbOptions options;
    writeAnimatedGlb(recording, (folder / "plain.glb").string(), options);
    options.drawContacts = true;
    writeAnimatedGlb(recording, (folder / "contacts.glb").string(), options);
    CHECK(readWhole(folder / "plain.glb").find("contacts at") == std::string::npos);
    const std::string glb = readWhole(folder / "contacts.glb");
    CHECK(glb.find("contacts at") != std::string::npos);
    CHECK(glb.find("\"STEP\"") != std::string::npos);
  }
}

}  // TEST_SUITE
