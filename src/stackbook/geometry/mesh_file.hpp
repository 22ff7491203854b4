#pragma once
/// \file
/// \brief Triangle meshes from the files people download (\ref ch06): Wavefront OBJ
/// (obj_loader.hpp), STL (ASCII and binary) and PLY, the last two read with assimp. Every
/// format gets the same checks as OBJ: a message that starts with the file and names the
/// line (ASCII STL) or element (binary STL triangle, PLY vertex or face) that is wrong,
/// then, in strict use, the mesh checks of validateMesh and findSelfIntersections().

#include <string>
#include <vector>

#include "stackbook/geometry/obj_loader.hpp"

namespace stackbook {

/// The mesh formats loadMeshFile() reads, by file extension (lower case, with the dot).
const std::vector<std::string>& meshFileExtensions();

/// Loads the triangle mesh in `path`, in the format its extension names (.obj, .stl,
/// .ply, case ignored), with the same settings as loadObjMesh(): vertices within
/// settings.mergeTolerance merged (STL repeats every corner of every triangle), unused
/// vertices dropped, the result validated when settings.validate. Throws MeshError whose
/// message starts with the path.
TriangleMesh loadMeshFile(const std::string& path, const ObjLoadSettings& settings = {});

/// The same for STL or PLY bytes in memory; `sourceName` names them in messages and its
/// extension chooses the format.
TriangleMesh parseAssimpMesh(const std::string& bytes, const std::string& sourceName,
                             const ObjLoadSettings& settings = {});

}  // namespace stackbook
