// Scene files (chapter 10): building the bodies of a scene (their shapes, masses, poses,
// velocities, materials, colours and arrays) and checking that they do not start inside
// each other. See scene_bodies.hpp and docs/scene_format.md.
#include "stackbook/scene/scene_bodies.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <utility>
#include <vector>

#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/geometry/sdf_grid.hpp"
#include "stackbook/scene/scene_shapes.hpp"

namespace stackbook::scene_detail {

namespace {

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
    // What a repaired mesh changed, and what stays approximate, once per distinct shape.
    for (const std::string& line : built.repairs) out.notes.push_back(r.file() + ": " + ptr + "/shape/file: " + line);
    for (const std::string& line : built.approximations) {
      out.warnings.push_back(r.file() + ": " + ptr + "/shape/file: approximate: " + line);
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
      // The field the mass properties come from: "mass" or "density" with the shape.
      const std::string massField = mass != nullptr ? ptr + "/mass" : density != nullptr ? ptr + "/density" : ptr + "/shape";
      const AngVec<D> moments = scale * shape.unitMoments;
      if (!(std::isfinite(bodyMass) && bodyMass > 0.0 && std::isfinite(1.0 / bodyMass))) {
        r.fail(massField, "gives the body a mass of " + formatNumber(bodyMass) +
                              " kg, which the step cannot use (its inverse must be finite and > 0)");
      }
      if (!(moments.allFinite() && (moments.array() > 0.0).all() && moments.cwiseInverse().allFinite())) {
        r.fail(massField, "gives the body principal moments of inertia that the step cannot use (each must be "
                          "finite and > 0 with a finite inverse); check the shape's size and the mass");
      }
      try {
        rigid = makeDynamicBody<D>(bodyMass, moments);
      } catch (const std::exception& e) {
        r.fail(massField, e.what());
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
    bool poseFinite = rigid.position.allFinite();
    if constexpr (D == 2) {
      poseFinite = poseFinite && std::isfinite(rigid.orientation.angle());
    } else {
      poseFinite = poseFinite && rigid.orientation.coeffs().allFinite();
    }
    if (!poseFinite) r.fail(suffix.empty() ? ptr + "/position" : ptr + "/array/spacing", "gives a position that is not finite");
    if (!(rigid.angularMomentum.allFinite() && rigid.velocity.allFinite())) {
      r.fail(ptr + "/angularVelocity", "gives an angular momentum that is not finite (too large for the body's inertia)");
    }
    if (static_cast<long long>(out.world.size()) >= r.limits().bodies) {
      r.fail(ptr, "the scene has more than " + std::to_string(r.limits().bodies) + " bodies (the limit of the scene format)");
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

/// The pairs of bodies whose bounding boxes (about each body's position, a sphere's box
/// holding its shape) overlap at the start, not both static; fails past the limit, which
/// bounds the work of the start-overlap check and of the first step's broad phase.
template <int D>
std::vector<std::pair<std::size_t, std::size_t>> startPairs(const Reader& r, const SceneBodies<D>& b) {
  const World<D>& w = b.world;
  const std::size_t n = w.bodies.size();
  std::vector<double> radius(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Aabb<D> box = w.shapes[i]->bounds();
    radius[i] = std::max(box.lower.norm(), box.upper.norm());
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  const auto low = [&](std::size_t i) { return w.bodies[i].position[0] - radius[i]; };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t c) { return low(a) < low(c); });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  const auto limit = static_cast<std::size_t>(r.limits().startPairs);
  for (std::size_t a = 0; a < n; ++a) {
    const std::size_t i = order[a];
    const double high = w.bodies[i].position[0] + radius[i];
    for (std::size_t c = a + 1; c < n && low(order[c]) <= high; ++c) {
      const std::size_t j = order[c];
      if (w.bodies[i].isStatic() && w.bodies[j].isStatic()) continue;
      bool overlap = true;
      for (int k = 1; k < D && overlap; ++k) {
        overlap = std::abs(w.bodies[i].position[k] - w.bodies[j].position[k]) <= radius[i] + radius[j];
      }
      if (!overlap) continue;
      pairs.emplace_back(i, j);
      if (pairs.size() > limit) {
        r.fail(b.pointers[j], "more than " + std::to_string(limit) +
                                  " pairs of bodies are within reach of each other at the start (the limit of the "
                                  "scene format); spread the bodies out");
      }
    }
  }
  return pairs;
}

/// Rejects bodies that start inside each other (unless the scene allows it): the deepest
/// surface sample of one body inside another must be within a tolerance of the surface,
/// 1e-6 plus half a cell for a grid shape (whose phi is only that accurate), and no two
/// bodies may each have their centre inside the other (two identical bodies at one place
/// have no surface sample inside each other).
template <int D>
void checkStartOverlap(const Reader& r, const SceneBodies<D>& b,
                       const std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
  const World<D>& w = b.world;
  const auto tolerance = [&](std::size_t j) {
    double t = 1e-6;
    if (const auto* grid = dynamic_cast<const GridShape<D>*>(w.shapes[j].get())) t += 0.5 * grid->grid().cellSize();
    return t;
  };
  std::vector<CollisionBody<D>> views;
  for (std::size_t i = 0; i < w.bodies.size(); ++i) views.push_back(collisionBody<D>(w.bodies[i], *w.shapes[i]));
  // The deepest sample beyond its tolerance, so that the message gives the real overlap.
  const InterferenceSample<D>* worst = nullptr;
  std::vector<PairInterference<D>> found = detectInterference<D>(views);
  for (const PairInterference<D>& pair : found) {
    for (const InterferenceSample<D>& s : pair.samples) {
      if (-s.depth > tolerance(static_cast<std::size_t>(s.other)) && (worst == nullptr || s.depth < worst->depth)) {
        worst = &s;
      }
    }
  }
  if (worst != nullptr) {
    const auto owner = static_cast<std::size_t>(worst->owner), inside = static_cast<std::size_t>(worst->other);
    r.fail(b.pointers[owner], "body \"" + b.visuals[owner].name + "\" starts " + formatNumber(-worst->depth) +
                                  " inside body \"" + b.visuals[inside].name + "\" (" + b.pointers[inside] +
                                  "); move it or set \"allowOverlap\": true");
  }
  // Whether body i's centre is inside body j.
  const auto centreInside = [&](std::size_t i, std::size_t j) {
    const Pose<D> pose{w.bodies[j].position, w.bodies[j].orientation};
    const Vec<D> local = pose.toBody(w.bodies[i].position);
    return w.shapes[j]->bounds().contains(local) && w.shapes[j]->signedDistance(local) < -tolerance(j);
  };
  // Each centre inside the other (a ring's centre may be around a peg that does not touch it).
  for (const auto& [i, j] : pairs) {
    if (centreInside(i, j) && centreInside(j, i)) {
      r.fail(b.pointers[j], "body \"" + b.visuals[j].name + "\" and body \"" + b.visuals[i].name + "\" (" +
                                b.pointers[i] + ") start with each centre inside the other; move one or set "
                                "\"allowOverlap\": true");
    }
  }
}

}  // namespace

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
  const auto pairs = startPairs<D>(r, out);
  if (!allowOverlap) checkStartOverlap<D>(r, out, pairs);
  return out;
}

template SceneBodies<2> buildBodies<2>(const Reader&, const json&, const std::map<std::string, Material>&,
                                       const std::filesystem::path&, const Vec<2>&, bool);
template SceneBodies<3> buildBodies<3>(const Reader&, const json&, const std::map<std::string, Material>&,
                                       const std::filesystem::path&, const Vec<3>&, bool);

}  // namespace stackbook::scene_detail
