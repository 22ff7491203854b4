// Chapter 10 exercises: suite ch10_exercises, skipped by default. The exercises preset builds
// them into build/exercises/tests/ch10/test_ch10_exercises. It registers one CTest entry per
// exercise, ex10.1 to ex10.3, with the labels exercise and ch10. Run all of them, or one, with
//   ctest --preset exercises -L ch10
//   ctest --preset exercises -R ex10.1
// An entry runs its tests once its stub has no "// TODO(reader)" comment left. The binary
// runs them at any time:
//   build/exercises/tests/ch10/test_ch10_exercises --no-skip -ts=ch10_exercises -tc="Exercise 10.1*"
// They fail until you solve the exercise (the stubs return empty results and write nothing).
// The main build runs them against the reference solutions: ctest --preset solutions -L ch10
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <unistd.h>

#include "stackbook/exercises/ex10_1_regular_polygon.hpp"
#include "stackbook/exercises/ex10_2_domino_scene.hpp"
#include "stackbook/exercises/ex10_3_obj_sequence.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/geometry/sdf_grid.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"

namespace {

using namespace stackbook;

/// The message of the std::invalid_argument `f` throws ("" if it throws none).
template <class F>
std::string invalidArgumentMessage(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

/// A fresh folder under the system's temporary folder.
std::filesystem::path scratchFolder(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("stackbook_ch10_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The vertices ("v") and faces ("f") of an OBJ file, and its object names ("o").
struct ObjFile {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
  std::vector<std::string> objects;
  std::vector<std::size_t> firstFace;  // index into faces where each object's faces start
};

ObjFile readObj(const std::string& path) {
  ObjFile obj;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "v") {
      double x = 0, y = 0, z = 0;
      fields >> x >> y >> z;
      obj.vertices.push_back(Vec3(x, y, z));
    } else if (kind == "f") {
      std::array<int, 3> f{};
      fields >> f[0] >> f[1] >> f[2];
      obj.faces.push_back(f);
    } else if (kind == "o") {
      std::string name;
      std::getline(fields >> std::ws, name);
      obj.objects.push_back(name);
      obj.firstFace.push_back(obj.faces.size());
    }
  }
  return obj;
}

/// Two bodies, a 1 x 2 x 3 brick and a unit cube, over three frames with known poses.
Recording<3> twoBodyRecording() {
  Recording<3> recording({BodyVisual<3>{"brick", boxMesh(Vec3(1.0, 2.0, 3.0)), false, {0.8, 0.3, 0.2}},
                          BodyVisual<3>{"unit cube", boxMesh(Vec3(1.0, 1.0, 1.0)), true, {0.5, 0.5, 0.5}}});
  for (int f = 0; f < 3; ++f) {
    Pose<3> brick, cube;
    brick.position = Vec3(0.25 * f, -1.0, 2.0 - 0.5 * f);
    brick.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * M_PI * f, Vec3(1.0, 1.0, 0.0).normalized()));
    cube.position = Vec3(3.0, 0.0, 0.5);
    recording.recordPoses(0.1 * f, {brick, cube});
  }
  return recording;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER "_exercises" * doctest::skip()) {

// --- Exercise 10.1 ------------------------------------------------------------------------

TEST_CASE("Exercise 10.1: the polygon's area and polar moment match the closed forms") {
  const double R = 0.7, R2 = R * R, R4 = R2 * R2, s3 = std::sqrt(3.0);
  // Independent closed forms: the equilateral triangle (side R sqrt 3), the square (side
  // R sqrt 2), the regular hexagon (side R), and the disk as the limit of many sides.
  struct Case {
    int sides;
    double area, moment, tolerance;
  };
  for (const Case& c : {Case{3, 3.0 * s3 / 4.0 * R2, 3.0 * s3 / 16.0 * R4, 1e-12},
                        Case{4, 2.0 * R2, 4.0 * R4 / 6.0, 1e-12},
                        Case{6, 3.0 * s3 / 2.0 * R2, 5.0 * s3 / 8.0 * R4, 1e-12},
                        Case{1000, M_PI * R2, M_PI * R4 / 2.0, 1e-4}}) {
    CAPTURE(c.sides);
    const PolygonShapeBuild p = regularPolygonShape({{"type", "polygon"}, {"sides", c.sides}, {"radius", R},
                                                     {"sdfResolution", 8}});
    CHECK(p.area == doctest::Approx(c.area).epsilon(c.tolerance));
    CHECK(p.unitMoment == doctest::Approx(c.moment).epsilon(c.tolerance));
  }
}

TEST_CASE("Exercise 10.1: the polygon's outline runs counterclockwise around its centroid") {
  const double R = 0.5;
  const PolygonShapeBuild p = regularPolygonShape({{"type", "polygon"}, {"sides", 5}, {"radius", R}});
  const Polygon& outline = p.outline;
  REQUIRE(outline.vertices.size() >= 5);
  REQUIRE(outline.faces.size() == outline.vertices.size());
  // Shoelace over the segments: the signed area is +A for a counterclockwise outline, and
  // the first moment is zero about the centroid.
  double twiceArea = 0.0;
  Vec2 firstMoment = Vec2::Zero();
  for (const auto& f : outline.faces) {
    const Vec2 a = outline.vertices[static_cast<std::size_t>(f[0])];
    const Vec2 b = outline.vertices[static_cast<std::size_t>(f[1])];
    const double cross = a.x() * b.y() - a.y() * b.x();
    twiceArea += cross;
    firstMoment += cross * (a + b) / 3.0;
  }
  const double area = 2.5 * R * R * std::sin(2.0 * M_PI / 5.0);
  CHECK(0.5 * twiceArea == doctest::Approx(area).epsilon(1e-12));
  CHECK(firstMoment.norm() <= 1e-12);
  // A corner points up: the highest vertex is (0, R).
  double top = -1.0;
  for (const Vec2& v : outline.vertices) top = std::max(top, v.y());
  CHECK(top == doctest::Approx(R).epsilon(1e-12));
}

TEST_CASE("Exercise 10.1: the polygon's signed distance is negative inside and positive outside") {
  const double R = 0.5;
  const PolygonShapeBuild p =
      regularPolygonShape({{"type", "polygon"}, {"sides", 6}, {"radius", R}, {"sdfResolution", 64}});
  REQUIRE(p.shape != nullptr);
  const auto* grid = dynamic_cast<const GridShape<2>*>(p.shape.get());
  REQUIRE(grid != nullptr);
  const double h = grid->grid().cellSize();
  const double apothem = R * std::cos(M_PI / 6.0);
  // Grid tier: phi is exact at the nodes and interpolated between them, so within a cell.
  CHECK(std::abs(p.shape->signedDistance(Vec2::Zero()) + apothem) <= h);
  // A corner is on the surface; past a side's midpoint is outside by the extra distance.
  CHECK(std::abs(p.shape->signedDistance(Vec2(0.0, R))) <= h);
  const Vec2 midpoint = Vec2(-apothem, 0.0);  // the left side is vertical (corners at 150 and 210 degrees)
  CHECK(std::abs(p.shape->signedDistance(1.2 * midpoint) - 0.2 * apothem) <= h);
  CHECK(p.shape->signedDistance(0.8 * midpoint) < 0.0);
  CHECK(p.shape->signedDistance(Vec2(0.0, 1.3 * R)) > 0.0);
}

TEST_CASE("Exercise 10.1: a bad polygon description is rejected naming its field") {
  using nlohmann::json;
  const json good{{"type", "polygon"}, {"sides", 5}, {"radius", 0.5}};
  CHECK_NOTHROW(regularPolygonShape(good));
  const auto rejects = [&](json spec, const std::string& field) {
    CAPTURE(spec.dump());
    const std::string message = invalidArgumentMessage([&] { regularPolygonShape(spec); });
    CHECK(message.find(field) != std::string::npos);
  };
  json s = good;
  s["sides"] = 2;
  rejects(s, "sides");
  s["sides"] = 4.5;
  rejects(s, "sides");
  s = good;
  s.erase("sides");
  rejects(s, "sides");
  s = good;
  s["radius"] = -1.0;
  rejects(s, "radius");
  s["radius"] = "big";
  rejects(s, "radius");
  s = good;
  s["sdfResolution"] = 2;
  rejects(s, "sdfResolution");
  s = good;
  s["colour"] = "red";
  rejects(s, "colour");
  s = good;
  s["type"] = "polygn";
  rejects(s, "type");
}

// --- Exercise 10.2 ------------------------------------------------------------------------

TEST_CASE("Exercise 10.2: the domino scene loads with the dominoes standing in a row") {
  DominoRow row;
  row.count = 4;
  const Scene scene = parseScene(dominoRowScene(row), "dominoes.json", ".");
  REQUIRE(scene.dimension == 2);
  REQUIRE(scene.bodyCount() == row.count + 1);
  CHECK(scene.settings.dt == row.dt);
  CHECK(scene.duration == row.duration);
  const World<2>& world = std::get<SceneBodies<2>>(scene.bodies).world;
  CHECK(world.bodies[0].isStatic());
  for (int k = 1; k <= row.count; ++k) {
    CAPTURE(k);
    const RigidBody<2>& b = world.bodies[static_cast<std::size_t>(k)];
    CHECK_FALSE(b.isStatic());
    CHECK(b.position.x() == doctest::Approx((k - 1) * row.spacing).epsilon(1e-12));
    CHECK(b.position.y() == doctest::Approx(0.5 * row.height).epsilon(1e-12));
    // Mass of a default-density (1000 kg/m^3) box of thickness x height, per unit depth.
    CHECK(b.mass() == doctest::Approx(1000.0 * row.thickness * row.height).epsilon(1e-12));
    CHECK(b.angularVelocity[0] == doctest::Approx(k == 1 ? -row.push : 0.0));
    // The first turns about its bottom corner on the +x side: that corner is at rest.
    const Vec2 corner(0.5 * row.thickness, -0.5 * row.height);
    const Vec2 cornerVelocity = b.velocity + b.angularVelocity[0] * Vec2(-corner.y(), corner.x());
    CHECK(cornerVelocity.norm() <= 1e-12);
    if (k == 1) CHECK(b.velocity.norm() > 0.0);
    CHECK(world.materials[static_cast<std::size_t>(k)].friction == doctest::Approx(row.friction));
  }
  CHECK(invalidArgumentMessage([] { dominoRowScene(DominoRow{0}); }) != "");
  DominoRow tooFar;
  tooFar.spacing = 1.5;
  CHECK(invalidArgumentMessage([&] { dominoRowScene(tooFar); }) != "");
}

TEST_CASE("Exercise 10.2: the dominoes fall one after another") {
  DominoRow row;  // 5 dominoes, 2.5 s
  const Scene scene = parseScene(dominoRowScene(row), "dominoes.json", ".");
  REQUIRE(scene.bodyCount() == row.count + 1);
  const SceneRun run = runScene(scene);
  const RunResult<2>& r = std::get<RunResult<2>>(run);
  REQUIRE(r.finite);
  const Recording<2>& rec = r.recording;
  // [domino_order]
  // The moment each domino has tipped 20 degrees towards +x (clockwise: angle < 0).
  std::vector<double> tipped;
  for (int k = 1; k <= row.count; ++k) {
    double when = -1.0;
    for (std::size_t f = 0; f < rec.frameCount() && when < 0.0; ++f) {
      if (rec.poses()[f][static_cast<std::size_t>(k)].orientation.angle() < -20.0 * M_PI / 180.0) {
        when = rec.times()[f];
      }
    }
    CAPTURE(k);
    CHECK(when >= 0.0);
    tipped.push_back(when);
  }
  for (std::size_t k = 1; k < tipped.size(); ++k) {
    CAPTURE(k);
    CHECK(tipped[k] > tipped[k - 1]);
  }
  // The last one has nothing to lean on: it ends lying down, within 10 degrees of -90.
  const double last = rec.poses().back()[static_cast<std::size_t>(row.count)].orientation.angle();
  CHECK(std::abs(last + 0.5 * M_PI) < 10.0 * M_PI / 180.0);
  // [domino_order]
}

// --- Exercise 10.3 ------------------------------------------------------------------------

TEST_CASE("Exercise 10.3: an OBJ frame holds every body moved by its pose") {
  const Recording<3> recording = twoBodyRecording();
  const std::filesystem::path dir = scratchFolder("obj_frame");
  const std::string path = (dir / "frame.obj").string();
  writeObjFrame(recording, 1, path);
  const ObjFile obj = readObj(path);
  REQUIRE(obj.objects == std::vector<std::string>{"brick", "unit cube"});
  const std::size_t n0 = recording.visuals()[0].mesh.vertices.size();
  const std::size_t n1 = recording.visuals()[1].mesh.vertices.size();
  REQUIRE(obj.vertices.size() == n0 + n1);
  for (std::size_t i = 0; i < 2; ++i) {
    const Pose<3>& pose = recording.poses()[1][i];
    const std::size_t base = i == 0 ? 0 : n0;
    const TriangleMesh& mesh = recording.visuals()[i].mesh;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      CHECK((obj.vertices[base + v] - pose.toWorld(mesh.vertices[v])).norm() <= 1e-12);
    }
  }
  // Faces: 1-based, the second body's offset by the first body's vertex count.
  const std::size_t f0 = recording.visuals()[0].mesh.faces.size();
  REQUIRE(obj.faces.size() == f0 + recording.visuals()[1].mesh.faces.size());
  REQUIRE(obj.firstFace == std::vector<std::size_t>{0, f0});
  for (std::size_t f = 0; f < obj.faces.size(); ++f) {
    const bool second = f >= f0;
    const auto& expected = second ? recording.visuals()[1].mesh.faces[f - f0] : recording.visuals()[0].mesh.faces[f];
    for (int c = 0; c < 3; ++c) {
      CHECK(obj.faces[f][static_cast<std::size_t>(c)] ==
            expected[static_cast<std::size_t>(c)] + 1 + (second ? static_cast<int>(n0) : 0));
    }
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("Exercise 10.3: an OBJ sequence writes one file per frame in time order") {
  const Recording<3> recording = twoBodyRecording();
  const std::filesystem::path dir = scratchFolder("obj_sequence") / "frames";
  const std::vector<std::string> paths = writeObjSequence(recording, dir.string());
  REQUIRE(paths.size() == recording.frameCount());
  for (std::size_t f = 0; f < paths.size(); ++f) {
    CAPTURE(f);
    CHECK(std::filesystem::path(paths[f]).parent_path() == dir);
    if (f > 0) CHECK(std::filesystem::path(paths[f - 1]).filename() < std::filesystem::path(paths[f]).filename());
    const ObjFile obj = readObj(paths[f]);
    REQUIRE_FALSE(obj.vertices.empty());
    const Vec3 expected = recording.poses()[f][0].toWorld(recording.visuals()[0].mesh.vertices[0]);
    CHECK((obj.vertices[0] - expected).norm() <= 1e-12);
  }
  CHECK_THROWS_AS(writeObjFrame(recording, recording.frameCount(), (dir / "past_the_end.obj").string()),
                  std::out_of_range);
  std::filesystem::remove_all(dir.parent_path());
}

}  // TEST_SUITE
