// STL and PLY through assimp, with stackbook's checks (mesh_file.hpp).
#include "stackbook/geometry/mesh_file.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace stackbook {

namespace {

[[noreturn]] void failMeshFile(const std::string& source, const std::string& what) {
  throw MeshError(source + ": " + what, {});
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool isAsciiStl(const std::string& bytes) {
  // "solid" starts an ASCII file, but many binary exporters write it into the 80-byte
  // header too; a binary file is one whose size is exactly 84 + 50 n for its count n.
  if (bytes.compare(0, 5, "solid") != 0) return false;
  if (bytes.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * static_cast<std::uint64_t>(n)) return false;
  }
  return true;
}

// [stl_checks]
/// The checks assimp does not make on an STL file, with the line or triangle that fails:
/// ASCII: every `vertex` line has three finite numbers and every facet three vertices;
/// binary: the size is 84 + 50 n bytes for the n triangles the header announces, and
/// every coordinate is finite.
void checkStl(const std::string& bytes, const std::string& source) {
  if (isAsciiStl(bytes)) {
    std::istringstream in(bytes);
    std::string line;
    int number = 0, inFacet = 0, facets = 0;
    while (std::getline(in, line)) {
      ++number;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      std::istringstream words(line);
      std::string keyword;
      if (!(words >> keyword)) continue;
      std::ostringstream where;
      where << "line " << number << " ('" << line << "')";
      if (keyword == "facet") {
        inFacet = 0;
      } else if (keyword == "vertex") {
        for (int k = 0; k < 3; ++k) {
          std::string token;
          if (!(words >> token)) failMeshFile(source, where.str() + ": malformed vertex: expected three numbers x y z");
          errno = 0;
          char* end = nullptr;
          const double value = std::strtod(token.c_str(), &end);
          if (end == token.c_str() || *end != '\0') {
            failMeshFile(source, where.str() + ": malformed vertex: coordinate " + std::to_string(k + 1) + " ('" +
                             token + "') is not a number");
          }
          if (!std::isfinite(value) || errno == ERANGE) {
            failMeshFile(source, where.str() + ": vertex coordinate " + std::to_string(k + 1) + " ('" + token +
                             "') is not a finite double");
          }
        }
        ++inFacet;
      } else if (keyword == "endfacet") {
        if (inFacet != 3) {
          failMeshFile(source, where.str() + ": facet " + std::to_string(facets) + " has " + std::to_string(inFacet) +
                           " vertices, a triangle needs 3");
        }
        ++facets;
      }
    }
    if (facets == 0) failMeshFile(source, "the ASCII STL file contains no facets");
    return;
  }
  if (bytes.size() < 84) {
    failMeshFile(source, "a binary STL file has an 84-byte header, this file has " + std::to_string(bytes.size()) +
                     " bytes");
  }
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);
  const std::uint64_t expected = 84 + 50 * static_cast<std::uint64_t>(n);
  if (bytes.size() != expected) {
    failMeshFile(source, "the binary STL header announces " + std::to_string(n) + " triangles (" +
                     std::to_string(expected) + " bytes), but the file has " + std::to_string(bytes.size()) +
                     " bytes");
  }
  if (n == 0) failMeshFile(source, "the binary STL file contains no triangles");
  for (std::uint32_t t = 0; t < n; ++t) {
    for (int k = 0; k < 9; ++k) {  // three vertices after the normal
      float value = 0.0f;
      std::memcpy(&value, bytes.data() + 84 + 50 * static_cast<std::size_t>(t) + 12 + 4 * k, 4);
      if (!std::isfinite(value)) {
        failMeshFile(source, "triangle " + std::to_string(t) + " vertex " + std::to_string(k / 3) +
                         " has a non-finite coordinate");
      }
    }
  }
}
// [stl_checks]

// [ply_checks]
/// The checks assimp does not make on a PLY header, with the line that fails: it ends
/// with `end_header`, its format is ascii or binary, every element count is an integer,
/// every property type is one PLY defines, and the elements fit in the bytes after the
/// header (an ASCII number takes at least 2 bytes with its separator; a binary one its
/// size; a list at least its count). assimp reserves memory for the counts the header
/// announces before it reads any item: "element vertex 1000000000" in a 200-byte file
/// would take more than 10 GB.
void checkPly(const std::string& bytes, const std::string& source) {
  const std::size_t headerEnd = bytes.find("end_header");
  if (bytes.compare(0, 3, "ply") != 0) failMeshFile(source, "not a PLY file: it does not start with 'ply'");
  if (headerEnd == std::string::npos) failMeshFile(source, "the PLY header has no 'end_header' line");
  const std::size_t dataStart = bytes.find('\n', headerEnd);
  const std::size_t dataBytes = dataStart == std::string::npos ? 0 : bytes.size() - dataStart - 1;
  const auto scalarSize = [](const std::string& type) -> int {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32")
      return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
  };
  std::istringstream in(bytes.substr(0, headerEnd));
  std::string line, element;
  bool ascii = true;
  unsigned long long count = 0;
  long double needed = 0.0L;  // bytes the elements need at least (long double: counts up to 2^64 x 8)
  std::uint64_t perItem = 0;
  const auto finishElement = [&] { needed += static_cast<long double>(count) * static_cast<long double>(perItem); };
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    const std::string where = "header line " + std::to_string(number) + " ('" + line.substr(0, 60) + "')";
    if (keyword == "format") {
      std::string format;
      words >> format;
      if (format == "ascii") {
        ascii = true;
      } else if (format == "binary_little_endian" || format == "binary_big_endian") {
        ascii = false;
      } else {
        failMeshFile(source, where + ": unknown format '" + format + "' (ascii, binary_little_endian or binary_big_endian)");
      }
    } else if (keyword == "element") {
      finishElement();
      std::string countWord;
      words >> element >> countWord;
      errno = 0;
      char* end = nullptr;
      count = std::strtoull(countWord.c_str(), &end, 10);
      if (countWord.empty() || !std::isdigit(static_cast<unsigned char>(countWord[0])) || *end != '\0' ||
          errno == ERANGE) {
        failMeshFile(source, where + ": the element count '" + countWord.substr(0, 30) +
                                 "' is not a non-negative integer");
      }
      perItem = 0;
    } else if (keyword == "property") {
      std::string type;
      words >> type;
      if (type == "list") {
        std::string countType, itemType;
        words >> countType >> itemType;
        if (scalarSize(countType) == 0 || scalarSize(itemType) == 0) {
          failMeshFile(source, where + ": unknown list property types '" + countType + " " + itemType + "'");
        }
        perItem += ascii ? 2 : static_cast<std::uint64_t>(scalarSize(countType));
      } else {
        if (scalarSize(type) == 0) failMeshFile(source, where + ": unknown property type '" + type + "'");
        perItem += ascii ? 2 : static_cast<std::uint64_t>(scalarSize(type));
      }
    }
  }
  finishElement();
  // The last ASCII number of the file may lack its separator.
  if (needed > static_cast<long double>(dataBytes) + 1.0L) {
    std::ostringstream msg;
    msg << "the PLY header announces elements of at least " << static_cast<double>(needed)
        << " bytes, but the file has " << dataBytes << " bytes after the header (a wrong element count?)";
    failMeshFile(source, msg.str());
  }
}
// [ply_checks]

}  // namespace

const std::vector<std::string>& meshFileExtensions() {
  static const std::vector<std::string> extensions{".obj", ".stl", ".ply"};
  return extensions;
}

TriangleMesh parseAssimpMesh(const std::string& bytes, const std::string& sourceName,
                             const ObjLoadSettings& settings) {
  const std::string ext = lowerExtension(sourceName);
  if (ext == ".stl") checkStl(bytes, sourceName);
  if (ext == ".ply") checkPly(bytes, sourceName);
  if (ext != ".stl" && ext != ".ply") failMeshFile(sourceName, "not an STL or PLY file (extension '" + ext + "')");
  Assimp::Importer importer;
  // Triangulate polygons; nothing else: welding and validation are stackbook's own.
  const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), aiProcess_Triangulate,
                                                     ext.c_str() + 1);
  if (scene == nullptr) {
    std::string error = importer.GetErrorString();
    while (!error.empty() && (error.back() == '\n' || error.back() == '\r')) error.pop_back();
    failMeshFile(sourceName, "cannot read the " + ext.substr(1) + " file: " + error);
  }
  TriangleMesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    const int base = static_cast<int>(mesh.vertices.size());
    for (unsigned v = 0; v < part->mNumVertices; ++v) {
      const aiVector3D& p = part->mVertices[v];
      const Vec3 x(static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z));
      if (!x.allFinite()) {
        failMeshFile(sourceName, "vertex " + std::to_string(v) + " of mesh " + std::to_string(m) +
                             " has a non-finite coordinate");
      }
      mesh.vertices.push_back(x);
    }
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) {
        // Points and lines (PLY edges) do not bound a solid; assimp keeps them apart.
        continue;
      }
      std::array<int, 3> t{};
      for (int k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= part->mNumVertices) {
          failMeshFile(sourceName, "face " + std::to_string(f) + " refers to vertex " + std::to_string(face.mIndices[k]) +
                               ", but the mesh has " + std::to_string(part->mNumVertices) + " vertices");
        }
        t[static_cast<std::size_t>(k)] = base + static_cast<int>(face.mIndices[k]);
      }
      mesh.faces.push_back(t);
    }
  }
  if (mesh.faces.empty()) failMeshFile(sourceName, "the file contains no triangles");
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

TriangleMesh loadMeshFile(const std::string& path, const ObjLoadSettings& settings) {
  const std::string ext = lowerExtension(path);
  if (ext == ".obj") return loadObjMesh(path, settings);
  if (ext != ".stl" && ext != ".ply") {
    failMeshFile(path, "unknown mesh format '" + ext + "': stackbook reads .obj, .stl and .ply files");
  }
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) failMeshFile(path, "cannot open the file: it does not exist");
  std::ifstream in(path, std::ios::binary);
  if (!in) failMeshFile(path, "cannot open the file: permission denied or I/O error");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) failMeshFile(path, "cannot read the file");
  return parseAssimpMesh(bytes.str(), path, settings);
}

}  // namespace stackbook
