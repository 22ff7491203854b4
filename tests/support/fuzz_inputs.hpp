#pragma once
// The bodies of the fuzz targets (fuzz/, chapter 10): what the scene loader and the OBJ
// loader must do with any byte string. Each function returns "" when the input was
// handled as promised (accepted and usable, or refused with one clear line) and otherwise
// says what broke. The libFuzzer targets abort on a non-empty answer; the checked-in
// corpus (tests/ch10/corpus) runs through the same functions as ordinary ch10 tests.
#include <algorithm>
#include <exception>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "stackbook/geometry/obj_loader.hpp"
#include "stackbook/geometry/mesh_repair.hpp"
#include "stackbook/geometry/sdf_grid.hpp"
#include "stackbook/geometry/winding_mass_properties.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"

namespace stackbook::fuzz {

/// The work limits of a fuzz input: small enough that one input loads and runs in well
/// under a second under AddressSanitizer.
inline SceneLimits sceneFuzzLimits() {
  SceneLimits limits;
  limits.fileBytes = 1u << 20;
  limits.bodies = 64;
  limits.startPairs = 2000;
  limits.meshVertices = 20'000;
  limits.meshFileBytes = 1u << 20;
  limits.sdfResolution3 = 16;
  limits.sdfResolution2 = 64;
  return limits;
}

/// Steps a fuzz input runs after it loads (what `check` accepts, `run` must run).
constexpr int kFuzzSteps = 3;

/// Whether `line` is one printable line (no byte below 0x20, no DEL).
inline bool oneLine(const std::string& line) {
  return !line.empty() && std::none_of(line.begin(), line.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7F;
  });
}

/// A fuzz input of the scene loader: the scene text, then (after a NUL byte) --set
/// overrides separated by NUL bytes. Mesh files are looked up in `baseDir`.
inline std::string sceneInput(const std::string& data, const std::filesystem::path& baseDir) {
  const std::string file = "fuzz.json";
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t nul = data.find('\0', start);
    parts.push_back(data.substr(start, nul == std::string::npos ? std::string::npos : nul - start));
    if (nul == std::string::npos) break;
    start = nul + 1;
  }
  const std::vector<std::string> overrides(parts.begin() + 1, parts.end());
  Scene scene;
  try {
    scene = loadSceneText(parts[0], file, baseDir, overrides, sceneFuzzLimits());
  } catch (const SceneError& e) {
    const std::string line = e.what();
    if (!oneLine(line)) return "a SceneError that is not one printable line: " + printable(line);
    if (line.rfind(file + ": ", 0) != 0) return "a SceneError that does not start with the file: " + line;
    return "";
  } catch (const std::exception& e) {
    return std::string("the loader threw something other than a SceneError: ") + printable(e.what());
  }
  try {
    RunOptions options;
    options.duration = kFuzzSteps * scene.settings.dt;
    const SceneRun run = runScene(scene, options);
    (void)runSummaryJson(scene, run).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  } catch (const std::exception& e) {
    return std::string("the scene loaded but its run failed: ") + printable(e.what());
  }
  return "";
}

/// A fuzz input of the OBJ loader: the text of an OBJ file, read strictly (and, if
/// accepted, turned into a small signed-distance grid) and in repair mode (repaired, and
/// its mass properties integrated by the winding number). A refusal must be a
/// std::invalid_argument or std::runtime_error; a mesh beyond the vertex limit is skipped.
inline std::string objInput(const std::string& data) {
  if (data.size() > (1u << 16)) return "";
  const auto refusal = [](const std::exception& e) -> std::string {
    if (dynamic_cast<const std::bad_alloc*>(&e) != nullptr || dynamic_cast<const std::logic_error*>(&e) != nullptr) {
      if (dynamic_cast<const std::invalid_argument*>(&e) == nullptr) {
        return std::string("an internal error, not a refusal: ") + printable(e.what());
      }
    }
    return "";
  };
  try {
    TriangleMesh mesh = parseObjMesh(data, "fuzz.obj");
    if (mesh.vertices.size() <= 2000) {
      SdfGridSettings grid;
      grid.cellsAcrossLargestExtent = 8;
      const GridShape<3> shape(mesh, "fuzz", grid);
      (void)shape.bounds();
    }
  } catch (const std::exception& e) {
    if (std::string problem = refusal(e); !problem.empty()) return "strict: " + problem;
  }
  try {
    ObjLoadSettings raw;
    raw.mergeTolerance = -1.0;
    raw.dropUnusedVertices = false;
    raw.validate = false;
    TriangleMesh mesh = parseObjMesh(data, "fuzz.obj", raw);
    if (mesh.vertices.size() <= 2000 && mesh.faces.size() <= 4000) {
      (void)repairMesh(mesh);
      if (!mesh.faces.empty()) (void)windingNumberMassProperties(mesh, 1.0, 6);
    }
  } catch (const std::exception& e) {
    if (std::string problem = refusal(e); !problem.empty()) return "repair: " + problem;
  }
  return "";
}

}  // namespace stackbook::fuzz
