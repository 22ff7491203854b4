// Chapter 10: the incline against its closed form. Runs scenes/incline.json as the program
// does, writes its trajectory CSV, reads the CSV back as any analysis tool would, and
// compares each block's distance down the slope s(t) with Coulomb's closed form
//   s(t) = v0 t + a t^2 / 2,  a = g (sin(theta) - mu cos(theta)),
// which holds while the block slides (a < 0 ends it at t = -v0 / a) and gives s = 0 for a
// block at rest with mu >= tan(theta). theta, mu, g and v0 are read from the scene file.
// Prints a Markdown table and writes figures/incline_plot.svg.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "stackbook/output/trajectory_csv.hpp"
#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/simulation.hpp"

namespace {

struct Block {
  std::string name;
  std::string color;
  double mu = 0.0;
  double v0 = 0.0;  // initial speed down the slope
  double a = 0.0;   // acceleration down the slope while sliding
  std::vector<double> t, s;  // from the CSV

  /// Closed-form distance down the slope.
  double closedForm(double time) const {
    if (v0 == 0.0 && a <= 0.0) return 0.0;  // static friction holds it
    if (a < 0.0) {
      const double stop = -v0 / a;
      time = std::min(time, stop);
    }
    return v0 * time + 0.5 * a * time * time;
  }
};

std::string hexColor(const nlohmann::json& c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", static_cast<int>(std::lround(255 * c[0].get<double>())),
                static_cast<int>(std::lround(255 * c[1].get<double>())),
                static_cast<int>(std::lround(255 * c[2].get<double>())));
  return text;
}

}  // namespace

int main() {
  using namespace stackbook;
  const std::string path = "scenes/incline.json";
  const nlohmann::json doc = readSceneJson(path);
  const Scene scene = loadScene(path);
  const double g = -doc.at("gravity")[1].get<double>();
  const nlohmann::json& bodies = doc.at("bodies");
  const nlohmann::json& materials = doc.at("materials");
  const double slopeMu = materials.at(bodies[0].at("material").get<std::string>()).at("friction").get<double>();
  const double theta = bodies[0].at("angleDeg").get<double>() * M_PI / 180.0;
  const double downX = -std::cos(theta), downY = -std::sin(theta);  // unit vector down the slope

  std::vector<Block> blocks;
  for (std::size_t k = 1; k < bodies.size(); ++k) {
    const nlohmann::json& b = bodies[k];
    Block block;
    block.name = b.at("name").get<std::string>();
    block.color = b.contains("color") ? hexColor(b.at("color")) : "#444444";
    // A pair's friction is the smaller of the two materials' (the min rule of chapter 8).
    block.mu = std::min(slopeMu, materials.at(b.at("material").get<std::string>()).at("friction").get<double>());
    if (b.contains("velocity")) {
      block.v0 = b.at("velocity")[0].get<double>() * downX + b.at("velocity")[1].get<double>() * downY;
    }
    block.a = g * (std::sin(theta) - block.mu * std::cos(theta));
    blocks.push_back(block);
  }

  // Run, write the trajectory, read it back.
  const SceneRun run = runScene(scene);
  const std::string figures = STACKBOOK_FIGURES_DIR;
  std::filesystem::create_directories(figures);
  const std::string csv = figures + "/incline_trajectory.csv";
  writeTrajectoryCsv<2>(std::get<RunResult<2>>(run).recording, csv);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header: time,body,name,x,y,angle,vx,vy,omega
  std::map<int, std::array<double, 2>> start;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string time, body, name, x, y;
    std::getline(fields, time, ',');
    std::getline(fields, body, ',');
    std::getline(fields, name, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    const int i = std::stoi(body);
    if (i == 0) continue;  // the incline itself
    const double px = std::stod(x), py = std::stod(y);
    if (!start.count(i)) start[i] = {px, py};
    Block& block = blocks[static_cast<std::size_t>(i - 1)];
    block.t.push_back(std::stod(time));
    block.s.push_back((px - start[i][0]) * downX + (py - start[i][1]) * downY);
  }

  // Plain HTML entities, not \f$ formulas: Doxygen's \include{doc} does not run MathJax.
  std::printf("| block | &mu; | v<sub>0</sub> (m/s) | a (m/s<sup>2</sup>) | stops at (s) | "
              "s(T) closed form (m) | s(T) simulated (m) | largest gap over the run (m) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  double tEnd = 0.0, sMin = 0.0, sMax = 0.0;
  for (const Block& b : blocks) {
    double gap = 0.0;
    for (std::size_t f = 0; f < b.t.size(); ++f) {
      gap = std::max(gap, std::abs(b.s[f] - b.closedForm(b.t[f])));
      sMin = std::min({sMin, b.s[f], b.closedForm(b.t[f])});
      sMax = std::max({sMax, b.s[f], b.closedForm(b.t[f])});
    }
    tEnd = std::max(tEnd, b.t.back());
    std::string stops = "never (static friction holds)";
    if (b.v0 > 0.0 || b.a > 0.0) stops = b.a < 0.0 ? "" : "never (accelerates)";
    if (stops.empty()) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3f", -b.v0 / b.a);
      stops = text;
    }
    std::printf("| %s | %g | %.3f | %.3f | %s | %.4f | %.4f | %.2e |\n", b.name.c_str(), b.mu, b.v0, b.a,
                stops.c_str(), b.closedForm(b.t.back()), b.s.back(), gap);
  }
  std::printf("\nThe slope is at &theta; = %g&deg; (tan &theta; = %.4f), g = %g m/s<sup>2</sup>, "
              "T = %g s, %zu frames read from the CSV.\n",
              theta * 180.0 / M_PI, std::tan(theta), g, tEnd, blocks.front().t.size());

  // The plot: closed forms as lines, the simulated samples as dots.
  const double W = 640, H = 380, left = 60, right = 150, top = 20, bottom = 45;
  const double pw = W - left - right, ph = H - top - bottom;
  const double s0 = std::floor(sMin), s1 = std::ceil(sMax);
  const auto X = [&](double t) { return left + pw * t / tEnd; };
  const auto Y = [&](double s) { return top + ph * (1.0 - (s - s0) / (s1 - s0)); };
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 "
      << W << ' ' << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  for (double s = s0; s <= s1 + 1e-9; s += 1.0) {
    svg << "<line x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << Y(s) << "\" y2=\"" << Y(s)
        << "\" stroke=\"#e4e4e4\"/><text x=\"" << left - 8 << "\" y=\"" << Y(s) + 4
        << "\" text-anchor=\"end\">" << s << "</text>\n";
  }
  for (double t = 0.0; t <= tEnd + 1e-9; t += 0.5) {
    svg << "<line x1=\"" << X(t) << "\" x2=\"" << X(t) << "\" y1=\"" << top << "\" y2=\"" << top + ph
        << "\" stroke=\"#e4e4e4\"/><text x=\"" << X(t) << "\" y=\"" << top + ph + 16
        << "\" text-anchor=\"middle\">" << t << "</text>\n";
  }
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"#333\"/>\n"
      << "<text x=\"" << left + pw / 2 << "\" y=\"" << H - 8 << "\" text-anchor=\"middle\">time t (s)</text>\n"
      << "<text transform=\"translate(16," << top + ph / 2
      << ") rotate(-90)\" text-anchor=\"middle\">distance down the slope s (m)</text>\n";
  double legendY = top + 10;
  for (const Block& b : blocks) {
    svg << "<polyline fill=\"none\" stroke=\"" << b.color << "\" stroke-width=\"2\" points=\"";
    for (int k = 0; k <= 200; ++k) {
      const double t = tEnd * k / 200.0;
      svg << X(t) << ',' << Y(b.closedForm(t)) << ' ';
    }
    svg << "\"/>\n";
    for (std::size_t f = 0; f < b.t.size(); f += 4) {
      svg << "<circle cx=\"" << X(b.t[f]) << "\" cy=\"" << Y(b.s[f]) << "\" r=\"2.6\" fill=\"none\" stroke=\""
          << b.color << "\"/>\n";
    }
    if (b.a < 0.0 && b.v0 > 0.0) {
      const double stop = -b.v0 / b.a;
      svg << "<line x1=\"" << X(stop) << "\" x2=\"" << X(stop) << "\" y1=\"" << top << "\" y2=\"" << top + ph
          << "\" stroke=\"" << b.color << "\" stroke-dasharray=\"4 3\"/>\n";
    }
    svg << "<line x1=\"" << left + pw + 12 << "\" x2=\"" << left + pw + 32 << "\" y1=\"" << legendY << "\" y2=\""
        << legendY << "\" stroke=\"" << b.color << "\" stroke-width=\"2\"/><text x=\"" << left + pw + 38
        << "\" y=\"" << legendY + 4 << "\">" << b.name << " (mu " << b.mu << ")</text>\n";
    legendY += 20;
  }
  svg << "<text x=\"" << left + pw + 12 << "\" y=\"" << legendY + 8 << "\">lines: closed form</text>\n"
      << "<text x=\"" << left + pw + 12 << "\" y=\"" << legendY + 24 << "\">circles: simulated</text>\n"
      << "</svg>\n";
  std::ofstream(figures + "/incline_plot.svg") << svg.str();
  return 0;
}
