// Chapter 10: sample outputs of every writer, for people (and tests/ch10/render_check.sh)
// to open in a browser, and the sizes of a 100-body run. The files go to the folder named
// by the environment variable STACKBOOK_SAMPLES_DIR, or to a temporary folder.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <doctest/doctest.h>

#include "output_fixtures.hpp"
#include "stackbook/output/animated_gltf.hpp"
#include "stackbook/output/animated_svg.hpp"
#include "stackbook/output/trajectory_csv.hpp"
#include "stackbook/output/viewer_html.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

std::filesystem::path samplesFolder(const std::string& fallback) {
  const char* chosen = std::getenv("STACKBOOK_SAMPLES_DIR");
  if (chosen == nullptr || *chosen == '\0') return scratchFolder(fallback);
  std::filesystem::create_directories(chosen);
  return chosen;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("The sample outputs of a few falling boxes are written") {
  const auto folder = samplesFolder("samples");
  const Recording<2> flat = fallingRecording2D(fewFalls(), 61, 30.0, true);
  const Recording<3> solid = fallingRecording3D(fewFalls(), 61, 30.0);
  writeTrajectoryCsv(flat, (folder / "falling_2d.csv").string());
  writeAnimatedSvg(flat, (folder / "falling_2d.svg").string());
  writeTrajectoryCsv(solid, (folder / "falling_3d.csv").string());
  writeAnimatedGlb(solid, (folder / "falling_3d.glb").string());
  writeViewerHtml((folder / "falling_3d.glb").string(), (folder / "falling_3d.html").string());
  for (const char* name : {"falling_2d.csv", "falling_2d.svg", "falling_3d.csv", "falling_3d.glb", "falling_3d.html"}) {
    CAPTURE(name);
    CHECK(std::filesystem::file_size(folder / name) > 1000u);
  }
}

TEST_CASE("A 100 body 10 s run at 30 fps gives files of a sane size") {
  // Budgets: an SVG under 1.5 MB plays smoothly in a browser; the GLB holds 301 frames of
  // 100 float poses (28 bytes each: 0.84 MB) plus the meshes; the page adds three.js
  // (0.6 MB) and base64 (4/3) to the GLB.
  const auto folder = samplesFolder("samples100");
  const Recording<2> flat = fallingRecording2D(manyFalls(100), 301, 30.0);
  const Recording<3> solid = fallingRecording3D(manyFalls(100), 301, 30.0);
  const auto start = std::chrono::steady_clock::now();
  writeTrajectoryCsv(flat, (folder / "many_2d.csv").string());
  writeAnimatedSvg(flat, (folder / "many_2d.svg").string());
  writeTrajectoryCsv(solid, (folder / "many_3d.csv").string());
  writeAnimatedGlb(solid, (folder / "many_3d.glb").string());
  writeViewerHtml((folder / "many_3d.glb").string(), (folder / "many_3d.html").string());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto size = [&](const char* name) { return double(std::filesystem::file_size(folder / name)) / 1e6; };
  MESSAGE("100 bodies, 301 frames: csv2d " << size("many_2d.csv") << " MB, svg " << size("many_2d.svg")
          << " MB, csv3d " << size("many_3d.csv") << " MB, glb " << size("many_3d.glb") << " MB, html "
          << size("many_3d.html") << " MB, written in " << seconds << " s");
  CHECK(size("many_2d.svg") < 1.5);
  CHECK(size("many_3d.glb") < 1.2);
  CHECK(size("many_3d.html") < 0.6 + 1.2 * 4.0 / 3.0 + 0.1);
}

}  // TEST_SUITE
