// Exercise 10.3, reference solution: a 3D recording as one OBJ file per frame.
#include "stackbook/exercises/ex10_3_obj_sequence.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "stackbook/output/output_files.hpp"

namespace stackbook {

void writeObjFrame(const Recording<3>& recording, std::size_t frame, const std::string& path) {
  if (frame >= recording.frameCount()) {
    throw std::out_of_range("writeObjFrame: frame " + std::to_string(frame) + " of a recording with " +
                            std::to_string(recording.frameCount()) + " frames");
  }
  using output_detail::exactDecimal;
  std::string text = "# stackbook frame " + std::to_string(frame) + ", t = " +
                     exactDecimal(recording.times()[frame]) + " s\n";
  int offset = 1;  // OBJ indices start at 1 and run over the whole file
  for (std::size_t i = 0; i < recording.bodyCount(); ++i) {
    const BodyVisual<3>& visual = recording.visuals()[i];
    const Pose<3>& pose = recording.poses()[frame][i];
    text += "o " + visual.name + "\n";
    for (const Vec3& v : visual.mesh.vertices) {
      const Vec3 x = pose.toWorld(v);
      text += "v " + exactDecimal(x.x()) + ' ' + exactDecimal(x.y()) + ' ' + exactDecimal(x.z()) + '\n';
    }
    for (const std::array<int, 3>& f : visual.mesh.faces) {
      text += "f " + std::to_string(f[0] + offset) + ' ' + std::to_string(f[1] + offset) + ' ' +
              std::to_string(f[2] + offset) + '\n';
    }
    offset += static_cast<int>(visual.mesh.vertices.size());
  }
  output_detail::writeFileOrThrow("writeObjFrame", path, text);
}

std::vector<std::string> writeObjSequence(const Recording<3>& recording, const std::string& directory) {
  std::filesystem::create_directories(directory);
  std::vector<std::string> paths;
  for (std::size_t f = 0; f < recording.frameCount(); ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.obj", f);
    paths.push_back((std::filesystem::path(directory) / name).string());
    writeObjFrame(recording, f, paths.back());
  }
  return paths;
}

}  // namespace stackbook
