// Prints, as a Markdown table, how the interpolation error of a signed-distance grid falls
// with the cell size h (chapter 6): grids sampled from exact distances (no tessellation),
// smooth shapes (sphere, torus, disk, annulus) and kinked ones (box, rectangle). Errors at
// 2000 seeded points of a band (sphere, disk: |phi| <= 0.25; torus, annulus: |phi| <= 0.1;
// box, rectangle: the inside and 0.02 outside), with the observed order log2(e_2h / e_h);
// normal errors are the largest angle to the exact normal, for central differences (CD)
// and for the interpolant's own gradient (ID).
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

using namespace stackbook;

namespace {

template <int D, class Sdf>
void interpolationRows(const char* name, const Sdf& sdf, double lo, double hi,
                       const std::vector<int>& resolutions) {
  const std::function<double(const Vec<D>&)> phi = [&](const Vec<D>& x) { return sdf.distance(x); };
  const std::vector<Vec<D>> points = sampleBand<D>(phi, sdf.bounds(), lo, hi, 2000, 5);
  SdfErrorStats previous[2];
  for (std::size_t r = 0; r < resolutions.size(); ++r) {
    SdfErrorStats stats[2];
    double h = 0.0;
    for (int method = 0; method < 2; ++method) {
      SdfGridSettings settings;
      settings.cellsAcrossLargestExtent = resolutions[r];
      settings.gradient = method == 0 ? SdfGradientMethod::CentralDifferences
                                      : SdfGradientMethod::InterpolantDerivative;
      const SdfGrid<D> grid = sampleSdfGrid<D>(phi, sdf.bounds(), settings);
      h = grid.cellSize();
      stats[method] = compareSdf<D>(
          points, [&](const Vec<D>& x) { return grid.value(x); },
          [&](const Vec<D>& x) { return grid.normal(x); }, phi,
          [&](const Vec<D>& x) { return sdf.normal(x); });
    }
    const auto order = [&](double before, double now) {
      if (r == 0) return std::string("");
      std::ostringstream out;
      out.precision(2);
      out << std::fixed << std::log2(before / now);
      return out.str();
    };
    std::printf("| %s | %d | %.4f | %.2e | %s | %.2e | %s | %.2e | %s | %.2e | %s |\n", name,
                resolutions[r], h, stats[0].maxError,
                order(previous[0].maxError, stats[0].maxError).c_str(), stats[0].rmsError,
                order(previous[0].rmsError, stats[0].rmsError).c_str(), stats[0].maxAngle,
                order(previous[0].maxAngle, stats[0].maxAngle).c_str(), stats[1].maxAngle,
                order(previous[1].maxAngle, stats[1].maxAngle).c_str());
    previous[0] = stats[0];
    previous[1] = stats[1];
  }
}

}  // namespace

int main() {
  std::printf("| shape | cells | h | max error | order | RMS error | order | CD angle | order | ID angle | order |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  interpolationRows<3>("sphere r 0.5", SphereSdf<3>(0.5), -0.25, 0.25, {16, 32, 64});
  interpolationRows<3>("torus 0.5, 0.2", TorusSdf<3>(0.5, 0.2), -0.1, 0.1, {16, 32, 64});
  interpolationRows<3>("box 1 x 0.6 x 0.4", BoxSdf<3>(Vec3(0.5, 0.3, 0.2)), -1.0, 0.02, {16, 32, 64});
  interpolationRows<2>("disk r 0.5", SphereSdf<2>(0.5), -0.25, 0.25, {16, 32, 64, 128});
  interpolationRows<2>("annulus 0.5, 0.2", TorusSdf<2>(0.5, 0.2), -0.1, 0.1, {16, 32, 64, 128});
  interpolationRows<2>("rectangle 1 x 0.6", BoxSdf<2>(Vec2(0.5, 0.3)), -1.0, 0.02, {16, 32, 64, 128});
  return 0;
}
