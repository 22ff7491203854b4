// Chapter 10: the examples of docs/scene_format.md are real. The page's first fenced
// block is a complete scene and every later one a JSON merge patch on it; each result
// must load without error, so the page cannot drift from the loader.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "stackbook/scene/scene.hpp"

using nlohmann::json;

namespace {

/// The ``` fenced blocks of a Markdown file (~~~ blocks, used for terminal text, are not).
std::vector<std::string> fencedBlocks(const std::filesystem::path& page) {
  std::ifstream in(page);
  std::vector<std::string> blocks;
  std::string line, block;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) == 0) {
      if (inside) blocks.push_back(block);
      inside = !inside;
      block.clear();
    } else if (inside) {
      block += line + "\n";
    }
  }
  return blocks;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("Every example of the scene format page builds a valid scene") {
  const std::filesystem::path page = std::filesystem::path(STACKBOOK_SCENES_DIR) / ".." / "docs" / "scene_format.md";
  const std::vector<std::string> blocks = fencedBlocks(page);
  REQUIRE(blocks.size() >= 10);
  const json base = json::parse(blocks[0]);
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    CAPTURE(k);
    CAPTURE(blocks[k]);
    json doc = base;
    doc.merge_patch(json::parse(blocks[k]));
    const std::string name = "scene_format.md example " + std::to_string(k);
    CHECK_NOTHROW((void)stackbook::parseScene(doc, name, STACKBOOK_TEST_DATA_DIR));
  }
}

}  // TEST_SUITE
