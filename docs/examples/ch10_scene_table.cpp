// Chapter 10: the table of bundled scenes. Every row is read from scenes/*.json (its
// "description" field and what the loader builds from it), so the table in
// chapters/10_simulator.md cannot drift from the files.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>
#include <variant>
#include <vector>

#include "stackbook/scene/scene.hpp"

namespace {

/// The effects a scene runs (inferred from its bodies, then its "effects" overrides).
std::string effectsOf(const stackbook::Scene& scene) {
  using namespace stackbook;
  if (scene.dimension == 2) {
    return resolveEffects<2>(std::get<SceneBodies<2>>(scene.bodies).world, scene.settings.effects).summary();
  }
  return resolveEffects<3>(std::get<SceneBodies<3>>(scene.bodies).world, scene.settings.effects).summary();
}

/// `text` safe inside a Markdown table cell of Doxygen's: a '|' would end the cell (and
/// Doxygen shows numeric entities such as &#124; literally), so it becomes '/'; '<' would
/// start an HTML tag. A command-line option ("--set key=value") is set as code, so that
/// Markdown does not turn its "--" into a dash and the reader can paste it; a validation
/// case code (A17, B15, A2b) links to its entry in the course's validation catalogue.
std::string cell(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    if (c == '|') {
      escaped += '/';
    } else if (c == '<') {
      escaped += "&lt;";
    } else {
      escaped += c;
    }
  }
  static const std::regex option(R"((--[a-z]+(?: [^ ),;]+)?))");
  static const std::regex caseCode(R"((^|[^A-Za-z0-9_.])([AB][0-9]{1,2})([a-z]?)(?![A-Za-z0-9_]))");
  std::string out;
  // Codes outside the code spans only: split on the options first.
  std::sregex_iterator it(escaped.begin(), escaped.end(), option), end;
  std::size_t last = 0;
  const auto linkCodes = [&](const std::string& plain) {
    return std::regex_replace(plain, caseCode, "$1\\ref case_$2$3 \"$2$3\"");
  };
  for (; it != end; ++it) {
    out += linkCodes(escaped.substr(last, static_cast<std::size_t>(it->position()) - last));
    out += "`" + it->str() + "`";
    last = static_cast<std::size_t>(it->position() + it->length());
  }
  out += linkCodes(escaped.substr(last));
  return out;
}

}  // namespace

int main() {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator("scenes")) {
    if (e.path().extension() == ".json") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  std::printf("| scene | D | bodies | dt (s) | duration (s) | effects | what it shows |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const fs::path& file : files) {
    const std::string stem = file.stem().string();
    if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, "_full") == 0) {
      // A full-size demonstration (minutes to run, seconds to build): read, not loaded.
      const nlohmann::json doc = stackbook::readSceneJson(file.string());
      std::printf("| `%s` | %d | %zu entries | | | | %s |\n", stem.c_str(), doc.value("dimension", 0),
                  doc.value("bodies", nlohmann::json::array()).size(),
                  cell(doc.value("description", std::string())).c_str());
      continue;
    }
    try {
      const stackbook::Scene scene = stackbook::loadScene(file.string());
      std::printf("| `%s` | %d | %d | %g | %g | %s | %s |\n", file.stem().string().c_str(), scene.dimension,
                  scene.bodyCount(), scene.settings.dt, scene.duration, effectsOf(scene).c_str(),
                  cell(scene.description).c_str());
    } catch (const stackbook::SceneError& e) {
      // A scene that does not load is shown as such (tests/ch10 fails on it too).
      std::fprintf(stderr, "ch10_scene_table: %s\n", e.what());
      std::printf("| `%s` | | | | | | **does not load:** %s |\n", file.stem().string().c_str(),
                  cell(e.what()).c_str());
    }
  }
  return 0;
}
