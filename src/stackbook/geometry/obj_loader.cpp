// Wavefront OBJ loading for chapter 6 (obj_loader.hpp): strict line checks, tinyobjloader
// (double precision) for parsing and triangulation, vertex merging, validation.
#include "stackbook/geometry/obj_loader.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace stackbook {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw MeshError(source + ": " + what, {});
}

std::vector<std::string> splitWhitespace(const std::string& line) {
  std::vector<std::string> tokens;
  std::istringstream in(line);
  std::string token;
  while (in >> token) tokens.push_back(token);
  return tokens;
}

/// Parses the whole token as a double (strtod must consume every byte of it).
bool parseNumber(const std::string& token, double& value) {
  errno = 0;
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end != token.c_str() && end == token.c_str() + token.size() && errno != ERANGE;
}

/// Parses the whole token as a (possibly negative) integer.
bool parseInteger(const std::string& token, long& value) {
  errno = 0;
  char* end = nullptr;
  value = std::strtol(token.c_str(), &end, 10);
  return end != token.c_str() && end == token.c_str() + token.size() && errno != ERANGE;
}

/// A line as a message quotes it: at most 60 bytes, so one long line cannot make the
/// message long.
std::string quoteLine(const std::string& line) {
  constexpr std::size_t kShown = 60;
  return "'" + (line.size() <= kShown ? line : line.substr(0, kShown) + "...") + "'";
}

// [obj_line_checks]
/// The most vertices one face may have: tinyobjloader triangulates a polygon by ear
/// clipping, whose cost grows with the square of its vertices per ear, so a face of a
/// million vertices would run for hours. Modelling tools write polygons of a few hundred
/// vertices at most (the cap of a finely divided cylinder).
constexpr std::size_t kMaxFaceVertices = 1000;

/// What checkObjLines accepted: the vertex positions, and the text tinyobjloader reads.
struct CheckedObj {
  std::vector<Vec3> positions;
  std::string text;
};

/// The checks tinyobjloader does not make: every `v` line has 3 finite numbers (4 with a
/// weight, 6 or 7 with a colour), every `f` line 3 to kMaxFaceVertices vertex references
/// whose vertex index is a nonzero integer naming an existing vertex (negative: relative to
/// the vertices defined so far). Other lines (vt, vn, o, g, s, usemtl, mtllib, l, p, t)
/// do not affect the solid. Lines end at LF, CR LF or a lone CR (as tinyobjloader splits
/// them); a `#` starts a comment anywhere on a line; a NUL byte is an error (the
/// file is not text). The positions are parsed with strtod, which rounds correctly:
/// tinyobjloader's own number parser is off by a few units in the last place for most
/// 17-digit numbers, and a mesh saved and loaded again must not move.
///
/// tinyobjloader then reads not the file but the returned text: the `v` and `f` lines as
/// checked here, one space between their words, and an empty line in place of every other
/// line. So the two readers cannot split a line differently (a `#` after a face, a byte
/// one takes for a space and the other does not), and the lines the solid does not use
/// (a `t` line makes tinyobjloader allocate 8192 values per line) cost nothing.
CheckedObj checkObjLines(const std::string& text, const std::string& source) {
  std::vector<std::string> lines;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find_first_of("\r\n", start);
    const std::size_t stop = end == std::string::npos ? text.size() : end;
    lines.push_back(text.substr(start, stop - start));
    if (end == std::string::npos) break;
    start = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
  }
  for (std::size_t number = 1; number <= lines.size(); ++number) {
    if (lines[number - 1].find('\0') != std::string::npos) {
      std::ostringstream msg;
      msg << "line " << number << ": a NUL byte: an OBJ file is text, and this one is binary or damaged";
      fail(source, msg.str());
    }
    const std::size_t hash = lines[number - 1].find('#');
    if (hash != std::string::npos) lines[number - 1].erase(hash);
  }
  long totalVertices = 0;
  for (const std::string& line : lines) {
    const std::vector<std::string> tokens = splitWhitespace(line);
    if (!tokens.empty() && tokens[0] == "v") ++totalVertices;
  }
  long verticesSoFar = 0;
  CheckedObj checked;
  for (std::size_t number = 1; number <= lines.size(); ++number) {
    const std::vector<std::string> tokens = splitWhitespace(lines[number - 1]);
    std::string& forTinyobj = lines[number - 1];  // becomes the line tinyobjloader reads
    if (tokens.empty() || (tokens[0] != "v" && tokens[0] != "f")) {
      forTinyobj.clear();
      continue;
    }
    std::ostringstream where;
    where << "line " << number << " (" << quoteLine(lines[number - 1]) << ")";
    if (tokens[0] == "v") {
      const std::size_t count = tokens.size() - 1;
      if (count != 3 && count != 4 && count != 6 && count != 7) {
        std::ostringstream msg;
        msg << where.str() << ": malformed vertex: " << count
            << " numbers, expected x y z (optionally w, or r g b)";
        fail(source, msg.str());
      }
      Vec3 position;
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        double value = 0.0;
        if (!parseNumber(tokens[k], value)) {
          std::ostringstream msg;
          msg << where.str() << ": malformed vertex: coordinate " << k << " (" << quoteLine(tokens[k]) << ") ";
          // A number out of the range of a double says so, too large or too small.
          errno = 0;
          char* end = nullptr;
          const double x = std::strtod(tokens[k].c_str(), &end);
          if (end != tokens[k].c_str() && end == tokens[k].c_str() + tokens[k].size() && errno == ERANGE) {
            msg << (std::abs(x) > 1.0 ? "is beyond the range of a double (about 1.8e308)"
                                      : "is too small for a normal double (below about 2.2e-308); write 0");
          } else {
            msg << "is not a number";
          }
          fail(source, msg.str());
        }
        if (!std::isfinite(value)) {
          std::ostringstream msg;
          msg << where.str() << ": non-finite vertex coordinate " << k << " (" << quoteLine(tokens[k]) << ")";
          fail(source, msg.str());
        }
        if (k <= 3) position[static_cast<Eigen::Index>(k - 1)] = value;
      }
      checked.positions.push_back(position);
      ++verticesSoFar;
      std::ostringstream vertex;  // the correctly rounded numbers, so both readers see one polygon
      vertex << std::setprecision(17) << "v " << position.x() << " " << position.y() << " " << position.z();
      forTinyobj = vertex.str();
    } else {
      if (tokens.size() < 4) {
        std::ostringstream msg;
        msg << where.str() << ": malformed face: " << tokens.size() - 1
            << " vertices, a face needs at least 3";
        fail(source, msg.str());
      }
      if (tokens.size() - 1 > kMaxFaceVertices) {
        std::ostringstream msg;
        msg << where.str() << ": a face of " << tokens.size() - 1 << " vertices; at most " << kMaxFaceVertices
            << " (triangulating a polygon costs the square of its vertices; split it into smaller faces)";
        fail(source, msg.str());
      }
      forTinyobj = "f";
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string vertexPart = tokens[k].substr(0, tokens[k].find('/'));
        long index = 0;
        if (!parseInteger(vertexPart, index) || index == 0) {
          std::ostringstream msg;
          msg << where.str() << ": malformed face: " << quoteLine(tokens[k])
              << " is not a vertex reference (a nonzero integer, 1-based)";
          fail(source, msg.str());
        }
        const bool inRange = index > 0 ? index <= totalVertices : -index <= verticesSoFar;
        if (!inRange) {
          std::ostringstream msg;
          msg << where.str() << ": face refers to vertex " << index << ", but the file has "
              << totalVertices << " vertices";
          if (index < 0) msg << " (" << verticesSoFar << " defined before this line)";
          fail(source, msg.str());
        }
        forTinyobj += " " + std::to_string(index);  // the vertex only: texture and normal indices are not used
      }
    }
  }
  std::size_t size = 0;
  for (const std::string& line : lines) size += line.size() + 1;
  checked.text.reserve(size);
  for (const std::string& line : lines) checked.text += line + "\n";
  return checked;
}
// [obj_line_checks]

}  // namespace

int mergeDuplicateVertices(TriangleMesh& mesh, double tolerance) {
  const std::size_t n = mesh.vertices.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Vec3& p = mesh.vertices[a];
    const Vec3& q = mesh.vertices[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  });
  // Sweep in x order; a vertex joins the first earlier representative within tolerance.
  std::vector<std::size_t> representative(n);
  std::iota(representative.begin(), representative.end(), std::size_t{0});
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t i = order[s];
    for (std::size_t back = s; back-- > 0;) {
      const std::size_t j = order[back];
      if (mesh.vertices[i].x() - mesh.vertices[j].x() > tolerance) break;
      if (representative[j] == j && (mesh.vertices[i] - mesh.vertices[j]).norm() <= tolerance) {
        representative[i] = j;
        break;
      }
    }
  }
  std::vector<int> newIndex(n, -1);
  std::vector<Vec3> kept;
  for (std::size_t i = 0; i < n; ++i) {
    if (representative[i] != i) continue;
    newIndex[i] = static_cast<int>(kept.size());
    kept.push_back(mesh.vertices[i]);
  }
  for (std::array<int, 3>& face : mesh.faces) {
    for (int& v : face) v = newIndex[representative[static_cast<std::size_t>(v)]];
  }
  const int removed = static_cast<int>(n - kept.size());
  mesh.vertices = std::move(kept);
  return removed;
}

int dropUnusedVertices(TriangleMesh& mesh) {
  std::vector<int> newIndex(mesh.vertices.size(), -1);
  for (const std::array<int, 3>& face : mesh.faces) {
    for (const int v : face) newIndex[static_cast<std::size_t>(v)] = 0;
  }
  std::vector<Vec3> kept;
  for (std::size_t i = 0; i < newIndex.size(); ++i) {
    if (newIndex[i] < 0) continue;
    newIndex[i] = static_cast<int>(kept.size());
    kept.push_back(mesh.vertices[i]);
  }
  for (std::array<int, 3>& face : mesh.faces) {
    for (int& v : face) v = newIndex[static_cast<std::size_t>(v)];
  }
  const int removed = static_cast<int>(mesh.vertices.size() - kept.size());
  mesh.vertices = std::move(kept);
  return removed;
}

// [parse_obj_mesh]
TriangleMesh parseObjMesh(const std::string& text, const std::string& sourceName,
                          const ObjLoadSettings& settings) {
  const CheckedObj checked = checkObjLines(text, sourceName);
  const std::vector<Vec3>& positions = checked.positions;
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;     // polygons become triangle fans
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(checked.text, "", config)) {
    std::string error = reader.Error();
    while (!error.empty() && (error.back() == '\n' || error.back() == '\r')) error.pop_back();
    fail(sourceName, "parse error: " + error);
  }
  // Warnings (an unknown material, a texture index out of range) concern attributes the
  // solid does not use; what matters for it was checked by checkObjLines.
  // The positions are the correctly rounded ones of checkObjLines, in the same file order.
  if (reader.GetAttrib().vertices.size() != 3 * positions.size()) {
    fail(sourceName, "tinyobjloader read a different number of vertices than the file has");
  }
  TriangleMesh mesh;
  mesh.vertices = positions;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t offset = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t count = shape.mesh.num_face_vertices[f];
      if (count != 3) {
        std::ostringstream msg;
        msg << "object '" << shape.name << "' face " << f << " has " << count
            << " vertices after triangulation";
        fail(sourceName, msg.str());
      }
      std::array<int, 3> face{};
      for (std::size_t k = 0; k < 3; ++k) {
        // tinyobjloader read the face lines checkObjLines wrote; should the two ever
        // disagree, an index outside the vertices still must not reach the mesh.
        const int index = shape.mesh.indices[offset + k].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= positions.size()) {
          std::ostringstream msg;
          msg << "object '" << shape.name << "' face " << f << " refers to vertex " << index + 1
              << " of " << positions.size() << " (a face line this reader could not check)";
          fail(sourceName, msg.str());
        }
        face[k] = index;
      }
      mesh.faces.push_back(face);
      offset += count;
    }
  }
  if (mesh.faces.empty()) fail(sourceName, "the file contains no faces");
  if (settings.mergeTolerance >= 0.0) {
    const double diagonal = mesh.bounds().extent().norm();
    mergeDuplicateVertices(mesh, settings.mergeTolerance * diagonal);
  }
  if (settings.dropUnusedVertices) dropUnusedVertices(mesh);
  if (settings.validate) validateMesh<3>(mesh, sourceName, settings.validation);
  if (settings.validate && settings.rejectSelfIntersections) {
    rejectSelfIntersections(mesh, sourceName, static_cast<std::size_t>(std::max(1, settings.validation.maxReportedPerKind)));
  }
  return mesh;
}
// [parse_obj_mesh]

TriangleMesh loadObjMesh(const std::string& path, const ObjLoadSettings& settings) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) fail(path, "cannot open the file: it does not exist");
  if (!std::filesystem::is_regular_file(path, error)) fail(path, "cannot open the file: not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the file: permission denied or I/O error");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) fail(path, "cannot read the file");
  return parseObjMesh(text.str(), path, settings);
}

std::string formatObj(const TriangleMesh& mesh, const std::string& comment) {
  std::ostringstream out;
  out << std::setprecision(17);
  if (!comment.empty()) out << "# " << comment << "\n";
  for (const Vec3& v : mesh.vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const std::array<int, 3>& f : mesh.faces) {
    out << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
  }
  return out.str();
}

void saveObjMesh(const TriangleMesh& mesh, const std::string& path, const std::string& comment) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot open the file for writing");
  out << formatObj(mesh, comment);
  if (!out) throw std::runtime_error(path + ": writing failed");
}

}  // namespace stackbook
