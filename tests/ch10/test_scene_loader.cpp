// Chapter 10: what a scene file builds. A body from JSON equals the body built in C++
// (mass, inertia, pose, velocity); the closed-form mass properties of the analytic shapes
// agree with chapter 5's integration over a fine mesh; arrays place bodies where they
// say; mesh bodies sit with their centre of mass where the file's frame puts it.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;
using nlohmann::json;

namespace {

/// A one-body scene in dimension D (nothing to collide with).
json oneBody(int dimension, const json& body) {
  return json{{"dimension", dimension}, {"bodies", json::array({body})}};
}

template <int D>
const SceneBodies<D>& bodiesOf(const Scene& s) {
  return std::get<SceneBodies<D>>(s.bodies);
}

template <int D>
json zeroVector() {
  return D == 2 ? json{0.0, 0.0} : json{0.0, 0.0, 0.0};
}

/// Mass and principal moments of a closed mesh at density rho (chapter 5), sorted.
template <int D>
MassProperties<D> meshProperties(const SurfaceMesh<D>& mesh, double rho) {
  return computeMassProperties<D>(mesh, rho);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("A box from JSON equals the box built in C++", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const double rho = 250.0;
  Vec<D> size;
  json body;
  if constexpr (D == 2) {
    size = Vec2(0.6, 0.2);
    body = json::parse(R"({"shape": {"type": "box", "size": [0.6, 0.2]}, "density": 250, "position": [1, 2],
                           "angleDeg": 30, "velocity": [3, -1], "angularVelocity": 2})");
  } else {
    size = Vec3(0.6, 0.2, 0.4);
    body = json::parse(R"({"shape": {"type": "box", "size": [0.6, 0.2, 0.4]}, "density": 250, "position": [1, 2, 3],
                           "axis": [0, 0, 2], "angleDeg": 30, "velocity": [3, -1, 0.5], "angularVelocity": [0, 0, 2]})");
  }
  json doc = oneBody(D, body);
  doc["gravity"] = zeroVector<D>();
  const Scene scene = parseScene(doc, "box.json", ".");
  const RigidBody<D>& got = bodiesOf<D>(scene).world.bodies.at(0);

  // The same body by hand: m = rho V, I = m/12 (b^2 + c^2) and cyclic (chapter 5).
  const double m = rho * size.prod();
  AngVec<D> inertia;
  if constexpr (D == 2) {
    inertia[0] = m / 12.0 * (size[0] * size[0] + size[1] * size[1]);
  } else {
    inertia = m / 12.0 * Vec3(size[1] * size[1] + size[2] * size[2], size[0] * size[0] + size[2] * size[2],
                              size[0] * size[0] + size[1] * size[1]);
  }
  RigidBody<D> expected = makeDynamicBody<D>(m, inertia);
  const double angle = 30.0 * M_PI / 180.0;
  if constexpr (D == 2) {
    expected.position = Vec2(1, 2);
    expected.orientation = Eigen::Rotation2Dd(angle);
    expected.velocity = Vec2(3, -1);
    expected.setAngularVelocity(AngVec<2>::Constant(2.0));
  } else {
    expected.position = Vec3(1, 2, 3);
    expected.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(angle, Vec3::UnitZ()));
    expected.velocity = Vec3(3, -1, 0.5);
    expected.setAngularVelocity(Vec3(0, 0, 2));
  }
  CHECK(got.mass() == doctest::Approx(expected.mass()).epsilon(1e-14));
  for (int k = 0; k < AngVec<D>::RowsAtCompileTime; ++k) {
    CHECK(got.inertia[k] == doctest::Approx(expected.inertia[k]).epsilon(1e-14));
  }
  CHECK((got.position - expected.position).norm() <= 1e-15);
  CHECK((got.velocity - expected.velocity).norm() <= 1e-15);
  CHECK((got.angularMomentum - expected.angularMomentum).norm() <= 1e-12 * expected.angularMomentum.norm());
  if constexpr (D == 2) {
    CHECK(got.orientation.angle() == doctest::Approx(angle).epsilon(1e-15));
  } else {
    CHECK(got.orientation.angularDistance(expected.orientation) <= 1e-15);
  }
  CHECK(bodiesOf<D>(scene).visuals.at(0).name == "body0");
}

TEST_CASE_TEMPLATE("A given mass overrides the density and scales the inertia", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const json shape = D == 2 ? json::parse(R"({"type": "disk", "radius": 0.5})")
                            : json::parse(R"({"type": "sphere", "radius": 0.5})");
  json doc = oneBody(D, json{{"shape", shape}, {"mass", 7.0}});
  doc["gravity"] = zeroVector<D>();
  const Scene built = parseScene(doc, "m.json", ".");
  const RigidBody<D>& b = bodiesOf<D>(built).world.bodies.at(0);
  CHECK(b.mass() == doctest::Approx(7.0).epsilon(1e-15));
  // Disk: I = m r^2 / 2; ball: I = 2 m r^2 / 5.
  const double expected = D == 2 ? 7.0 * 0.25 / 2.0 : 0.4 * 7.0 * 0.25;
  CHECK(b.inertia[0] == doctest::Approx(expected).epsilon(1e-14));
}

TEST_CASE_TEMPLATE("Closed-form mass properties agree with chapter 5 on a fine mesh", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Each analytic shape against the divergence-theorem integral over a fine inscribed mesh;
  // the mesh is inscribed, so it falls short by about (2 pi / n)^2 / 6 per circle of n
  // segments: 1e-4 for n = 256, 4e-4 for the torus's 128 segments around its tube.
  struct Case {
    json shape;
    SurfaceMesh<D> mesh;
  };
  std::vector<Case> cases;
  cases.push_back({json::parse(R"({"type": "capsule", "radius": 0.3, "length": 0.8})"),
                   capsuleBoundary<D>(0.4, 0.3, 256, 0.004)});
  cases.push_back({json::parse(R"({"type": "torus", "majorRadius": 0.5, "minorRadius": 0.2})"),
                   ringBoundary<D>(0.5, 0.2, 256, 128)});
  if constexpr (D == 3) {
    cases.push_back({json::parse(R"({"type": "cylinder", "radius": 0.3, "height": 0.7})"),
                     cylinderMesh(0.3, 0.7, 512, 1, 1)});
    cases.push_back({json::parse(R"({"type": "sphere", "radius": 0.4})"), icosphereMesh(0.4, 5)});
  } else {
    cases.push_back({json::parse(R"({"type": "disk", "radius": 0.4})"), regularPolygon(0.4, 2048)});
  }
  for (const Case& c : cases) {
    CAPTURE(c.shape.dump());
    json doc = oneBody(D, json{{"shape", c.shape}, {"density", 3.0}});
    doc["gravity"] = zeroVector<D>();
    const Scene built = parseScene(doc, "mp.json", ".");
    const RigidBody<D>& b = bodiesOf<D>(built).world.bodies.at(0);
    const MassProperties<D> ref = meshProperties<D>(c.mesh, 3.0);
    CHECK(b.mass() == doctest::Approx(ref.mass).epsilon(1e-3));
    for (int k = 0; k < AngVec<D>::RowsAtCompileTime; ++k) {
      CHECK(b.inertia[k] == doctest::Approx(ref.inertia(k, k)).epsilon(2e-3));
    }
  }
}

TEST_CASE("A 3D rotation can be a quaternion or an axis and angle") {
  json a = oneBody(3, json::parse(R"({"shape": {"type": "box", "size": [1, 2, 3]}, "quaternion": [0, 1, 0, 0]})"));
  json b = oneBody(3, json::parse(R"({"shape": {"type": "box", "size": [1, 2, 3]}, "axis": [1, 0, 0], "angleDeg": 180})"));
  a["gravity"] = b["gravity"] = json{0, 0, -9.81};
  const Orientation<3> qa = bodiesOf<3>(parseScene(a, "a.json", ".")).world.bodies[0].orientation;
  const Orientation<3> qb = bodiesOf<3>(parseScene(b, "b.json", ".")).world.bodies[0].orientation;
  CHECK(qa.angularDistance(qb) <= 1e-15);
  CHECK(qa.angularDistance(Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, Vec3::UnitX()))) <= 1e-15);
}

TEST_CASE("A pyramid array of base 4 places 10 bodies in rows shifted by half a spacing") {
  const json doc = json::parse(R"({"dimension": 2, "bodies": [
    {"name": "box", "shape": {"type": "box", "size": [1, 1]}, "position": [0, 0.5],
     "array": {"pyramid": 4, "spacing": [1.5, 1]}}]})");
  const Scene built = parseScene(doc, "p.json", ".");
  const SceneBodies<2>& b = bodiesOf<2>(built);
  REQUIRE(b.world.size() == 10);
  // Level l holds 4 - l boxes at x = (i + l/2) 1.5, y = 0.5 + l.
  int k = 0;
  for (int level = 0; level < 4; ++level) {
    for (int i = 0; i < 4 - level; ++i, ++k) {
      const Vec2 x = b.world.bodies[static_cast<std::size_t>(k)].position;
      CHECK(x.x() == doctest::Approx((i + 0.5 * level) * 1.5).epsilon(1e-15));
      CHECK(x.y() == doctest::Approx(0.5 + level).epsilon(1e-15));
      CHECK(b.visuals[static_cast<std::size_t>(k)].name ==
            "box_" + std::to_string(level) + "_" + std::to_string(i));
    }
  }
  // Boxes of one shape share it.
  CHECK(b.world.shapes[0] == b.world.shapes[9]);
}

TEST_CASE("A grid array of 2 by 3 by 2 places 12 bodies at the spacing") {
  const json doc = json::parse(R"({"dimension": 3, "bodies": [
    {"shape": {"type": "sphere", "radius": 0.2}, "position": [1, 2, 3],
     "array": {"count": [2, 3, 2], "spacing": [0.5, 0.6, 0.7]}}]})");
  const Scene built = parseScene(doc, "g.json", ".");
  const SceneBodies<3>& b = bodiesOf<3>(built);
  REQUIRE(b.world.size() == 12);
  CHECK((b.world.bodies[11].position - Vec3(1.5, 3.2, 3.7)).norm() <= 1e-15);
  CHECK(b.pointers[11] == "/bodies/0");
}

TEST_CASE_TEMPLATE("An L body has its centre of mass at the centroid of its three cells", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // The L of cells (0,0), (1,0), (0,1) of side a is centred on its bounding box [0, 2a]^2, so
  // its centroid (5a/6, 5a/6) sits at (-a/6, -a/6) from the placed origin (z = 0 in 3D).
  const double a = 0.3;
  json doc = oneBody(D, json{{"shape", {{"type", "L"}, {"cellSize", a}, {"sdfResolution", 16}}},
                             {"position", D == 2 ? json{2.0, 1.0} : json{2.0, 1.0, 0.0}}, {"density", 2.0}});
  doc["gravity"] = zeroVector<D>();
  const Scene built = parseScene(doc, "l.json", ".");
  const SceneBodies<D>& b = bodiesOf<D>(built);
  const RigidBody<D>& body = b.world.bodies.at(0);
  CHECK(body.position[0] == doctest::Approx(2.0 - a / 6.0).epsilon(1e-12));
  CHECK(body.position[1] == doctest::Approx(1.0 - a / 6.0).epsilon(1e-12));
  const double measure = 3.0 * std::pow(a, D);
  CHECK(body.mass() == doctest::Approx(2.0 * measure).epsilon(1e-12));
  // The drawn outline, carried to the world, is the L at its place: its lowest x is 2 - a.
  double lowest = 1e9;
  for (const Vec<D>& v : b.visuals.at(0).mesh.vertices) lowest = std::min(lowest, poseOf<D>(body).toWorld(v)[0]);
  CHECK(lowest == doctest::Approx(2.0 - a).epsilon(1e-12));
}

TEST_CASE("A mesh body from an OBJ file has the cube's mass and its centre where the file puts it") {
  const Scene scene = loadScene(std::string(STACKBOOK_TEST_DATA_DIR) + "/good_mesh.json");
  const SceneBodies<3>& b = bodiesOf<3>(scene);
  const RigidBody<3>& cube = b.world.bodies.at(1);
  // Unit cube with a corner at the placed origin (0, 0, 2), density 500: m = 500,
  // I = m (1 + 1) / 12 about every axis, centre at (0.5, 0.5, 2.5).
  CHECK(cube.mass() == doctest::Approx(500.0).epsilon(1e-12));
  CHECK(cube.inertia[0] == doctest::Approx(500.0 / 6.0).epsilon(1e-12));
  CHECK((cube.position - Vec3(0.5, 0.5, 2.5)).norm() <= 1e-12);
  CHECK(scene.description == "A unit cube from an OBJ file, 2 m above the ground");
}

TEST_CASE("Scene defaults are gravity down the last axis and GBF's step settings") {
  const json doc2 = json::parse(R"({"dimension": 2, "bodies": [{"shape": {"type": "disk", "radius": 1}}]})");
  const Scene s2 = parseScene(doc2, "d.json", ".");
  CHECK(bodiesOf<2>(s2).world.gravity == Vec2(0.0, -9.81));
  const json doc3 = json::parse(R"({"dimension": 3, "bodies": [{"shape": {"type": "sphere", "radius": 1}}]})");
  const Scene s3 = parseScene(doc3, "d.json", ".");
  CHECK(bodiesOf<3>(s3).world.gravity == Vec3(0.0, 0.0, -9.81));
  const StepSettings defaults;
  CHECK(s3.settings.dt == defaults.dt);
  CHECK(s3.settings.contactIterations == defaults.contactIterations);
  CHECK(s3.settings.collisionIterations == defaults.collisionIterations);
  // Density 1000 by default: a ball of radius 1 weighs 4000 pi / 3.
  CHECK(bodiesOf<3>(s3).world.bodies[0].mass() == doctest::Approx(4000.0 * M_PI / 3.0).epsilon(1e-14));
}

TEST_CASE("Solver and effect settings reach the step settings") {
  const json doc = json::parse(R"({"dimension": 2, "dt": 0.0005,
    "solver": {"collisionIterations": 3, "contactIterations": 2, "contactRestitution": [-0.4, 0],
               "shock": {"sweepsPerLevel": 3, "pairIterations": 7, "replacesContactStage": true},
               "order": "traditional",
               "impulsePoint": "centre", "impulsePointNormalCosine": 0.9, "frictionCone": "step",
               "candidateReach": 0.2},
    "effects": {"friction": false, "shockPropagation": true},
    "bodies": [{"shape": {"type": "disk", "radius": 1}}]})");
  const Scene s = parseScene(doc, "s.json", ".");
  CHECK(s.settings.dt == 0.0005);
  CHECK(s.settings.collisionIterations == 3);
  CHECK(s.settings.contactRestitutionAt(1) == -0.4);
  CHECK(s.settings.shock.sweepsPerLevel == 3);
  CHECK(s.settings.shock.pairIterations == 7);
  CHECK(s.settings.shock.replacesContactStage);
  CHECK(s.settings.order == StepOrder::Traditional);
  CHECK(s.settings.impulsePoint.rule == ImpulsePointRule::DepthWeightedCentre);
  CHECK(s.settings.impulsePoint.normalCosine == 0.9);
  CHECK(s.settings.frictionCone == FrictionConeRule::StepTotal);
  CHECK(s.settings.detection.narrow.candidateReach == 0.2);
  REQUIRE(s.settings.effects.friction.has_value());
  CHECK(*s.settings.effects.friction == false);
  CHECK(*s.settings.effects.shockPropagation == true);
  CHECK_FALSE(s.settings.effects.gravity.has_value());
}

TEST_CASE("A solver preset is applied first and the scene's other solver fields change it") {
  // "passAsContactShortLoops" is passAsContactStageShortLoops() on the scene's dt; a field
  // beside it wins, and the preset's ramp follows a changed sweep count.
  const json doc = json::parse(R"({"dimension": 2, "dt": 0.0025,
    "solver": {"preset": "passAsContactShortLoops", "collisionPairIterations": 7, "shock": {"sweepsPerLevel": 4}},
    "bodies": [{"shape": {"type": "disk", "radius": 1}}]})");
  const Scene s = parseScene(doc, "p.json", ".");
  StepSettings base;
  base.dt = 0.0025;
  const StepSettings preset = passAsContactStageShortLoops(base);
  CHECK(s.settings.dt == 0.0025);
  CHECK(s.settings.shock.replacesContactStage);
  CHECK(s.settings.frictionCone == FrictionConeRule::StepTotal);
  CHECK(s.settings.shock.pairIterations == preset.shock.pairIterations);
  CHECK(s.settings.shock.pairImpulseTolerance == preset.shock.pairImpulseTolerance);
  CHECK(s.settings.pairImpulseTolerance == preset.pairImpulseTolerance);
  CHECK(s.settings.collisionPairIterations == 7);
  CHECK(s.settings.shock.sweepsPerLevel == 4);
  CHECK(s.settings.shock.restitutionAt(4) == 0.0);

  const json pass = json::parse(R"({"dimension": 2, "solver": {"preset": "passAsContact"},
    "bodies": [{"shape": {"type": "disk", "radius": 1}}]})");
  const Scene p = parseScene(pass, "q.json", ".");
  CHECK(p.settings.shock.replacesContactStage);
  CHECK(p.settings.shock.sweepsPerLevel == passAsContactStage().shock.sweepsPerLevel);
  CHECK(p.settings.shock.pairIterations == StepSettings{}.shock.pairIterations);

  const json gbf = json::parse(R"({"dimension": 2, "solver": {"preset": "gbf"},
    "bodies": [{"shape": {"type": "disk", "radius": 1}}]})");
  const Scene g = parseScene(gbf, "g.json", ".");
  CHECK_FALSE(g.settings.shock.replacesContactStage);
  CHECK(g.settings.shock.sweepsPerLevel == StepSettings{}.shock.sweepsPerLevel);
}

TEST_CASE("An override sets a nested field and a bare word becomes a string") {
  json doc = json::parse(R"({"dimension": 2, "solver": {}, "bodies": [{"shape": {"type": "disk", "radius": 1}}]})");
  applySceneOverride(doc, "solver.contactIterations=4", "o.json");
  applySceneOverride(doc, "bodies/0/velocity=[1, 2]", "o.json");
  applySceneOverride(doc, "solver.order=traditional", "o.json");
  CHECK(doc["solver"]["contactIterations"] == 4);
  CHECK(doc["bodies"][0]["velocity"] == json{1, 2});
  CHECK(doc["solver"]["order"] == "traditional");
  const Scene s = parseScene(doc, "o.json", ".");
  CHECK(bodiesOf<2>(s).world.bodies[0].velocity == Vec2(1, 2));
}

}  // TEST_SUITE
