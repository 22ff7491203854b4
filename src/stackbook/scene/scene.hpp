#pragma once
/// \file
/// \brief Scene files (chapter 10): a JSON description of a simulation (dimension,
/// gravity, time step, solver knobs, effect overrides, materials, bodies) read, checked
/// and turned into a World, its step settings and what each body looks like.
///
/// Every error is a SceneError naming the file, the JSON pointer of the offending field
/// (RFC 6901, e.g. `/bodies/3/shape/size/1`) and what is wrong with it. Loading stops at
/// the first error: later fields are often meaningless once an earlier one is wrong (a
/// body whose shape type is misspelt has no size to check), and one precise line is what
/// a person editing the file needs. The schema is docs/scene_format.md.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "stackbook/output/recording.hpp"
#include "stackbook/stepping/step_settings.hpp"
#include "stackbook/stepping/world.hpp"

namespace stackbook {

// [scene_error]
/// A problem with a scene file: which file, where in it (a JSON pointer, empty for the
/// file as a whole) and what is wrong. what() is the one line a program prints:
/// `scenes/stack.json: /bodies/2/shape/size/0: must be > 0, got -1`.
class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, const std::string& pointer, const std::string& reason,
             std::vector<std::string> details = {});
  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& reason() const { return reason_; }
  /// More than the one line says, one item per line, for a program that asks for it: every
  /// defect of a refused mesh (`stackbook check --all-defects`). Often empty.
  const std::vector<std::string>& details() const { return details_; }

 private:
  std::string file_;
  std::string pointer_;
  std::string reason_;
  std::vector<std::string> details_;
};
// [scene_error]

/// What the recorder keeps (the "output" object of a scene).
struct SceneOutputSettings {
  /// Frames recorded per second of simulated time (> 0); the first frame is t = 0 and
  /// the last one the end of the run.
  double frameRate = 60.0;
  /// Write contacts.csv: every impulse of the run, with its frame, step time, stage,
  /// bodies, point, normal and impulse (writeContactsCsv()). Off: no contact is recorded.
  bool contacts = false;
  /// Draw the contact points and normals of the step that reaches each frame in the
  /// animation (SVG in 2D, glTF in 3D).
  bool drawContacts = false;
  /// Whether the run records contacts at all (either output asks for them).
  bool recordsContacts() const { return contacts || drawContacts; }
};

// [scene_bodies]
/// The bodies of a scene in dimension D: the world the step advances, how each body is
/// drawn (its name, its surface in the body frame, its colour), and the JSON pointer each
/// body came from (for messages about a body, e.g. an overlapping start).
template <int D>
struct SceneBodies {
  World<D> world;
  std::vector<BodyVisual<D>> visuals;
  std::vector<std::string> pointers;
  /// The loader's notes and warnings about these bodies (Scene::notes, Scene::warnings).
  std::vector<std::string> notes;
  std::vector<std::string> warnings;
};
// [scene_bodies]

// [scene]
/// A loaded and checked scene.
struct Scene {
  std::string file;         ///< the file it came from, as named to loadScene()
  std::string description;  ///< one line: what the scene shows
  int dimension = 2;        ///< 2 or 3
  double duration = 1.0;    ///< simulated seconds (> 0)
  StepSettings settings;    ///< dt, loop counts, effect overrides, shock settings
  SceneOutputSettings output;
  bool allowOverlap = false;  ///< start even if bodies interpenetrate
  std::variant<SceneBodies<2>, SceneBodies<3>> bodies;
  /// What the loader changed, one line each, "FILE: POINTER: what" (the repairs of a mesh
  /// loaded with "meshMode": "repair"); the program prints them on stderr.
  std::vector<std::string> notes;
  /// What is approximate because of it, one line each in the same form (a mesh that is
  /// still open, non-manifold or self-intersecting after repair).
  std::vector<std::string> warnings;

  /// Number of bodies.
  int bodyCount() const;
};
// [scene]

// [scene_limits]
/// The limits that protect the machine from a scene (docs/scene_format.md, "Limits"):
/// each is checked where the scene is read, before anything large is built or run, and
/// breaking one is a SceneError naming the field. The defaults are the program's; a fuzz
/// target lowers the work limits so that one input runs in a fraction of a second.
struct SceneLimits {
  int jsonDepth = 64;                  ///< nesting of arrays and objects in the JSON text
  std::size_t fileBytes = 64u << 20;   ///< size of a scene file
  double numberMagnitude = 1e12;       ///< |x| of any number in a scene
  double smallestPositive = 1e-12;     ///< least value of a size, mass, density, dt, ...
  long long bodies = 100'000;          ///< bodies in a scene, arrays counted
  double steps = 1e9;                  ///< duration / dt
  double bodySteps = 1e11;             ///< steps x bodies
  double longRunBodySteps = 1e8;       ///< steps x bodies above which the program warns
  double frameBodies = 5e7;            ///< recorded frames x bodies (the recording's memory)
  long long startPairs = 1'000'000;    ///< pairs of bounding boxes that overlap at the start
  long long meshVertices = 1'000'000;  ///< vertices of a generated or loaded surface mesh
  std::size_t meshFileBytes = 256u << 20;  ///< size of a mesh file
  int sdfResolution3 = 256;            ///< largest sdfResolution in 3D
  int sdfResolution2 = 1024;           ///< largest sdfResolution in 2D
};
// [scene_limits]

/// Reads, checks and builds the scene in `path`. Each entry of `overrides` is
/// "key=value" (the --set option of the program): key is a path into the JSON separated
/// by '.' or '/', e.g. `dt`, `solver.contactIterations`, `bodies.2.velocity`, and value is
/// JSON (a bare word that is not JSON is taken as a string). Overrides are applied before
/// the checks, so they are checked like the file. Throws SceneError.
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides = {},
                const SceneLimits& limits = {});

/// The same for the text of a scene file already read (`file` names it in messages,
/// `baseDir` is where mesh files are looked up): what loadScene() does after reading the
/// file, and the body of the scene loader's fuzz target. Throws SceneError only.
Scene loadSceneText(const std::string& text, const std::string& file, const std::filesystem::path& baseDir,
                    const std::vector<std::string>& overrides = {}, const SceneLimits& limits = {});

/// The same for a JSON document already read: `file` names it in messages and `baseDir`
/// is where mesh files are looked up. Throws SceneError.
Scene parseScene(const nlohmann::json& document, const std::string& file,
                 const std::filesystem::path& baseDir, const SceneLimits& limits = {});

/// The JSON of a scene file, with syntax errors reported as a SceneError with the line
/// and column in the reason. Nesting deeper than limits.jsonDepth, a number beyond the
/// range of a double and a key given twice in one object are errors too (with the JSON
/// pointer where they are).
nlohmann::json readSceneJson(const std::string& path, const SceneLimits& limits = {});

/// The same for text already read; `file` names it in messages.
nlohmann::json parseSceneJsonText(const std::string& text, const std::string& file, const SceneLimits& limits = {});

/// Applies one "key=value" override to `document` (see loadScene()). Throws SceneError
/// naming `file` and the key's pointer if the text has no '=', the key is empty, a part
/// of the key walks into a number or string or past the end of an array (an index may be
/// at most the array's size, which appends), or the value is nested too deep or is not
/// valid UTF-8.
void applySceneOverride(nlohmann::json& document, const std::string& keyValue,
                        const std::string& file, const SceneLimits& limits = {});

/// Why `path` cannot be read as a file, in words for a message: "no such file", "a
/// folder, not a file", "not a regular file (a device, a pipe or a socket)"; "" if it is a
/// regular file.
std::string whyNotARegularFile(const std::filesystem::path& path);

/// `text` printable on one line: control characters and bytes that are not valid UTF-8
/// become `\xNN` (a path or name from the user may hold any byte string).
std::string printable(const std::string& text);

/// Levenshtein distance: single-character insertions, deletions and substitutions.
std::size_t editDistance(const std::string& a, const std::string& b);

/// The candidate closest to `word` if it is close enough to be a plausible typo
/// (distance at most max(1, |word| / 3), case ignored), else "".
std::string closestName(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace stackbook
