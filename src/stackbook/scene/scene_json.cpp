// Scene files (chapter 10): reading the JSON text of a scene file and applying --set
// overrides to it. See scene.hpp and docs/scene_format.md.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "stackbook/scene/scene.hpp"

namespace stackbook {

using nlohmann::json;

json readSceneJson(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw SceneError(path, "", "no such scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, "", "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string content = text.str();
  try {
    return json::parse(content);
  } catch (const json::parse_error& e) {
    // Line and column of the byte the parser stopped at.
    std::size_t line = 1, column = 1;
    for (std::size_t k = 0; k + 1 < e.byte && k < content.size(); ++k) {
      if (content[k] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string what = e.what();
    const auto colon = what.find("syntax error");
    if (colon != std::string::npos) what = what.substr(colon);
    throw SceneError(path, "", "line " + std::to_string(line) + ", column " + std::to_string(column) +
                                   ": not valid JSON (" + what + ")");
  }
}

void applySceneOverride(json& doc, const std::string& keyValue, const std::string& file) {
  const auto eq = keyValue.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw SceneError(file, "", "--set expects key=value (e.g. dt=0.0005), got \"" + keyValue + "\"");
  }
  std::string key = keyValue.substr(0, eq);
  const std::string text = keyValue.substr(eq + 1);
  std::replace(key.begin(), key.end(), '.', '/');
  if (key.front() != '/') key.insert(key.begin(), '/');
  json value;
  try {
    value = json::parse(text);
  } catch (const json::parse_error&) {
    value = text;  // a bare word: a string, e.g. --set solver.order=traditional
  }
  try {
    doc[json::json_pointer(key)] = value;
  } catch (const json::exception& e) {
    throw SceneError(file, key, std::string("--set cannot set this field: ") + e.what());
  }
}

}  // namespace stackbook
