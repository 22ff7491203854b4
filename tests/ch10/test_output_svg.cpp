// Chapter 10: the animated SVG of a 2D recording is well-formed, fits the motion and
// replays the recorded poses.
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "output_fixtures.hpp"
#include "stackbook/output/animated_svg.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// Check that every element opened is closed in order: returns the first problem, or "".
std::string tagBalanceProblem(const std::string& xml) {
  std::vector<std::string> open;
  std::size_t at = 0;
  while ((at = xml.find('<', at)) != std::string::npos) {
    const std::size_t end = xml.find('>', at);
    if (end == std::string::npos) return "unterminated tag at " + std::to_string(at);
    const std::string tag = xml.substr(at + 1, end - at - 1);
    at = end + 1;
    if (tag.empty()) return "empty tag";
    if (tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name) return "</" + name + "> closes " + (open.empty() ? "nothing" : open.back());
      open.pop_back();
      continue;
    }
    if (tag.back() == '/') continue;
    open.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
  }
  return open.empty() ? "" : "<" + open.back() + "> never closed";
}

/// The value of attribute `name` in an element's text ("" if absent).
std::string attribute(const std::string& element, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t at = element.find(key);
  if (at == std::string::npos) return "";
  const std::size_t start = at + key.size();
  return element.substr(start, element.find('"', start) - start);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

/// Every element of the given name, as its opening tag's text.
std::vector<std::string> elements(const std::string& xml, const std::string& name) {
  std::vector<std::string> found;
  const std::string open = "<" + name + " ";
  std::size_t at = 0;
  while ((at = xml.find(open, at)) != std::string::npos) {
    const std::size_t end = xml.find('>', at);
    found.push_back(xml.substr(at, end - at + 1));
    at = end;
  }
  return found;
}

/// The text of the body group with data-body="i" up to its path element.
std::string bodyGroup(const std::string& svg, std::size_t i) {
  const std::size_t at = svg.find("data-body=\"" + std::to_string(i) + "\"");
  REQUIRE(at != std::string::npos);
  return svg.substr(at, svg.find("/>", svg.find("<path", at)) - at);
}

struct WrittenSvg {
  Recording<2> recording;
  std::string svg;
};

WrittenSvg writeFallingSvg(const SvgOptions& options = {}, int frames = 60) {
  WrittenSvg w{fallingRecording2D(fewFalls(), frames, 30.0, true), ""};
  const auto path = scratchFolder("svg") / "falling.svg";
  writeAnimatedSvg(w.recording, path.string(), options);
  w.svg = readWhole(path);
  return w;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("The animated SVG is well-formed with balanced tags") {
  const WrittenSvg w = writeFallingSvg();
  CHECK(w.svg.rfind("<?xml", 0) == 0);
  CHECK(tagBalanceProblem(w.svg) == "");
  CHECK(w.svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\"") != std::string::npos);
}

TEST_CASE("The SVG has one animated group per dynamic body and draws static bodies once") {
  const WrittenSvg w = writeFallingSvg();
  std::size_t dynamic = 0, statics = 0;
  for (const auto& visual : w.recording.visuals()) (visual.isStatic ? statics : dynamic) += 1;
  const auto groups = elements(w.svg, "g");
  std::size_t animatedGroups = 0, staticGroups = 0;
  for (const std::string& g : groups) {
    animatedGroups += attribute(g, "class") == "dynamic";
    staticGroups += attribute(g, "class") == "static";
  }
  CHECK(animatedGroups == dynamic);
  CHECK(staticGroups == statics);
  // Two animateTransforms (translate, rotate) per dynamic body and none anywhere else.
  CHECK(elements(w.svg, "animateTransform").size() == 2 * dynamic);
  CHECK(elements(w.svg, "path").size() == w.recording.bodyCount());
}

TEST_CASE("Every SVG animation has as many keyTimes as values and they rise from 0 to 1") {
  const WrittenSvg w = writeFallingSvg();
  auto animations = elements(w.svg, "animateTransform");
  const auto plain = elements(w.svg, "animate");
  animations.insert(animations.end(), plain.begin(), plain.end());
  REQUIRE(animations.size() > 8);
  for (const std::string& a : animations) {
    CAPTURE(a.substr(0, 160));
    CHECK(attribute(a, "repeatCount") == "indefinite");
    const std::string keyTimes = attribute(a, "keyTimes");
    if (keyTimes.empty()) continue;  // the progress bar: two values, evenly timed
    const auto keys = split(keyTimes, ';');
    CHECK(keys.size() == split(attribute(a, "values"), ';').size());
    CHECK(std::stod(keys.front()) == 0.0);
    if (attribute(a, "calcMode") != "discrete") CHECK(std::stod(keys.back()) == 1.0);
    for (std::size_t k = 1; k < keys.size(); ++k) CHECK(std::stod(keys[k]) >= std::stod(keys[k - 1]));
  }
}

TEST_CASE("The SVG view box holds every vertex of every body at every frame") {
  const WrittenSvg w = writeFallingSvg();
  const auto box = split(attribute(elements(w.svg, "svg").front(), "viewBox"), ' ');
  REQUIRE(box.size() == 4);
  const double left = std::stod(box[0]), top = std::stod(box[1]);
  const double right = left + std::stod(box[2]), bottom = top + std::stod(box[3]);
  double worst = -1e300;  // largest excursion past the view box (negative: inside)
  for (const auto& frame : w.recording.poses()) {
    for (std::size_t i = 0; i < w.recording.bodyCount(); ++i) {
      for (const Vec2& v : w.recording.visuals()[i].mesh.vertices) {
        const Vec2 p = frame[i].toWorld(v);
        const double sx = p.x(), sy = -p.y();  // SVG y points down
        worst = std::max({worst, left - sx, sx - right, top - sy, sy - bottom});
      }
    }
  }
  CHECK(worst < 0.0);
}

TEST_CASE("The SVG keyframes replay the recorded positions and unwrapped angles") {
  const WrittenSvg w = writeFallingSvg();
  const auto& rec = w.recording;
  // Positions are written to 1e-4 of the drawing's size (here about 13 units: 3 decimals).
  const double tolerance = 5e-4 + 1e-12;
  for (std::size_t i = 1; i < rec.bodyCount(); ++i) {
    CAPTURE(i);
    const std::string group = bodyGroup(w.svg, i);
    const auto animations = elements(group, "animateTransform");
    REQUIRE(animations.size() == 2);
    const auto translations = split(attribute(animations[0], "values"), ';');
    const auto rotations = split(attribute(animations[1], "values"), ';');
    REQUIRE(translations.size() == rec.frameCount());
    REQUIRE(rotations.size() == rec.frameCount());
    double previous = 0.0;
    for (std::size_t f = 0; f < rec.frameCount(); ++f) {
      std::istringstream in(translations[f]);
      double x = 0.0, y = 0.0;
      in >> x >> y;
      CHECK(std::abs(x - rec.poses()[f][i].position.x()) <= tolerance);
      CHECK(std::abs(y - rec.poses()[f][i].position.y()) <= tolerance);
      const double degrees = std::stod(rotations[f]);
      // Same rotation as recorded (mod 360 degrees, to the 1e-3 degree written) ...
      const double recorded = rec.poses()[f][i].orientation.angle() * 180.0 / M_PI;
      const double turns = (degrees - recorded) / 360.0;
      CHECK(std::abs(turns - std::round(turns)) * 360.0 <= 1e-3);
      // ... and no jump of half a turn or more between frames (the ring spins at
      // 10 rad/s = 19 degrees per frame, so its angle must keep growing past 180).
      if (f > 0) CHECK(std::abs(degrees - previous) < 180.0);
      previous = degrees;
    }
  }
  // The spinning ring (last body) turns 10 rad/s * 59/30 s = 1127 degrees in all.
  const auto ring = split(attribute(elements(bodyGroup(w.svg, rec.bodyCount() - 1), "animateTransform")[1], "values"), ';');
  CHECK(std::stod(ring.back()) == doctest::Approx(10.0 * 59.0 / 30.0 * 180.0 / M_PI).epsilon(1e-6));
}

TEST_CASE("An annulus is drawn as two closed loops filled even-odd") {
  const WrittenSvg w = writeFallingSvg();
  const std::string group = bodyGroup(w.svg, w.recording.bodyCount() - 1);
  const std::string d = attribute(elements(group, "path").front(), "d");
  CHECK(std::count(d.begin(), d.end(), 'M') == 2);
  CHECK(std::count(d.begin(), d.end(), 'Z') == 2);
  CHECK(std::count(d.begin(), d.end(), 'L') == (24 - 1) + (16 - 1));
  CHECK(w.svg.find("fill-rule=\"evenodd\"") != std::string::npos);
}

TEST_CASE("The SVG keeps at most maxFrames frames including the first and the last") {
  SvgOptions options;
  options.maxFrames = 10;
  const WrittenSvg w = writeFallingSvg(options, 91);  // 3 s at 30 fps
  const std::string group = bodyGroup(w.svg, 1);
  const auto animation = elements(group, "animateTransform").front();
  const auto keys = split(attribute(animation, "keyTimes"), ';');
  REQUIRE(keys.size() == 10);
  // Frames 0, 10, 20, ..., 90 out of 0..90: keyTimes k/9, and the clip lasts 3 s.
  for (std::size_t k = 0; k < keys.size(); ++k) CHECK(std::stod(keys[k]) == doctest::Approx(double(k) / 9.0).epsilon(1e-6));
  CHECK(attribute(animation, "dur") == "3s");
  const auto last = split(split(attribute(animation, "values"), ';').back(), ' ');
  CHECK(std::stod(last[1]) == doctest::Approx(w.recording.poses().back()[1].position.y()).epsilon(1e-4));
}

TEST_CASE("Writing the SVG into a missing folder fails with the path in the message") {
  const std::string path = (scratchFolder("svgbad") / "no such folder" / "a.svg").string();
  const Recording<2> recording = fallingRecording2D(fewFalls(), 2, 30.0);
  CHECK_THROWS_WITH_AS(writeAnimatedSvg(recording, path), doctest::Contains(("cannot write '" + path + "'").c_str()),
                       std::runtime_error);
}

}  // TEST_SUITE
