// Chapter 10 / the scene format page: what `stackbook check` prints for a mesh the strict
// loader refuses. The mesh is tests/support/damaged_mesh.hpp's damaged box (holes, a flipped
// face and faces that repeat a vertex, as downloaded meshes have them), written as an OBJ
// file into doc_out/refused_mesh/ with a scene that uses it. The output is the program's one
// error line and the first lines of `stackbook check --all-defects`. The docs build fails if
// the line stops being one line of at most 300 characters with the hint, or if the full
// list stops holding every defect.
#include <cstdio>
#include <filesystem>
#include <string>

#include "stackbook/scene/scene.hpp"
#include "support/damaged_mesh.hpp"

int main() {
  namespace fs = std::filesystem;
  using namespace stackbook;
  const fs::path dir = fs::path(STACKBOOK_FIGURES_DIR).parent_path() / "refused_mesh";
  fs::create_directories(dir);
  const test_support::DamagedMesh damaged = test_support::damagedBox(8, 12, 100);
  test_support::writeMeshFile(damaged.mesh, dir / "character.obj");
  const nlohmann::json scene = {
      {"dimension", 3},
      {"bodies",
       {{{"static", true}, {"shape", {{"type", "box"}, {"size", {8, 8, 1}}}}, {"position", {0, 0, -0.5}}},
        {{"shape", {{"type", "mesh"}, {"file", "character.obj"}}}, {"position", {0, 0, 1}}}}}};
  try {
    (void)parseScene(scene, "mesh.json", dir);
  } catch (const SceneError& e) {
    const std::string line = e.what();
    std::printf("$ stackbook check mesh.json\nstackbook: error: %s\n\n", line.c_str());
    std::printf("$ stackbook check --all-defects mesh.json\nstackbook: error: (the same line)\n");
    const std::size_t shown = 4;
    for (std::size_t k = 0; k < e.details().size() && k < shown; ++k) std::printf("  %s\n", e.details()[k].c_str());
    std::printf("  ... (%zu lines in all, one per defect)\n", e.details().size());
    const bool ok = line.find('\n') == std::string::npos && line.size() <= 300 &&
                    line.find("set \"meshMode\": \"repair\" to repair it (chapter 6)") != std::string::npos &&
                    e.details().size() == static_cast<std::size_t>(damaged.defects());
    if (!ok) {
      std::fprintf(stderr, "ch10_refused_mesh: the refusal is not one short line with the hint and every defect\n");
      return 1;
    }
    return 0;
  }
  std::fprintf(stderr, "ch10_refused_mesh: the damaged mesh was accepted\n");
  return 1;
}
