#pragma once
/// \file
/// \brief Meshes as people download them (\ref ch06, "Repairing downloaded meshes"): weld
/// duplicate vertices within a tolerance relative to the mesh's size, drop degenerate and
/// repeated faces, orient the faces of each connected part consistently and outward, and
/// say on one line each what was changed. What cannot be repaired (holes, non-manifold
/// edges, self-intersections) is listed too: such a mesh is used with the generalised
/// winding number deciding inside from outside (Eq. (6.9)), which is approximate near the
/// defects, instead of being rejected.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "stackbook/geometry/mesh_validation.hpp"
#include "stackbook/geometry/obj_loader.hpp"

namespace stackbook {

// [mesh_repair_settings]
/// What a scene's mesh file must be (the shape field "meshMode").
enum class MeshMode {
  /// The mesh must bound a solid as it is: closed, manifold, consistently and outwardly
  /// oriented, free of degenerate faces and self-intersections; any defect is an error.
  Strict,
  /// Repair what can be repaired (repairMesh()), use the winding number for the rest.
  Repair,
};

/// The knobs of repairMesh().
struct MeshRepairSettings {
  /// Weld vertices closer than weldTolerance x (bounding-box diagonal) (>= 0; 0 welds
  /// exact duplicates only).
  double weldTolerance = 1e-6;
  /// A face whose area is at most degenerateTolerance x diagonal^2, or whose height
  /// (2 area / longest edge) is at most weldTolerance x diagonal, is dropped.
  double degenerateTolerance = 1e-12;
};
// [mesh_repair_settings]

/// What repairMesh() changed and what it could not repair.
struct MeshRepairReport {
  /// One line per repair, e.g. "welded 24 duplicate vertices (within 1.7e-06)".
  std::vector<std::string> repairs;
  /// One line per defect left, with what is approximate because of it.
  std::vector<std::string> remaining;
  /// Closed, manifold, consistently oriented, outward and free of self-intersections:
  /// the mesh bounds a solid exactly and no approximation is needed.
  bool watertight() const { return remaining.empty(); }
};

namespace detail {

/// Reverse a triangle's orientation (its normal).
inline void flipTriangle(std::array<int, 3>& face) { std::swap(face[1], face[2]); }

/// Signed volume of a subset of the faces about a point, Eq. (6.20).
inline double partVolume(const TriangleMesh& mesh, const std::vector<int>& faces, const Vec3& origin) {
  double sum = 0.0;
  for (const int f : faces) {
    const auto& t = mesh.faces[static_cast<std::size_t>(f)];
    sum += (mesh.vertices[t[0]] - origin).dot((mesh.vertices[t[1]] - origin).cross(mesh.vertices[t[2]] - origin)) / 6.0;
  }
  return sum;
}

inline std::string faceList(const std::vector<int>& faces, std::size_t limit = 5) {
  std::ostringstream out;
  for (std::size_t i = 0; i < faces.size() && i < limit; ++i) out << (i ? ", " : "") << faces[i];
  if (faces.size() > limit) out << ", ...";
  return out.str();
}

}  // namespace detail

// [orient_faces]
/// Orient each edge-connected part of the mesh consistently, then outward. Walking from
/// the part's first face across edges shared by exactly two faces, a neighbour must
/// traverse the shared edge the other way (surface_mesh.hpp); if it does not, it is
/// flipped. A part whose signed volume (about its bounding-box centre) is then negative is
/// inside-out and reversed whole; for an open part that volume is that of the cone the
/// open surface makes with the centre, which is positive for a mostly outward surface.
/// Returns the faces whose orientation changed, and counts in `conflicts` the shared edges
/// no orientation can make consistent (a Moebius-like part).
inline std::vector<int> orientFaces(TriangleMesh& mesh, int& conflicts) {
  const std::size_t F = mesh.faces.size();
  const std::vector<std::array<int, 3>> original = mesh.faces;
  std::map<std::pair<int, int>, std::vector<int>> edgeFaces;  // ordered: deterministic
  for (std::size_t f = 0; f < F; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      edgeFaces[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
    }
  }
  // Does face f traverse a -> b?
  const auto traverses = [&mesh](int f, int a, int b) {
    const auto& t = mesh.faces[static_cast<std::size_t>(f)];
    for (int k = 0; k < 3; ++k) {
      if (t[k] == a && t[(k + 1) % 3] == b) return true;
    }
    return false;
  };
  conflicts = 0;
  std::vector<char> visited(F, 0);
  for (std::size_t seed = 0; seed < F; ++seed) {
    if (visited[seed]) continue;
    std::vector<int> part{static_cast<int>(seed)};
    visited[seed] = 1;
    for (std::size_t next = 0; next < part.size(); ++next) {
      const int f = part[next];
      const auto t = mesh.faces[static_cast<std::size_t>(f)];
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        const std::vector<int>& shared = edgeFaces[{std::min(a, b), std::max(a, b)}];
        if (shared.size() != 2) continue;  // a hole's rim or a non-manifold edge: no walk
        const int g = shared[0] == f ? shared[1] : shared[0];
        if (g == f) continue;
        const bool agrees = traverses(g, b, a);
        if (visited[static_cast<std::size_t>(g)]) {
          if (!agrees) ++conflicts;
          continue;
        }
        if (!agrees) detail::flipTriangle(mesh.faces[static_cast<std::size_t>(g)]);
        visited[static_cast<std::size_t>(g)] = 1;
        part.push_back(g);
      }
    }
    Aabb<3> box;
    for (const int f : part) {
      for (const int v : mesh.faces[static_cast<std::size_t>(f)]) box.extend(mesh.vertices[v]);
    }
    if (detail::partVolume(mesh, part, box.center()) < 0.0) {
      for (const int f : part) detail::flipTriangle(mesh.faces[static_cast<std::size_t>(f)]);
    }
  }
  conflicts /= 2;  // each inconsistent edge is met from both of its faces
  std::vector<int> changed;
  for (std::size_t f = 0; f < F; ++f) {
    if (mesh.faces[f] != original[f]) changed.push_back(static_cast<int>(f));
  }
  return changed;
}
// [orient_faces]

// [repair_mesh]
/// Repair `mesh` in place (`source` names it in the report) in this order: weld
/// duplicate vertices, drop degenerate faces, drop repeated faces (the same three
/// vertices, in either orientation: the first is kept), drop unused vertices, orient
/// each part consistently and outward (orientFaces()); then list what is left: holes,
/// non-manifold edges, faces that could not be oriented, self-intersections
/// (findSelfIntersections()). Never throws for a mesh with faces and finite vertices in
/// range; an empty result is reported in `remaining`.
inline MeshRepairReport repairMesh(TriangleMesh& mesh, const MeshRepairSettings& settings = {}) {
  MeshRepairReport report;
  const double diagonal = mesh.bounds().extent().norm();
  {
    const double tolerance = settings.weldTolerance * diagonal;
    const int welded = mergeDuplicateVertices(mesh, tolerance);
    if (welded > 0) {
      std::ostringstream line;
      line << "welded " << welded << " duplicate vertices (closer than " << tolerance << ")";
      report.repairs.push_back(line.str());
    }
  }
  {
    const double minArea = settings.degenerateTolerance * diagonal * diagonal;
    // A sliver thinner than the weld tolerance is degenerate at the welding scale: its
    // height 2 A / (longest edge) is below what welding already treats as zero.
    const double minHeight = settings.weldTolerance * diagonal;
    std::vector<std::array<int, 3>> kept;
    std::vector<int> dropped;
    std::map<std::array<int, 3>, int> seen;
    std::vector<int> repeated;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      const std::array<int, 3>& t = mesh.faces[f];
      const Vec3& a = mesh.vertices[t[0]];
      const Vec3& b = mesh.vertices[t[1]];
      const Vec3& c = mesh.vertices[t[2]];
      const double area = 0.5 * (b - a).cross(c - a).norm();
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || !(area > minArea) || !(2.0 * area > minHeight * longest)) {
        dropped.push_back(static_cast<int>(f));
        continue;
      }
      std::array<int, 3> key = t;
      std::sort(key.begin(), key.end());
      if (!seen.emplace(key, static_cast<int>(f)).second) {
        repeated.push_back(static_cast<int>(f));
        continue;
      }
      kept.push_back(t);
    }
    mesh.faces = std::move(kept);
    if (!dropped.empty()) {
      report.repairs.push_back("dropped " + std::to_string(dropped.size()) +
                               " degenerate faces (a repeated vertex, or thinner than the weld tolerance; faces " +
                               detail::faceList(dropped) + " of the file)");
    }
    if (!repeated.empty()) {
      report.repairs.push_back("dropped " + std::to_string(repeated.size()) +
                               " repeated faces (the same three vertices as an earlier face; faces " +
                               detail::faceList(repeated) + " of the file)");
    }
  }
  if (const int unused = dropUnusedVertices(mesh); unused > 0) {
    report.repairs.push_back("dropped " + std::to_string(unused) + " vertices no face uses");
  }
  if (mesh.faces.empty()) {
    report.remaining.push_back("no face is left: the mesh has no surface");
    return report;
  }
  int conflicts = 0;
  const std::vector<int> turned = orientFaces(mesh, conflicts);
  if (!turned.empty()) {
    report.repairs.push_back("turned " + std::to_string(turned.size()) +
                             " faces to agree with their neighbours and face outward (faces " +
                             detail::faceList(turned) + " after the repairs above)");
  }
  // What is left.
  MeshValidationSettings check;
  check.degenerateTolerance = settings.degenerateTolerance;
  check.maxReportedPerKind = 1;
  const MeshCheck left = findMeshDefects<3>(mesh, check);
  bool orientationReported = false;
  for (const MeshDefect& d : left.defects) {
    if (d.kind == MeshDefectKind::OpenBoundary) {
      report.remaining.push_back("holes (" + d.message +
                                 "): inside and outside are decided by the winding number, "
                                 "approximate within about a hole's size of the hole");
    }
    if (d.kind == MeshDefectKind::NonManifold) {
      report.remaining.push_back("non-manifold edges (" + d.message +
                                 "): inside and outside are decided by the winding number");
    }
    if (d.kind == MeshDefectKind::InconsistentOrientation && !orientationReported) {
      report.remaining.push_back("faces that no orientation makes consistent (" + d.message +
                                 "): the winding number near them is between 0 and 1");
      orientationReported = true;
    }
  }
  if (conflicts > 0 && !orientationReported) {
    report.remaining.push_back(std::to_string(conflicts) +
                               " edges that no orientation makes consistent: the winding number "
                               "near them is between 0 and 1");
  }
  const std::vector<std::string> crossings = findSelfIntersections(mesh, 1);
  if (!crossings.empty()) {
    report.remaining.push_back("the surface intersects itself (" + crossings[0] +
                               "): a point inside two parts counts once (winding number >= 1/2)");
  }
  if (report.watertight() && !(signedMeasure<3>(mesh) > 0.0)) {
    report.remaining.push_back("the enclosed volume is not positive");
  }
  return report;
}
// [repair_mesh]

}  // namespace stackbook
