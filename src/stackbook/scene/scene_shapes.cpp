// Scene files (chapter 10): building a body's shape from its "shape" object. See
// scene_shapes.hpp and docs/scene_format.md.
#include "stackbook/scene/scene_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/mesh_file.hpp"
#include "stackbook/geometry/mesh_repair.hpp"
#include "stackbook/geometry/obj_loader.hpp"
#include "stackbook/geometry/winding_mass_properties.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

namespace stackbook::scene_detail {

namespace {

/// What a refused mesh in a scene suggests: the field that loads it anyway.
constexpr const char* kSceneMeshRepairHint = "set \"meshMode\": \"repair\" to repair it (chapter 6)";

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

// [approximate_mesh_shape]
/// A shape from a mesh that is not watertight after repair (chapter 6, "Repairing
/// downloaded meshes"): the solid is {w > 1/2}. Its mass properties are integrated over
/// the cells of a grid with `resolution` cells across (Eq. (6.23)), and its signed-distance
/// grid signs every node by its own winding number, since the region shortcut of Eq.
/// (6.10) needs a closed surface.
BuiltShape<3> approximateMeshShape(TriangleMesh mesh, const std::string& name, int resolution) {
  const MassProperties<3> properties = windingNumberMassProperties(mesh, 1.0, resolution);
  const PrincipalAxes<3> axes = principalAxes<3>(properties);
  const Pose<3> frame{properties.centerOfMass, axes.rotation};
  for (Vec3& v : mesh.vertices) v = frame.toBody(v);
  SdfGridSettings grid;
  grid.cellsAcrossLargestExtent = resolution;
  grid.validate = false;
  grid.sign = SdfSignMethod::WindingNumberPerNode;
  BuiltShape<3> out;
  out.measure = properties.mass;
  out.unitMoments = axes.moments;
  out.frame = frame;
  out.shape = std::make_shared<GridShape<3>>(mesh, name, grid);
  out.mesh = std::move(mesh);
  return out;
}
// [approximate_mesh_shape]

}  // namespace

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
      {"box", {"type", "size", "samples"}},
      {"sphere", {"type", "radius", "samples"}},
      {"disk", {"type", "radius", "samples"}},
      {"torus", {"type", "majorRadius", "minorRadius", "samples"}},
      {"annulus", {"type", "majorRadius", "minorRadius", "samples"}},
      {"ring", {"type", "majorRadius", "minorRadius", "samples"}},
      {"capsule", {"type", "radius", "length", "samples"}},
      {"cylinder", {"type", "radius", "height", "samples"}},
      {"L", {"type", "cellSize", "sdfResolution"}},
      {"U", {"type", "outerRadius", "height", "wallThickness", "bottomThickness", "sdfResolution"}},
      {"cup", {"type", "outerRadius", "height", "wallThickness", "bottomThickness", "sdfResolution"}},
      {"bone", {"type", "ballRadius", "neckRadius", "length", "sdfResolution"}},
      {"star", {"type", "outerRadius", "innerRadius", "points", "sdfResolution"}},
      {"mesh", {"type", "file", "scale", "sdfResolution", "meshMode", "weldTolerance"}},
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
    const int most = D == 2 ? r.limits().sdfResolution2 : r.limits().sdfResolution3;
    return v == nullptr ? std::min(32, most) : r.integer(*v, ptr + "/sdfResolution", 4, most);
  };

  // The surface sample density of an analytic shape (chapter 11): "samples" is the
  // icosphere level of a sphere (3D), the pieces per edge of a box (and of a 2D cylinder,
  // a rectangle), and the vertices around each circle of the other round shapes.
  SampleMeshSettings sampling;
  if (const json* v = member(spec, "samples")) {
    const std::string at = ptr + "/samples";
    if (type == "box" || (type == "cylinder" && D == 2)) {
      sampling.boxSubdivisions = r.integer(*v, at, 1, 64);
    } else if (type == "sphere" && D == 3) {
      sampling.sphereLevel = r.integer(*v, at, 0, 6);
    } else {
      sampling.circleSegments = r.integer(*v, at, 8, 4096);
    }
  }

  if (type == "box") {
    const Vec<D> size = r.positiveVector<D>(need("size"), ptr + "/size");
    double measure = 0.0;
    AngVec<D> moments;
    boxMassProperties<D>(size, measure, moments);
    return analytic<D>(makeBoxShape<D>(size, sampling), measure, moments);
  }
  if (type == "sphere" || type == "disk") {
    const double radius = r.positive(need("radius"), ptr + "/radius");
    const double r2 = radius * radius;
    if constexpr (D == 2) {
      const double area = M_PI * r2;
      return analytic<2>(makeSphereShape<2>(radius, sampling), area, AngVec<2>::Constant(area * r2 / 2.0));
    } else {
      const double volume = 4.0 / 3.0 * M_PI * r2 * radius;
      return analytic<3>(makeSphereShape<3>(radius, sampling), volume, AngVec<3>::Constant(0.4 * volume * r2));
    }
  }
  if (type == "torus" || type == "annulus" || type == "ring") {
    const double R = r.positive(need("majorRadius"), ptr + "/majorRadius");
    const double a = r.positive(need("minorRadius"), ptr + "/minorRadius");
    if (!(a < R)) r.fail(ptr + "/minorRadius", "must be smaller than majorRadius = " + formatNumber(R));
    if constexpr (D == 2) {
      const double area = 4.0 * M_PI * R * a;  // pi (R+a)^2 - pi (R-a)^2
      return analytic<2>(makeTorusShape<2>(R, a, sampling), area, AngVec<2>::Constant(area * (R * R + a * a)));
    } else {
      const double volume = 2.0 * M_PI * M_PI * R * a * a;
      const double side = volume * (R * R / 2.0 + 5.0 * a * a / 8.0);
      const double axial = volume * (R * R + 3.0 * a * a / 4.0);
      return analytic<3>(makeTorusShape<3>(R, a, sampling), volume, Vec3(side, side, axial));
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
      return analytic<2>(makeCapsuleShape<2>(h, radius, sampling), rect + 2.0 * half, AngVec<2>::Constant(moment));
    } else {
      // A cylinder of length 2h and two hemispheres whose centroids are 3r/8 beyond its ends.
      const double cyl = M_PI * r2 * length;
      const double hemi = 2.0 / 3.0 * M_PI * r2 * radius;
      const double axial = cyl * r2 / 2.0 + 2.0 * 0.4 * hemi * r2;
      const double d0 = 3.0 * radius / 8.0;
      const double side = cyl * (3.0 * r2 + length * length) / 12.0 +
                          2.0 * hemi * (83.0 / 320.0 * r2 + (h + d0) * (h + d0));
      return analytic<3>(makeCapsuleShape<3>(h, radius, sampling), cyl + 2.0 * hemi, Vec3(side, side, axial));
    }
  }
  if (type == "cylinder") {
    const double radius = r.positive(need("radius"), ptr + "/radius");
    const double height = r.positive(need("height"), ptr + "/height");
    if constexpr (D == 2) {
      double measure = 0.0;
      AngVec<2> moments;
      boxMassProperties<2>(Vec2(2.0 * radius, height), measure, moments);
      return analytic<2>(makeCylinderShape<2>(radius, 0.5 * height, sampling), measure, moments);
    } else {
      const double volume = M_PI * radius * radius * height;
      const double side = volume * (3.0 * radius * radius + height * height) / 12.0;
      return analytic<3>(makeCylinderShape<3>(radius, 0.5 * height, sampling), volume,
                         Vec3(side, side, volume * radius * radius / 2.0));
    }
  }
  if (type == "L") {
    return meshShape<D>(lShapeBoundary<D>(optionalPositive("cellSize", 0.5)), "L", resolution());
  }
  // A revolved outline (cup, bone) has one profile point per `spacing` of its outline and
  // 48 copies of it around the axis in 3D: estimated before it is built, so that a long
  // bone fails here rather than filling the memory.
  const auto requireProfileSize = [&](const char* field, double outline, double spacing) {
    const double points = outline / spacing + 8.0;
    const double vertices = points * (D == 3 ? 48.0 : 2.0);
    if (!(vertices <= static_cast<double>(r.limits().meshVertices))) {
      r.fail(ptr + "/" + field, "the " + type + "'s surface would have about " + formatNumber(std::ceil(vertices)) +
                                    " vertices (one every " + formatNumber(spacing) + " along its outline); at most " +
                                    std::to_string(r.limits().meshVertices));
    }
  };
  if (type == "U" || type == "cup") {
    CupDimensions cup;
    cup.outerRadius = optionalPositive("outerRadius", cup.outerRadius);
    cup.height = optionalPositive("height", cup.height);
    cup.wallThickness = optionalPositive("wallThickness", cup.wallThickness);
    cup.bottomThickness = optionalPositive("bottomThickness", cup.bottomThickness);
    if (!(cup.wallThickness < cup.outerRadius)) r.fail(ptr + "/wallThickness", "must be smaller than outerRadius");
    if (!(cup.bottomThickness < cup.height)) r.fail(ptr + "/bottomThickness", "must be smaller than height");
    requireProfileSize(cup.height >= cup.outerRadius ? "height" : "outerRadius",
                       4.0 * (cup.outerRadius + cup.height), 0.05);
    return meshShape<D>(cupBoundary<D>(cup), type, resolution());
  }
  if (type == "bone") {
    BoneDimensions bone;
    bone.ballRadius = optionalPositive("ballRadius", bone.ballRadius);
    bone.neckRadius = optionalPositive("neckRadius", bone.neckRadius);
    bone.length = optionalPositive("length", bone.length);
    if (!(bone.neckRadius <= bone.ballRadius)) r.fail(ptr + "/neckRadius", "must be at most ballRadius");
    requireProfileSize(bone.length >= bone.ballRadius ? "length" : "ballRadius",
                       2.0 * M_PI * bone.ballRadius + bone.length, 0.04);
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
      if (const std::string why = whyNotARegularFile(path); !why.empty()) {
        r.fail(ptr + "/file", (why == "no such file" ? "no such mesh file: " : "the mesh file is " + why + ": ") +
                                  path.string());
      }
      const auto bytes = std::filesystem::file_size(path, ec);
      if (!ec && bytes > r.limits().meshFileBytes) {
        r.fail(ptr + "/file", "the mesh file has " + std::to_string(bytes) + " bytes; at most " +
                                  std::to_string(r.limits().meshFileBytes));
      }
      // [scene_mesh_mode]
      // "meshMode": strict (the default) takes the file as it is or rejects it; repair
      // loads it raw, repairs what it can and keeps the rest for the winding number.
      MeshMode mode = MeshMode::Strict;
      if (const json* m = member(spec, "meshMode")) {
        const std::string text = r.string(*m, ptr + "/meshMode");
        if (text == "repair") {
          mode = MeshMode::Repair;
        } else if (text != "strict") {
          r.fail(ptr + "/meshMode", "must be \"strict\" or \"repair\", got \"" + text + "\"");
        }
      }
      MeshRepairSettings repair;
      if (const json* w = member(spec, "weldTolerance")) {
        if (mode != MeshMode::Repair) r.fail(ptr + "/weldTolerance", "applies only with \"meshMode\": \"repair\"");
        repair.weldTolerance = r.number(*w, ptr + "/weldTolerance");
        if (!(repair.weldTolerance >= 0.0 && repair.weldTolerance < 0.01)) {
          r.fail(ptr + "/weldTolerance", "must be in [0, 0.01) (a fraction of the mesh's diagonal), got " +
                                             formatNumber(repair.weldTolerance));
        }
      }
      ObjLoadSettings load;
      if (mode == MeshMode::Repair) {
        load.mergeTolerance = -1.0;  // repairMesh welds, and says so
        load.dropUnusedVertices = false;
        load.validate = false;
      }
      // [scene_mesh_refusal]
      // A strict load keeps every defect (not five of each kind), for `check --all-defects`;
      // the line itself has the counts, the first of each kind and what to do.
      if (mode == MeshMode::Strict) load.validation.maxReportedPerKind = std::numeric_limits<int>::max();
      TriangleMesh mesh;
      try {
        mesh = loadMeshFile(path.string(), load);
      } catch (const MeshError& e) {
        if (!e.repairable()) r.fail(ptr + "/file", std::string("the mesh cannot be used: ") + e.what());
        std::vector<std::string> every;
        for (const MeshDefect& d : e.defects()) every.push_back(std::string(meshDefectName(d.kind)) + ": " + d.message);
        // The field names the file; the line names it as the scene wrote it, not by its path.
        std::string summary = e.summary();
        if (const std::string prefix = path.string() + ": "; summary.rfind(prefix, 0) == 0) {
          summary = name + ": " + summary.substr(prefix.size());
        }
        r.fail(ptr + "/file",
               summary + "; " + kSceneMeshRepairHint + "; stackbook check --all-defects lists all",
               std::move(every));
      } catch (const std::exception& e) {
        r.fail(ptr + "/file", std::string("the mesh cannot be used: ") + e.what());
      }
      // [scene_mesh_refusal]
      if (static_cast<long long>(mesh.vertices.size()) > r.limits().meshVertices) {
        r.fail(ptr + "/file", "the mesh has " + std::to_string(mesh.vertices.size()) + " vertices; at most " +
                                  std::to_string(r.limits().meshVertices));
      }
      const double scale = optionalPositive("scale", 1.0);
      for (Vec3& v : mesh.vertices) {
        v *= scale;
        if (!(v.allFinite() && v.cwiseAbs().maxCoeff() <= r.limits().numberMagnitude)) {
          r.fail(member(spec, "scale") != nullptr ? ptr + "/scale" : ptr + "/file",
                 "a vertex of the mesh (scaled) is beyond " + formatNumber(r.limits().numberMagnitude) +
                     " in magnitude (a limit of the scene format)");
        }
      }
      if (mode == MeshMode::Strict) return meshShape<3>(std::move(mesh), name, resolution());
      const MeshRepairReport report = repairMesh(mesh, repair);
      if (mesh.faces.empty()) r.fail(ptr + "/file", "the mesh cannot be used: no face is left after repair");
      BuiltShape<3> out;
      try {
        out = report.watertight() ? meshShape<3>(std::move(mesh), name, resolution())
                                  : approximateMeshShape(std::move(mesh), name, resolution());
      } catch (const std::exception& e) {
        r.fail(ptr + "/file", std::string("the repaired mesh cannot be used: ") + e.what());
      }
      out.repairs = report.repairs;
      out.approximations = report.remaining;
      if (!report.watertight()) {
        out.approximations.push_back(
            "mass, centre of mass and inertia integrated over the cells with winding number > 1/2 "
            "(about one cell of error); the distance is to the faces that exist");
      }
      return out;
      // [scene_mesh_mode]
    }
  }
  r.fail(ptr + "/type", "shape type \"" + type + "\" is not available in " + std::to_string(D) + "D");
}

template BuiltShape<2> buildShape<2>(const Reader&, const json&, const std::string&,
                                     const std::filesystem::path&);
template BuiltShape<3> buildShape<3>(const Reader&, const json&, const std::string&,
                                     const std::filesystem::path&);

}  // namespace stackbook::scene_detail
