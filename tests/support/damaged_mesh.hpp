#pragma once
// A mesh damaged the way downloaded meshes are (chapter 6, "Meshes from files"; chapter 10's
// scene files): a closed box of many triangles with faces that repeat a vertex, triangles
// missing (holes) and one triangle turned over. How many defects of each kind it has follows
// from how it is built, not from the checker, so tests can hold the checker's counts to it.
// Also writers for the three file formats the loaders read (OBJ, ASCII STL, ASCII PLY).
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "stackbook/geometry/mesh_primitives.hpp"

namespace stackbook::test_support {

/// The damaged box and the defects it has by construction.
struct DamagedMesh {
  TriangleMesh mesh;
  int degenerateFaces = 0;  ///< faces (v, v, v): they repeat a vertex
  int holeEdges = 0;        ///< 3 per missing triangle (no two missing triangles share a vertex)
  int flippedFaces = 0;     ///< 1: a triangle whose three neighbours are all intact
  int flippedFace = -1;     ///< its index
  int firstDegenerateFace = -1;
  int defects() const { return degenerateFaces + holeEdges + flippedFaces; }
};

/// A unit box of 12 n^2 triangles; `missing` triangles, no two sharing a vertex, removed;
/// one more triangle, sharing no vertex with them, reversed; then `degenerate` faces (v, v, v)
/// appended. A missing triangle leaves its three edges used once each (three hole edges); the
/// reversed one traverses each of its three edges in the same direction as its neighbour.
inline DamagedMesh damagedBox(int n, int missing, int degenerate) {
  const TriangleMesh box = boxMesh(Vec3(1, 1, 1), n);
  DamagedMesh out;
  out.mesh.vertices = box.vertices;
  std::set<int> touched;  // vertices of removed (or reversed) triangles
  const auto disjoint = [&touched](const std::array<int, 3>& f) {
    return touched.count(f[0]) == 0 && touched.count(f[1]) == 0 && touched.count(f[2]) == 0;
  };
  int removed = 0;
  bool flipped = false;
  for (std::size_t f = 0; f < box.faces.size(); ++f) {
    std::array<int, 3> face = box.faces[f];
    // Every seventh triangle is a candidate, so the holes spread over the box.
    if (f % 7 == 0 && disjoint(face)) {
      if (removed < missing) {
        touched.insert(face.begin(), face.end());
        ++removed;
        continue;
      }
      if (!flipped) {
        touched.insert(face.begin(), face.end());
        std::swap(face[0], face[1]);
        flipped = true;
        out.flippedFace = static_cast<int>(out.mesh.faces.size());
      }
    }
    out.mesh.faces.push_back(face);
  }
  if (removed < missing || !flipped) throw std::logic_error("damagedBox: the box is too small for the damage");
  out.firstDegenerateFace = static_cast<int>(out.mesh.faces.size());
  for (int v = 0; v < degenerate; ++v) out.mesh.faces.push_back({v, v, v});
  out.degenerateFaces = degenerate;
  out.holeEdges = 3 * missing;
  out.flippedFaces = 1;
  return out;
}

/// Writes `mesh` as OBJ (".obj"), ASCII STL (".stl", every triangle's corners written out) or
/// ASCII PLY (".ply"), by the path's extension.
inline void writeMeshFile(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::ofstream out(path);
  out.precision(17);
  const std::string ext = path.extension().string();
  if (ext == ".obj") {
    for (const Vec3& v : mesh.vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
    for (const auto& f : mesh.faces) out << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
  } else if (ext == ".stl") {
    out << "solid damaged\n";
    for (const auto& f : mesh.faces) {
      out << "facet normal 0 0 0\nouter loop\n";
      for (const int i : f) {
        const Vec3& v = mesh.vertices[static_cast<std::size_t>(i)];
        out << "vertex " << v.x() << " " << v.y() << " " << v.z() << "\n";
      }
      out << "endloop\nendfacet\n";
    }
    out << "endsolid damaged\n";
  } else if (ext == ".ply") {
    out << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertices.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.faces.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Vec3& v : mesh.vertices) out << v.x() << " " << v.y() << " " << v.z() << "\n";
    for (const auto& f : mesh.faces) out << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  } else {
    throw std::logic_error("writeMeshFile: unknown extension " + ext);
  }
  if (!out) throw std::runtime_error("writeMeshFile: cannot write " + path.string());
}

}  // namespace stackbook::test_support
