#pragma once
/// \file
/// \brief Triangle meshes from Wavefront OBJ files (\ref ch06), read with tinyobjloader in
/// double precision, then checked strictly: a malformed line, a missing file, an index out
/// of range or a mesh that does not bound a solid is an error whose message names the file
/// and the defect (with the line, face or edge where it is).
///
/// The pipeline: read the text; check every `v` and `f` line (tinyobjloader itself reads
/// "v 1 abc 0" as (1, 0, 0) and "v nan 0 0" as the origin without a word) and write them
/// out again, one space between words and nothing else on the line; parse that text with
/// tinyobjloader, which triangulates polygons; merge duplicate vertices; drop vertices no
/// face uses; validateMesh.

#include <string>

#include "stackbook/geometry/mesh_validation.hpp"

namespace stackbook {

// [obj_load_settings]
/// The knobs of the OBJ loader.
struct ObjLoadSettings {
  /// Merge vertices closer than mergeTolerance x (bounding-box diagonal): files written
  /// face by face (STL converters, some exporters) repeat every shared corner, which would
  /// leave the mesh open. 0 merges exact duplicates only; < 0 disables merging.
  double mergeTolerance = 0.0;
  /// Drop vertices that no face uses (free points in the file would become surface
  /// samples off the surface).
  bool dropUnusedVertices = true;
  /// Run validateMesh on the result (closed, oriented, outward, no degenerate faces).
  bool validate = true;
  /// Settings of that validation.
  MeshValidationSettings validation;
  /// With validate: also reject a surface that passes through itself (two overlapping
  /// parts), by findSelfIntersections().
  bool rejectSelfIntersections = true;
};
// [obj_load_settings]

/// Loads the triangle mesh in the OBJ file at `path` (all objects and groups of the file
/// as one mesh). Throws MeshError (a std::invalid_argument) whose message starts with the
/// path: "cannot open the file", "line 7: malformed vertex ...", or the validation defects.
TriangleMesh loadObjMesh(const std::string& path, const ObjLoadSettings& settings = {});

/// The same for OBJ text in memory; `sourceName` stands for the file name in messages.
TriangleMesh parseObjMesh(const std::string& text, const std::string& sourceName,
                          const ObjLoadSettings& settings = {});

/// The mesh as OBJ text: `v x y z` lines with 17 significant digits (a double survives
/// the round trip exactly) and 1-based `f a b c` lines. `comment` becomes a `#` line.
std::string formatObj(const TriangleMesh& mesh, const std::string& comment = "");

/// Writes formatObj(mesh) to `path`; throws std::runtime_error if the file cannot be written.
void saveObjMesh(const TriangleMesh& mesh, const std::string& path,
                 const std::string& comment = "");

/// Merges vertices within `tolerance` (absolute) of each other, keeping the first of each
/// cluster in sort order, and renumbers the faces. Returns the number of vertices removed.
/// Deterministic: vertices are swept in lexicographic order of their coordinates.
int mergeDuplicateVertices(TriangleMesh& mesh, double tolerance);

/// Removes vertices that no face refers to and renumbers the faces. Returns how many.
int dropUnusedVertices(TriangleMesh& mesh);

}  // namespace stackbook
