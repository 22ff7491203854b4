#include "stackbook/output/animated_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "stackbook/output/output_files.hpp"

namespace stackbook {

namespace {

using output_detail::fixedDecimal;

/// Chain a 2D mesh's segments into loops of vertex indices. Each closed loop comes back
/// to its first vertex; a chain that does not close (an open mesh) is returned as it is,
/// and the flag says whether it closed.
struct Loop {
  std::vector<int> vertices;
  bool closed = false;
};

std::vector<Loop> chainLoops(const Polygon& mesh, const std::string& name) {
  const int n = static_cast<int>(mesh.vertices.size());
  std::vector<std::vector<int>> outgoing(static_cast<std::size_t>(n));
  for (std::size_t s = 0; s < mesh.faces.size(); ++s) {
    const auto& face = mesh.faces[s];
    if (face[0] < 0 || face[0] >= n || face[1] < 0 || face[1] >= n) {
      throw std::invalid_argument("writeAnimatedSvg: body '" + name + "': segment " +
                                  std::to_string(s) + " refers to a missing vertex");
    }
    outgoing[static_cast<std::size_t>(face[0])].push_back(static_cast<int>(s));
  }
  std::vector<bool> used(mesh.faces.size(), false);
  std::vector<Loop> loops;
  for (std::size_t start = 0; start < mesh.faces.size(); ++start) {
    if (used[start]) continue;
    Loop loop;
    std::size_t s = start;
    const int first = mesh.faces[start][0];
    loop.vertices.push_back(first);
    while (true) {
      used[s] = true;
      const int next = mesh.faces[s][1];
      if (next == first) {
        loop.closed = true;
        break;
      }
      loop.vertices.push_back(next);
      const auto& candidates = outgoing[static_cast<std::size_t>(next)];
      const auto it = std::find_if(candidates.begin(), candidates.end(),
                                   [&](int c) { return !used[static_cast<std::size_t>(c)]; });
      if (it == candidates.end()) break;
      s = static_cast<std::size_t>(*it);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::string pathData(const Polygon& mesh, const std::vector<Loop>& loops, int decimals) {
  std::string d;
  for (const Loop& loop : loops) {
    for (std::size_t k = 0; k < loop.vertices.size(); ++k) {
      const Vec2& v = mesh.vertices[static_cast<std::size_t>(loop.vertices[k])];
      d += k == 0 ? (d.empty() ? "M" : " M") : " L";
      d += fixedDecimal(v.x(), decimals) + ' ' + fixedDecimal(v.y(), decimals);
    }
    if (loop.closed) d += " Z";
  }
  return d;
}

std::string cssColor(const std::array<double, 3>& rgb, double scale) {
  std::string css = "rgb(";
  for (std::size_t c = 0; c < 3; ++c) {
    const double v = std::clamp(rgb[c] * scale, 0.0, 1.0);
    css += std::to_string(static_cast<int>(std::lround(255.0 * v)));
    css += c < 2 ? "," : ")";
  }
  return css;
}

std::string xmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

/// Indices of at most maxFrames frames, evenly spaced in index, first and last included.
std::vector<std::size_t> keptFrames(std::size_t frameCount, int maxFrames) {
  std::vector<std::size_t> kept;
  const std::size_t limit = static_cast<std::size_t>(std::max(maxFrames, 2));
  if (frameCount <= limit) {
    for (std::size_t f = 0; f < frameCount; ++f) kept.push_back(f);
    return kept;
  }
  for (std::size_t k = 0; k < limit; ++k) {
    kept.push_back(static_cast<std::size_t>(std::llround(static_cast<double>(k) *
                                                         static_cast<double>(frameCount - 1) /
                                                         static_cast<double>(limit - 1))));
  }
  return kept;
}

bool moves(const Recording<2>& recording, std::size_t i) {
  const Pose<2>& first = recording.poses().front()[i];
  for (const auto& frame : recording.poses()) {
    if (frame[i].position != first.position ||
        frame[i].orientation.angle() != first.orientation.angle()) {
      return true;
    }
  }
  return false;
}

}  // namespace

void writeAnimatedSvg(const Recording<2>& recording, const std::string& path,
                      const SvgOptions& options) {
  if (recording.frameCount() == 0) {
    throw std::invalid_argument("writeAnimatedSvg: the recording has no frame (writing '" + path +
                                "')");
  }
  if (!(options.playbackSlowdown > 0.0) || !(options.widthPixels >= 0.0) || options.maxFrames < 2) {
    throw std::invalid_argument(
        "writeAnimatedSvg: options need playbackSlowdown > 0, widthPixels >= 0 and maxFrames >= 2");
  }
  const auto& visuals = recording.visuals();
  const auto& poses = recording.poses();
  const auto& times = recording.times();

  // The view box: every vertex of every body at every recorded frame (not only the kept
  // ones, so that nothing leaves the picture between two kept frames either).
  Aabb<2> box;
  for (const auto& frame : poses) {
    for (std::size_t i = 0; i < visuals.size(); ++i) {
      for (const Vec2& v : visuals[i].mesh.vertices) box.extend(frame[i].toWorld(v));
    }
  }
  if (box.isEmpty()) box.extend(Vec2::Zero());
  double side = std::max(box.upper.x() - box.lower.x(), box.upper.y() - box.lower.y());
  if (!(side > 0.0)) side = 1.0;
  const double pad = options.margin * side;
  const double minX = box.lower.x() - pad, maxX = box.upper.x() + pad;
  const double minY = box.lower.y() - pad, maxY = box.upper.y() + pad;
  const double width = maxX - minX, height = maxY - minY;
  // Coordinates to 1e-4 of the drawing (a tenth of a pixel at 1000 px), positions and
  // angles to match; extra digits would only make the file larger.
  const int decimals = std::max(0, 4 - static_cast<int>(std::floor(std::log10(side))));
  const auto num = [&](double v) { return fixedDecimal(v, decimals); };

  const std::vector<std::size_t> kept = keptFrames(recording.frameCount(), options.maxFrames);
  const double t0 = times[kept.front()];
  const double span = times[kept.back()] - t0;
  const bool animated = kept.size() >= 2 && span > 0.0;
  const double duration = span * options.playbackSlowdown;

  std::string keyTimes;
  if (animated) {
    for (std::size_t k = 0; k < kept.size(); ++k) {
      // keyTimes must start at 0, end at 1 and not decrease: pin the ends exactly.
      const double u = k == 0 ? 0.0 : k + 1 == kept.size() ? 1.0 : (times[kept[k]] - t0) / span;
      if (k) keyTimes += ';';
      keyTimes += fixedDecimal(u, 6);
    }
  }

  const double heightPixels = options.widthPixels * height / width;
  std::string svg;
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  const bool fill = options.widthPixels == 0.0;
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
         (fill ? std::string("100%") : fixedDecimal(options.widthPixels, 1)) + "\" height=\"" +
         (fill ? std::string("100%") : fixedDecimal(heightPixels, 1)) + "\" viewBox=\"" + num(minX) + " " + num(-maxY) + " " + num(width) + " " + num(height) +
         "\">\n";
  svg += "<title>stackbook recording: " + std::to_string(visuals.size()) + " bodies, " +
         fixedDecimal(times.back() - times.front(), 3) + " s</title>\n";
  svg += "<rect x=\"" + num(minX) + "\" y=\"" + num(-maxY) + "\" width=\"" + num(width) +
         "\" height=\"" + num(height) + "\" fill=\"" + xmlEscape(options.background) + "\"/>\n";
  // World y up: one flip for the whole scene; text is drawn outside it.
  svg += "<g transform=\"scale(1,-1)\" stroke-width=\"" + num(options.strokeFraction * side) +
         "\" stroke-linejoin=\"round\" fill-rule=\"evenodd\">\n";

  const std::string dur = fixedDecimal(duration, 6) + "s";
  for (std::size_t i = 0; i < visuals.size(); ++i) {
    const BodyVisual<2>& visual = visuals[i];
    const std::string d = pathData(visual.mesh, chainLoops(visual.mesh, visual.name), decimals);
    const std::string shape = "<path d=\"" + d + "\" fill=\"" + cssColor(visual.color, 1.0) +
                              "\" stroke=\"" + cssColor(visual.color, 0.55) + "\"/>";
    const std::string id = " data-body=\"" + std::to_string(i) + "\" data-name=\"" +
                           xmlEscape(visual.name) + "\"";
    if (!animated || visual.isStatic || !moves(recording, i)) {
      const Pose<2>& pose = poses[kept.front()][i];
      svg += "<g class=\"static\"" + id + " transform=\"translate(" + num(pose.position.x()) + " " +
             num(pose.position.y()) + ") rotate(" +
             fixedDecimal(pose.orientation.angle() * 180.0 / M_PI, 3) + ")\">" + shape + "</g>\n";
      continue;
    }
    std::string translate, rotate;
    double previous = 0.0;
    for (std::size_t k = 0; k < kept.size(); ++k) {
      const Pose<2>& pose = poses[kept[k]][i];
      // Unwrap: choose the representative of the angle closest to the previous frame's.
      double angle = pose.orientation.angle();
      if (k > 0) angle += 2.0 * M_PI * std::round((previous - angle) / (2.0 * M_PI));
      previous = angle;
      if (k) {
        translate += ';';
        rotate += ';';
      }
      translate += num(pose.position.x());
      translate += ' ';
      translate += num(pose.position.y());
      rotate += fixedDecimal(angle * 180.0 / M_PI, 3);
    }
    svg += "<g class=\"dynamic\"" + id + ">";
    svg += "<animateTransform attributeName=\"transform\" type=\"translate\" calcMode=\"linear\" dur=\"" +
           dur + "\" repeatCount=\"indefinite\" keyTimes=\"" + keyTimes + "\" values=\"" + translate +
           "\"/>";
    svg += "<g><animateTransform attributeName=\"transform\" type=\"rotate\" calcMode=\"linear\" dur=\"" +
           dur + "\" repeatCount=\"indefinite\" keyTimes=\"" + keyTimes + "\" values=\"" + rotate +
           "\"/>" + shape + "</g></g>\n";
  }
  if (options.drawContacts) {
    // The contacts of the step that reached each written frame, shown until the next one.
    const double dot = 1.5 * options.strokeFraction * side;
    const double normalLength = options.contactNormalFraction * side;
    const auto& contacts = recording.contacts();
    std::size_t next = 0;
    for (std::size_t k = 0; k < kept.size(); ++k) {
      const std::size_t f = kept[k];
      std::string marks;
      for (; next < contacts.size() && contacts[next].frame <= f; ++next) {
        const RecordedContact& c = contacts[next];
        if (c.frame != f || c.time != times[f]) continue;  // an earlier step of the interval
        const Vec2 p(c.contact.point[0], c.contact.point[1]);
        const Vec2 q = p + normalLength * Vec2(c.contact.normal[0], c.contact.normal[1]);
        marks += "<circle cx=\"" + num(p.x()) + "\" cy=\"" + num(p.y()) + "\" r=\"" + num(dot) + "\"/>";
        marks += "<line x1=\"" + num(p.x()) + "\" y1=\"" + num(p.y()) + "\" x2=\"" + num(q.x()) +
                 "\" y2=\"" + num(q.y()) + "\"/>";
      }
      if (marks.empty()) continue;
      std::string visibility = "visible";
      std::string animate;
      if (animated) {
        const auto u = [&](std::size_t j) {
          return j == 0 ? 0.0 : j + 1 >= kept.size() ? 1.0 : (times[kept[j]] - t0) / span;
        };
        visibility = "hidden";
        const std::string from = fixedDecimal(u(k), 6);
        const bool last = k + 1 >= kept.size();
        const std::string values = last ? "hidden;visible" : "hidden;visible;hidden";
        const std::string keys = last ? "0;" + from : "0;" + from + ";" + fixedDecimal(u(k + 1), 6);
        animate = "<animate attributeName=\"visibility\" calcMode=\"discrete\" dur=\"" + dur +
                  "\" repeatCount=\"indefinite\" keyTimes=\"" + keys + "\" values=\"" + values + "\"/>";
      }
      svg += "<g class=\"contacts\" data-frame=\"" + std::to_string(f) + "\" visibility=\"" + visibility +
             "\" fill=\"" + xmlEscape(options.contactColor) + "\" stroke=\"" +
             xmlEscape(options.contactColor) + "\">" + animate + marks + "</g>\n";
    }
  }
  svg += "</g>\n";

  if (options.showTime && animated) {
    // A progress bar along the bottom and the simulated time as discrete labels: each
    // label is visible during its own slice of the loop.
    const double font = 0.04 * side;
    const double barY = -minY - 0.25 * pad;
    svg += "<rect class=\"progress\" x=\"" + num(minX) + "\" y=\"" + num(barY) + "\" width=\"0\" height=\"" +
           num(0.2 * pad) + "\" fill=\"#888\"><animate attributeName=\"width\" calcMode=\"linear\" dur=\"" +
           dur + "\" repeatCount=\"indefinite\" values=\"0;" + num(width) + "\"/></rect>\n";
    double step = 0.1;
    while (span / step > 200.0) step *= 10.0;
    const int labels = static_cast<int>(std::floor(span / step + 1e-9)) + 1;
    svg += "<g class=\"time\" font-family=\"sans-serif\" font-size=\"" + num(font) + "\" fill=\"#333\">\n";
    for (int k = 0; k < labels; ++k) {
      const double from = std::min(1.0, k * step / span);
      const double to = std::min(1.0, (k + 1) * step / span);
      const int digits = step < 1.0 ? 1 : 0;
      char label[64];
      std::snprintf(label, sizeof label, "t = %.*f s", digits, times.front() + k * step);
      std::string values, keys;
      if (k == 0) {
        values = "visible;hidden";
        keys = "0;" + fixedDecimal(to, 6);
      } else if (to >= 1.0) {
        values = "hidden;visible";
        keys = "0;" + fixedDecimal(from, 6);
      } else {
        values = "hidden;visible;hidden";
        keys = "0;" + fixedDecimal(from, 6) + ";" + fixedDecimal(to, 6);
      }
      svg += "<text x=\"" + num(minX + 0.5 * pad) + "\" y=\"" + num(-maxY + 0.5 * pad + font) +
             "\" visibility=\"" + (k == 0 ? "visible" : "hidden") +
             "\">" + label + "<animate attributeName=\"visibility\" calcMode=\"discrete\" dur=\"" + dur +
             "\" repeatCount=\"indefinite\" keyTimes=\"" + keys + "\" values=\"" + values + "\"/></text>\n";
    }
    svg += "</g>\n";
  }
  svg += "</svg>\n";
  output_detail::writeFileOrThrow("writeAnimatedSvg", path, svg);
}

}  // namespace stackbook
