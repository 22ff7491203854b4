// Chapter 10: the offline viewer page inlines three.js and carries the .glb byte for byte.
#include <array>
#include <stdexcept>
#include <string>

#include <doctest/doctest.h>

#include "output_fixtures.hpp"
#include "stackbook/output/animated_gltf.hpp"
#include "stackbook/output/viewer_html.hpp"

using namespace stackbook;
using namespace stackbook::testing;

// The folder the library reads three.js from (the lead may pass the configured one to
// test_ch10 as STACKBOOK_THREE_DIR; Debian's libjs-three folder otherwise).
#ifndef STACKBOOK_THREE_DIR
#define STACKBOOK_THREE_DIR "/usr/share/javascript/three"
#endif

namespace {

/// Decode base64 (RFC 4648), ignoring whitespace; written here independently of the writer.
std::string base64Decode(const std::string& text) {
  std::array<int, 256> value{};
  value.fill(-1);
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (std::size_t k = 0; k < alphabet.size(); ++k) value[static_cast<unsigned char>(alphabet[k])] = int(k);
  std::string out;
  unsigned bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=' || c == '\n' || c == ' ' || c == '\r') continue;
    const int v = value[static_cast<unsigned char>(c)];
    REQUIRE_MESSAGE(v >= 0, "not base64: '" << c << "'");
    bits = (bits << 6) | unsigned(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out += char((bits >> count) & 0xFFu);
    }
  }
  return out;
}

std::string between(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t start = text.find(from);
  REQUIRE(start != std::string::npos);
  const std::size_t end = text.find(to, start + from.size());
  REQUIRE(end != std::string::npos);
  return text.substr(start + from.size(), end - start - from.size());
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("The viewer page inlines three.js and its loader and controls and embeds the GLB") {
  const auto folder = scratchFolder("html");
  const std::string glb = (folder / "falling.glb").string();
  writeAnimatedGlb(fallingRecording3D(fewFalls(), 31, 30.0), glb);
  writeViewerHtml(glb, (folder / "falling.html").string());
  const std::string html = readWhole(folder / "falling.html");
  const std::string three = STACKBOOK_THREE_DIR;
  for (const char* script : {"/three.min.js", "/examples/js/loaders/GLTFLoader.js", "/examples/js/controls/OrbitControls.js"}) {
    CAPTURE(script);
    CHECK(html.find("<script>\n" + readWhole(three + script) + "\n</script>") != std::string::npos);
  }
  CHECK(html.find("<script src") == std::string::npos);  // nothing fetched: the page works from file://
  CHECK(html.find("GLTFLoader().parse(") != std::string::npos);
  CHECK(html.find("AnimationMixer") != std::string::npos);
  CHECK(html.find("GridHelper") != std::string::npos);
  CHECK(html.find("OrbitControls(") != std::string::npos);
  const std::string payload = between(html, "<script id=\"glb\" type=\"application/octet-stream\">", "</script>");
  CHECK(base64Decode(payload) == readWhole(glb));
}

TEST_CASE("A missing three.js script is named in the viewer's error") {
  const auto folder = scratchFolder("htmlthree");
  const std::string glb = (folder / "a.glb").string();
  writeAnimatedGlb(fallingRecording3D(fewFalls(), 3, 30.0), glb);
  ViewerOptions options;
  options.threeDir = (folder / "no three here").string();
  CHECK_THROWS_WITH_AS(writeViewerHtml(glb, (folder / "a.html").string(), options),
                       doctest::Contains(("cannot read '" + options.threeDir + "/three.min.js'").c_str()),
                       std::runtime_error);
}

TEST_CASE("A missing GLB or an unwritable page is named in the viewer's error") {
  const auto folder = scratchFolder("htmlbad");
  const std::string missing = (folder / "missing.glb").string();
  CHECK_THROWS_WITH_AS(writeViewerHtml(missing, (folder / "a.html").string()),
                       doctest::Contains(("cannot read '" + missing + "'").c_str()), std::runtime_error);
  const std::string glb = (folder / "a.glb").string();
  writeAnimatedGlb(fallingRecording3D(fewFalls(), 3, 30.0), glb);
  const std::string page = (folder / "no such folder" / "a.html").string();
  CHECK_THROWS_WITH_AS(writeViewerHtml(glb, page), doctest::Contains(("cannot write '" + page + "'").c_str()),
                       std::runtime_error);
}

}  // TEST_SUITE
