// Scene files (chapter 10): reading, checking and building a scene. See scene.hpp and
// docs/scene_format.md.
#include "stackbook/scene/scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/obj_loader.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

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

SceneError::SceneError(const std::string& file, const std::string& pointer,
                       const std::string& reason)
    : std::runtime_error(file + ": " + (pointer.empty() ? std::string() : pointer + ": ") + oneLine(reason)),
      file_(file), pointer_(pointer), reason_(oneLine(reason)) {}

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

namespace {

// --- Reading typed values with the pointer of each ----------------------------------------

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
  std::string text = v.dump();
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

/// Reads the parts of one scene file; every failure is a SceneError with this file's name.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& reason) const {
    throw SceneError(file_, pointer, reason);
  }
  const std::string& file() const { return file_; }

  /// `v` must be an object whose keys are all in `allowed`.
  void requireObject(const json& v, const std::string& ptr, const std::vector<std::string>& allowed,
                     const std::string& what) const {
    if (!v.is_object()) fail(ptr, "expected " + what + " (a JSON object), got " + describeValue(v));
    for (const auto& item : v.items()) {
      if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
      std::string reason = "unknown field \"" + item.key() + "\" in " + what;
      const std::string hint = closestName(item.key(), allowed);
      if (!hint.empty()) {
        reason += "; did you mean \"" + hint + "\"?";
      } else {
        reason += "; allowed:";
        for (std::size_t k = 0; k < allowed.size(); ++k) reason += (k ? ", " : " ") + allowed[k];
      }
      fail(ptr + "/" + escapePointerToken(item.key()), reason);
    }
  }

  double number(const json& v, const std::string& ptr) const {
    if (!v.is_number()) fail(ptr, "expected a number, got " + describeValue(v));
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(ptr, "must be a finite number");
    return x;
  }
  double positive(const json& v, const std::string& ptr) const {
    const double x = number(v, ptr);
    if (!(x > 0.0)) fail(ptr, "must be > 0, got " + formatNumber(x));
    return x;
  }
  double nonNegative(const json& v, const std::string& ptr) const {
    const double x = number(v, ptr);
    if (!(x >= 0.0)) fail(ptr, "must be >= 0, got " + formatNumber(x));
    return x;
  }
  double inRange(const json& v, const std::string& ptr, double lo, double hi) const {
    const double x = number(v, ptr);
    if (!(x >= lo && x <= hi)) {
      fail(ptr, "must be in [" + formatNumber(lo) + ", " + formatNumber(hi) + "], got " +
                    formatNumber(x));
    }
    return x;
  }
  int integer(const json& v, const std::string& ptr, int least, int most = 1'000'000'000) const {
    if (!v.is_number_integer()) fail(ptr, "expected an integer, got " + describeValue(v));
    const auto x = v.get<std::int64_t>();
    if (x < least || x > most) {
      fail(ptr, "must be an integer in [" + std::to_string(least) + ", " + std::to_string(most) +
                    "], got " + std::to_string(x));
    }
    return static_cast<int>(x);
  }
  bool boolean(const json& v, const std::string& ptr) const {
    if (!v.is_boolean()) fail(ptr, "expected true or false, got " + describeValue(v));
    return v.get<bool>();
  }
  std::string string(const json& v, const std::string& ptr) const {
    if (!v.is_string()) fail(ptr, "expected a string, got " + describeValue(v));
    return v.get<std::string>();
  }
  template <int N>
  Eigen::Matrix<double, N, 1> vector(const json& v, const std::string& ptr) const {
    if (!v.is_array() || v.size() != static_cast<std::size_t>(N)) {
      fail(ptr, "expected an array of " + std::to_string(N) + " numbers, got " + describeValue(v));
    }
    Eigen::Matrix<double, N, 1> out;
    for (int k = 0; k < N; ++k) {
      out[k] = number(v[static_cast<std::size_t>(k)], ptr + "/" + std::to_string(k));
    }
    return out;
  }
  template <int N>
  Eigen::Matrix<double, N, 1> positiveVector(const json& v, const std::string& ptr) const {
    const Eigen::Matrix<double, N, 1> out = vector<N>(v, ptr);
    for (int k = 0; k < N; ++k) {
      if (!(out[k] > 0.0)) fail(ptr + "/" + std::to_string(k), "must be > 0, got " + formatNumber(out[k]));
    }
    return out;
  }

 private:
  std::string file_;
};

/// The member `key` of object `obj`, or nullptr.
const json* member(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

// --- Shapes -------------------------------------------------------------------------------

/// A built shape with its mass properties per unit density in its body frame (centre of
/// mass at the origin, principal axes on the coordinate axes), and where that body frame
/// sits in the frame the scene places ("frame": identity for the symmetric analytic
/// shapes; the centre of mass and principal axes for meshes).
template <int D>
struct BuiltShape {
  std::shared_ptr<const Shape<D>> shape;
  SurfaceMesh<D> mesh;     ///< drawing and samples, body frame
  double measure = 0.0;    ///< area (2D) or volume (3D)
  AngVec<D> unitMoments;   ///< principal moments of inertia at density 1
  Pose<D> frame;
};

const std::vector<std::string>& shapeTypes(int dimension) {
  static const std::vector<std::string> two{"box", "disk", "sphere", "annulus", "torus", "ring",
                                            "capsule", "cylinder", "L", "U", "cup", "bone", "star"};
  static const std::vector<std::string> three{"box", "sphere", "disk", "torus", "annulus", "ring",
                                              "capsule", "cylinder", "L", "cup", "U", "bone", "mesh"};
  return dimension == 2 ? two : three;
}

template <int D, class ShapeT>
BuiltShape<D> analytic(ShapeT shape, double measure, const AngVec<D>& unitMoments) {
  BuiltShape<D> out;
  out.mesh = shape.mesh();
  out.shape = std::make_shared<ShapeT>(std::move(shape));
  out.measure = measure;
  out.unitMoments = unitMoments;
  return out;
}

/// A box's (or rectangle's) measure and unit-density principal moments, by chapter 5's
/// closed forms: I_x = V (b^2 + c^2) / 12 and cyclic; a rectangle's I = A (a^2 + b^2) / 12.
template <int D>
void boxMassProperties(const Vec<D>& size, double& measure, AngVec<D>& moments) {
  measure = size.prod();
  if constexpr (D == 2) {
    moments[0] = measure * (size.squaredNorm()) / 12.0;
  } else {
    const Vec3 s2 = size.cwiseProduct(size);
    moments = measure / 12.0 * Vec3(s2[1] + s2[2], s2[0] + s2[2], s2[0] + s2[1]);
  }
}

// [mesh_shape]
/// A nonconvex shape from its closed surface mesh: the mesh is moved into its body frame
/// (centre of mass at the origin, principal axes on the coordinate axes; chapter 5), and
/// the signed-distance grid of chapter 6 is built there with `resolution` cells across the
/// largest extent. `frame` records where that body frame sat in the mesh's own coordinates,
/// which are the coordinates the scene's position and rotation place.
template <int D>
BuiltShape<D> meshShape(SurfaceMesh<D> mesh, const std::string& name, int resolution) {
  const BodyFrame<D> frame = moveToPrincipalFrame<D>(mesh, 1.0);
  SdfGridSettings grid;
  grid.cellsAcrossLargestExtent = resolution;
  BuiltShape<D> out;
  out.measure = frame.mass;
  out.unitMoments = frame.principalMoments;
  out.frame = frame.frame;
  auto shape = std::make_shared<GridShape<D>>(mesh, name, grid);
  out.mesh = std::move(mesh);
  out.shape = std::move(shape);
  return out;
}
// [mesh_shape]

/// Builds the shape of `spec` (at pointer `ptr`); `baseDir` resolves mesh files.
template <int D>
BuiltShape<D> buildShape(const Reader& r, const json& spec, const std::string& ptr,
                         const std::filesystem::path& baseDir) {
  if (!spec.is_object()) r.fail(ptr, "expected a shape (a JSON object with a \"type\"), got " + describeValue(spec));
  const json* typeValue = member(spec, "type");
  if (typeValue == nullptr) r.fail(ptr, "a shape needs a \"type\"");
  const std::string type = r.string(*typeValue, ptr + "/type");
  const std::vector<std::string>& types = shapeTypes(D);
  if (std::find(types.begin(), types.end(), type) == types.end()) {
    std::string reason = "unknown shape type \"" + type + "\" in " + std::to_string(D) + "D";
    if (type == "star") reason += " (star is 2D only)";
    if (type == "mesh") reason += " (OBJ meshes are 3D only)";
    const std::string hint = closestName(type, types);
    if (!hint.empty() && hint != type) reason += "; did you mean \"" + hint + "\"?";
    reason += "; known:";
    for (std::size_t k = 0; k < types.size(); ++k) reason += (k ? ", " : " ") + types[k];
    r.fail(ptr + "/type", reason);
  }
  // The keys each type takes; any other is an unknown field.
  static const std::map<std::string, std::vector<std::string>> keys{
      {"box", {"type", "size"}},
      {"sphere", {"type", "radius"}},
      {"disk", {"type", "radius"}},
      {"torus", {"type", "majorRadius", "minorRadius"}},
      {"annulus", {"type", "majorRadius", "minorRadius"}},
      {"ring", {"type", "majorRadius", "minorRadius"}},
      {"capsule", {"type", "radius", "length"}},
      {"cylinder", {"type", "radius", "height"}},
      {"L", {"type", "cellSize", "sdfResolution"}},
      {"U", {"type", "outerRadius", "height", "wallThickness", "bottomThickness", "sdfResolution"}},
      {"cup", {"type", "outerRadius", "height", "wallThickness", "bottomThickness", "sdfResolution"}},
      {"bone", {"type", "ballRadius", "neckRadius", "length", "sdfResolution"}},
      {"star", {"type", "outerRadius", "innerRadius", "points", "sdfResolution"}},
      {"mesh", {"type", "file", "scale", "sdfResolution"}},
  };
  r.requireObject(spec, ptr, keys.at(type), "a " + type + " shape");
  const auto need = [&](const char* key) -> const json& {
    const json* v = member(spec, key);
    if (v == nullptr) r.fail(ptr, "a " + type + " shape needs \"" + key + "\"");
    return *v;
  };
  const auto optionalPositive = [&](const char* key, double fallback) {
    const json* v = member(spec, key);
    return v == nullptr ? fallback : r.positive(*v, ptr + "/" + key);
  };
  const auto resolution = [&]() {
    const json* v = member(spec, "sdfResolution");
    // 256 cells in 3D is a 17-million-node grid that takes tens of seconds to build (chapter 6).
    return v == nullptr ? 32 : r.integer(*v, ptr + "/sdfResolution", 4, D == 2 ? 1024 : 256);
  };

  if (type == "box") {
    const Vec<D> size = r.positiveVector<D>(need("size"), ptr + "/size");
    double measure = 0.0;
    AngVec<D> moments;
    boxMassProperties<D>(size, measure, moments);
    return analytic<D>(makeBoxShape<D>(size), measure, moments);
  }
  if (type == "sphere" || type == "disk") {
    const double radius = r.positive(need("radius"), ptr + "/radius");
    const double r2 = radius * radius;
    if constexpr (D == 2) {
      const double area = M_PI * r2;
      return analytic<2>(makeSphereShape<2>(radius), area, AngVec<2>::Constant(area * r2 / 2.0));
    } else {
      const double volume = 4.0 / 3.0 * M_PI * r2 * radius;
      return analytic<3>(makeSphereShape<3>(radius), volume, AngVec<3>::Constant(0.4 * volume * r2));
    }
  }
  if (type == "torus" || type == "annulus" || type == "ring") {
    const double R = r.positive(need("majorRadius"), ptr + "/majorRadius");
    const double a = r.positive(need("minorRadius"), ptr + "/minorRadius");
    if (!(a < R)) r.fail(ptr + "/minorRadius", "must be smaller than majorRadius = " + formatNumber(R));
    if constexpr (D == 2) {
      const double area = 4.0 * M_PI * R * a;  // pi (R+a)^2 - pi (R-a)^2
      return analytic<2>(makeTorusShape<2>(R, a), area, AngVec<2>::Constant(area * (R * R + a * a)));
    } else {
      const double volume = 2.0 * M_PI * M_PI * R * a * a;
      const double side = volume * (R * R / 2.0 + 5.0 * a * a / 8.0);
      const double axial = volume * (R * R + 3.0 * a * a / 4.0);
      return analytic<3>(makeTorusShape<3>(R, a), volume, Vec3(side, side, axial));
    }
  }
  if (type == "capsule") {
    const double radius = r.positive(need("radius"), ptr + "/radius");
    const double length = r.positive(need("length"), ptr + "/length");
    const double h = 0.5 * length, r2 = radius * radius;
    if constexpr (D == 2) {
      // A 2r x 2h rectangle and two half disks whose centroids are 4r/(3 pi) beyond its ends.
      const double rect = 4.0 * radius * h;
      const double half = 0.5 * M_PI * r2;
      const double d0 = 4.0 * radius / (3.0 * M_PI);
      const double moment = rect * (4.0 * r2 + 4.0 * h * h) / 12.0 +
                            2.0 * half * (r2 / 2.0 - d0 * d0 + (h + d0) * (h + d0));
      return analytic<2>(makeCapsuleShape<2>(h, radius), rect + 2.0 * half, AngVec<2>::Constant(moment));
    } else {
      // A cylinder of length 2h and two hemispheres whose centroids are 3r/8 beyond its ends.
      const double cyl = M_PI * r2 * length;
      const double hemi = 2.0 / 3.0 * M_PI * r2 * radius;
      const double axial = cyl * r2 / 2.0 + 2.0 * 0.4 * hemi * r2;
      const double d0 = 3.0 * radius / 8.0;
      const double side = cyl * (3.0 * r2 + length * length) / 12.0 +
                          2.0 * hemi * (83.0 / 320.0 * r2 + (h + d0) * (h + d0));
      return analytic<3>(makeCapsuleShape<3>(h, radius), cyl + 2.0 * hemi, Vec3(side, side, axial));
    }
  }
  if (type == "cylinder") {
    const double radius = r.positive(need("radius"), ptr + "/radius");
    const double height = r.positive(need("height"), ptr + "/height");
    if constexpr (D == 2) {
      double measure = 0.0;
      AngVec<2> moments;
      boxMassProperties<2>(Vec2(2.0 * radius, height), measure, moments);
      return analytic<2>(makeCylinderShape<2>(radius, 0.5 * height), measure, moments);
    } else {
      const double volume = M_PI * radius * radius * height;
      const double side = volume * (3.0 * radius * radius + height * height) / 12.0;
      return analytic<3>(makeCylinderShape<3>(radius, 0.5 * height), volume,
                         Vec3(side, side, volume * radius * radius / 2.0));
    }
  }
  if (type == "L") {
    return meshShape<D>(lShapeBoundary<D>(optionalPositive("cellSize", 0.5)), "L", resolution());
  }
  if (type == "U" || type == "cup") {
    CupDimensions cup;
    cup.outerRadius = optionalPositive("outerRadius", cup.outerRadius);
    cup.height = optionalPositive("height", cup.height);
    cup.wallThickness = optionalPositive("wallThickness", cup.wallThickness);
    cup.bottomThickness = optionalPositive("bottomThickness", cup.bottomThickness);
    if (!(cup.wallThickness < cup.outerRadius)) r.fail(ptr + "/wallThickness", "must be smaller than outerRadius");
    if (!(cup.bottomThickness < cup.height)) r.fail(ptr + "/bottomThickness", "must be smaller than height");
    return meshShape<D>(cupBoundary<D>(cup), type, resolution());
  }
  if (type == "bone") {
    BoneDimensions bone;
    bone.ballRadius = optionalPositive("ballRadius", bone.ballRadius);
    bone.neckRadius = optionalPositive("neckRadius", bone.neckRadius);
    bone.length = optionalPositive("length", bone.length);
    if (!(bone.neckRadius <= bone.ballRadius)) r.fail(ptr + "/neckRadius", "must be at most ballRadius");
    return meshShape<D>(boneBoundary<D>(bone), "bone", resolution());
  }
  if constexpr (D == 2) {
    if (type == "star") {
      const double outer = optionalPositive("outerRadius", 0.5);
      const double inner = optionalPositive("innerRadius", 0.2);
      if (!(inner < outer)) r.fail(ptr + "/innerRadius", "must be smaller than outerRadius");
      const json* p = member(spec, "points");
      const int points = p == nullptr ? 5 : r.integer(*p, ptr + "/points", 3, 64);
      return meshShape<2>(starPolygon(outer, inner, points), "star", resolution());
    }
  } else {
    if (type == "mesh") {
      const std::string name = r.string(need("file"), ptr + "/file");
      const std::filesystem::path path = baseDir / name;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) {
        r.fail(ptr + "/file", "no such mesh file: " + path.string());
      }
      TriangleMesh mesh;
      try {
        mesh = loadObjMesh(path.string());
      } catch (const std::exception& e) {
        r.fail(ptr + "/file", std::string("the mesh cannot be used: ") + e.what());
      }
      const double scale = optionalPositive("scale", 1.0);
      for (Vec3& v : mesh.vertices) v *= scale;
      return meshShape<3>(std::move(mesh), name, resolution());
    }
  }
  r.fail(ptr + "/type", "shape type \"" + type + "\" is not available in " + std::to_string(D) + "D");
}

// --- Bodies -------------------------------------------------------------------------------

const std::vector<std::string>& bodyKeys(int dimension) {
  static const std::vector<std::string> two{"name", "shape", "static", "density", "mass", "position",
                                            "angleDeg", "velocity", "angularVelocity", "material",
                                            "color", "array"};
  static const std::vector<std::string> three{"name", "shape", "static", "density", "mass", "position",
                                              "angleDeg", "axis", "quaternion", "velocity",
                                              "angularVelocity", "material", "color", "array"};
  return dimension == 2 ? two : three;
}

template <int D>
Orientation<D> readOrientation(const Reader& r, const json& body, const std::string& ptr) {
  const json* angle = member(body, "angleDeg");
  const double radians = angle == nullptr ? 0.0 : r.number(*angle, ptr + "/angleDeg") * M_PI / 180.0;
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(radians);
  } else {
    const json* q = member(body, "quaternion");
    const json* axis = member(body, "axis");
    if (q != nullptr) {
      if (angle != nullptr || axis != nullptr) {
        r.fail(ptr + "/quaternion", "give either \"quaternion\" or \"axis\" with \"angleDeg\", not both");
      }
      const Eigen::Vector4d c = r.vector<4>(*q, ptr + "/quaternion");
      if (!(c.norm() > 1e-12)) r.fail(ptr + "/quaternion", "must not be zero");
      return Eigen::Quaterniond(c[0], c[1], c[2], c[3]).normalized();  // w x y z
    }
    Vec3 a = Vec3::UnitZ();
    if (axis != nullptr) {
      a = r.vector<3>(*axis, ptr + "/axis");
      if (!(a.norm() > 1e-12)) r.fail(ptr + "/axis", "must not be the zero vector");
    }
    return Eigen::Quaterniond(Eigen::AngleAxisd(radians, a.normalized()));
  }
}

std::array<double, 3> readColor(const Reader& r, const json& v, const std::string& ptr) {
  const Vec3 c = r.vector<3>(v, ptr);
  for (int k = 0; k < 3; ++k) {
    if (!(c[k] >= 0.0 && c[k] <= 1.0)) {
      r.fail(ptr + "/" + std::to_string(k), "colour components must be in [0, 1], got " + formatNumber(c[k]));
    }
  }
  return {c[0], c[1], c[2]};
}

/// The palette for bodies without a "color": dynamic bodies cycle through it.
std::array<double, 3> paletteColor(std::size_t k) {
  static const std::array<std::array<double, 3>, 6> palette{{{0.89, 0.45, 0.25},
                                                             {0.25, 0.55, 0.85},
                                                             {0.35, 0.70, 0.40},
                                                             {0.85, 0.70, 0.20},
                                                             {0.60, 0.40, 0.75},
                                                             {0.30, 0.70, 0.70}}};
  return palette[k % palette.size()];
}

/// "_i_j" (or "_i_j_k"): the name suffix of an array copy. Built by appending, which also
/// keeps GCC 12's -Wrestrict false positive on `"_" + std::to_string(i)` at -O3 away.
std::string indexSuffix(std::initializer_list<int> indices) {
  std::string out;
  for (int index : indices) {
    out += '_';
    out += std::to_string(index);
  }
  return out;
}

/// The offsets of a body array (`array` of a body entry), with their index suffixes.
template <int D>
std::vector<std::pair<Vec<D>, std::string>> arrayOffsets(const Reader& r, const json& spec,
                                                         const std::string& ptr) {
  r.requireObject(spec, ptr, {"count", "pyramid", "spacing"}, "a body array");
  const json* spacingValue = member(spec, "spacing");
  if (spacingValue == nullptr) r.fail(ptr, "a body array needs \"spacing\"");
  const Vec<D> spacing = r.vector<D>(*spacingValue, ptr + "/spacing");
  const json* count = member(spec, "count");
  const json* pyramid = member(spec, "pyramid");
  if ((count == nullptr) == (pyramid == nullptr)) {
    r.fail(ptr, "a body array needs exactly one of \"count\" (a grid) and \"pyramid\" (a base width)");
  }
  std::vector<std::pair<Vec<D>, std::string>> out;
  constexpr int kMaxBodies = 100'000;
  if (count != nullptr) {
    if (!count->is_array() || count->size() != static_cast<std::size_t>(D)) {
      r.fail(ptr + "/count", "expected an array of " + std::to_string(D) + " integers, got " + describeValue(*count));
    }
    std::array<int, 3> n{1, 1, 1};
    long long total = 1;
    for (int k = 0; k < D; ++k) {
      n[static_cast<std::size_t>(k)] =
          r.integer((*count)[static_cast<std::size_t>(k)], ptr + "/count/" + std::to_string(k), 1, kMaxBodies);
      total *= n[static_cast<std::size_t>(k)];
    }
    if (total > kMaxBodies) r.fail(ptr + "/count", "at most " + std::to_string(kMaxBodies) + " bodies per array");
    for (int k = 0; k < n[2]; ++k) {
      for (int j = 0; j < n[1]; ++j) {
        for (int i = 0; i < n[0]; ++i) {
          Vec<D> offset = spacing;
          offset[0] *= i;
          offset[1] *= j;
          if constexpr (D == 3) offset[2] *= k;
          out.emplace_back(offset, D == 3 ? indexSuffix({i, j, k}) : indexSuffix({i, j}));
        }
      }
    }
  } else {
    // Level l (0 at the bottom, along the last axis) has base - l bodies per row, shifted
    // by half a spacing per level: a 2D pyramid, or square layers in 3D.
    const int base = r.integer(*pyramid, ptr + "/pyramid", 1, D == 2 ? 400 : 40);
    for (int level = 0; level < base; ++level) {
      const int width = base - level;
      const double shift = 0.5 * level;
      for (int j = 0; j < (D == 3 ? width : 1); ++j) {
        for (int i = 0; i < width; ++i) {
          Vec<D> offset;
          offset[0] = (i + shift) * spacing[0];
          if constexpr (D == 2) {
            offset[1] = level * spacing[1];
          } else {
            offset[1] = (j + shift) * spacing[1];
            offset[2] = level * spacing[2];
          }
          out.emplace_back(offset, D == 3 ? indexSuffix({level, i, j}) : indexSuffix({level, i}));
        }
      }
    }
  }
  return out;
}

/// Reads the body entry at `ptr` and appends it (or, with an "array", every copy of it) to
/// `out`. Shapes are built once per distinct description and shared through `shapes`.
template <int D>
void addBodies(const Reader& r, const json& body, const std::string& ptr,
               const std::map<std::string, Material>& materials, const std::filesystem::path& baseDir,
               std::map<std::string, BuiltShape<D>>& shapes, SceneBodies<D>& out) {
  r.requireObject(body, ptr, bodyKeys(D), "a body");
  const json* shapeSpec = member(body, "shape");
  if (shapeSpec == nullptr) r.fail(ptr, "a body needs a \"shape\"");
  const std::string key = shapeSpec->dump();
  auto it = shapes.find(key);
  if (it == shapes.end()) {
    BuiltShape<D> built;
    try {
      built = buildShape<D>(r, *shapeSpec, ptr + "/shape", baseDir);
    } catch (const SceneError&) {
      throw;
    } catch (const std::exception& e) {
      r.fail(ptr + "/shape", e.what());  // the geometry code's own check, e.g. a too-thin bone
    }
    it = shapes.emplace(key, std::move(built)).first;
  }
  const BuiltShape<D>& shape = it->second;

  const json* isStaticValue = member(body, "static");
  const bool isStatic = isStaticValue != nullptr && r.boolean(*isStaticValue, ptr + "/static");
  const json* density = member(body, "density");
  const json* mass = member(body, "mass");
  const json* velocity = member(body, "velocity");
  const json* angular = member(body, "angularVelocity");
  if (isStatic) {
    for (const char* k : {"density", "mass", "velocity", "angularVelocity"}) {
      if (member(body, k) != nullptr) {
        r.fail(ptr + "/" + k, std::string("a static body has no ") + k + "; remove it or set \"static\": false");
      }
    }
  }
  if (density != nullptr && mass != nullptr) r.fail(ptr + "/mass", "give \"density\" or \"mass\", not both");

  Material material;
  if (const json* m = member(body, "material")) {
    const std::string name = r.string(*m, ptr + "/material");
    const auto found = materials.find(name);
    if (found == materials.end()) {
      std::vector<std::string> names;
      for (const auto& [n, unused] : materials) names.push_back(n);
      std::string reason = "unknown material \"" + name + "\"";
      const std::string hint = closestName(name, names);
      if (!hint.empty()) reason += "; did you mean \"" + hint + "\"?";
      if (names.empty()) reason += "; the scene defines no \"materials\"";
      r.fail(ptr + "/material", reason);
    }
    material = found->second;
  }

  const Orientation<D> orientation = readOrientation<D>(r, body, ptr);
  const json* positionValue = member(body, "position");
  const Vec<D> position = positionValue == nullptr ? Vec<D>::Zero() : r.vector<D>(*positionValue, ptr + "/position");
  const Vec<D> v = velocity == nullptr ? Vec<D>::Zero() : r.vector<D>(*velocity, ptr + "/velocity");
  AngVec<D> omega = AngVec<D>::Zero();
  if (angular != nullptr) {
    if constexpr (D == 2) {
      omega[0] = r.number(*angular, ptr + "/angularVelocity");
    } else {
      omega = r.vector<3>(*angular, ptr + "/angularVelocity");
    }
  }
  double bodyMass = 0.0;
  if (!isStatic) {
    if (mass != nullptr) {
      bodyMass = r.positive(*mass, ptr + "/mass");
    } else {
      const double rho = density == nullptr ? 1000.0 : r.positive(*density, ptr + "/density");
      bodyMass = rho * shape.measure;
    }
  }
  std::string name = "body" + std::to_string(out.world.size());
  if (const json* n = member(body, "name")) name = r.string(*n, ptr + "/name");
  std::optional<std::array<double, 3>> color;
  if (const json* c = member(body, "color")) color = readColor(r, *c, ptr + "/color");

  std::vector<std::pair<Vec<D>, std::string>> offsets{{Vec<D>::Zero(), ""}};
  if (const json* a = member(body, "array")) offsets = arrayOffsets<D>(r, *a, ptr + "/array");

  // [place_body]
  for (const auto& [offset, suffix] : offsets) {
    // The scene places the shape's own frame; the body frame sits at `shape.frame` in it.
    const Pose<D> placement{Vec<D>(position + offset), orientation};
    RigidBody<D> rigid;
    if (isStatic) {
      rigid = makeStaticBody<D>();
    } else {
      const double scale = bodyMass / shape.measure;  // Eq. (10.1)
      try {
        rigid = makeDynamicBody<D>(bodyMass, AngVec<D>(scale * shape.unitMoments));
      } catch (const std::exception& e) {
        r.fail(ptr, e.what());
      }
    }
    rigid.position = placement.toWorld(shape.frame.position);  // Eq. (10.2)
    if constexpr (D == 2) {
      rigid.orientation = Eigen::Rotation2Dd(orientation.angle() + shape.frame.orientation.angle());
    } else {
      rigid.orientation = (orientation * shape.frame.orientation).normalized();
    }
    if (!isStatic) {
      rigid.velocity = v;
      rigid.setAngularVelocity(omega);
    }
    out.world.addBody(rigid, shape.shape, material);
    BodyVisual<D> visual;
    visual.name = name + suffix;
    visual.mesh = shape.mesh;
    visual.isStatic = isStatic;
    visual.color = color ? *color : (isStatic ? std::array<double, 3>{0.55, 0.57, 0.60}
                                              : paletteColor(out.visuals.size()));
    out.visuals.push_back(std::move(visual));
    out.pointers.push_back(ptr);
  }
  // [place_body]
}

/// Rejects bodies that start inside each other (unless the scene allows it): the deepest
/// surface sample of one body inside another must be within a tolerance of the surface,
/// 1e-6 plus half a cell for a grid shape (whose phi is only that accurate).
template <int D>
void checkStartOverlap(const Reader& r, const SceneBodies<D>& b) {
  const World<D>& w = b.world;
  std::vector<CollisionBody<D>> views;
  for (std::size_t i = 0; i < w.bodies.size(); ++i) views.push_back(collisionBody<D>(w.bodies[i], *w.shapes[i]));
  // The deepest sample beyond its tolerance, so that the message gives the real overlap.
  const InterferenceSample<D>* worst = nullptr;
  std::vector<PairInterference<D>> found = detectInterference<D>(views);
  for (const PairInterference<D>& pair : found) {
    for (const InterferenceSample<D>& s : pair.samples) {
      const Shape<D>* other = w.shapes[static_cast<std::size_t>(s.other)].get();
      double tolerance = 1e-6;
      if (const auto* grid = dynamic_cast<const GridShape<D>*>(other)) tolerance += 0.5 * grid->grid().cellSize();
      if (-s.depth > tolerance && (worst == nullptr || s.depth < worst->depth)) worst = &s;
    }
  }
  if (worst != nullptr) {
    const auto owner = static_cast<std::size_t>(worst->owner), inside = static_cast<std::size_t>(worst->other);
    r.fail(b.pointers[owner], "body \"" + b.visuals[owner].name + "\" starts " + formatNumber(-worst->depth) +
                                  " inside body \"" + b.visuals[inside].name + "\" (" + b.pointers[inside] +
                                  "); move it or set \"allowOverlap\": true");
  }
}

template <int D>
SceneBodies<D> buildBodies(const Reader& r, const json& doc, const std::map<std::string, Material>& materials,
                           const std::filesystem::path& baseDir, const Vec<D>& gravity, bool allowOverlap) {
  SceneBodies<D> out;
  out.world.gravity = gravity;
  const json* bodies = member(doc, "bodies");
  if (bodies == nullptr) r.fail("", "a scene needs \"bodies\"");
  if (!bodies->is_array()) r.fail("/bodies", "expected an array of bodies, got " + describeValue(*bodies));
  if (bodies->empty()) r.fail("/bodies", "a scene needs at least one body");
  std::map<std::string, BuiltShape<D>> shapes;
  for (std::size_t i = 0; i < bodies->size(); ++i) {
    addBodies<D>(r, (*bodies)[i], "/bodies/" + std::to_string(i), materials, baseDir, shapes, out);
  }
  if (!allowOverlap) checkStartOverlap<D>(r, out);
  return out;
}

void readSolver(const Reader& r, const json& solver, StepSettings& s) {
  const std::string p = "/solver";
  r.requireObject(solver, p,
                  {"collisionIterations", "collisionPairIterations", "contactIterations",
                   "contactPairIterations", "contactRestitution", "shock", "order", "impulsePoint",
                   "impulsePointNormalCosine", "frictionCone"},
                  "the solver settings");
  if (const json* v = member(solver, "collisionIterations")) s.collisionIterations = r.integer(*v, p + "/collisionIterations", 0, 1000);
  if (const json* v = member(solver, "collisionPairIterations")) s.collisionPairIterations = r.integer(*v, p + "/collisionPairIterations", 1, 1000);
  if (const json* v = member(solver, "contactIterations")) s.contactIterations = r.integer(*v, p + "/contactIterations", 0, 1000);
  if (const json* v = member(solver, "contactPairIterations")) s.contactPairIterations = r.integer(*v, p + "/contactPairIterations", 1, 1000);
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
    s.impulsePoint.rule = choose("impulsePoint", "deepest", ImpulsePointRule::Deepest, "centre",
                                 ImpulsePointRule::DepthWeightedCentre);
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
    r.requireObject(*shock, q, {"passes", "sweepsPerLevel", "pairIterations", "restitution", "replacesContactStage"},
                    "the shock settings");
    if (const json* v = member(*shock, "passes")) s.shock.passes = r.integer(*v, q + "/passes", 1, 100);
    if (const json* v = member(*shock, "sweepsPerLevel")) s.shock.sweepsPerLevel = r.integer(*v, q + "/sweepsPerLevel", 1, 100);
    if (const json* v = member(*shock, "pairIterations")) s.shock.pairIterations = r.integer(*v, q + "/pairIterations", 1, 1000);
    if (const json* v = member(*shock, "restitution")) {
      s.shock.restitution = schedule(*v, q + "/restitution", static_cast<std::size_t>(s.shock.sweepsPerLevel), "sweepsPerLevel");
    }
    if (const json* v = member(*shock, "replacesContactStage")) {
      s.shock.replacesContactStage = r.boolean(*v, q + "/replacesContactStage");
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

}  // namespace

Scene parseScene(const json& doc, const std::string& file, const std::filesystem::path& baseDir) {
  const Reader r(file);
  r.requireObject(doc, "",
                  {"description", "dimension", "gravity", "dt", "duration", "solver", "effects", "output",
                   "materials", "bodies", "allowOverlap"},
                  "a scene");
  Scene scene;
  scene.file = file;
  const json* dimension = member(doc, "dimension");
  if (dimension == nullptr) r.fail("", "a scene needs \"dimension\": 2 or 3");
  if (!dimension->is_number_integer() || (dimension->get<std::int64_t>() != 2 && dimension->get<std::int64_t>() != 3)) {
    r.fail("/dimension", "must be 2 or 3, got " + describeValue(*dimension));
  }
  scene.dimension = static_cast<int>(dimension->get<std::int64_t>());
  if (const json* v = member(doc, "description")) scene.description = r.string(*v, "/description");
  if (const json* v = member(doc, "dt")) scene.settings.dt = r.positive(*v, "/dt");
  if (const json* v = member(doc, "duration")) scene.duration = r.positive(*v, "/duration");
  if (scene.duration / scene.settings.dt > 1e9) r.fail("/duration", "duration / dt must be at most 1e9 steps");
  if (const json* v = member(doc, "allowOverlap")) scene.allowOverlap = r.boolean(*v, "/allowOverlap");
  if (const json* v = member(doc, "solver")) readSolver(r, *v, scene.settings);
  if (const json* v = member(doc, "effects")) readEffects(r, *v, scene.settings.effects);
  if (const json* v = member(doc, "output")) {
    r.requireObject(*v, "/output", {"frameRate"}, "the output settings");
    if (const json* f = member(*v, "frameRate")) scene.output.frameRate = r.positive(*f, "/output/frameRate");
  }
  std::map<std::string, Material> materials;
  if (const json* v = member(doc, "materials")) materials = readMaterials(r, *v);
  try {
    validateStepSettings(scene.settings, "scene");
  } catch (const std::invalid_argument& e) {
    r.fail("/solver", e.what());
  }
  const json* gravity = member(doc, "gravity");
  if (scene.dimension == 2) {
    const Vec2 g = gravity == nullptr ? Vec2(0.0, -9.81) : r.vector<2>(*gravity, "/gravity");
    scene.bodies = buildBodies<2>(r, doc, materials, baseDir, g, scene.allowOverlap);
  } else {
    const Vec3 g = gravity == nullptr ? Vec3(0.0, 0.0, -9.81) : r.vector<3>(*gravity, "/gravity");
    scene.bodies = buildBodies<3>(r, doc, materials, baseDir, g, scene.allowOverlap);
  }
  return scene;
}

json readSceneJson(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw SceneError(path, "", "no such scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, "", "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string content = text.str();
  try {
    return json::parse(content);
  } catch (const json::parse_error& e) {
    // Line and column of the byte the parser stopped at.
    std::size_t line = 1, column = 1;
    for (std::size_t k = 0; k + 1 < e.byte && k < content.size(); ++k) {
      if (content[k] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string what = e.what();
    const auto colon = what.find("syntax error");
    if (colon != std::string::npos) what = what.substr(colon);
    throw SceneError(path, "", "line " + std::to_string(line) + ", column " + std::to_string(column) +
                                   ": not valid JSON (" + what + ")");
  }
}

void applySceneOverride(json& doc, const std::string& keyValue, const std::string& file) {
  const auto eq = keyValue.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw SceneError(file, "", "--set expects key=value (e.g. dt=0.0005), got \"" + keyValue + "\"");
  }
  std::string key = keyValue.substr(0, eq);
  const std::string text = keyValue.substr(eq + 1);
  std::replace(key.begin(), key.end(), '.', '/');
  if (key.front() != '/') key.insert(key.begin(), '/');
  json value;
  try {
    value = json::parse(text);
  } catch (const json::parse_error&) {
    value = text;  // a bare word: a string, e.g. --set solver.order=traditional
  }
  try {
    doc[json::json_pointer(key)] = value;
  } catch (const json::exception& e) {
    throw SceneError(file, key, std::string("--set cannot set this field: ") + e.what());
  }
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
  json doc = readSceneJson(path);
  for (const std::string& o : overrides) applySceneOverride(doc, o, path);
  return parseScene(doc, path, std::filesystem::path(path).parent_path());
}

}  // namespace stackbook
