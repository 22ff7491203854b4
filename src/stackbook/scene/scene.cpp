// Scene files (chapter 10): a scene from its JSON, part by part. The parts live in
// scene_json.cpp (the text and --set), scene_validation.cpp (messages, typed values,
// settings), scene_shapes.cpp (shapes) and scene_bodies.cpp (bodies). See scene.hpp and
// docs/scene_format.md.
#include "stackbook/scene/scene.hpp"
#include "stackbook/stacking/solver_preset.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "stackbook/scene/scene_bodies.hpp"
#include "stackbook/scene/scene_reader.hpp"

namespace stackbook {

using nlohmann::json;
using scene_detail::describeValue;
using scene_detail::member;
using scene_detail::Reader;

Scene parseScene(const json& doc, const std::string& file, const std::filesystem::path& baseDir,
                 const SceneLimits& limits) {
  const Reader r(file, limits);
  r.requireObject(doc, "",
                  {"description", "dimension", "gravity", "dt", "duration", "solver", "effects", "output",
                   "materials", "bodies", "allowOverlap"},
                  "a scene");
  Scene scene;
  scene.file = file;
  scene.settings = applySolverPreset(kDefaultScenePreset, scene.settings);  // a "preset" in the file replaces it
  const json* dimension = member(doc, "dimension");
  if (dimension == nullptr) r.fail("", "a scene needs \"dimension\": 2 or 3");
  if (!dimension->is_number_integer() || (dimension->get<std::int64_t>() != 2 && dimension->get<std::int64_t>() != 3)) {
    r.fail("/dimension", "must be 2 or 3, got " + describeValue(*dimension));
  }
  scene.dimension = static_cast<int>(dimension->get<std::int64_t>());
  if (const json* v = member(doc, "description")) scene.description = r.string(*v, "/description");
  if (const json* v = member(doc, "dt")) scene.settings.dt = r.positive(*v, "/dt");
  if (const json* v = member(doc, "duration")) scene.duration = r.positive(*v, "/duration");
  const double steps = std::ceil(scene.duration / scene.settings.dt - 1e-9);
  if (!(steps <= limits.steps)) {
    r.fail(member(doc, "dt") != nullptr ? "/dt" : "/duration",
           "duration / dt is " + scene_detail::formatNumber(steps) + " steps; at most " +
               scene_detail::formatNumber(limits.steps));
  }
  if (const json* v = member(doc, "allowOverlap")) scene.allowOverlap = r.boolean(*v, "/allowOverlap");
  if (const json* v = member(doc, "solver")) scene_detail::readSolver(r, *v, scene.settings);
  if (const json* v = member(doc, "effects")) scene_detail::readEffects(r, *v, scene.settings.effects);
  if (const json* v = member(doc, "output")) {
    r.requireObject(*v, "/output", {"frameRate", "contacts", "drawContacts"}, "the output settings");
    if (const json* f = member(*v, "frameRate")) scene.output.frameRate = r.positive(*f, "/output/frameRate");
    if (const json* c = member(*v, "contacts")) scene.output.contacts = r.boolean(*c, "/output/contacts");
    if (const json* c = member(*v, "drawContacts")) scene.output.drawContacts = r.boolean(*c, "/output/drawContacts");
  }
  std::map<std::string, Material> materials;
  if (const json* v = member(doc, "materials")) materials = scene_detail::readMaterials(r, *v);
  try {
    validateStepSettings(scene.settings, "scene");
  } catch (const std::invalid_argument& e) {
    r.fail("/solver", e.what());
  }
  const json* gravity = member(doc, "gravity");
  if (scene.dimension == 2) {
    const Vec2 g = gravity == nullptr ? Vec2(0.0, -9.81) : r.vector<2>(*gravity, "/gravity");
    scene.bodies = scene_detail::buildBodies<2>(r, doc, materials, baseDir, g, scene.allowOverlap);
  } else {
    const Vec3 g = gravity == nullptr ? Vec3(0.0, 0.0, -9.81) : r.vector<3>(*gravity, "/gravity");
    scene.bodies = scene_detail::buildBodies<3>(r, doc, materials, baseDir, g, scene.allowOverlap);
  }
  std::visit([&scene](const auto& b) {
    scene.notes = b.notes;
    scene.warnings = b.warnings;
  }, scene.bodies);
  // The work of the run and the memory of its recording, estimated here so that what
  // `check` accepts, `run` can finish (docs/scene_format.md, "Limits").
  const double bodies = scene.bodyCount();
  const char* timeField = member(doc, "dt") != nullptr ? "/dt" : "/duration";
  if (!(steps * bodies <= limits.bodySteps)) {
    r.fail(timeField, "the run is " + scene_detail::formatNumber(steps) + " steps x " + scene_detail::formatNumber(bodies) +
                          " bodies = " + scene_detail::formatNumber(steps * bodies) + " body-steps; at most " +
                          scene_detail::formatNumber(limits.bodySteps));
  }
  // Frames: one per 1/frameRate, at most one per step, and the first and the last.
  const double frames = std::min(steps, std::ceil(scene.duration * scene.output.frameRate)) + 2.0;
  if (!(frames * bodies <= limits.frameBodies)) {
    r.fail(member(doc, "output") != nullptr && member(*member(doc, "output"), "frameRate") != nullptr
               ? "/output/frameRate"
               : "/duration",
           "the recording would hold " + scene_detail::formatNumber(frames) + " frames x " +
               scene_detail::formatNumber(bodies) + " bodies; at most " + scene_detail::formatNumber(limits.frameBodies) +
               " (lower the frame rate or the duration)");
  }
  if (steps * bodies > limits.longRunBodySteps) {
    scene.warnings.push_back(printable(file) + ": " + timeField + ": a long run: " + scene_detail::formatNumber(steps) +
                             " steps x " + scene_detail::formatNumber(bodies) + " bodies = " +
                             scene_detail::formatNumber(steps * bodies) + " body-steps");
  }
  return scene;
}

Scene loadSceneText(const std::string& text, const std::string& file, const std::filesystem::path& baseDir,
                    const std::vector<std::string>& overrides, const SceneLimits& limits) {
  json doc = parseSceneJsonText(text, file, limits);
  for (const std::string& o : overrides) applySceneOverride(doc, o, file, limits);
  return parseScene(doc, file, baseDir, limits);
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides, const SceneLimits& limits) {
  json doc = readSceneJson(path, limits);
  for (const std::string& o : overrides) applySceneOverride(doc, o, path, limits);
  return parseScene(doc, path, std::filesystem::path(path).parent_path(), limits);
}

}  // namespace stackbook
