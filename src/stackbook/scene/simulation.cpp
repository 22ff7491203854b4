// Running a scene (chapter 10). See simulation.hpp.
#include "stackbook/scene/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stacking/welded_pass.hpp"
#include "stackbook/stepping/traditional_step.hpp"

namespace stackbook {

using nlohmann::json;

template <int D>
EnergyReport worldEnergy(const World<D>& world) {
  const FrameEnergy f = frameEnergy<D>(world);
  return EnergyReport{f.kinetic, f.potential};
}

template <int D>
double maxPenetration(const World<D>& world) {
  std::vector<CollisionBody<D>> views;
  views.reserve(world.bodies.size());
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    views.push_back(collisionBody<D>(world.bodies[i], *world.shapes[i]));
  }
  double deepest = 0.0;
  for (const PairInterference<D>& pair : detectInterference<D>(views)) {
    for (const InterferenceSample<D>& s : pair.samples) deepest = std::max(deepest, -s.depth);
  }
  return deepest;
}

std::int64_t frameStep(std::int64_t frame, double frameRate, double dt) {
  // Steps per frame r = 1/(frameRate dt); the product f r is rounded up, less a relative
  // 1e-9 so that a rounding error in r (1000 * 0.001 is not always exactly 1) never pushes a
  // frame to the next step.
  const double at = std::min(static_cast<double>(frame) / (frameRate * dt), 4e18);  // no int64 overflow
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(at - 1e-9 * std::max(1.0, at))));
}

template EnergyReport worldEnergy<2>(const World<2>&);
template EnergyReport worldEnergy<3>(const World<3>&);
template double maxPenetration<2>(const World<2>&);
template double maxPenetration<3>(const World<3>&);

namespace {

template <int D>
bool worldFinite(const World<D>& world) {
  for (const RigidBody<D>& b : world.bodies) {
    if (!b.position.allFinite() || !b.velocity.allFinite() || !b.angularMomentum.allFinite()) return false;
    if constexpr (D == 2) {
      if (!std::isfinite(b.orientation.angle())) return false;
    } else {
      if (!b.orientation.coeffs().allFinite()) return false;
    }
  }
  return true;
}

template <int D>
RunResult<D> runBodies(const Scene& scene, const SceneBodies<D>& bodies, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  World<D> world = bodies.world;
  // The contacts output (chapter 10): the step records its impulses only when asked.
  ContactRecorder recorder;
  StepSettings settings = scene.settings;
  if (scene.output.recordsContacts()) settings.contactRecorder = &recorder;
  const double duration = options.duration > 0.0 ? options.duration : scene.duration;
  // The number of steps that covers the duration (a last partial step is taken whole).
  const auto steps = static_cast<std::int64_t>(std::ceil(duration / settings.dt - 1e-9));

  RunResult<D> result{Recording<D>(bodies.visuals), {}, 0.0, 0.0, 0.0, 0.0, {}, {}, true};
  result.energyStart = worldEnergy<D>(world);
  const auto measure = [&](double t) {
    result.recording.record(t, world);
    const double depth = maxPenetration<D>(world);
    if (depth > result.maxPenetration) {
      result.maxPenetration = depth;
      result.maxPenetrationTime = t;
    }
  };
  measure(0.0);
  // [run_loop]
  const PostContactHook<D> hook = shockPropagationHook<D>();
  std::int64_t frame = 1;
  // At most one frame per step: a frame rate above 1/dt records every step (as it would
  // anyway) without counting the frames between two steps one by one.
  const double frameRate = std::min(scene.output.frameRate, 1.0 / settings.dt);
  for (std::int64_t n = 1; n <= steps; ++n) {
    result.counters += sceneStep<D>(world, settings, hook);  // the welded pass by default (chapter 9)
    const double t = static_cast<double>(n) * settings.dt;
    if (settings.contactRecorder != nullptr) {
      result.recording.recordContacts(t, recorder.records());
      recorder.clear();
    }
    // Frames at multiples of 1/frameRate (the step that reaches each one, counted in whole
    // steps), and the end: Eq. (10.3).
    if (n >= frameStep(frame, frameRate, settings.dt) || n == steps) {
      measure(t);
      while (frameStep(frame, frameRate, settings.dt) <= n) ++frame;
    }
    if (options.progress) options.progress(static_cast<double>(n) / static_cast<double>(steps), t);
  }
  // [run_loop]
  result.simulatedSeconds = static_cast<double>(steps) * settings.dt;
  result.energyEnd = worldEnergy<D>(world);
  // Finite: the state and the energies (a state near the limits of a double can be finite
  // while its energy overflows, and a run that cannot report its energy did not succeed).
  result.finite = worldFinite<D>(world) && std::isfinite(result.energyStart.total()) &&
                  std::isfinite(result.energyEnd.total());
  result.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

json stageJson(const StageCounters& s) {
  return json{{"seconds", s.seconds},
              {"sweeps", s.sweeps},
              {"pairVisits", s.pairVisits},
              {"impulses", s.impulses},
              {"frictionless", s.frictionless},
              {"sticking", s.sticking},
              {"sliding", s.sliding},
              {"elastic", s.elasticImpulses},
              {"rolling", s.rollingImpulses},
              {"patches", s.patchImpulses},
              {"tiedLandings", s.tiedLandings},
              {"heldSamples", s.detection.heldSamples},
              {"pairIterationCapHits", s.pairIterationCapHits},
              {"islandSweeps", s.islandSweeps},
              {"pairQueries", s.detection.pairQueries},
              {"phiQueries", s.detection.phiQueries},
              {"interferenceSamples", s.detection.interferenceSamples}};
}

json energyJson(const EnergyReport& e) {
  return json{{"kinetic", e.kinetic}, {"potential", e.potential}, {"total", e.total()}};
}

std::vector<std::string> effectList(const Effects& e) {
  std::vector<std::string> out;
  std::istringstream in(e.summary());
  for (std::string word; in >> word;) {
    if (word != "none") out.push_back(word);
  }
  return out;
}

}  // namespace

SceneRun runScene(const Scene& scene, const RunOptions& options) {
  if (scene.dimension == 2) return runBodies<2>(scene, std::get<SceneBodies<2>>(scene.bodies), options);
  return runBodies<3>(scene, std::get<SceneBodies<3>>(scene.bodies), options);
}

json runSummaryJson(const Scene& scene, const SceneRun& run) {
  return std::visit(
      [&](const auto& r) {
        const StepCounters& c = r.counters;
        json quarantined = json::array();
        for (const Quarantine& q : c.quarantined) quarantined.push_back({{"body", q.body}, {"message", q.message}});
        const double perStep = c.steps > 0 ? r.wallSeconds / static_cast<double>(c.steps) : 0.0;
        return json{
            {"scene", scene.file},
            {"description", scene.description},
            {"dimension", scene.dimension},
            {"bodies", scene.bodyCount()},
            {"dt", scene.settings.dt},
            {"simulatedSeconds", r.simulatedSeconds},
            {"steps", c.steps},
            {"frames", r.recording.frameCount()},
            {"contacts", r.recording.contacts().size()},
            {"effects", effectList(c.effects)},
            {"wallSeconds", r.wallSeconds},
            {"secondsPerStep", perStep},
            {"stages",
             {{"collision", stageJson(c.collision)},
              {"velocityUpdate", {{"seconds", c.velocityUpdateSeconds}}},
              {"contact", stageJson(c.contact)},
              {"shockPropagation", stageJson(c.shock)},
              {"positionUpdate", {{"seconds", c.positionUpdateSeconds}}}}},
            {"impulsePoint",
             {{"leverArms", scene.settings.impulsePoint.arms == LeverArms::AtStartPose ? "startPose" : "testedPose"},
              {"heldSamples", scene.settings.impulsePoint.heldSamples},
              {"tiedLanding", scene.settings.impulsePoint.tiedLanding}}},
            {"freeze",
             {{"rule", scene.settings.shock.freeze == FreezeRule::WhenItCarries ? "whenItCarries" : "everyLevel"},
              {"uncarriedBodies", c.shock.uncarried}}},
            {"weldedPass",
             {{"enabled", scene.settings.shock.welded.enabled},
              {"passes", c.welded.passes},
              {"loadsCarried", c.welded.carriedLoads},
              {"weldTries", c.welded.weldTries},
              {"welds", c.welded.welds},
              {"islands", c.welded.islands},
              {"islandsOnGbfPass", c.welded.gbfIslands}}},
            {"threads", resolvedThreadCount(scene.settings.parallel.threads)},
            {"pairOrder", scene.settings.pairOrder == PairOrder::Colours ? "colours" : "list"},
            {"sleep",
             {{"enabled", scene.settings.sleep.enabled},
              {"bodyStepsAsleep", c.sleep.sleepingBodySteps},
              {"fellAsleep", c.sleep.fellAsleep},
              {"wokenUp", c.sleep.wokenUp},
              {"asleepAtEnd", c.sleep.sleepingAtEnd}}},
            {"maxPenetration", r.maxPenetration},
            {"maxPenetrationTime", r.maxPenetrationTime},
            {"energy", {{"start", energyJson(r.energyStart)}, {"end", energyJson(r.energyEnd)}}},
            {"finite", r.finite},
            {"quarantined", quarantined},
            {"files", json::array()}};
      },
      run);
}

std::string runSummaryText(const json& s) {
  std::ostringstream out;
  out << std::setprecision(4);
  out << s.at("scene").get<std::string>() << ": " << s.at("bodies").get<int>() << " bodies, "
      << s.at("dimension").get<int>() << "D, " << s.at("steps").get<std::int64_t>() << " steps of dt = "
      << s.at("dt").get<double>() << " s (" << s.at("simulatedSeconds").get<double>() << " s simulated) in "
      << s.at("wallSeconds").get<double>() << " s wall, " << s.at("secondsPerStep").get<double>() * 1e3
      << " ms per step\n";
  out << "  effects: ";
  const json& effects = s.at("effects");
  if (effects.empty()) out << "none";
  for (std::size_t k = 0; k < effects.size(); ++k) out << (k ? ", " : "") << effects[k].get<std::string>();
  out << "\n";
  for (const char* stage : {"collision", "contact", "shockPropagation"}) {
    const json& st = s.at("stages").at(stage);
    out << "  " << std::left << std::setw(17) << stage << std::right << std::setw(9)
        << st.at("seconds").get<double>() << " s, " << st.at("impulses").get<std::int64_t>() << " impulses ("
        << st.at("sticking").get<std::int64_t>() << " sticking, " << st.at("sliding").get<std::int64_t>()
        << " sliding), " << st.at("sweeps").get<std::int64_t>() << " sweeps, "
        << st.at("pairQueries").get<std::int64_t>() << " pair queries, " << st.at("phiQueries").get<std::int64_t>()
        << " phi queries\n";
  }
  if (s.at("pairOrder").get<std::string>() != "list") {  // chapter 10, "Colours": a different method, so said
    out << "  pairs swept colour by colour on " << s.at("threads").get<int>() << " thread(s)\n";
  }
  out << "  velocity update " << s.at("stages").at("velocityUpdate").at("seconds").get<double>()
      << " s, position update " << s.at("stages").at("positionUpdate").at("seconds").get<double>() << " s\n";
  if (const json& sl = s.at("sleep"); sl.at("enabled").get<bool>()) {
    out << "  sleeping: " << sl.at("bodyStepsAsleep").get<std::int64_t>() << " body-steps asleep, "
        << sl.at("fellAsleep").get<std::int64_t>() << " fell asleep, " << sl.at("wokenUp").get<std::int64_t>()
        << " woken, " << sl.at("asleepAtEnd").get<std::int64_t>() << " asleep at the end\n";
  }
  out << "  max penetration " << s.at("maxPenetration").get<double>() << " at t = "
      << s.at("maxPenetrationTime").get<double>() << " s\n";
  const json& e = s.at("energy");
  out << "  energy (kinetic + potential): start " << e.at("start").at("total").get<double>() << " J, end "
      << e.at("end").at("total").get<double>() << " J\n";
  for (const json& q : s.at("quarantined")) {
    out << "  quarantined body " << q.at("body").get<int>() << ": " << q.at("message").get<std::string>() << "\n";
  }
  if (!s.at("finite").get<bool>()) out << "  WARNING: the final state is not finite\n";
  const json& files = s.at("files");
  if (!files.empty()) {
    out << "  files:";
    for (const json& f : files) out << "\n    " << f.get<std::string>();
    out << "\n";
  }
  return out.str();
}

}  // namespace stackbook
