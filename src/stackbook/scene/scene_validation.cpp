// Scene files (chapter 10): the messages (SceneError, "did you mean"), the typed reading
// of values and the checks of the scene's settings objects. See scene.hpp and
// docs/scene_format.md.
#include <algorithm>
#include <cctype>
#include <optional>
#include <sstream>

#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/scene_reader.hpp"
#include "stackbook/stacking/solver_preset.hpp"

namespace stackbook {

using nlohmann::json;

namespace {

/// `text` on one line: each line break (with the indentation after it) becomes "; " (or a
/// space after a colon), so
/// that a multi-line message from the geometry code (a mesh's list of defects) still
/// prints as the one line a SceneError promises.
std::string oneLine(const std::string& text) {
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '\n') {
      out += text[k];
      continue;
    }
    while (k + 1 < text.size() && (text[k + 1] == ' ' || text[k + 1] == '\n')) ++k;
    if (k + 1 < text.size()) out += !out.empty() && out.back() == ':' ? " " : "; ";
  }
  return out;
}

}  // namespace

SceneError::SceneError(const std::string& file, const std::string& pointer, const std::string& reason,
                       std::vector<std::string> details)
    : std::runtime_error(printable(file) + ": " + (pointer.empty() ? std::string() : printable(pointer) + ": ") +
                         printable(oneLine(reason))),
      file_(file), pointer_(pointer), reason_(oneLine(reason)), details_(std::move(details)) {
  for (std::string& line : details_) line = printable(oneLine(line));
}

int Scene::bodyCount() const {
  return std::visit([](const auto& b) { return b.world.size(); }, bodies);
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string closestName(const std::string& word, const std::vector<std::string>& candidates) {
  const auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  const std::string w = lower(word);
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = editDistance(w, lower(c));
    if (d < bestDistance) {
      bestDistance = d;
      best = c;
    }
  }
  return best;
}

namespace scene_detail {

std::string escapePointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

/// A short account of a JSON value for "got ..." in messages.
std::string describeValue(const json& v) {
  // Only scalars are printed (the document's depth is limited, but a message needs no more).
  std::string text = v.is_structured() ? std::string() : v.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "the boolean " + text;
    case json::value_t::string: return "the string " + text;
    case json::value_t::array: return "an array of " + std::to_string(v.size()) + " elements";
    case json::value_t::object: return "an object";
    default: return "the number " + text;
  }
}

std::string formatNumber(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

void readSolver(const Reader& r, const json& solver, StepSettings& s) {
  const std::string p = "/solver";
  r.requireObject(solver, p,
                  {"collisionIterations", "collisionPairIterations", "contactIterations",
                   "contactPairIterations", "contactRestitution", "shock", "order", "impulsePoint",
                   "impulsePointNormalCosine", "leverArms", "heldSamples", "tiedLanding", "tieTolerance",
                   "frictionCone", "rotation", "surfaceQuery", "threads", "sleep",
                   "pairImpulseTolerance", "stageApproachTolerance", "candidateReach", "pairOrder", "preset"},
                  "the solver settings");
  // A preset (chapter 9) sets several fields at once; it is applied first, so that the
  // scene's other solver fields change it.
  if (const json* v = member(solver, "preset")) {
    const std::string ptr = p + "/preset";
    const std::string word = r.string(*v, ptr);
    const std::optional<SolverPreset> preset = solverPresetNamed(word);
    if (!preset) r.fail(ptr, "must be " + solverPresetWords() + ", got \"" + word + "\"");
    s = applySolverPreset(*preset, s);
  }
  // Threads (chapter 10): 0 is every hardware thread; any count gives the same result.
  if (const json* v = member(solver, "threads")) s.parallel.threads = r.integer(*v, p + "/threads", 0, 1024);
  // Sleeping (chapter 8): off unless the scene asks for it.
  if (const json* sleep = member(solver, "sleep")) {
    const std::string q = p + "/sleep";
    r.requireObject(*sleep, q, {"enabled", "linearSpeed", "angularSpeed", "time", "wakeMargin"},
                    "the sleep settings");
    if (const json* v = member(*sleep, "enabled")) s.sleep.enabled = r.boolean(*v, q + "/enabled");
    if (const json* v = member(*sleep, "linearSpeed")) s.sleep.linearSpeed = r.nonNegative(*v, q + "/linearSpeed");
    if (const json* v = member(*sleep, "angularSpeed")) s.sleep.angularSpeed = r.nonNegative(*v, q + "/angularSpeed");
    if (const json* v = member(*sleep, "time")) s.sleep.time = r.nonNegative(*v, q + "/time");
    if (const json* v = member(*sleep, "wakeMargin")) s.sleep.wakeMargin = r.nonNegative(*v, q + "/wakeMargin");
  }
  if (const json* v = member(solver, "collisionIterations")) s.collisionIterations = r.integer(*v, p + "/collisionIterations", 0, 1000);
  if (const json* v = member(solver, "collisionPairIterations")) s.collisionPairIterations = r.integer(*v, p + "/collisionPairIterations", 1, 1000);
  if (const json* v = member(solver, "contactIterations")) s.contactIterations = r.integer(*v, p + "/contactIterations", 0, 1000);
  if (const json* v = member(solver, "contactPairIterations")) s.contactPairIterations = r.integer(*v, p + "/contactPairIterations", 1, 1000);
  // The loop tolerances (chapter 8, "Ending the loops"): 0, GBF's loops, unless the scene asks.
  if (const json* v = member(solver, "pairImpulseTolerance")) {
    s.pairImpulseTolerance = r.inRange(*v, p + "/pairImpulseTolerance", 0.0, 1.0);
    if (!(s.pairImpulseTolerance < 1.0)) r.fail(p + "/pairImpulseTolerance", "must be < 1, got 1");
  }
  if (const json* v = member(solver, "stageApproachTolerance")) {
    s.stageApproachTolerance = r.nonNegative(*v, p + "/stageApproachTolerance");
  }
  // Candidate lists (chapter 7): exact for any reach, so this field changes time only.
  if (const json* v = member(solver, "candidateReach")) {
    s.detection.narrow.candidateReach = r.nonNegative(*v, p + "/candidateReach");
  }
  // A field that names one of two choices: "must be \"a\" or \"b\", got \"c\"" otherwise.
  const auto choose = [&](const char* field, const char* a, auto valueA, const char* b, auto valueB) {
    const std::string ptr = p + "/" + field;
    const std::string word = r.string(*member(solver, field), ptr);
    if (word == a) return valueA;
    if (word != b) {
      r.fail(ptr, "must be \"" + std::string(a) + "\" or \"" + b + "\", got \"" + word + "\"");
    }
    return valueB;
  };
  if (member(solver, "order")) {
    s.order = choose("order", "gbf", StepOrder::Gbf, "traditional", StepOrder::Traditional);
  }
  if (member(solver, "impulsePoint")) {
    const std::string ptr = p + "/impulsePoint";
    const std::string word = r.string(*member(solver, "impulsePoint"), ptr);
    if (word == "deepest") {
      s.impulsePoint.rule = ImpulsePointRule::Deepest;
    } else if (word == "centre") {
      s.impulsePoint.rule = ImpulsePointRule::DepthWeightedCentre;
    } else if (word == "patch") {
      s.impulsePoint.rule = ImpulsePointRule::StickingPatch;
    } else {
      r.fail(ptr, "must be \"deepest\", \"centre\" or \"patch\", got \"" + word + "\"");
    }
  }
  // Where impulses measure their lever arms, and the landing rules (chapter 8, "Where the lever
  // arms are measured"; chapter 12, "Landing on a support").
  if (member(solver, "leverArms")) {
    s.impulsePoint.arms = choose("leverArms", "startPose", LeverArms::AtStartPose, "testedPose", LeverArms::AtTestedPose);
  }
  if (const json* v = member(solver, "heldSamples")) s.impulsePoint.heldSamples = r.boolean(*v, p + "/heldSamples");
  if (const json* v = member(solver, "tiedLanding")) s.impulsePoint.tiedLanding = r.boolean(*v, p + "/tiedLanding");
  if (const json* v = member(solver, "tieTolerance")) {
    s.impulsePoint.tieTolerance = r.inRange(*v, p + "/tieTolerance", 0.0, 1.0);
  }
  if (member(solver, "rotation")) {
    s.rotation = choose("rotation", "exponentialMap", RotationUpdate::ExponentialMap, "implicitMidpoint",
                        RotationUpdate::ImplicitMidpoint);
  }
  if (member(solver, "surfaceQuery")) {
    const std::string ptr = p + "/surfaceQuery";
    const std::string word = r.string(*member(solver, "surfaceQuery"), ptr);
    if (word == "samples") {
      s.detection.narrow.surfaceQuery = SurfaceQuery::Samples;
    } else if (word == "deepestPoint") {
      s.detection.narrow.surfaceQuery = SurfaceQuery::DeepestPoint;
    } else if (word == "roundShapes") {
      s.detection.narrow.surfaceQuery = SurfaceQuery::RoundShapes;
    } else {
      r.fail(ptr, "must be \"samples\", \"deepestPoint\" or \"roundShapes\", got \"" + word + "\"");
    }
  }
  // The order of a sweep's pairs (chapter 10, "Colours"): unlike threads, it changes the result.
  if (member(solver, "pairOrder")) {
    s.pairOrder = choose("pairOrder", "list", PairOrder::List, "colours", PairOrder::Colours);
  }
  if (member(solver, "frictionCone")) {
    s.frictionCone = choose("frictionCone", "impulse", FrictionConeRule::EachImpulse, "step",
                            FrictionConeRule::StepTotal);
  }
  if (const json* v = member(solver, "impulsePointNormalCosine")) {
    s.impulsePoint.normalCosine = r.inRange(*v, p + "/impulsePointNormalCosine", 0.0, 1.0);
    if (!(s.impulsePoint.normalCosine > 0.0)) r.fail(p + "/impulsePointNormalCosine", "must be > 0, got 0");
  }
  const auto schedule = [&](const json& v, const std::string& ptr, std::size_t count, const char* countName) {
    if (!v.is_array()) r.fail(ptr, "expected an array of numbers in [-1, 0], got " + describeValue(v));
    if (v.size() != count) {
      r.fail(ptr, "must hold " + std::string(countName) + " = " + std::to_string(count) + " values, got " +
                      std::to_string(v.size()));
    }
    std::vector<double> out;
    for (std::size_t k = 0; k < v.size(); ++k) out.push_back(r.inRange(v[k], ptr + "/" + std::to_string(k), -1.0, 0.0));
    return out;
  };
  if (const json* v = member(solver, "contactRestitution")) {
    s.contactRestitution = schedule(*v, p + "/contactRestitution",
                                    static_cast<std::size_t>(s.contactIterations), "contactIterations");
  }
  if (const json* shock = member(solver, "shock")) {
    const std::string q = p + "/shock";
    r.requireObject(*shock, q,
                    {"passes", "sweepsPerLevel", "pairIterations", "restitution", "replacesContactStage",
                     "pairImpulseTolerance", "levelApproachTolerance", "welded", "freeze", "carryTolerance"},
                    "the shock settings");
    if (const json* v = member(*shock, "pairImpulseTolerance")) {
      s.shock.pairImpulseTolerance = r.inRange(*v, q + "/pairImpulseTolerance", 0.0, 1.0);
      if (!(s.shock.pairImpulseTolerance < 1.0)) r.fail(q + "/pairImpulseTolerance", "must be < 1, got 1");
    }
    if (const json* v = member(*shock, "levelApproachTolerance")) {
      s.shock.levelApproachTolerance = r.nonNegative(*v, q + "/levelApproachTolerance");
    }
    // Which levels the pass freezes (chapter 12): every level (GBF) or what carries its load.
    if (member(*shock, "freeze")) {
      const std::string ptr = q + "/freeze";
      const std::string word = r.string(*member(*shock, "freeze"), ptr);
      if (word == "everyLevel") {
        s.shock.freeze = FreezeRule::EveryLevel;
      } else if (word == "whenItCarries") {
        s.shock.freeze = FreezeRule::WhenItCarries;
      } else {
        r.fail(ptr, "must be \"everyLevel\" or \"whenItCarries\", got \"" + word + "\"");
      }
    }
    if (const json* v = member(*shock, "carryTolerance")) s.shock.carryTolerance = r.nonNegative(*v, q + "/carryTolerance");
    if (const json* v = member(*shock, "passes")) s.shock.passes = r.integer(*v, q + "/passes", 1, 100);
    if (const json* v = member(*shock, "sweepsPerLevel")) s.shock.sweepsPerLevel = r.integer(*v, q + "/sweepsPerLevel", 1, 100);
    if (const json* v = member(*shock, "pairIterations")) s.shock.pairIterations = r.integer(*v, q + "/pairIterations", 1, 1000);
    if (const json* v = member(*shock, "restitution")) {
      s.shock.restitution = schedule(*v, q + "/restitution", static_cast<std::size_t>(s.shock.sweepsPerLevel), "sweepsPerLevel");
    }
    // The welded pass (chapter 9): on by default (the preset "weldedPass"), its own loops.
    if (const json* welded = member(*shock, "welded")) {
      const std::string w = q + "/welded";
      r.requireObject(*welded, w,
                      {"enabled", "sweepsPerLevel", "pairIterations", "pairImpulseTolerance", "levelApproachTolerance",
                       "bodyWelds", "energyGuard"},
                      "the welded pass's settings");
      WeldedPassSettings& ws = s.shock.welded;
      if (const json* v = member(*welded, "enabled")) ws.enabled = r.boolean(*v, w + "/enabled");
      if (const json* v = member(*welded, "sweepsPerLevel")) ws.sweepsPerLevel = r.integer(*v, w + "/sweepsPerLevel", 1, 100);
      if (const json* v = member(*welded, "pairIterations")) ws.pairIterations = r.integer(*v, w + "/pairIterations", 1, 1000);
      if (const json* v = member(*welded, "pairImpulseTolerance")) {
        ws.pairImpulseTolerance = r.inRange(*v, w + "/pairImpulseTolerance", 0.0, 1.0);
        if (!(ws.pairImpulseTolerance < 1.0)) r.fail(w + "/pairImpulseTolerance", "must be < 1, got 1");
      }
      if (const json* v = member(*welded, "levelApproachTolerance")) {
        ws.levelApproachTolerance = r.nonNegative(*v, w + "/levelApproachTolerance");
      }
      if (const json* v = member(*welded, "bodyWelds")) ws.bodyWelds = r.boolean(*v, w + "/bodyWelds");
      if (const json* v = member(*welded, "energyGuard")) ws.energyGuard = r.boolean(*v, w + "/energyGuard");
    }
    if (const json* v = member(*shock, "replacesContactStage")) {
      s.shock.replacesContactStage = r.boolean(*v, q + "/replacesContactStage");
      // The pass as the contact stage, asked for by name, replaces the default's welded pass.
      if (s.shock.replacesContactStage) s.shock.welded.enabled = false;
    }
  }
}

void readEffects(const Reader& r, const json& effects, EffectOverrides& e) {
  r.requireObject(effects, "/effects",
                  {"gravity", "collision", "restitution", "contact", "friction", "rollingFriction", "shockPropagation"},
                  "the effect overrides");
  const auto read = [&](const char* key, std::optional<bool>& slot) {
    if (const json* v = member(effects, key)) slot = r.boolean(*v, std::string("/effects/") + key);
  };
  read("gravity", e.gravity);
  read("collision", e.collision);
  read("restitution", e.restitution);
  read("contact", e.contact);
  read("friction", e.friction);
  read("rollingFriction", e.rollingFriction);
  read("shockPropagation", e.shockPropagation);
}

std::map<std::string, Material> readMaterials(const Reader& r, const json& materials) {
  if (!materials.is_object()) r.fail("/materials", "expected an object of named materials, got " + describeValue(materials));
  std::map<std::string, Material> out;
  for (const auto& item : materials.items()) {
    const std::string ptr = "/materials/" + escapePointerToken(item.key());
    r.requireObject(item.value(), ptr, {"restitution", "friction", "rollingFriction"}, "a material");
    Material m;
    if (const json* v = member(item.value(), "restitution")) m.restitution = r.inRange(*v, ptr + "/restitution", 0.0, 1.0);
    if (const json* v = member(item.value(), "friction")) m.friction = r.nonNegative(*v, ptr + "/friction");
    if (const json* v = member(item.value(), "rollingFriction")) m.rollingFriction = r.nonNegative(*v, ptr + "/rollingFriction");
    out.emplace(item.key(), m);
  }
  return out;
}

}  // namespace scene_detail

}  // namespace stackbook
