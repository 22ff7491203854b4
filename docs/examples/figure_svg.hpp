#pragma once
// A small SVG writer for the course's figures. The docs programs compute a figure with
// the library's own functions and draw it with these few primitives: a view that maps
// world coordinates (y up) to pixels, lines, arrows, polygons, circles, text, plot axes
// and a legend. The file lands in the build's figure folder (STACKBOOK_FIGURES_DIR), which
// the docs build copies next to the pages; a page shows it with \image html.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifndef STACKBOOK_FIGURES_DIR
#error "figure programs are built by docs/CMakeLists.txt, which sets STACKBOOK_FIGURES_DIR"
#endif

namespace figure_svg {

/// A number with a fixed number of decimals, no "-0".
inline std::string fmt(double x, int decimals = 2) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
  std::string s = buffer;
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);
  return s;
}

/// A number with `digits` significant digits (for tick labels).
inline std::string tick(double x) {
  if (std::abs(x) < 1e-12) return "0";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4g", x);
  return buffer;
}

inline std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

/// A rectangle of pixels showing the world rectangle [x0, x1] x [y0, y1] (y up).
struct View {
  double left, top, width, height;   // pixels
  double x0, x1, y0, y1;             // world
  double X(double x) const { return left + (x - x0) / (x1 - x0) * width; }
  double Y(double y) const { return top + (y1 - y) / (y1 - y0) * height; }
  /// A view of the world box with equal scales on both axes, centred in the pixel box.
  static View equal(double left, double top, double width, double height, double x0, double x1,
                    double y0, double y1) {
    const double scale = std::min(width / (x1 - x0), height / (y1 - y0));
    const double w = scale * (x1 - x0), h = scale * (y1 - y0);
    return View{left + 0.5 * (width - w), top + 0.5 * (height - h), w, h, x0, x1, y0, y1};
  }
};

struct Style {
  std::string stroke = "#222";
  double width = 1.5;
  std::string fill = "none";
  std::string dash;  // e.g. "5 3"
  double opacity = 1.0;
  std::string attributes() const {
    std::string a = "stroke=\"" + stroke + "\" stroke-width=\"" + fmt(width, 2) + "\" fill=\"" +
                    fill + "\"";
    if (!dash.empty()) a += " stroke-dasharray=\"" + dash + "\"";
    if (opacity < 1.0) a += " opacity=\"" + fmt(opacity, 3) + "\"";
    return a;
  }
};

inline Style stroke(const std::string& colour, double width = 1.5, const std::string& dash = "") {
  Style s;
  s.stroke = colour;
  s.width = width;
  s.dash = dash;
  return s;
}
inline Style filled(const std::string& fill, const std::string& edge = "#222", double width = 1.0,
                    double opacity = 1.0) {
  Style s;
  s.fill = fill;
  s.stroke = edge;
  s.width = width;
  s.opacity = opacity;
  return s;
}

using Points = std::vector<std::pair<double, double>>;

/// An SVG document in pixel coordinates; the drawing calls take world coordinates
/// through a View.
class Svg {
 public:
  Svg(int width, int height, std::string description)
      : width_(width), height_(height), description_(std::move(description)) {}

  void line(const View& v, double xa, double ya, double xb, double yb, const Style& s) {
    body_ += "<line x1=\"" + fmt(v.X(xa)) + "\" y1=\"" + fmt(v.Y(ya)) + "\" x2=\"" +
             fmt(v.X(xb)) + "\" y2=\"" + fmt(v.Y(yb)) + "\" " + s.attributes() + "/>\n";
  }

  void polyline(const View& v, const Points& p, const Style& s, bool closed = false) {
    if (p.empty()) return;
    std::string d;
    for (std::size_t k = 0; k < p.size(); ++k) {
      d += (k == 0 ? "M" : " L") + fmt(v.X(p[k].first)) + " " + fmt(v.Y(p[k].second));
    }
    if (closed) d += " Z";
    body_ += "<path d=\"" + d + "\" " + s.attributes() + " stroke-linejoin=\"round\"/>\n";
  }

  void polygon(const View& v, const Points& p, const Style& s) { polyline(v, p, s, true); }

  void circle(const View& v, double x, double y, double radiusPixels, const Style& s) {
    body_ += "<circle cx=\"" + fmt(v.X(x)) + "\" cy=\"" + fmt(v.Y(y)) + "\" r=\"" +
             fmt(radiusPixels) + "\" " + s.attributes() + "/>\n";
  }

  /// A rectangle given in world coordinates (used for colour-map cells).
  void cell(const View& v, double xa, double ya, double xb, double yb, const std::string& fill) {
    const double px = std::min(v.X(xa), v.X(xb)), py = std::min(v.Y(ya), v.Y(yb));
    const double w = std::abs(v.X(xb) - v.X(xa)), h = std::abs(v.Y(yb) - v.Y(ya));
    body_ += "<rect x=\"" + fmt(px) + "\" y=\"" + fmt(py) + "\" width=\"" + fmt(w + 0.3) +
             "\" height=\"" + fmt(h + 0.3) + "\" fill=\"" + fill + "\"/>\n";
  }

  /// An arrow from (xa, ya) to (xb, yb) with a filled head of the stroke's colour.
  void arrow(const View& v, double xa, double ya, double xb, double yb, const std::string& colour,
             double width = 2.0, const std::string& dash = "") {
    const double ax = v.X(xa), ay = v.Y(ya), bx = v.X(xb), by = v.Y(yb);
    const double length = std::hypot(bx - ax, by - ay);
    if (length < 1e-9) return;
    const double ux = (bx - ax) / length, uy = (by - ay) / length;
    const double head = std::min(10.0 + 1.5 * width, 0.5 * length), half = 0.45 * head;
    const double sx = bx - head * ux, sy = by - head * uy;  // where the shaft ends
    body_ += "<line x1=\"" + fmt(ax) + "\" y1=\"" + fmt(ay) + "\" x2=\"" + fmt(sx) + "\" y2=\"" +
             fmt(sy) + "\" stroke=\"" + colour + "\" stroke-width=\"" + fmt(width) + "\"" +
             (dash.empty() ? "" : " stroke-dasharray=\"" + dash + "\"") + "/>\n";
    body_ += "<path d=\"M" + fmt(bx) + " " + fmt(by) + " L" + fmt(sx - half * uy) + " " +
             fmt(sy + half * ux) + " L" + fmt(sx + half * uy) + " " + fmt(sy - half * ux) +
             " Z\" fill=\"" + colour + "\"/>\n";
  }

  /// Text at a world point, shifted by (dx, dy) pixels; anchor "start", "middle" or "end".
  void text(const View& v, double x, double y, const std::string& label, const std::string& anchor,
            double dx = 0.0, double dy = 0.0, const std::string& colour = "#222", int size = 13,
            bool italic = false) {
    textPixels(v.X(x) + dx, v.Y(y) + dy, label, anchor, colour, size, italic);
  }

  void textPixels(double px, double py, const std::string& label, const std::string& anchor,
                  const std::string& colour = "#222", int size = 13, bool italic = false,
                  double rotate = 0.0) {
    body_ += "<text x=\"" + fmt(px) + "\" y=\"" + fmt(py) + "\" font-size=\"" +
             std::to_string(size) + "\" text-anchor=\"" + anchor + "\" fill=\"" + colour + "\"" +
             (italic ? " font-style=\"italic\"" : "") +
             // A white halo under the letters keeps a label legible where it crosses a line.
             " stroke=\"white\" stroke-width=\"3\" stroke-linejoin=\"round\" paint-order=\"stroke\"" +
             (rotate != 0.0 ? " transform=\"rotate(" + fmt(rotate) + " " + fmt(px) + " " +
                                  fmt(py) + ")\""
                            : "") +
             ">" + escape(label) + "</text>\n";
  }

  /// A plot frame: the view's box, ticks on both axes and the axis labels.
  void axes(const View& v, const std::string& xlabel, const std::string& ylabel, int xticks = 5,
            int yticks = 5) {
    body_ += "<rect x=\"" + fmt(v.left) + "\" y=\"" + fmt(v.top) + "\" width=\"" + fmt(v.width) +
             "\" height=\"" + fmt(v.height) + "\" fill=\"none\" stroke=\"#444\"/>\n";
    for (double t : ticks(v.x0, v.x1, xticks)) {
      const double px = v.X(t);
      body_ += "<line x1=\"" + fmt(px) + "\" y1=\"" + fmt(v.top) + "\" x2=\"" + fmt(px) +
               "\" y2=\"" + fmt(v.top + v.height) + "\" stroke=\"#ddd\"/>\n";
      textPixels(px, v.top + v.height + 16, tick(t), "middle", "#444", 12);
    }
    for (double t : ticks(v.y0, v.y1, yticks)) {
      const double py = v.Y(t);
      body_ += "<line x1=\"" + fmt(v.left) + "\" y1=\"" + fmt(py) + "\" x2=\"" +
               fmt(v.left + v.width) + "\" y2=\"" + fmt(py) + "\" stroke=\"#ddd\"/>\n";
      textPixels(v.left - 6, py + 4, tick(t), "end", "#444", 12);
    }
    textPixels(v.left + 0.5 * v.width, v.top + v.height + 36, xlabel, "middle", "#222", 13);
    textPixels(v.left - 48, v.top + 0.5 * v.height, ylabel, "middle", "#222", 13, false, -90.0);
  }

  /// A legend box at pixel (px, py): one short line of each style and its label.
  void legend(double px, double py, const std::vector<std::pair<Style, std::string>>& entries) {
    double widest = 0.0;
    for (const auto& e : entries) widest = std::max(widest, 7.0 * static_cast<double>(e.second.size()));
    body_ += "<rect x=\"" + fmt(px) + "\" y=\"" + fmt(py) + "\" width=\"" + fmt(widest + 48) +
             "\" height=\"" + fmt(20.0 * static_cast<double>(entries.size()) + 8) +
             "\" fill=\"white\" fill-opacity=\"0.85\" stroke=\"#bbb\"/>\n";
    double y = py + 18;
    for (const auto& [style, label] : entries) {
      Style s = style;
      s.fill = "none";
      body_ += "<line x1=\"" + fmt(px + 8) + "\" y1=\"" + fmt(y - 4) + "\" x2=\"" + fmt(px + 34) +
               "\" y2=\"" + fmt(y - 4) + "\" " + s.attributes() + "/>\n";
      textPixels(px + 40, y, label, "start", "#222", 12);
      y += 20;
    }
  }

  /// Raw SVG for what the primitives above do not cover.
  void raw(const std::string& markup) { body_ += markup; }

  /// Write the figure to STACKBOOK_FIGURES_DIR/name; throws if the file cannot be written.
  void save(const std::string& name) const {
    const std::string path = std::string(STACKBOOK_FIGURES_DIR) + "/" + name;
    std::ofstream out(path);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width_ << "\" height=\""
        << height_ << "\" viewBox=\"0 0 " << width_ << " " << height_
        << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n"
        << "<title>" << escape(description_) << "</title>\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << body_ << "</svg>\n";
    if (!out) throw std::runtime_error("cannot write the figure " + path);
  }

 private:
  static std::vector<double> ticks(double a, double b, int count) {
    const double raw = (b - a) / std::max(1, count);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
      if (m * magnitude >= raw) {
        step = m * magnitude;
        break;
      }
    }
    std::vector<double> t;
    for (double x = std::ceil(a / step - 1e-9) * step; x <= b + 1e-9 * step; x += step) {
      t.push_back(std::abs(x) < 1e-12 * step ? 0.0 : x);
    }
    return t;
  }

  int width_, height_;
  std::string description_;
  std::string body_;
};

/// The zero contour of values sampled on a raster (marching squares): value(i, k) at
/// (x0 + i dx, y0 + k dy), i < nx, k < ny. Returns segments as point pairs.
template <class Value>
std::vector<std::pair<std::pair<double, double>, std::pair<double, double>>> zeroContour(
    const Value& value, int nx, int ny, double x0, double y0, double dx, double dy) {
  std::vector<std::pair<std::pair<double, double>, std::pair<double, double>>> segments;
  for (int i = 0; i + 1 < nx; ++i) {
    for (int k = 0; k + 1 < ny; ++k) {
      const double c[4] = {value(i, k), value(i + 1, k), value(i + 1, k + 1), value(i, k + 1)};
      const double px[4] = {x0 + i * dx, x0 + (i + 1) * dx, x0 + (i + 1) * dx, x0 + i * dx};
      const double py[4] = {y0 + k * dy, y0 + k * dy, y0 + (k + 1) * dy, y0 + (k + 1) * dy};
      std::vector<std::pair<double, double>> crossings;
      for (int e = 0; e < 4; ++e) {
        const int f = (e + 1) % 4;
        if ((c[e] < 0.0) != (c[f] < 0.0)) {
          const double t = c[e] / (c[e] - c[f]);
          crossings.emplace_back(px[e] + t * (px[f] - px[e]), py[e] + t * (py[f] - py[e]));
        }
      }
      for (std::size_t m = 0; m + 1 < crossings.size(); m += 2) {
        segments.emplace_back(crossings[m], crossings[m + 1]);
      }
    }
  }
  return segments;
}

/// A colour for a signed value: blue (negative) through white (0) to red (positive).
inline std::string divergingColour(double value, double range) {
  const double t = std::clamp(value / range, -1.0, 1.0);
  auto channel = [](double a, double b, double s) {
    return static_cast<int>(std::lround(a + (b - a) * s));
  };
  int r, g, b;
  if (t < 0.0) {  // white -> blue (#2166ac)
    r = channel(247, 33, -t), g = channel(247, 102, -t), b = channel(247, 172, -t);
  } else {  // white -> red (#b2182b)
    r = channel(247, 178, t), g = channel(247, 24, t), b = channel(247, 43, t);
  }
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", r, g, b);
  return buffer;
}

}  // namespace figure_svg
