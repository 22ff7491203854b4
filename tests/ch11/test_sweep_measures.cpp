// Chapter 11 (the knobs' curves): the two structure and closed-form measures the knob sweeps
// use, checked against their definitions and closed forms, not against the code's output:
// the bounce apexes (e^(2k) h for restitution e) and a symmetric pyramid's mirror error.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/sweep.hpp"

using namespace stackbook;

namespace {

const std::string kMeasureSweeps = std::string(STACKBOOK_SOURCE_DIR) + "/docs/sweeps/";

}  // namespace

TEST_SUITE("ch11") {

TEST_CASE("the apex of a free flight under symplectic Euler is the vertex of its parabola") {
  // y_n = y0 + n dt v0 - g dt^2 n (n + 1) / 2 exactly (v_{n+1} = v_n - g dt, y_{n+1} = y_n + dt
  // v_{n+1}): a parabola in t = n dt whose vertex is at n* = v0 / (g dt) - 1/2, height
  // y0 + (v0 - g dt / 2)^2 / (2 g).
  const double g = 9.81, dt = 1e-3, y0 = 0.3, v0 = 2.0;
  std::vector<double> t, y;
  double v = v0, h = y0;
  for (int n = 0; n <= 1000; ++n) {
    t.push_back(n * dt);
    y.push_back(h);
    v -= g * dt;
    h += dt * v;
  }
  const double apex = y0 + (v0 - 0.5 * g * dt) * (v0 - 0.5 * g * dt) / (2.0 * g);
  CHECK(sweepApexHeight(t, y, 1) == doctest::Approx(apex).epsilon(1e-12));
  // One apex only: the second does not exist, and the start (a frame with no left neighbour)
  // is never an apex.
  CHECK(std::isinf(sweepApexHeight(t, y, 2)));
  CHECK(std::isinf(sweepApexHeight({0.0, 1.0, 2.0}, {1.0, 0.5, 0.0}, 1)));
}

TEST_CASE("a dropped disk's bounce apexes are e^(2k) h above its resting height within a step's travel") {
  // bounce_2d.json: r = 0.1 m, gap h = 1 m, e = 0.5. The collision stage reverses the normal
  // velocity exactly (e v), but it acts on the step whose predicted pose is in contact, so the
  // disk turns up to one step's travel v dt above the floor, v = sqrt(2 g h) at the first
  // impact, and symplectic Euler's fall and rise are each off by half a step's travel
  // (Eq. (11.3)): each apex is within three steps' travel of the closed form. Where in its
  // step the impact falls depends on dt, so the error is bounded by dt, not proportional to it.
  const double g = 9.81, h = 1.0, e = 0.5, r = 0.1;
  const double impact = std::sqrt(2.0 * g * h);
  SweepSpec spec = loadSweepSpec(kMeasureSweeps + "bounce_2d_sweep.json");
  spec.knobs = {SweepKnob{"dt", {0.004, 0.002, 0.001}}};
  spec.errors.clear();
  for (int k = 1; k <= 3; ++k) {
    SweepError apex;
    apex.name = "apex " + std::to_string(k);
    apex.quantity = "bounceApex";
    apex.body = 1;
    apex.apex = k;
    spec.errors.push_back(apex);
  }
  const std::vector<SweepRun> runs = sweepRuns(spec);
  REQUIRE(runs.size() == 3);
  for (const SweepRun& run : runs) {
    const SweepRow row = runSweepRun(spec, run);
    const double dt = std::stod(run.value);
    for (int k = 1; k <= 3; ++k) {
      const double exact = r + std::pow(e, 2 * k) * h;
      const double err = std::abs(row.errors[static_cast<std::size_t>(k - 1)] - exact);
      INFO("dt " << dt << " apex " << k << " err " << err);
      CHECK(err <= 3.0 * impact * dt);
    }
  }
  // Without the collision stage the contact stage stops the disk at the floor: no apex at all.
  spec.sets = {"solver.collisionIterations=0"};
  spec.knobs = {SweepKnob{"dt", {0.002}}};
  CHECK(std::isinf(runSweepRun(spec, sweepRuns(spec).at(0)).errors[0]));
}

TEST_CASE("the mirror error is the largest distance between a body's reflected end and its partner's") {
  // Three bodies symmetric about x = 1 (their mean), and a static one that does not count.
  const std::vector<Eigen::Vector3d> start = {{0, -5, 0}, {0, 0, 0}, {1, 1, 0}, {2, 0, 0}};
  const std::vector<bool> isStatic = {true, false, false, false};
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  // A symmetric motion (the outer two move apart by the same amount, the middle one straight
  // up) has no mirror error.
  std::vector<Eigen::Vector3d> end = {{0, -5, 0}, {-0.5, 0.1, 0}, {1, 0.7, 0}, {2.5, 0.1, 0}};
  CHECK(sweepMirrorError(start, end, isStatic, x, 1e-9, "f") <= 1e-15);
  // The whole structure moved sideways by d: the reflected middle body misses itself by 2 d.
  const double d = 0.01;
  end = {{0, -5, 0}, {d, 0, 0}, {1 + d, 1, 0}, {2 + d, 0, 0}};
  CHECK(sweepMirrorError(start, end, isStatic, x, 1e-9, "f") == doctest::Approx(2 * d).epsilon(1e-12));
  // One outer body sank by s: it and its partner each miss by s.
  end = {{0, -5, 0}, {0, -0.003, 0}, {1, 1, 0}, {2, 0, 0}};
  CHECK(sweepMirrorError(start, end, isStatic, x, 1e-9, "f") == doctest::Approx(0.003).epsilon(1e-12));
  // A start that is not symmetric is one line naming a body without a partner.
  const std::vector<Eigen::Vector3d> lopsided = {{0, -5, 0}, {0, 0, 0}, {1.2, 1, 0}, {2, 0, 0}};
  CHECK_THROWS_WITH(sweepMirrorError(lopsided, lopsided, isStatic, x, 1e-6, "f"),
                    doctest::Contains("has no mirror image within 1e-06 m"));
}

TEST_CASE("the apex field's one-line error") {
  const nlohmann::json doc = {{"scene", "stack_2d.json"},
                              {"knobs", {{{"key", "dt"}, {"values", {0.01}}}}},
                              {"errors", {{{"quantity", "bounceApex"}, {"body", 1}, {"apex", 0}}}}};
  CHECK_THROWS_WITH(parseSweepSpec(doc, "spec.json"),
                    "spec.json: /errors/0/apex: must be >= 1 (the first apex after the start is 1)");
}

TEST_CASE("seconds standing: the first time a body is farther than the bound from its start") {
  // A ground and one box that stays put until t = 0.3 s and then slides 1 mm per frame.
  SweepTrajectory t;
  t.dimension = 2;
  t.gravity = Eigen::Vector3d(0, -9.81, 0);
  t.isStatic = {true, false};
  for (int f = 0; f <= 10; ++f) {
    t.times.push_back(0.1 * f);
    std::vector<SweepBodyState> frame(2);
    frame[1].position = Eigen::Vector3d(f <= 3 ? 0.0 : 1e-3 * (f - 3), 0.5, 0);
    t.frames.push_back(frame);
    t.energies.push_back(0.0);
  }
  SweepError e;
  e.name = "seconds standing";
  e.quantity = "standing";
  e.relative = false;
  // 2.5 mm is passed at the third millimetre, frame 6.
  e.tolerance = 2.5e-3;
  CHECK(measureSweepTrajectory(e, t, "f") == doctest::Approx(0.6));
  // A bound it never passes: it stands the whole run.
  e.tolerance = 1.0;
  CHECK(measureSweepTrajectory(e, t, "f") == doctest::Approx(1.0));
  CHECK(sweepHigherIsBetter(e));
  // The bound and the seconds asked for are required.
  const nlohmann::json doc = {{"scene", "stack_2d.json"},
                              {"knobs", {{{"key", "dt"}, {"values", {0.01}}}}},
                              {"errors", {{{"quantity", "standing"}, {"within", {1.0}}}}}};
  CHECK_THROWS_WITH(parseSweepSpec(doc, "spec.json"),
                    doctest::Contains("missing field \"tolerance\""));
}

}  // TEST_SUITE
