#pragma once
/// \file
/// \brief Checks that a `SurfaceMesh<D>` bounds a solid the way the signed-distance grid and
/// the mass properties need (\ref ch06): indices in range, finite coordinates, no
/// degenerate faces, closed, consistently oriented, outward. Every defect is reported with
/// the mesh's source (a file or shape name), what is wrong and where (face, vertices).
///
/// What "closed and consistently oriented" means, per dimension:
/// - 3D: every undirected edge {a, b} is used by exactly two triangles, once as (a, b) and
///   once as (b, a). One use is a hole's rim; more than two is a non-manifold edge; two uses
///   in the same direction mean one of the two triangles is flipped.
/// - 2D: every vertex starts exactly one segment and ends exactly one. One use is an open
///   end; more than two a non-manifold vertex; two starts (or two ends) a flipped segment.
/// Self-intersections of a triangle mesh are found separately, by findSelfIntersections().

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stackbook/geometry/surface_mesh.hpp"

namespace stackbook {

/// The kinds of defect validateMesh reports.
enum class MeshDefectKind {
  Empty,                    ///< no faces
  IndexOutOfRange,          ///< a face refers to a vertex that does not exist
  NonFiniteVertex,          ///< a coordinate is NaN or infinite
  DegenerateFace,           ///< zero length (2D) or area (3D), or a repeated index
  OpenBoundary,             ///< an edge (3D) or vertex (2D) used once: a hole
  NonManifold,              ///< an edge (3D) or vertex (2D) used more than twice
  InconsistentOrientation,  ///< neighbours traverse a shared edge or vertex the same way
  InwardOrientation,        ///< consistently oriented, but the enclosed volume is negative
  UnusedVertex,             ///< a vertex no face refers to (it would be a stray sample)
  SelfIntersection,         ///< the surface passes through itself (findSelfIntersections())
};

/// A short name for a defect kind ("hole", "flipped face", ...).
inline const char* meshDefectName(MeshDefectKind kind) {
  switch (kind) {
    case MeshDefectKind::Empty: return "empty mesh";
    case MeshDefectKind::IndexOutOfRange: return "vertex index out of range";
    case MeshDefectKind::NonFiniteVertex: return "non-finite vertex";
    case MeshDefectKind::DegenerateFace: return "degenerate face";
    case MeshDefectKind::OpenBoundary: return "hole (open boundary)";
    case MeshDefectKind::NonManifold: return "non-manifold";
    case MeshDefectKind::InconsistentOrientation: return "inconsistent orientation (flipped face)";
    case MeshDefectKind::InwardOrientation: return "inward orientation";
    case MeshDefectKind::UnusedVertex: return "unused vertex";
    case MeshDefectKind::SelfIntersection: return "self-intersection";
  }
  return "unknown defect";
}

/// How many defects of a kind there are, in words: "1 degenerate face", "129 degenerate
/// faces", "12 hole edges". The unit follows the dimension: an open or non-manifold edge in
/// 3D, an open end or non-manifold vertex in 2D.
inline std::string meshDefectCount(MeshDefectKind kind, int count, int dimension) {
  const bool one = count == 1;
  const bool solid = dimension == 3;
  std::string what;
  switch (kind) {
    case MeshDefectKind::Empty: return "no faces";
    case MeshDefectKind::IndexOutOfRange: what = one ? "vertex index out of range" : "vertex indices out of range"; break;
    case MeshDefectKind::NonFiniteVertex: what = one ? "non-finite vertex" : "non-finite vertices"; break;
    case MeshDefectKind::DegenerateFace: what = one ? "degenerate face" : "degenerate faces"; break;
    case MeshDefectKind::OpenBoundary:
      what = solid ? (one ? "hole edge" : "hole edges") : (one ? "open end" : "open ends");
      break;
    case MeshDefectKind::NonManifold:
      what = solid ? (one ? "non-manifold edge" : "non-manifold edges")
                   : (one ? "non-manifold vertex" : "non-manifold vertices");
      break;
    case MeshDefectKind::InconsistentOrientation: what = one ? "flipped face" : "flipped faces"; break;
    case MeshDefectKind::InwardOrientation: return "faces oriented inward (reverse them all)";
    case MeshDefectKind::UnusedVertex: what = one ? "unused vertex" : "unused vertices"; break;
    case MeshDefectKind::SelfIntersection: what = one ? "self-intersection" : "self-intersections"; break;
  }
  return std::to_string(count) + " " + what;
}

/// One defect: its kind, where it is, and a sentence that says so.
struct MeshDefect {
  MeshDefectKind kind = MeshDefectKind::Empty;
  int face = -1;              ///< the face concerned, or -1
  std::vector<int> vertices;  ///< the vertices concerned (an edge's two ends, ...)
  std::string message;        ///< "face 7 (vertices 3, 4, 9) has zero area"
};

/// Where a defect is, in a few words: "face 924", "edge 3-17", "vertex 5" (the message
/// itself for the kinds that have no single place).
inline std::string meshDefectPlace(const MeshDefect& d, int dimension) {
  switch (d.kind) {
    case MeshDefectKind::IndexOutOfRange:
      return "face " + std::to_string(d.face) +
             (d.vertices.empty() ? std::string() : " refers to vertex " + std::to_string(d.vertices[0]));
    case MeshDefectKind::DegenerateFace:
    case MeshDefectKind::InconsistentOrientation: return "face " + std::to_string(d.face);
    case MeshDefectKind::OpenBoundary:
    case MeshDefectKind::NonManifold:
      if (dimension == 3 && d.vertices.size() == 2) {
        return "edge " + std::to_string(d.vertices[0]) + "-" + std::to_string(d.vertices[1]);
      }
      return d.vertices.empty() ? d.message : "vertex " + std::to_string(d.vertices[0]);
    case MeshDefectKind::NonFiniteVertex:
    case MeshDefectKind::UnusedVertex:
      return d.vertices.empty() ? d.message : "vertex " + std::to_string(d.vertices[0]);
    default: return d.message;
  }
}

/// The defects findMeshDefects found: at most settings.maxReportedPerKind of each kind are
/// listed; `omitted` counts the others; `counts` has how many of each kind there are (listed
/// or not), in the order of MeshDefectKind.
struct MeshCheck {
  std::vector<MeshDefect> defects;
  int omitted = 0;
  std::vector<std::pair<MeshDefectKind, int>> counts;
  bool ok() const { return defects.empty(); }
  bool has(MeshDefectKind kind) const {
    return std::any_of(defects.begin(), defects.end(),
                       [kind](const MeshDefect& d) { return d.kind == kind; });
  }
};

/// Knobs of findMeshDefects.
struct MeshValidationSettings {
  /// A face counts as degenerate when its length (2D) or area (3D) is at most
  /// degenerateTolerance x (bounding-box diagonal)^(D-1).
  double degenerateTolerance = 1e-12;
  /// Report vertices no face uses (they would become surface samples off the surface).
  bool rejectUnusedVertices = true;
  /// Report at most this many defects of each kind (the rest are counted).
  int maxReportedPerKind = 5;
};

/// The thrown error: a std::invalid_argument whose what() is one line, the summary and a
/// hint of what to do, and which keeps the listed defects for programs that want to react to
/// a particular kind or show them all. A file that cannot be read at all (a malformed line,
/// a truncated STL) has no defects and no hint: repairing would not help.
class MeshError : public std::invalid_argument {
 public:
  MeshError(const std::string& message, std::vector<MeshDefect> defects, const std::string& hint = {})
      : std::invalid_argument(hint.empty() ? message : message + "; " + hint),
        summary_(message),
        defects_(std::move(defects)) {}
  /// what() without the hint: "crate.obj: invalid triangle mesh (...), 3 defects: ...".
  const std::string& summary() const { return summary_; }
  /// Whether the mesh was read and failed its checks (so repairing it may help).
  bool repairable() const { return !defects_.empty(); }
  const std::vector<MeshDefect>& defects() const { return defects_; }
  bool has(MeshDefectKind kind) const {
    return std::any_of(defects_.begin(), defects_.end(),
                       [kind](const MeshDefect& d) { return d.kind == kind; });
  }

 private:
  std::string summary_;
  std::vector<MeshDefect> defects_;
};

/// What the library's mesh errors suggest (a scene file suggests its own field instead).
inline constexpr const char* kMeshRepairHint = "repairMesh() repairs it (chapter 6)";

/// Signed volume (3D) or area (2D) enclosed by the faces, by the divergence theorem:
/// sum over faces of a.(b x c)/6, or of (a x b)/2. Positive for an outward-oriented mesh.
template <int D>
double signedMeasure(const SurfaceMesh<D>& mesh) {
  // Relative to the box centre, so that far-off meshes do not lose digits.
  const Vec<D> origin = mesh.bounds().center();
  double sum = 0.0;
  for (const std::array<int, D>& face : mesh.faces) {
    const Vec<D> a = mesh.vertices[face[0]] - origin;
    const Vec<D> b = mesh.vertices[face[1]] - origin;
    if constexpr (D == 3) {
      const Vec3 c = mesh.vertices[face[2]] - origin;
      sum += a.dot(b.cross(c)) / 6.0;
    } else {
      sum += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
  }
  return sum;
}

namespace detail {

template <int D>
std::string listVertices(const std::array<int, D>& face) {
  std::ostringstream out;
  for (int k = 0; k < D; ++k) out << (k ? ", " : "") << face[k];
  return out.str();
}

/// Collects defects, at most `limit` of each kind, counting the ones left out.
class DefectLog {
 public:
  explicit DefectLog(int limit) : limit_(limit) {}
  void add(MeshDefectKind kind, int face, std::vector<int> vertices, const std::string& message) {
    int& n = counts_[kind];
    ++n;
    if (n <= limit_) defects_.push_back({kind, face, std::move(vertices), message});
  }
  bool any(MeshDefectKind kind) const { return counts_.count(kind) > 0; }
  bool empty() const { return counts_.empty(); }
  MeshCheck take() {
    MeshCheck check;
    check.defects = std::move(defects_);
    for (const auto& [kind, n] : counts_) {
      check.omitted += std::max(0, n - limit_);
      check.counts.emplace_back(kind, n);
    }
    return check;
  }

 private:
  int limit_;
  std::map<MeshDefectKind, int> counts_;
  std::vector<MeshDefect> defects_;
};

}  // namespace detail

// [find_mesh_defects]
/// The defects of the mesh (at most settings.maxReportedPerKind of each kind), in the
/// order: structure (empty, indices, finite coordinates), faces (degenerate), topology
/// (holes, non-manifold elements, flipped faces), orientation (inward), unused vertices.
/// Topology is checked only when the structure is sound, and orientation only when the
/// topology is.
template <int D>
MeshCheck findMeshDefects(const SurfaceMesh<D>& mesh, const MeshValidationSettings& settings = {}) {
  detail::DefectLog log(settings.maxReportedPerKind);
  const int n = static_cast<int>(mesh.vertices.size());
  if (mesh.faces.empty()) {
    log.add(MeshDefectKind::Empty, -1, {}, "the mesh has no faces");
    return log.take();
  }
  // Structure: indices in range, finite coordinates.
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (int k = 0; k < D; ++k) {
      const int i = mesh.faces[f][k];
      if (i < 0 || i >= n) {
        std::ostringstream msg;
        msg << "face " << f << " (vertices " << detail::listVertices<D>(mesh.faces[f])
            << ") refers to vertex " << i << ", but the mesh has " << n << " vertices (0 to "
            << n - 1 << ")";
        log.add(MeshDefectKind::IndexOutOfRange, static_cast<int>(f), {i}, msg.str());
      }
    }
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!mesh.vertices[v].allFinite()) {
      std::ostringstream msg;
      msg << "vertex " << v << " has a non-finite coordinate (" << mesh.vertices[v].transpose()
          << ")";
      log.add(MeshDefectKind::NonFiniteVertex, -1, {static_cast<int>(v)}, msg.str());
    }
  }
  if (!log.empty()) return log.take();

  // Faces: zero length or area, or a repeated index.
  const double diagonal = mesh.bounds().extent().norm();
  const double minMeasure = settings.degenerateTolerance * std::pow(diagonal, D - 1);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::array<int, D>& face = mesh.faces[f];
    const Vec<D>& a = mesh.vertices[face[0]];
    const Vec<D>& b = mesh.vertices[face[1]];
    double measure = 0.0;
    bool repeated = face[0] == face[1];
    if constexpr (D == 3) {
      const Vec3& c = mesh.vertices[face[2]];
      measure = 0.5 * (b - a).cross(c - a).norm();
      repeated = repeated || face[1] == face[2] || face[2] == face[0];
    } else {
      measure = (b - a).norm();
    }
    if (repeated || !(measure > minMeasure)) {
      std::ostringstream msg;
      msg << "face " << f << " (vertices " << detail::listVertices<D>(face) << ") ";
      if (repeated) {
        msg << "repeats a vertex";
      } else {
        msg << "has zero " << (D == 3 ? "area" : "length") << " (" << measure << " <= "
            << minMeasure << ")";
      }
      log.add(MeshDefectKind::DegenerateFace, static_cast<int>(f),
              std::vector<int>(face.begin(), face.end()), msg.str());
    }
  }

  // Topology. The unit of adjacency is an edge (3D) or a vertex (2D); for each we count
  // the faces that traverse it forwards (a -> b, or "start here") and backwards.
  struct Uses {
    std::vector<int> forward, backward;
  };
  std::map<std::pair<int, int>, Uses> elements;  // ordered: deterministic reports
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::array<int, D>& face = mesh.faces[f];
    const int fi = static_cast<int>(f);
    if constexpr (D == 3) {
      for (std::size_t k = 0; k < 3; ++k) {
        const int a = face[k], b = face[(k + 1) % 3];
        if (a == b) continue;
        if (a < b) {
          elements[{a, b}].forward.push_back(fi);
        } else {
          elements[{b, a}].backward.push_back(fi);
        }
      }
    } else {
      if (face[0] == face[1]) continue;
      elements[{face[0], face[0]}].forward.push_back(fi);   // starts at face[0]
      elements[{face[1], face[1]}].backward.push_back(fi);  // ends at face[1]
    }
  }
  std::vector<int> disagreements(mesh.faces.size(), 0);  // per face: flipped neighbours
  for (const auto& [key, uses] : elements) {
    const std::size_t total = uses.forward.size() + uses.backward.size();
    std::vector<int> faces = uses.forward;
    faces.insert(faces.end(), uses.backward.begin(), uses.backward.end());
    std::sort(faces.begin(), faces.end());
    std::ostringstream where;
    if constexpr (D == 3) {
      where << "edge " << key.first << "-" << key.second;
    } else {
      where << "vertex " << key.first;
    }
    std::ostringstream faceList;
    for (std::size_t i = 0; i < faces.size(); ++i) faceList << (i ? ", " : "") << faces[i];
    const std::vector<int> keyVertices =
        D == 3 ? std::vector<int>{key.first, key.second} : std::vector<int>{key.first};
    if (total == 1) {
      std::ostringstream msg;
      msg << where.str() << " belongs to face " << faces[0] << " only: the mesh has a hole there";
      log.add(MeshDefectKind::OpenBoundary, faces[0], keyVertices, msg.str());
    } else if (total > 2) {
      std::ostringstream msg;
      msg << where.str() << " is shared by " << total << " faces (" << faceList.str()
          << "): non-manifold";
      log.add(MeshDefectKind::NonManifold, faces[0], keyVertices, msg.str());
    } else if (uses.forward.size() != 1) {
      for (const int f : faces) ++disagreements[f];
    }
  }
  // A flipped face disagrees with (nearly) all of its neighbours; each neighbour disagrees
  // across one edge only. Report the faces that disagree most.
  const int worst = *std::max_element(disagreements.begin(), disagreements.end());
  if (worst > 0) {
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      if (disagreements[f] != worst) continue;
      std::ostringstream msg;
      msg << "face " << f << " (vertices " << detail::listVertices<D>(mesh.faces[f])
          << ") is flipped: it traverses " << worst << " of its " << (D == 3 ? "edges" : "ends")
          << " in the same direction as its neighbour";
      log.add(MeshDefectKind::InconsistentOrientation, static_cast<int>(f),
              std::vector<int>(mesh.faces[f].begin(), mesh.faces[f].end()), msg.str());
    }
  }

  // Orientation: only meaningful on a closed, consistently oriented mesh.
  const bool topologySound = !log.any(MeshDefectKind::OpenBoundary) &&
                             !log.any(MeshDefectKind::NonManifold) &&
                             !log.any(MeshDefectKind::InconsistentOrientation);
  if (topologySound) {
    const double measure = signedMeasure<D>(mesh);
    if (!(measure > 0.0)) {
      std::ostringstream msg;
      msg << "the enclosed " << (D == 3 ? "volume" : "area") << " is " << measure
          << " (not positive): every face is oriented inward; reverse them";
      log.add(MeshDefectKind::InwardOrientation, -1, {}, msg.str());
    }
  }

  if (settings.rejectUnusedVertices) {
    std::vector<char> used(mesh.vertices.size(), 0);
    for (const std::array<int, D>& face : mesh.faces) {
      for (const int i : face) used[i] = 1;
    }
    for (std::size_t v = 0; v < used.size(); ++v) {
      if (used[v]) continue;
      std::ostringstream msg;
      msg << "vertex " << v << " (" << mesh.vertices[v].transpose()
          << ") is used by no face: it would be a surface sample off the surface";
      log.add(MeshDefectKind::UnusedVertex, -1, {static_cast<int>(v)}, msg.str());
    }
  }
  return log.take();
}
// [find_mesh_defects]

// [self_intersections]
/// Where a triangle mesh crosses itself: an edge of one triangle that passes through
/// another triangle with which it shares no vertex (both ends strictly on opposite sides
/// of the triangle's plane, and the line through the edge inside or on the triangle's
/// three edges, all decided by signs of 4x4 determinants, Eq. (6.21)). Two
/// overlapping closed parts (two cubes that interpenetrate) always have such an edge.
/// Touching without crossing (coplanar faces, a vertex on a face) is not reported: a
/// determinant within `relativeTolerance` x diagonal^3 of zero counts as zero. Candidate
/// pairs come from sorting the faces' boxes along x; returns at most `limit` sentences
/// "edge 3-7 of face 2 passes through face 15", in face order.
/// `total`, when given, receives the number of crossings found (listed or not).
inline std::vector<std::string> findSelfIntersections(const TriangleMesh& mesh, std::size_t limit = 5,
                                                      double relativeTolerance = 1e-12,
                                                      std::size_t* total = nullptr) {
  std::vector<std::string> found;
  const std::size_t F = mesh.faces.size();
  if (total != nullptr) *total = 0;
  if (F < 2 || (limit == 0 && total == nullptr)) return found;
  const double diagonal = mesh.bounds().extent().norm();
  const double zero = relativeTolerance * diagonal * diagonal * diagonal;
  const auto orient = [](const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return (b - a).cross(c - a).dot(d - a);
  };
  const auto sign = [zero](double v) { return v > zero ? 1 : (v < -zero ? -1 : 0); };
  std::vector<Aabb<3>> boxes(F);
  std::vector<std::size_t> order(F);
  for (std::size_t f = 0; f < F; ++f) {
    for (const int v : mesh.faces[f]) boxes[f].extend(mesh.vertices[v]);
    order[f] = f;
  }
  std::sort(order.begin(), order.end(), [&boxes](std::size_t a, std::size_t b) {
    return boxes[a].lower.x() != boxes[b].lower.x() ? boxes[a].lower.x() < boxes[b].lower.x() : a < b;
  });
  // Does an edge (p, q) of face e cross the interior of triangle t?
  const auto crosses = [&](const std::array<int, 3>& t, int p, int q) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    const Vec3& P = mesh.vertices[p];
    const Vec3& Q = mesh.vertices[q];
    const int sp = sign(orient(a, b, c, P)), sq = sign(orient(a, b, c, Q));
    if (sp == 0 || sq == 0 || sp == sq) return false;
    // The line through P, Q meets the closed triangle: no two of the three signs differ
    // (a zero is an edge or a corner of the triangle hit, which crosses the surface too).
    const int s1 = sign(orient(P, Q, a, b)), s2 = sign(orient(P, Q, b, c)), s3 = sign(orient(P, Q, c, a));
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  };
  std::vector<std::pair<std::size_t, std::string>> hits;
  for (std::size_t i = 0; i < F; ++i) {
    const std::size_t f = order[i];
    for (std::size_t j = i + 1; j < F; ++j) {
      const std::size_t g = order[j];
      if (boxes[g].lower.x() > boxes[f].upper.x()) break;
      if (!boxes[f].overlaps(boxes[g])) continue;
      const auto& tf = mesh.faces[f];
      const auto& tg = mesh.faces[g];
      bool sharesVertex = false;
      for (const int u : tf) {
        for (const int v : tg) sharesVertex = sharesVertex || u == v;
      }
      if (sharesVertex) continue;
      for (int pass = 0; pass < 2; ++pass) {
        const auto& edgeFace = pass == 0 ? tf : tg;
        const auto& target = pass == 0 ? tg : tf;
        const std::size_t e = pass == 0 ? f : g;
        const std::size_t t = pass == 0 ? g : f;
        bool reported = false;
        for (int k = 0; k < 3 && !reported; ++k) {
          const int p = edgeFace[k], q = edgeFace[(k + 1) % 3];
          if (!crosses(target, p, q)) continue;
          std::ostringstream msg;
          msg << "edge " << std::min(p, q) << "-" << std::max(p, q) << " of face " << e
              << " passes through face " << t;
          hits.emplace_back(std::min(e, t), msg.str());
          reported = true;
        }
        if (reported) break;
      }
    }
  }
  std::stable_sort(hits.begin(), hits.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t k = 0; k < hits.size() && k < limit; ++k) found.push_back(hits[k].second);
  if (total != nullptr) *total = hits.size();
  return found;
}
// [self_intersections]

/// Throws MeshError when findSelfIntersections() finds anything, in one line: "SOURCE: the
/// surface intersects itself, so it does not bound one solid: 4 self-intersections (first:
/// edge 3-7 of face 2 passes through face 15)"; the error keeps the first `listed` crossings.
inline void rejectSelfIntersections(const TriangleMesh& mesh, const std::string& source, std::size_t listed = 5) {
  std::size_t total = 0;
  const std::vector<std::string> crossings = findSelfIntersections(mesh, std::max<std::size_t>(listed, 1), 1e-12, &total);
  if (crossings.empty()) return;
  std::ostringstream msg;
  msg << source << ": the surface intersects itself, so it does not bound one solid: "
      << meshDefectCount(MeshDefectKind::SelfIntersection, static_cast<int>(total), 3) << " (first: " << crossings[0]
      << ")";
  std::vector<MeshDefect> defects;
  for (const std::string& c : crossings) defects.push_back(MeshDefect{MeshDefectKind::SelfIntersection, -1, {}, c});
  throw MeshError(msg.str(), std::move(defects), "join the parts into one closed surface, or " + std::string(kMeshRepairHint));
}

// [mesh_error_line]
/// The one line of a refused mesh: the source, its size, the number of defects, then for
/// each kind its count and the first place, "crate.obj: invalid triangle mesh (8 vertices,
/// 11 faces), 4 defects: 3 hole edges (first: edge 0-4), 1 flipped face (face 6)".
template <int D>
std::string meshDefectSummary(const SurfaceMesh<D>& mesh, const MeshCheck& check, const std::string& source) {
  int count = 0;
  for (const auto& [kind, n] : check.counts) count += n;
  std::ostringstream msg;
  msg << source << ": invalid " << (D == 3 ? "triangle mesh" : "polygon") << " (" << mesh.vertices.size()
      << " vertices, " << mesh.faces.size() << " faces), " << count << (count == 1 ? " defect" : " defects") << ": ";
  bool firstKind = true;
  for (const auto& [kind, n] : check.counts) {
    msg << (firstKind ? "" : ", ") << meshDefectCount(kind, n, D);
    firstKind = false;
    const auto first = std::find_if(check.defects.begin(), check.defects.end(),
                                    [kind = kind](const MeshDefect& d) { return d.kind == kind; });
    if (first == check.defects.end() || kind == MeshDefectKind::Empty || kind == MeshDefectKind::InwardOrientation) {
      continue;
    }
    msg << " (" << (n == 1 ? "" : "first: ") << meshDefectPlace(*first, D) << ")";
  }
  return msg.str();
}
// [mesh_error_line]

/// Throws MeshError when findMeshDefects reports anything. what() is the line of
/// meshDefectSummary() and the hint kMeshRepairHint; defects() holds the listed defects (at
/// most settings.maxReportedPerKind of each kind), each with its full sentence.
template <int D>
void validateMesh(const SurfaceMesh<D>& mesh, const std::string& source,
                  const MeshValidationSettings& settings = {}) {
  MeshCheck check = findMeshDefects<D>(mesh, settings);
  if (check.ok()) return;
  // The line first: the defects move into the error, and argument order is unspecified.
  std::string line = meshDefectSummary<D>(mesh, check, source);
  throw MeshError(std::move(line), std::move(check.defects), kMeshRepairHint);
}

}  // namespace stackbook
