// Parameter sweeps (chapter 11). See sweep.hpp.
#include "stackbook/scene/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <Eigen/Geometry>

#include "stackbook/output/csv.hpp"
#include "stackbook/output/output_files.hpp"
#include "stackbook/stacking/shock_propagation.hpp"
#include "stackbook/stacking/welded_pass.hpp"
#include "stackbook/stepping/traditional_step.hpp"

namespace stackbook {

using nlohmann::json;

namespace {

const std::vector<std::string> kQuantities = {"position",       "velocity",    "angularVelocity",
                                              "energyDrift",    "maxPenetration", "rollingStart",
                                              "flipPeriod",     "drift",       "sag",
                                              "windowed",       "bounceApex",  "mirror",
                                              "standing",       "distance",    "speed",
                                              "precession",     "rockingRatio"};

/// The peers a spec may name and each one's knobs (whether or not this program has them built).
const std::vector<std::pair<std::string, std::vector<std::string>>> kPeerKnobs = {
    {"box2d", {"dt", "velocityIterations", "positionIterations"}},
    {"bullet", {"dt", "iterations"}}};

std::mutex& peerLock() {
  static std::mutex m;
  return m;
}
std::vector<SweepPeerEngine>& peerRegistry() {
  static std::vector<SweepPeerEngine> engines;
  return engines;
}

std::string joinPointer(const std::string& base, const std::string& key) { return base + "/" + key; }

const json& require(const json& object, const std::string& key, const std::string& pointer,
                    const std::string& file) {
  if (!object.contains(key)) throw SceneError(file, pointer, "missing field \"" + key + "\"");
  return object.at(key);
}

std::string requireString(const json& v, const std::string& pointer, const std::string& file) {
  if (!v.is_string() || v.get<std::string>().empty()) {
    throw SceneError(file, pointer, "must be a non-empty string, got " + v.dump());
  }
  return v.get<std::string>();
}

double requireNumber(const json& v, const std::string& pointer, const std::string& file) {
  if (!v.is_number() || !std::isfinite(v.get<double>())) {
    throw SceneError(file, pointer, "must be a finite number, got " + v.dump());
  }
  return v.get<double>();
}

int requireIndex(const json& v, const std::string& pointer, const std::string& file) {
  if (!v.is_number_integer() || v.get<long long>() < 0) {
    throw SceneError(file, pointer, "must be an integer >= 0, got " + v.dump());
  }
  return static_cast<int>(v.get<long long>());
}

void rejectUnknown(const json& object, const std::vector<std::string>& known, const std::string& pointer,
                   const std::string& file) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
    const std::string close = closestName(it.key(), known);
    throw SceneError(file, joinPointer(pointer, it.key()),
                     "unknown field" + (close.empty() ? std::string() : " (did you mean \"" + close + "\"?)"));
  }
}

std::string number(double x) { return output_detail::exactDecimal(x); }

/// "Up" for the height-based measures (sag, bounce apex): against gravity, or the last axis
/// when a scene has none.
template <int D>
Vec<D> sweepUp(const Vec<D>& gravity) {
  return gravity.norm() > 0.0 ? Vec<D>(-gravity.normalized()) : Vec<D>(Vec<D>::Unit(D - 1));
}

std::string fileStem(const std::string& name) {
  std::string out;
  for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_');
  return out;
}

}  // namespace

SweepSpec parseSweepSpec(const json& doc, const std::string& file) {
  SweepSpec spec;
  spec.file = file;
  if (!doc.is_object()) throw SceneError(file, "", "a sweep spec must be a JSON object");
  rejectUnknown(doc, {"name", "description", "scene", "engine", "set", "knobs", "errors", "peers"}, "", file);
  spec.name = doc.contains("name") ? requireString(doc.at("name"), "/name", file)
                                   : std::filesystem::path(file).stem().string();
  const std::string scene = requireString(require(doc, "scene", "", file), "/scene", file);
  const std::filesystem::path base = std::filesystem::path(file).parent_path();
  // A path is taken relative to the spec's folder; a bare name is a bundled scene.
  const bool bare = scene.find('/') == std::string::npos && scene.find(".json") == std::string::npos;
  spec.scene = bare || std::filesystem::path(scene).is_absolute() ? scene
                                                                  : (base / scene).lexically_normal().string();
  if (doc.contains("engine")) {
    spec.engine = requireString(doc.at("engine"), "/engine", file);
    if (spec.engine != "stackbook") {
      throw SceneError(file, "/engine", "only \"stackbook\" runs here, got \"" + spec.engine + "\"");
    }
  }
  if (doc.contains("set")) {
    const json& sets = doc.at("set");
    if (!sets.is_array()) throw SceneError(file, "/set", "must be an array of \"key=value\" strings");
    for (std::size_t k = 0; k < sets.size(); ++k) {
      const std::string p = "/set/" + std::to_string(k);
      const std::string s = requireString(sets[k], p, file);
      if (s.find('=') == std::string::npos || s.front() == '=') {
        throw SceneError(file, p, "must be \"key=value\", got \"" + s + "\"");
      }
      spec.sets.push_back(s);
    }
  }
  const json& knobs = require(doc, "knobs", "", file);
  if (!knobs.is_array() || knobs.empty()) throw SceneError(file, "/knobs", "must be a non-empty array of knobs");
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    const std::string p = "/knobs/" + std::to_string(k);
    const json& knob = knobs[k];
    if (!knob.is_object()) throw SceneError(file, p, "must be an object {\"key\": ..., \"values\": [...]}");
    rejectUnknown(knob, {"key", "values"}, p, file);
    SweepKnob out;
    out.key = requireString(require(knob, "key", p, file), p + "/key", file);
    const json& values = require(knob, "values", p, file);
    if (!values.is_array() || values.empty()) throw SceneError(file, p + "/values", "must be a non-empty array");
    for (const json& v : values) out.values.push_back(v);
    for (const SweepKnob& earlier : spec.knobs) {
      if (earlier.key == out.key) throw SceneError(file, p + "/key", "\"" + out.key + "\" is already a knob");
    }
    spec.knobs.push_back(std::move(out));
  }
  const json& errors = require(doc, "errors", "", file);
  if (!errors.is_array() || errors.empty()) throw SceneError(file, "/errors", "must be a non-empty array of error measures");
  for (std::size_t k = 0; k < errors.size(); ++k) {
    const std::string p = "/errors/" + std::to_string(k);
    const json& e = errors[k];
    if (!e.is_object()) throw SceneError(file, p, "must be an object {\"name\": ..., \"quantity\": ...}");
    rejectUnknown(e, {"name", "quantity", "body", "axis", "radius", "tolerance", "expected", "relative", "within", "unit",
                     "windows", "window", "refine", "apex", "rest"},
                  p, file);
    SweepError out;
    out.quantity = requireString(require(e, "quantity", p, file), p + "/quantity", file);
    if (std::find(kQuantities.begin(), kQuantities.end(), out.quantity) == kQuantities.end()) {
      const std::string close = closestName(out.quantity, kQuantities);
      throw SceneError(file, p + "/quantity",
                       "unknown quantity \"" + out.quantity + "\"" +
                           (close.empty() ? std::string(" (position, velocity, angularVelocity, energyDrift, "
                                                        "maxPenetration, rollingStart, flipPeriod, drift, sag, windowed, bounceApex, mirror, standing, "
                                                        "distance, speed, precession, rockingRatio)")
                                          : " (did you mean \"" + close + "\"?)"));
    }
    out.name = e.contains("name") ? requireString(e.at("name"), p + "/name", file) : out.quantity;
    if (e.contains("body")) out.body = requireIndex(e.at("body"), p + "/body", file);
    if (e.contains("axis")) {
      out.axis = requireIndex(e.at("axis"), p + "/axis", file);
      if (out.axis > 2) throw SceneError(file, p + "/axis", "must be 0, 1 or 2, got " + std::to_string(out.axis));
    }
    if (e.contains("radius")) {
      out.radius = requireNumber(e.at("radius"), p + "/radius", file);
      if (!(out.radius > 0.0)) throw SceneError(file, p + "/radius", "must be > 0");
    } else if (out.quantity == "rollingStart") {
      throw SceneError(file, p, "missing field \"radius\" (rollingStart needs the ball's radius)");
    }
    if (out.quantity == "standing" && !e.contains("tolerance")) {
      throw SceneError(file, p, "missing field \"tolerance\" (standing needs the distance, m, a body may move)");
    }
    if (out.quantity == "standing" && !e.contains("within")) {
      throw SceneError(file, p, "missing field \"within\" (standing needs the seconds the table asks for)");
    }
    if (e.contains("tolerance")) {
      out.tolerance = requireNumber(e.at("tolerance"), p + "/tolerance", file);
      if (!(out.tolerance > 0.0)) throw SceneError(file, p + "/tolerance", "must be > 0");
    }
    if (e.contains("expected")) {
      out.hasExpected = true;
      out.expected = requireNumber(e.at("expected"), p + "/expected", file);
    }
    if (e.contains("relative")) {
      if (!e.at("relative").is_boolean()) throw SceneError(file, p + "/relative", "must be true or false");
      out.relative = e.at("relative").get<bool>();
    }
    if (out.relative && out.hasExpected && out.expected == 0.0) {
      throw SceneError(file, p + "/relative", "a relative error needs an expected value other than 0");
    }
    if (e.contains("within")) {
      const json& w = e.at("within");
      if (!w.is_array() || w.empty()) throw SceneError(file, p + "/within", "must be a non-empty array of numbers > 0");
      out.within.clear();
      for (std::size_t j = 0; j < w.size(); ++j) {
        const double bound = requireNumber(w[j], p + "/within/" + std::to_string(j), file);
        if (!(bound > 0.0)) throw SceneError(file, p + "/within/" + std::to_string(j), "must be > 0");
        out.within.push_back(bound);
      }
    }
    if (e.contains("unit")) out.unit = requireString(e.at("unit"), p + "/unit", file);
    if (e.contains("windows")) {
      out.windows = requireIndex(e.at("windows"), p + "/windows", file);
      if (out.windows < 1) throw SceneError(file, p + "/windows", "must be >= 1");
    }
    if (e.contains("window")) {
      out.window = requireNumber(e.at("window"), p + "/window", file);
      if (!(out.window > 0.0)) throw SceneError(file, p + "/window", "must be > 0");
    }
    if (e.contains("refine")) {
      out.refine = requireIndex(e.at("refine"), p + "/refine", file);
      if (out.refine < 2) throw SceneError(file, p + "/refine", "must be >= 2 (the fine run's step is dt / refine)");
    }
    if (e.contains("rest")) {
      out.rest = requireNumber(e.at("rest"), p + "/rest", file);
    } else if (out.quantity == "rockingRatio") {
      throw SceneError(file, p, "missing field \"rest\" (rockingRatio needs the height, m, of the centre at rest)");
    }
    if (e.contains("apex")) {
      out.apex = requireIndex(e.at("apex"), p + "/apex", file);
      if (out.apex < 1) throw SceneError(file, p + "/apex", "must be >= 1 (the first apex after the start is 1)");
    }
    for (const SweepError& earlier : spec.errors) {
      if (earlier.name == out.name) throw SceneError(file, p + "/name", "\"" + out.name + "\" is already an error's name");
    }
    spec.errors.push_back(out);
  }
  if (doc.contains("peers")) {
    const json& peers = doc.at("peers");
    if (!peers.is_array()) throw SceneError(file, "/peers", "must be an array of {\"engine\": ..., \"knobs\": [...]}");
    for (std::size_t k = 0; k < peers.size(); ++k) {
      const std::string p = "/peers/" + std::to_string(k);
      const json& peer = peers[k];
      if (!peer.is_object()) throw SceneError(file, p, "must be an object {\"engine\": ..., \"knobs\": [...]}");
      rejectUnknown(peer, {"engine", "knobs"}, p, file);
      SweepPeerSpec out;
      out.engine = requireString(require(peer, "engine", p, file), p + "/engine", file);
      const auto known = std::find_if(kPeerKnobs.begin(), kPeerKnobs.end(),
                                      [&](const auto& entry) { return entry.first == out.engine; });
      if (known == kPeerKnobs.end()) {
        throw SceneError(file, p + "/engine", "unknown peer \"" + out.engine + "\" (box2d or bullet)");
      }
      const json& knobs2 = require(peer, "knobs", p, file);
      if (!knobs2.is_array() || knobs2.empty()) throw SceneError(file, p + "/knobs", "must be a non-empty array of knobs");
      for (std::size_t j = 0; j < knobs2.size(); ++j) {
        const std::string q = p + "/knobs/" + std::to_string(j);
        const json& knob = knobs2[j];
        if (!knob.is_object()) throw SceneError(file, q, "must be an object {\"key\": ..., \"values\": [...]}");
        rejectUnknown(knob, {"key", "values"}, q, file);
        SweepKnob kn;
        kn.key = requireString(require(knob, "key", q, file), q + "/key", file);
        if (std::find(known->second.begin(), known->second.end(), kn.key) == known->second.end()) {
          const std::string close = closestName(kn.key, known->second);
          std::string names;
          for (const std::string& n : known->second) names += (names.empty() ? "" : ", ") + n;
          throw SceneError(file, q + "/key",
                           "\"" + kn.key + "\" is not a knob of " + out.engine +
                               (close.empty() ? " (" + names + ")" : " (did you mean \"" + close + "\"?)"));
        }
        for (const SweepKnob& earlier : out.knobs) {
          if (earlier.key == kn.key) throw SceneError(file, q + "/key", "\"" + kn.key + "\" is already a knob");
        }
        const json& values = require(knob, "values", q, file);
        if (!values.is_array() || values.empty()) throw SceneError(file, q + "/values", "must be a non-empty array");
        for (std::size_t v = 0; v < values.size(); ++v) {
          const std::string r = q + "/values/" + std::to_string(v);
          if (kn.key == "dt") {
            if (!(requireNumber(values[v], r, file) > 0.0)) throw SceneError(file, r, "must be > 0");
          } else if (!values[v].is_number_integer() || values[v].get<long long>() < 1) {
            throw SceneError(file, r, "must be an integer >= 1, got " + values[v].dump());
          }
          kn.values.push_back(values[v]);
        }
        out.knobs.push_back(std::move(kn));
      }
      spec.peers.push_back(std::move(out));
    }
  }
  return spec;
}

void registerSweepPeer(SweepPeerEngine engine) {
  std::lock_guard<std::mutex> guard(peerLock());
  for (SweepPeerEngine& e : peerRegistry()) {
    if (e.name == engine.name) {
      e = std::move(engine);
      return;
    }
  }
  peerRegistry().push_back(std::move(engine));
}

const SweepPeerEngine* findSweepPeer(const std::string& name) {
  std::lock_guard<std::mutex> guard(peerLock());
  for (const SweepPeerEngine& e : peerRegistry()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::vector<std::string> sweepNotes(const SweepSpec& spec) {
  std::vector<std::string> notes;
  for (std::size_t k = 0; k < spec.peers.size(); ++k) {
    if (findSweepPeer(spec.peers[k].engine) != nullptr) continue;
    const std::string package = spec.peers[k].engine == "box2d" ? "libbox2d-dev" : "libbullet-dev";
    notes.push_back(spec.file + ": /peers/" + std::to_string(k) + ": " + spec.peers[k].engine +
                    " is not built into this program (install " + package +
                    " and configure again): its rows are skipped");
  }
  return notes;
}

SweepSpec loadSweepSpec(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw SceneError(path, "", "no such sweep spec file");
  return parseSweepSpec(readSceneJson(path), path);
}

std::vector<SweepRun> sweepRuns(const SweepSpec& spec) {
  std::size_t total = 1;
  for (const SweepKnob& k : spec.knobs) total *= k.values.size();
  std::vector<SweepRun> runs;
  runs.reserve(total);
  for (std::size_t index = 0; index < total; ++index) {
    SweepRun run;
    run.index = index;
    run.overrides = spec.sets;
    std::size_t rest = index;
    std::string config;
    for (std::size_t k = 0; k < spec.knobs.size(); ++k) {
      const SweepKnob& knob = spec.knobs[k];
      const json& value = knob.values[rest % knob.values.size()];
      rest /= knob.values.size();
      const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
      run.overrides.push_back(knob.key + "=" + value.dump());
      if (k == 0) {
        run.knob = knob.key;
        run.value = text;
      } else {
        config += (config.empty() ? "" : ";") + knob.key + "=" + text;
      }
    }
    run.config = config.empty() ? "-" : config;
    runs.push_back(std::move(run));
  }
  // Each built peer's grid after stackbook's, so that stackbook's run indices do not depend
  // on which peers are installed.
  for (std::size_t p = 0; p < spec.peers.size(); ++p) {
    const SweepPeerEngine* engine = findSweepPeer(spec.peers[p].engine);
    if (engine == nullptr) continue;
    const std::vector<SweepKnob>& knobs = spec.peers[p].knobs;
    std::size_t count = 1;
    for (const SweepKnob& k : knobs) count *= k.values.size();
    for (std::size_t local = 0; local < count; ++local) {
      SweepRun run;
      run.index = runs.size();
      run.overrides = spec.sets;
      run.engine = engine->label;
      run.peer = static_cast<int>(p);
      std::size_t rest = local;
      std::string config;
      for (std::size_t k = 0; k < knobs.size(); ++k) {
        const json& value = knobs[k].values[rest % knobs[k].values.size()];
        rest /= knobs[k].values.size();
        run.peerKnobs.emplace_back(knobs[k].key, value);
        if (k == 0) {
          run.knob = knobs[k].key;
          run.value = value.dump();
        } else {
          config += (config.empty() ? "" : ";") + knobs[k].key + "=" + value.dump();
        }
      }
      run.config = config.empty() ? "-" : config;
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

bool sweepHigherIsBetter(const SweepError& e) { return e.quantity == "standing"; }

bool sweepNeedsEveryStep(const SweepSpec& spec) {
  for (const SweepError& e : spec.errors) {
    if (e.quantity == "energyDrift" || e.quantity == "rollingStart" || e.quantity == "flipPeriod" ||
        e.quantity == "maxPenetration" || e.quantity == "bounceApex" || e.quantity == "rockingRatio" ||
        e.quantity == "standing" ||
        e.quantity == "precession") {
      return true;
    }
  }
  return false;
}

double sweepApexHeight(const std::vector<double>& times, const std::vector<double>& heights, int k) {
  int found = 0;
  for (std::size_t f = 1; f + 1 < heights.size() && f < times.size(); ++f) {
    if (!(heights[f - 1] < heights[f] && heights[f] >= heights[f + 1])) continue;
    if (++found < k) continue;
    // y(s) = y1 + B s + A s^2 with s = t - t1 through the three points; its vertex.
    const double d0 = times[f - 1] - times[f], d2 = times[f + 1] - times[f];
    const double q0 = (heights[f - 1] - heights[f]) / d0, q2 = (heights[f + 1] - heights[f]) / d2;
    const double a = (q0 - q2) / (d0 - d2), b = q0 - a * d0;
    return a < 0.0 ? heights[f] - b * b / (4.0 * a) : heights[f];
  }
  return std::numeric_limits<double>::infinity();
}

double sweepRockingRatio(const std::vector<double>& times, const std::vector<double>& heights, int k, double rest) {
  if (heights.empty()) return std::numeric_limits<double>::infinity();
  const double apex = sweepApexHeight(times, heights, k);
  const double start = heights.front() - rest;
  if (!std::isfinite(apex) || !(start > 0.0)) return std::numeric_limits<double>::infinity();
  return std::pow(std::max(apex - rest, 0.0) / start, 1.0 / (2.0 * k));  // E_k / E_0 = r^(2k)
}

double sweepMirrorError(const std::vector<Eigen::Vector3d>& start, const std::vector<Eigen::Vector3d>& end,
                        const std::vector<bool>& isStatic, const Eigen::Vector3d& normal, double tolerance,
                        const std::string& file) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  std::size_t dynamic = 0;
  for (std::size_t k = 0; k < start.size(); ++k) {
    if (isStatic[k]) continue;
    centre += start[k];
    ++dynamic;
  }
  if (dynamic == 0) return 0.0;
  centre /= static_cast<double>(dynamic);
  const auto reflect = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return p - 2.0 * (p - centre).dot(normal) * normal;
  };
  double worst = 0.0;
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (isStatic[i]) continue;
    const Eigen::Vector3d image = reflect(start[i]);
    std::size_t partner = start.size();
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < start.size(); ++j) {
      if (isStatic[j]) continue;
      const double d = (start[j] - image).norm();
      if (d < nearest) {
        nearest = d;
        partner = j;
      }
    }
    if (!(nearest <= tolerance)) {
      throw SceneError(file, "", "the mirror error needs a symmetric start: body " + std::to_string(i) +
                                     " has no mirror image within " + number(tolerance) + " m");
    }
    worst = std::max(worst, (reflect(end[i]) - end[partner]).norm());
  }
  return worst;
}

double sweepPrecessionError(const std::vector<double>& times, const std::vector<Eigen::Matrix3d>& rotations,
                            const Eigen::Vector3d& omega0, const Eigen::Vector3d& inertia, int axis,
                            double tolerance, const std::string& file) {
  if (times.empty() || rotations.size() != times.size()) {
    throw SceneError(file, "", "the precession error needs one orientation per frame");
  }
  if (axis < 0 || axis > 2) throw SceneError(file, "", "the precession error needs a body axis 0, 1 or 2");
  const double i1 = inertia[(axis + 1) % 3], i2 = inertia[(axis + 2) % 3];
  if (!(std::abs(i1 - i2) <= tolerance * std::max(std::abs(i1), std::abs(i2)))) {
    throw SceneError(file, "", "the precession error needs an axisymmetric body: the moments about the axes other "
                               "than " + std::to_string(axis) + " are " + number(i1) + " and " + number(i2));
  }
  const Eigen::Matrix3d& r0 = rotations.front();
  const Eigen::Vector3d angularMomentum = r0 * inertia.asDiagonal() * r0.transpose() * omega0;
  const Eigen::Vector3d a0 = r0.col(axis);
  const double l = angularMomentum.norm();
  const double sinCone = l > 0.0 ? angularMomentum.cross(a0).norm() / l : 0.0;
  const double arc = sinCone * l * (times.back() - times.front()) / i1;
  if (!(arc > 0.0)) {
    throw SceneError(file, "", "the precession error needs a spin off the symmetry axis and a run of some length: "
                               "the closed-form axis does not move");
  }
  const Eigen::Vector3d n = angularMomentum / l;
  double worst = 0.0;
  for (std::size_t f = 0; f < times.size(); ++f) {
    const Eigen::Vector3d exact = Eigen::AngleAxisd(l * (times[f] - times.front()) / i1, n) * a0;
    const Eigen::Vector3d a = rotations[f].col(axis);
    worst = std::max(worst, std::atan2(a.cross(exact).norm(), a.dot(exact)));
  }
  return worst / arc;
}

double measureSweepTrajectory(const SweepError& e, const SweepTrajectory& t, const std::string& file) {
  const std::size_t bodies = t.isStatic.size();
  if (t.frames.empty()) throw SceneError(file, "", "error \"" + e.name + "\": the run has no frames");
  const std::size_t last = t.frames.size() - 1;
  const auto bodyCheck = [&] {
    if (e.body >= static_cast<int>(bodies)) {
      throw SceneError(file, "", "error \"" + e.name + "\": body " + std::to_string(e.body) + " is not in the scene (" +
                                     std::to_string(bodies) + " bodies)");
    }
  };
  const auto axisCheck = [&](int size) {
    if (e.axis >= size) {
      throw SceneError(file, "", "error \"" + e.name + "\": axis " + std::to_string(e.axis) + " does not exist in " +
                                     std::to_string(t.dimension) + "D");
    }
  };
  const std::size_t b = static_cast<std::size_t>(e.body);
  Eigen::Vector3d up = Eigen::Vector3d::Unit(t.dimension - 1);
  if (t.gravity.norm() > 0.0) up = -t.gravity.normalized();
  double value = 0.0;
  if (e.quantity == "position") {
    bodyCheck();
    axisCheck(t.dimension);
    value = t.frames[last][b].position[e.axis];
  } else if (e.quantity == "velocity") {
    bodyCheck();
    axisCheck(t.dimension);
    value = t.frames[last][b].velocity[e.axis];
  } else if (e.quantity == "angularVelocity") {
    bodyCheck();
    axisCheck(t.dimension == 2 ? 1 : 3);
    value = t.frames[last][b].angularVelocity[t.dimension == 2 ? 2 : e.axis];
  } else if (e.quantity == "energyDrift") {
    const double e0 = t.energies.front();
    double worst = 0.0;
    for (double f : t.energies) worst = std::max(worst, std::abs(f - e0));
    value = e0 != 0.0 ? worst / std::abs(e0) : worst;
  } else if (e.quantity == "maxPenetration") {
    value = t.maxPenetration;
  } else if (e.quantity == "rollingStart") {
    bodyCheck();
    const Eigen::Vector3d down = -e.radius * up;
    value = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < t.frames.size(); ++f) {
      const Eigen::Vector3d u = t.frames[f][b].velocity + t.frames[f][b].angularVelocity.cross(down);
      if (u.norm() < e.tolerance) {
        value = t.times[f];
        break;
      }
    }
  } else if (e.quantity == "flipPeriod") {
    bodyCheck();
    if (t.dimension == 2) throw SceneError(file, "", "error \"" + e.name + "\": flipPeriod needs a 3D scene");
    std::vector<double> flips;
    double previous = 0.0;
    for (std::size_t f = 0; f < t.frames.size(); ++f) {
      const double w = (t.frames[f][b].rotation.transpose() * t.frames[f][b].angularVelocity)[e.axis];
      if (f > 0 && (previous > 0.0) != (w > 0.0)) {
        flips.push_back(t.times[f - 1] + (t.times[f] - t.times[f - 1]) * previous / (previous - w));
      }
      previous = w;
    }
    value = flips.size() >= 2 ? 2.0 * (flips.back() - flips.front()) / static_cast<double>(flips.size() - 1)
                              : std::numeric_limits<double>::infinity();
  } else if (e.quantity == "drift") {
    for (std::size_t k = 0; k < bodies; ++k) {
      if (t.isStatic[k]) continue;
      const Eigen::Vector3d d = t.frames[last][k].position - t.frames[0][k].position;
      value = std::max(value, (d - d.dot(up) * up).norm());
    }
  } else if (e.quantity == "standing") {
    value = t.times[last];
    for (std::size_t f = 0; f < t.frames.size() && value == t.times[last]; ++f) {
      for (std::size_t k = 0; k < bodies; ++k) {
        if (!t.isStatic[k] && (t.frames[f][k].position - t.frames[0][k].position).norm() > e.tolerance) {
          value = t.times[f];
          break;
        }
      }
    }
  } else if (e.quantity == "bounceApex" || e.quantity == "rockingRatio") {
    bodyCheck();
    std::vector<double> heights;
    heights.reserve(t.frames.size());
    for (const auto& frame : t.frames) heights.push_back(frame[b].position.dot(up));
    value = e.quantity == "bounceApex" ? sweepApexHeight(t.times, heights, e.apex)
                                       : sweepRockingRatio(t.times, heights, e.apex, e.rest);
  } else if (e.quantity == "mirror") {
    axisCheck(t.dimension);
    std::vector<Eigen::Vector3d> start, end;
    for (std::size_t k = 0; k < bodies; ++k) {
      start.push_back(t.frames[0][k].position);
      end.push_back(t.frames[last][k].position);
    }
    value = sweepMirrorError(start, end, t.isStatic, Eigen::Vector3d::Unit(e.axis), e.tolerance, file);
  } else if (e.quantity == "windowed") {
    throw SceneError(file, "", "error \"" + e.name + "\": the windowed error restarts stackbook's step; a peer's run has no such measure");
  } else if (e.quantity == "sag") {
    bodyCheck();
    value = std::abs((t.frames[0][b].position - t.frames[last][b].position).dot(up));
  } else if (e.quantity == "distance") {
    bodyCheck();
    value = (t.frames[last][b].position - t.frames[0][b].position).norm();
  } else if (e.quantity == "speed") {
    bodyCheck();
    value = t.frames[last][b].velocity.norm();
  } else if (e.quantity == "precession") {
    bodyCheck();
    if (t.dimension == 2) throw SceneError(file, "", "error \"" + e.name + "\": precession needs a 3D scene");
    if (t.inertia.size() != bodies) {
      throw SceneError(file, "", "error \"" + e.name + "\": precession needs the bodies' moments of inertia");
    }
    std::vector<Eigen::Matrix3d> rotations;
    rotations.reserve(t.frames.size());
    for (const auto& frame : t.frames) rotations.push_back(frame[b].rotation);
    value = sweepPrecessionError(t.times, rotations, t.frames[0][b].angularVelocity, t.inertia[b], e.axis,
                                 e.tolerance, file);
  }
  if (!e.hasExpected) return value;
  const double diff = std::abs(value - e.expected);
  return e.relative ? diff / std::abs(e.expected) : diff;
}

namespace {

template <int D>
double measureError(const SweepError& e, const RunResult<D>& r, const Scene& scene, const std::string& file) {
  const Recording<D>& rec = r.recording;
  const std::size_t last = rec.frameCount() - 1;
  const auto bodyCheck = [&] {
    if (e.body >= static_cast<int>(rec.bodyCount())) {
      throw SceneError(file, "", "error \"" + e.name + "\": body " + std::to_string(e.body) + " is not in the scene (" +
                                     std::to_string(rec.bodyCount()) + " bodies)");
    }
  };
  const auto axisCheck = [&](int size) {
    if (e.axis >= size) {
      throw SceneError(file, "", "error \"" + e.name + "\": axis " + std::to_string(e.axis) + " does not exist in " +
                                     std::to_string(D) + "D");
    }
  };
  const std::size_t b = static_cast<std::size_t>(e.body);
  double value = 0.0;
  if (e.quantity == "position") {
    bodyCheck();
    axisCheck(D);
    value = rec.poses()[last][b].position[e.axis];
  } else if (e.quantity == "velocity") {
    bodyCheck();
    axisCheck(D);
    value = rec.velocities()[last][b][e.axis];
  } else if (e.quantity == "angularVelocity") {
    bodyCheck();
    axisCheck(D == 2 ? 1 : 3);
    value = rec.angularVelocities()[last][b][e.axis];
  } else if (e.quantity == "energyDrift") {
    const double e0 = rec.energies().front().total();
    double worst = 0.0;
    for (const FrameEnergy& f : rec.energies()) worst = std::max(worst, std::abs(f.total() - e0));
    value = e0 != 0.0 ? worst / std::abs(e0) : worst;
  } else if (e.quantity == "maxPenetration") {
    value = r.maxPenetration;
  } else if (e.quantity == "rollingStart") {
    bodyCheck();
    Vec<D> down = Vec<D>::Zero();
    const Vec<D> g = std::get<SceneBodies<D>>(scene.bodies).world.gravity;
    if (g.norm() > 0.0) down = e.radius * g.normalized();
    value = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < rec.frameCount(); ++f) {
      const Vec<D> u = rec.velocities()[f][b] + crossAngular<D>(rec.angularVelocities()[f][b], down);
      if (u.norm() < e.tolerance) {
        value = rec.times()[f];
        break;
      }
    }
  } else if (e.quantity == "flipPeriod") {
    bodyCheck();
    if constexpr (D == 2) {
      throw SceneError(file, "", "error \"" + e.name + "\": flipPeriod needs a 3D scene");
    } else {
      std::vector<double> flips;
      double previous = 0.0;
      for (std::size_t f = 0; f < rec.frameCount(); ++f) {
        const double w = (rec.poses()[f][b].orientation.conjugate() * rec.angularVelocities()[f][b])[e.axis];
        if (f > 0 && (previous > 0.0) != (w > 0.0)) {
          const double t0 = rec.times()[f - 1], t1 = rec.times()[f];
          flips.push_back(t0 + (t1 - t0) * previous / (previous - w));
        }
        previous = w;
      }
      value = flips.size() >= 2 ? 2.0 * (flips.back() - flips.front()) / static_cast<double>(flips.size() - 1)
                                : std::numeric_limits<double>::infinity();
    }
  } else if (e.quantity == "windowed") {
    // Erez, Tassa and Todorov's self-consistency (ICRA 2015): a fine run at dt / refine goes
    // on through all windows; each window restarts the run's own step from the fine state and
    // compares the two at the window's end, so that sensitivity to the start is not error.
    World<D> fine = std::get<SceneBodies<D>>(scene.bodies).world;
    StepSettings coarseSettings = scene.settings, fineSettings = scene.settings;
    coarseSettings.contactRecorder = nullptr;
    fineSettings.contactRecorder = nullptr;
    fineSettings.dt = scene.settings.dt / static_cast<double>(e.refine);
    const auto steps = std::max<std::int64_t>(1, std::llround(e.window / scene.settings.dt));
    const PostContactHook<D> hook = shockPropagationHook<D>();
    double sum = 0.0;
    for (int w = 0; w < e.windows; ++w) {
      World<D> coarse = fine;
      for (std::int64_t n = 0; n < steps; ++n) sceneStep<D>(coarse, coarseSettings, hook);
      for (std::int64_t n = 0; n < steps * e.refine; ++n) sceneStep<D>(fine, fineSettings, hook);
      double worst = 0.0;
      for (std::size_t k = 0; k < fine.bodies.size(); ++k) {
        if (fine.bodies[k].isStatic()) continue;
        worst = std::max(worst, (coarse.bodies[k].position - fine.bodies[k].position).norm());
      }
      sum += worst;
    }
    value = sum / static_cast<double>(e.windows);
  } else if (e.quantity == "standing") {
    // The same definition as measureSweepTrajectory()'s, on the recorded poses.
    const World<D>& world = std::get<SceneBodies<D>>(scene.bodies).world;
    value = rec.times()[last];
    for (std::size_t f = 0; f < rec.frameCount() && value == rec.times()[last]; ++f) {
      for (std::size_t k = 0; k < rec.bodyCount(); ++k) {
        if (!world.bodies[k].isStatic() && (rec.poses()[f][k].position - rec.poses()[0][k].position).norm() > e.tolerance) {
          value = rec.times()[f];
          break;
        }
      }
    }
  } else if (e.quantity == "bounceApex" || e.quantity == "rockingRatio" || e.quantity == "mirror") {
    // The same definitions as measureSweepTrajectory()'s, on the recorded poses.
    const World<D>& world = std::get<SceneBodies<D>>(scene.bodies).world;
    const Vec<D> up = sweepUp<D>(world.gravity);
    if (e.quantity != "mirror") {
      bodyCheck();
      std::vector<double> heights;
      heights.reserve(rec.frameCount());
      for (std::size_t f = 0; f < rec.frameCount(); ++f) heights.push_back(rec.poses()[f][b].position.dot(up));
      value = e.quantity == "bounceApex" ? sweepApexHeight(rec.times(), heights, e.apex)
                                         : sweepRockingRatio(rec.times(), heights, e.apex, e.rest);
    } else {
      axisCheck(D);
      std::vector<Eigen::Vector3d> start, end;
      std::vector<bool> isStatic;
      for (std::size_t k = 0; k < rec.bodyCount(); ++k) {
        Eigen::Vector3d p0 = Eigen::Vector3d::Zero(), p1 = Eigen::Vector3d::Zero();
        p0.head<D>() = rec.poses()[0][k].position;
        p1.head<D>() = rec.poses()[last][k].position;
        start.push_back(p0);
        end.push_back(p1);
        isStatic.push_back(world.bodies[k].isStatic());
      }
      value = sweepMirrorError(start, end, isStatic, Eigen::Vector3d::Unit(e.axis), e.tolerance, file);
    }
  } else if (e.quantity == "distance" || e.quantity == "speed") {
    // The same definitions as measureSweepTrajectory()'s, on the recorded poses.
    bodyCheck();
    value = e.quantity == "distance" ? (rec.poses()[last][b].position - rec.poses()[0][b].position).norm()
                                     : rec.velocities()[last][b].norm();
  } else if (e.quantity == "precession") {
    bodyCheck();
    if constexpr (D == 2) {
      throw SceneError(file, "", "error \"" + e.name + "\": precession needs a 3D scene");
    } else {
      const World<D>& world = std::get<SceneBodies<D>>(scene.bodies).world;
      std::vector<Eigen::Matrix3d> rotations;
      rotations.reserve(rec.frameCount());
      for (std::size_t f = 0; f < rec.frameCount(); ++f) {
        rotations.push_back(rec.poses()[f][b].orientation.toRotationMatrix());
      }
      value = sweepPrecessionError(rec.times(), rotations, rec.angularVelocities()[0][b], world.bodies[b].inertia,
                                   e.axis, e.tolerance, file);
    }
  } else if (e.quantity == "drift" || e.quantity == "sag") {
    // The same definitions as measureSweepTrajectory()'s, on the recorded poses.
    const World<D>& world = std::get<SceneBodies<D>>(scene.bodies).world;
    const Vec<D> up = sweepUp<D>(world.gravity);
    if (e.quantity == "sag") {
      bodyCheck();
      value = std::abs((rec.poses()[0][b].position - rec.poses()[last][b].position).dot(up));
    } else {
      for (std::size_t k = 0; k < rec.bodyCount(); ++k) {
        if (world.bodies[k].isStatic()) continue;
        const Vec<D> d = rec.poses()[last][k].position - rec.poses()[0][k].position;
        value = std::max(value, (d - d.dot(up) * up).norm());
      }
    }
  }
  if (!e.hasExpected) return value;
  const double diff = std::abs(value - e.expected);
  return e.relative ? diff / std::abs(e.expected) : diff;
}

}  // namespace

SweepRow runSweepRun(const SweepSpec& spec, const SweepRun& run) {
  if (run.peer >= 0) {
    const std::string name = spec.peers.at(static_cast<std::size_t>(run.peer)).engine;
    const SweepPeerEngine* engine = findSweepPeer(name);
    if (engine == nullptr) {
      throw SceneError(spec.file, "/peers/" + std::to_string(run.peer), name + " is not built into this program");
    }
    return engine->run(spec, run);
  }
  // One thread per run unless the spec says otherwise: the sweep runs runs side by side.
  std::vector<std::string> overrides = {"solver.threads=1"};
  overrides.insert(overrides.end(), run.overrides.begin(), run.overrides.end());
  Scene scene = loadScene(spec.scene, overrides);
  if (sweepNeedsEveryStep(spec)) scene.output.frameRate = 1.0 / scene.settings.dt;
  const SceneRun result = runScene(scene);
  SweepRow row;
  row.run = run;
  std::visit(
      [&](const auto& r) {
        row.steps = r.counters.steps;
        const double seconds = r.counters.totalSeconds;
        row.msPerStep = r.counters.steps > 0 ? 1e3 * seconds / static_cast<double>(r.counters.steps) : 0.0;
        row.msPerSimulatedSecond = r.simulatedSeconds > 0.0 ? 1e3 * seconds / r.simulatedSeconds : 0.0;
        for (const SweepError& e : spec.errors) row.errors.push_back(measureError(e, r, scene, spec.file));
      },
      result);
  return row;
}

std::string sweepCsvHeader(const SweepSpec& spec) {
  std::string h = "run,scene,engine,config,knob,value,steps,ms_per_step,ms_per_simulated_second";
  for (const SweepError& e : spec.errors) h += "," + csvField(e.name);
  return h + "\n";
}

std::string sweepCsvLine(const SweepSpec& spec, const SweepRow& row) {
  std::string line = std::to_string(row.run.index) + "," + csvField(std::filesystem::path(spec.scene).stem().string()) +
                     "," + csvField(row.run.engine) + "," + csvField(row.run.config) + "," + csvField(row.run.knob) +
                     "," + csvField(row.run.value) + "," + std::to_string(row.steps) + "," + number(row.msPerStep) +
                     "," + number(row.msPerSimulatedSecond);
  for (double e : row.errors) line += "," + number(e);
  return line + "\n";
}

std::vector<std::vector<std::string>> readSweepCsv(const std::string& csvPath) {
  std::ifstream in(csvPath, std::ios::binary);
  if (!in) return {};
  std::ostringstream text;
  text << in.rdbuf();
  return csvRecords(text.str());  // a last line without its newline was cut short: not a row
}

std::vector<std::size_t> completedRuns(const SweepSpec& spec, const std::string& csvPath) {
  const auto rows = readSweepCsv(csvPath);
  std::vector<std::size_t> done;
  if (rows.empty()) return done;
  std::string header;
  for (std::size_t k = 0; k < rows[0].size(); ++k) header += (k ? "," : "") + csvField(rows[0][k]);
  if (header + "\n" != sweepCsvHeader(spec)) {
    throw SceneError(csvPath, "", "its header is not the one this spec writes (" + header +
                                      "); move it away or name another CSV");
  }
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r].size() != rows[0].size()) continue;
    done.push_back(static_cast<std::size_t>(std::strtoull(rows[r][0].c_str(), nullptr, 10)));
  }
  return done;
}

std::size_t runSweep(const SweepSpec& spec, const SweepOptions& options) {
  const std::vector<SweepRun> all = sweepRuns(spec);
  const std::vector<std::size_t> done = completedRuns(spec, options.csvPath);
  const std::set<std::size_t> skip(done.begin(), done.end());
  std::vector<SweepRun> todo;
  for (const SweepRun& run : all) {
    if (skip.count(run.index) != 0) continue;
    if (!options.only.empty() &&
        std::find(options.only.begin(), options.only.end(), run.index) == options.only.end()) {
      continue;
    }
    todo.push_back(run);
  }
  for (std::size_t k : options.only) {
    if (k >= all.size()) {
      throw SceneError(spec.file, "", "run " + std::to_string(k) + " does not exist: the grid has " +
                                          std::to_string(all.size()) + " runs (0 to " +
                                          std::to_string(all.size() - 1) + ")");
    }
  }
  if (todo.empty()) return 0;
  {
    std::error_code ec;
    const std::filesystem::path parent = std::filesystem::path(options.csvPath).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  }
  if (done.empty() && !std::filesystem::exists(options.csvPath)) {
    output_detail::writeFileOrThrow("sweep", options.csvPath, sweepCsvHeader(spec));
  }
  // Workers take runs in order; rows are appended in index order as soon as every earlier
  // one is in, so an interrupted sweep leaves a CSV that resumes cleanly.
  std::vector<SweepRow> rows(todo.size());
  std::vector<bool> finished(todo.size(), false);
  std::vector<std::string> failures(todo.size());
  std::atomic<std::size_t> next{0};
  std::mutex lock;
  std::size_t written = 0, count = 0;
  std::ofstream csv(options.csvPath, std::ios::binary | std::ios::app);
  if (!csv) throw std::runtime_error("sweep: cannot append to '" + options.csvPath + "'");
  const auto worker = [&] {
    for (std::size_t k = next++; k < todo.size(); k = next++) {
      SweepRow row;
      std::string failure;
      try {
        row = runSweepRun(spec, todo[k]);
      } catch (const std::exception& e) {
        failure = e.what();
      }
      std::lock_guard<std::mutex> guard(lock);
      rows[k] = row;
      failures[k] = failure;
      finished[k] = true;
      ++count;
      if (options.progress && failure.empty()) options.progress(count, todo.size(), row);
      while (written < todo.size() && finished[written] && failures[written].empty()) {
        csv << sweepCsvLine(spec, rows[written]) << std::flush;
        ++written;
      }
    }
  };
  const int jobs = std::max(1, std::min<int>(options.jobs, static_cast<int>(todo.size())));
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  for (std::size_t k = 0; k < todo.size(); ++k) {
    if (!failures[k].empty()) {
      throw std::runtime_error("run " + std::to_string(todo[k].index) + " failed: " + failures[k]);
    }
  }
  return todo.size();
}

std::vector<std::size_t> paretoFront(const std::vector<double>& cost, const std::vector<double>& error) {
  std::vector<std::size_t> order(cost.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return cost[a] != cost[b] ? cost[a] < cost[b] : error[a] < error[b];
  });
  std::vector<std::size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k : order) {
    if (error[k] < best) {
      front.push_back(k);
      best = error[k];
    }
  }
  return front;
}

namespace {

/// The bound of a table row as the reader reads it: "1 %" for a relative error, "0.001 m"
/// for an absolute one.
std::string boundText(const SweepError& e, double bound) {
  char text[48];
  if (sweepHigherIsBetter(e)) {
    std::snprintf(text, sizeof text, "at least %g%s%s", bound, e.unit.empty() ? "" : " ", e.unit.c_str());
  } else if ((e.relative && e.hasExpected) || e.quantity == "energyDrift" || e.quantity == "precession") {
    // A fraction: relative to the closed form, or relative by definition.
    std::snprintf(text, sizeof text, "%g %%", bound * 100.0);
  } else {
    std::snprintf(text, sizeof text, "%g%s%s", bound, e.unit.empty() ? "" : " ", e.unit.c_str());
  }
  return text;
}

std::string settingText(const std::vector<std::string>& row) {
  return row[4] + " = " + row[5] + (row[3] == "-" ? "" : ", " + row[3]);
}

/// The cheapest row (index into `rows`, 0 if none) of a sweep CSV whose error column `e` meets
/// `bound`: of the spec's engine (peer false) or of any peer (peer true).
std::size_t cheapestWithin(const std::vector<std::vector<std::string>>& rows, const SweepSpec& spec, std::size_t e,
                           double bound, bool peer) {
  std::size_t best = 0;
  double bestCost = std::numeric_limits<double>::infinity();
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r].size() != rows[0].size() || (rows[r][2] != spec.engine) != peer) continue;
    const double err = std::strtod(rows[r][9 + e].c_str(), nullptr);
    const double cost = std::strtod(rows[r][8].c_str(), nullptr);
    const bool meets = sweepHigherIsBetter(spec.errors[e]) ? err >= bound : err <= bound;
    if (meets && cost < bestCost) {
      best = r;
      bestCost = cost;
    }
  }
  return best;
}

std::string shortNumber(double x) {
  char t[32];
  std::snprintf(t, sizeof t, "%.3g", x);
  return t;
}

}  // namespace

std::string sweepParetoTable(const SweepSpec& spec, const std::string& csvPath) {
  const auto rows = readSweepCsv(csvPath);
  bool anyPeer = false;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r].size() == rows[0].size() && rows[r][2] != spec.engine) anyPeer = true;
  }
  std::ostringstream md;
  md << "| error | within | cheapest setting | its error | ms per simulated s |";
  if (anyPeer) md << " cheapest peer run | its error | ms per simulated s |";
  md << "\n|---|---|---|---|---|" << (anyPeer ? "---|---|---|" : "") << "\n";
  const auto fmt = shortNumber;
  for (std::size_t e = 0; e < spec.errors.size(); ++e) {
    for (const double bound : spec.errors[e].within) {
      // The cheapest row within the bound, of stackbook (peer false) or of any peer.
      const auto cheapest = [&](bool peer) { return cheapestWithin(rows, spec, e, bound, peer); };
      md << "| " << spec.errors[e].name << " | " << boundText(spec.errors[e], bound) << " | ";
      const std::size_t ours = cheapest(false);
      if (ours == 0) {
        md << "none | | |";
      } else {
        md << settingText(rows[ours]) << " | " << fmt(std::strtod(rows[ours][9 + e].c_str(), nullptr)) << " | "
           << fmt(std::strtod(rows[ours][8].c_str(), nullptr)) << " |";
      }
      if (anyPeer) {
        const std::size_t theirs = cheapest(true);
        if (theirs == 0) {
          md << " none | | |";
        } else {
          md << " " << rows[theirs][2] << ": " << settingText(rows[theirs]) << " | "
             << fmt(std::strtod(rows[theirs][9 + e].c_str(), nullptr)) << " | "
             << fmt(std::strtod(rows[theirs][8].c_str(), nullptr)) << " |";
        }
      }
      md << "\n";
    }
  }
  return md.str();
}

std::string sweepValueLabel(const std::string& value) {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(v)) return value;
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  // A time step such as 1/60 s has no short decimal: name it by its reciprocal.
  if (std::strtod(text, nullptr) != v && v > 0.0 && v < 1.0) {
    const double n = std::round(1.0 / v);
    if (n >= 2.0 && n <= 1e6 && std::abs(1.0 / n - v) <= 1e-12 * v) {
      std::snprintf(text, sizeof text, "1/%.0f", n);
    }
  }
  return text;
}

std::string sweepSummaryTable(const std::vector<SweepSpec>& specs, const std::vector<std::string>& csvPaths) {
  if (specs.size() != csvPaths.size()) throw std::invalid_argument("sweepSummaryTable: one CSV per spec");
  // One line per (scene, error, accuracy), in the order first met; each keeps the cheapest
  // stackbook row and the cheapest peer row over every sweep of that scene.
  struct Best {
    double cost = std::numeric_limits<double>::infinity(), error = 0.0;
    std::string setting;
  };
  struct Line {
    std::string scene, error, within;
    Best ours, theirs;
  };
  std::vector<Line> lines;
  bool anyPeer = false;
  for (std::size_t s = 0; s < specs.size(); ++s) {
    const SweepSpec& spec = specs[s];
    const auto rows = readSweepCsv(csvPaths[s]);
    std::string fixed;
    for (const std::string& set : spec.sets) fixed += ", " + set;
    const std::string scene = std::filesystem::path(spec.scene).filename().string();
    for (std::size_t e = 0; e < spec.errors.size(); ++e) {
      const SweepError& err = spec.errors[e];
      const std::string measure = err.name + " (" + err.quantity +
                                  (err.hasExpected ? " against " + shortNumber(err.expected) : std::string()) + ")";
      for (const double bound : err.within) {
        const std::string within = boundText(err, bound);
        auto it = std::find_if(lines.begin(), lines.end(), [&](const Line& l) {
          return l.scene == scene && l.error == measure && l.within == within;
        });
        if (it == lines.end()) {
          lines.push_back(Line{scene, measure, within, {}, {}});
          it = lines.end() - 1;
        }
        for (const bool peer : {false, true}) {
          const std::size_t r = cheapestWithin(rows, spec, e, bound, peer);
          if (r == 0) continue;
          const double cost = std::strtod(rows[r][8].c_str(), nullptr);
          Best& best = peer ? it->theirs : it->ours;
          if (cost < best.cost) {
            best.cost = cost;
            best.error = std::strtod(rows[r][9 + e].c_str(), nullptr);
            best.setting = (peer ? rows[r][2] + ": " : std::string()) + settingText(rows[r]) + fixed +
                           " (" + spec.name + ")";
          }
          if (peer) anyPeer = true;
        }
      }
    }
  }
  std::ostringstream md;
  md << "| scene | error | within | cheapest stackbook setting (sweep) | its error | ms per simulated s |";
  if (anyPeer) md << " cheapest peer run (sweep) | its error | ms per simulated s |";
  md << "\n|---|---|---|---|---|---|" << (anyPeer ? "---|---|---|" : "") << "\n";
  const auto cell = [](const Best& b) {
    return b.setting.empty() ? std::string("none | | |")
                             : b.setting + " | " + shortNumber(b.error) + " | " + shortNumber(b.cost) + " |";
  };
  for (const Line& l : lines) {
    md << "| " << l.scene << " | " << l.error << " | " << l.within << " | " << cell(l.ours);
    if (anyPeer) md << " " << cell(l.theirs);
    md << "\n";
  }
  return md.str();
}

std::vector<std::string> plotSweep(const SweepSpec& spec, const std::string& csvPath, const std::string& prefix) {
  const auto rows = readSweepCsv(csvPath);
  if (rows.size() < 2) throw std::runtime_error("plotSweep: '" + csvPath + "' has no rows");
  const std::size_t costColumn = 8, firstError = 9;
  // Lines: one per engine and config, points in the order of the first knob's values; with
  // peers in the CSV each line is titled by its engine too.
  std::map<std::string, std::vector<std::size_t>> lines;
  std::vector<std::string> configs;
  std::map<std::string, std::string> titles;
  bool anyPeer = false;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r].size() == rows[0].size() && rows[r][2] != spec.engine) anyPeer = true;
  }
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r].size() != rows[0].size()) continue;
    const std::string key = rows[r][2] + "\t" + rows[r][3];
    if (lines.find(key) == lines.end()) {
      configs.push_back(key);
      std::string config = rows[r][3];
      for (std::size_t at = config.find(';'); at != std::string::npos; at = config.find(';', at + 2)) {
        config.replace(at, 1, "; ");
      }
      titles[key] = !anyPeer ? config : rows[r][2] + (config == "-" ? "" : ": " + config);
    }
    lines[key].push_back(r);
  }
  std::ostringstream gp;
  // noenhanced: scene and knob names are shown as written (gnuplot's enhanced text would
  // turn the underscore of "tumbling_box" into a subscript); the key goes below the plot so
  // that long configuration names do not narrow it.
  // Errors span decades, so the error axis is labelled in powers of ten. Each line has its own
  // colour; a peer's points are squares, stackbook's circles.
  gp << "set terminal svg size 720,480 dynamic noenhanced font 'sans,12'\nset logscale xy\nset grid\n"
     << "set format x '%g'\nset format y '%.0e'\n"
     << "set xlabel 'ms of computation per simulated second'\nset key below font 'sans,10'\n";
  static const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                         "#17becf", "#8c564b", "#e377c2", "#bcbd22", "#7f7f7f"};
  std::vector<std::string> svgs;
  for (std::size_t e = 0; e < spec.errors.size(); ++e) {
    const std::string name = fileStem(spec.errors[e].name);
    const std::string data = prefix + "_" + name + ".dat";
    std::ostringstream out;
    std::vector<double> cost, error;
    std::vector<std::size_t> rowOf;
    for (const std::string& c : configs) {
      out << "# " << c << "\n";
      for (std::size_t r : lines[c]) {
        const double x = std::strtod(rows[r][costColumn].c_str(), nullptr);
        const double y = std::strtod(rows[r][firstError + e].c_str(), nullptr);
        out << number(x) << " " << number(std::max(y, 1e-17)) << " \"" << sweepValueLabel(rows[r][5]) << "\"\n";
        cost.push_back(x);
        error.push_back(y);
        rowOf.push_back(r);
      }
      out << "\n\n";
    }
    out << "# Pareto front\n";
    // The front of a measure where higher is better (seconds standing) is the front of its negative.
    std::vector<double> worse = error;
    if (sweepHigherIsBetter(spec.errors[e])) {
      for (double& w : worse) w = -w;
    }
    for (std::size_t k : paretoFront(cost, worse)) {
      out << number(cost[k]) << " " << number(std::max(error[k], 1e-17)) << " \"\"\n";
    }
    output_detail::writeFileOrThrow("plotSweep", data, out.str());
    const std::string svg = prefix + "_" + name + ".svg";
    gp << "set output '" << svg << "'\nset ylabel '" << spec.errors[e].name << "'\nset title '"
       << spec.name << ": " << spec.knobs.front().key << " along each line'\nplot ";
    for (std::size_t c = 0; c < configs.size(); ++c) {
      const bool peer = configs[c].rfind(spec.engine + "\t", 0) != 0;
      gp << "'" << data << "' index " << c << " using 1:2 with linespoints pt " << (peer ? 5 : 7) << " lc rgb '"
         << kColours[c % std::size(kColours)] << "' title '" << titles[configs[c]]
         << "', '" << data << "' index " << c << " using 1:2:3 with labels offset 0.8,0.6 font 'sans,9' notitle, ";
    }
    gp << "'" << data << "' index " << configs.size()
       << " using 1:2 with lines dashtype 2 lw 2 lc rgb '#444444' title 'Pareto front'\n";
    svgs.push_back(svg);
  }
  output_detail::writeFileOrThrow("plotSweep", prefix + "_pareto.md", sweepParetoTable(spec, csvPath));
  const std::string script = prefix + ".gp";
  output_detail::writeFileOrThrow("plotSweep", script, gp.str());
  const std::string command = "gnuplot '" + script + "' 2>&1";
  std::FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("plotSweep: cannot start gnuplot");
  std::string said;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) said += buffer;
  const int status = pclose(pipe);
  if (status != 0) {
    throw std::runtime_error("plotSweep: gnuplot failed on '" + script + "' (is gnuplot-nox installed?): " + said);
  }
  return svgs;
}

}  // namespace stackbook
